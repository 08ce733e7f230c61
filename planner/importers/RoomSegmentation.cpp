// Room segmentation of a cleaned occupancy grid (issue 15), after ipa_room_segmentation's
// distance-transform and morphological variants. The distance variant splits the free space
// into the basins of the distance to the walls and keeps apart the basins whose peaks stand
// clearly above the doorway between them; the morphological variant erodes the free space
// into room cores and grows them back over the free cells, the narrow places dearest.
#include "importers/OccupancyGrid.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <queue>

namespace fc::importing {

namespace {

// Islands up to this area (m^2) are furniture: beds, desks, a nurses' station, a pillar. The
// gaps beside them are not doorways, so the rooms are found as if they were floor.
constexpr double kFurnitureArea = 10.0;

// A doorway spans at most this share of the floor beside it, on one side at least, measured
// along it these distances (m) into each side.
constexpr double kDoorwayShareOfSide = 0.6;
constexpr double kDoorwaySideDepths[] = {0.5, 0.8, 1.1, 1.4, 1.7, 2.0};

// `free` with the obstacle islands of at most `maxCells` cells (not touching the map's edge)
// made free.
cv::Mat withoutFurniture(const cv::Mat& free, int maxCells) {
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(free == 0, labels, stats, centroids, 8, CV_32S);
    std::vector<unsigned char> furniture(n, 0);
    for (int i = 1; i < n; ++i) {
        const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
        const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
        furniture[i] = x > 0 && y > 0 && x + w < free.cols && y + h < free.rows &&
                       stats.at<int>(i, cv::CC_STAT_AREA) <= maxCells;
    }
    cv::Mat out = free.clone();
    for (int r = 0; r < out.rows; ++r)
        for (int c = 0; c < out.cols; ++c)
            if (furniture[labels.at<int>(r, c)])
                out.at<unsigned char>(r, c) = 255;
    return out;
}

// Distance variant: the basins of the distance to the walls. Cells are taken from the widest
// place down; each joins the basin of its neighbour that stands highest (so the band along a
// wall joins the room it lines, never the basin next door). Where two basins meet, at a saddle
// (a doorway), both stay rooms when each peak stands clearly above the saddle (by `minRatio`
// times and `minRise` cells) and holds `minCells`; otherwise the lesser joins the greater (a
// corridor's bumps, the two sides of a pillar, an alcove). Topological persistence, in short.
int distanceBasins(const cv::Mat& free, const cv::Mat& dist, int minCells, double minRise,
                   double minRatio, cv::Mat& markers) {
    const int width = free.cols;
    std::vector<int> order;
    for (int r = 0; r < free.rows; ++r)
        for (int c = 0; c < width; ++c)
            if (free.at<unsigned char>(r, c))
                order.push_back(r * width + c);
    const auto height = [&](int cell) { return dist.at<float>(cell / width, cell % width); };
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return height(a) > height(b); });
    std::vector<int> parent(free.total(), -1), size(free.total(), 0);
    std::vector<float> peak(free.total(), 0);
    const auto find = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    const auto significant = [&](int root, float saddle) {
        return peak[root] - saddle >= minRise && peak[root] >= minRatio * saddle &&
               size[root] >= minCells;
    };
    for (const int cell : order) {
        const int r = cell / width, c = cell % width;
        const float level = height(cell);
        std::vector<int> neighbours;
        int steepest = -1;
        for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc) {
                const int rr = r + dr, cc = c + dc;
                if ((dr || dc) && rr >= 0 && cc >= 0 && rr < free.rows && cc < width &&
                    parent[rr * width + cc] >= 0) {
                    neighbours.push_back(rr * width + cc);
                    if (steepest < 0 || height(rr * width + cc) > height(steepest))
                        steepest = rr * width + cc;
                }
            }
        if (steepest < 0) { // a peak: a basin of its own
            parent[cell] = cell, size[cell] = 1, peak[cell] = level;
            continue;
        }
        const int basin = find(steepest);
        parent[cell] = basin;
        ++size[basin];
        for (const int neighbour : neighbours) {
            int a = find(cell), b = find(neighbour);
            if (a == b)
                continue;
            if (peak[a] < peak[b])
                std::swap(a, b);
            if (significant(b, level))
                continue; // two rooms meet here
            parent[b] = a;
            size[a] += size[b];
        }
    }
    markers = cv::Mat::zeros(free.size(), CV_32S);
    std::vector<int> labelOfRoot(free.total(), 0);
    int rooms = 0;
    for (const int cell : order) {
        const int root = find(cell);
        if (!labelOfRoot[root])
            labelOfRoot[root] = ++rooms;
        markers.at<int>(cell / width, cell % width) = labelOfRoot[root];
    }
    return rooms;
}

// Morphological variant: the free space is eroded cell by cell; a component that has become
// smaller than `maxCells` (and not smaller than `minCells`) is taken as a room core and
// removed from further erosion.
int morphologicalCores(const cv::Mat& free, int minCells, int maxCells, cv::Mat& markers) {
    markers = cv::Mat::zeros(free.size(), CV_32S);
    cv::Mat eroded = free.clone();
    const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3));
    int rooms = 0;
    while (cv::countNonZero(eroded) > 0) {
        cv::erode(eroded, eroded, cross);
        cv::Mat labels, stats, centroids;
        const int n = cv::connectedComponentsWithStats(eroded, labels, stats, centroids, 8, CV_32S);
        std::vector<int> take(n, 0);
        for (int i = 1; i < n; ++i) {
            const int area = stats.at<int>(i, cv::CC_STAT_AREA);
            if (area <= maxCells && area >= minCells)
                take[i] = ++rooms;
        }
        for (int r = 0; r < labels.rows; ++r) {
            const int* label = labels.ptr<int>(r);
            int* marker = markers.ptr<int>(r);
            unsigned char* e = eroded.ptr<unsigned char>(r);
            for (int c = 0; c < labels.cols; ++c)
                if (take[label[c]]) {
                    marker[c] = take[label[c]];
                    e[c] = 0;
                }
        }
    }
    return rooms;
}

// Grows the cores over the free cells (4-connected) by the cheapest route, where a step costs
// the inverse of the clearance there: narrow places are dear, so two rooms meet in the
// doorway between them, and a cell next to a wall joins the room it stands in (a watershed
// on the distance relief floods at equal levels: a corridor's basin crept through each door
// along the band next to every wall of the office behind it, and rooms touched everywhere).
void growCores(cv::Mat& markers, const cv::Mat& free, const cv::Mat& dist) {
    cv::Mat cost(markers.size(), CV_32F, cv::Scalar(INFINITY));
    using Entry = std::pair<float, std::pair<int, int>>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    for (int r = 0; r < markers.rows; ++r)
        for (int c = 0; c < markers.cols; ++c)
            if (markers.at<int>(r, c) > 0) {
                cost.at<float>(r, c) = 0;
                open.push({0.0f, {r, c}});
            }
    while (!open.empty()) {
        const auto [g, cell] = open.top();
        open.pop();
        const auto [r, c] = cell;
        if (g > cost.at<float>(r, c))
            continue;
        const int label = markers.at<int>(r, c);
        for (const auto& [dr, dc] :
             {std::pair{0, 1}, std::pair{1, 0}, std::pair{0, -1}, std::pair{-1, 0}}) {
            const int rr = r + dr, cc = c + dc;
            if (rr < 0 || cc < 0 || rr >= markers.rows || cc >= markers.cols ||
                !free.at<unsigned char>(rr, cc))
                continue;
            const float next = g + 1.0f / std::max(dist.at<float>(rr, cc), 0.5f);
            if (next < cost.at<float>(rr, cc)) {
                cost.at<float>(rr, cc) = next;
                markers.at<int>(rr, cc) = label;
                open.push({next, {rr, cc}});
            }
        }
    }
}

// How far the free space reaches from (r, c) along (dr, dc) and against it, in cells (at most
// `cap` each way).
double reachAcross(const cv::Mat& free, double r, double c, double dr, double dc, double cap) {
    double total = 0.0;
    for (const double sign : {1.0, -1.0}) {
        double t = 0.0;
        while (t < cap) {
            const int rr = static_cast<int>(std::lround(r + sign * (t + 0.5) * dr)),
                      cc = static_cast<int>(std::lround(c + sign * (t + 0.5) * dc));
            if (rr < 0 || cc < 0 || rr >= free.rows || cc >= free.cols ||
                !free.at<unsigned char>(rr, cc))
                break;
            t += 0.5;
        }
        total += t;
    }
    return total;
}

// Whether a border no wider than a door is one: a doorway is much narrower than the floor on
// at least one side of it (a room's width, a corridor's length), measured along the border a
// little way into each side. A corridor that clutter narrows to a door's width is not: the
// border spans most of the corridor's width on both sides (the office map whose corridor a
// speck blob narrowed from 2 m to 1.6 m was cut in two there).
bool bordersLikeADoorway(const std::vector<std::pair<int, int>>& cells, int span, int a, int b,
                         const std::vector<std::int32_t>& labels, const cv::Mat& free,
                         double resolution) {
    double mr = 0, mc = 0;
    for (const auto& [r, c] : cells)
        mr += r, mc += c;
    mr /= cells.size(), mc /= cells.size();
    double srr = 0, scc = 0, src = 0;
    for (const auto& [r, c] : cells)
        srr += (r - mr) * (r - mr), scc += (c - mc) * (c - mc), src += (r - mr) * (c - mc);
    // The border's direction: the principal axis of its cells.
    const double angle = 0.5 * std::atan2(2 * src, srr - scc);
    const double ur = std::cos(angle), uc = std::sin(angle);
    const double cap = 3.0 * span;
    // Each room's width beside the border: the least at the depths that lie in it (a line
    // that escapes through a door, or two doors facing each other across a corridor, does not
    // make the side wide); a room with no such depth counts as wide.
    double sideA = INFINITY, sideB = INFINITY;
    for (const double sign : {1.0, -1.0})
        for (const double depth : kDoorwaySideDepths) {
            const double d = sign * depth / resolution;
            const int r = static_cast<int>(std::lround(mr - d * uc)),
                      c = static_cast<int>(std::lround(mc + d * ur));
            if (r < 0 || c < 0 || r >= free.rows || c >= free.cols)
                continue;
            const int label = labels[static_cast<size_t>(r) * free.cols + c];
            if (label != a && label != b)
                continue;
            double& side = label == a ? sideA : sideB;
            side = std::min(side, reachAcross(free, r, c, ur, uc, cap));
        }
    const double widest = std::max(sideA, sideB);
    return span <= kDoorwayShareOfSide * widest;
}

// Rooms that meet along more than a doorway's width are one room cut at a wide place (a
// hall around a pillar, a corridor's bend), and so are rooms whose border spans most of the
// floor on both sides (bordersLikeADoorway; with `acrossNarrowings`): merged, and the labels
// renumbered 1..n.
int mergeAcrossWideBorders(std::vector<std::int32_t>& labels, const cv::Mat& free, int rooms,
                           double maxDoorCells, bool acrossNarrowings, double resolution) {
    const int width = free.cols, height = free.rows;
    // Where two rooms touch, as the span of those cells: a door's border spans the door, a
    // room cut at a wide place spans that place (a jagged border counts as its span, not as
    // its staircase's length).
    struct Border {
        int r0 = INT_MAX, r1 = INT_MIN, c0 = INT_MAX, c1 = INT_MIN;
        std::vector<std::pair<int, int>> cells;
        int span() const { return std::max(r1 - r0, c1 - c0) + 1; }
        void add(int r, int c) {
            r0 = std::min(r0, r), r1 = std::max(r1, r), c0 = std::min(c0, c), c1 = std::max(c1, c);
            cells.emplace_back(r, c);
        }
    };
    std::map<std::pair<int, int>, Border> border;
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const int a = labels[static_cast<size_t>(r) * width + c];
            if (a <= 0)
                continue;
            for (const auto& [dr, dc] : {std::pair{0, 1}, std::pair{1, 0}}) {
                if (r + dr >= height || c + dc >= width)
                    continue;
                const int b = labels[static_cast<size_t>(r + dr) * width + c + dc];
                if (b > 0 && b != a) {
                    Border& e = border[{std::min(a, b), std::max(a, b)}];
                    e.add(r, c);
                    e.add(r + dr, c + dc);
                }
            }
        }
    std::vector<int> parent(rooms + 1);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const auto& [pair, b] : border)
        if (b.span() > maxDoorCells ||
            (acrossNarrowings && !bordersLikeADoorway(b.cells, b.span(), pair.first, pair.second,
                                                      labels, free, resolution)))
            parent[find(pair.first)] = find(pair.second);
    std::vector<int> renumber(rooms + 1, 0);
    int merged = 0;
    for (int room = 1; room <= rooms; ++room)
        if (find(room) == room)
            renumber[room] = ++merged;
    for (std::int32_t& label : labels)
        if (label > 0)
            label = renumber[find(label)];
    return merged;
}

} // namespace

std::vector<std::int32_t> segmentRooms(const std::vector<unsigned char>& freeCells, int width,
                                       int height, double resolution,
                                       const RoomSegmentationOptions& options, int& rooms) {
    rooms = 0;
    std::vector<std::int32_t> out(freeCells.size(), 0);
    if (options.method == RoomSegmentationMethod::None)
        return out;
    const double cellArea = resolution * resolution;
    const cv::Mat free = withoutFurniture(
        cv::Mat(height, width, CV_8U, const_cast<unsigned char*>(freeCells.data())) != 0,
        static_cast<int>(kFurnitureArea / cellArea));
    const int minCells = std::max(1, static_cast<int>(options.minRoomArea / cellArea));
    cv::Mat dist;
    cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    cv::Mat markers;
    if (options.method == RoomSegmentationMethod::Distance) {
        // A doorway 0.9 m wide off a corridor 1.8 m wide: the corridor's peak stands twice as
        // high as the saddle in the door; a corridor's own bumps stand a few cells high.
        rooms =
            distanceBasins(free, dist, std::max(1, minCells / 4), 0.25 / resolution, 1.4, markers);
    } else {
        const int maxCells = std::max(minCells, static_cast<int>(60.0 / cellArea));
        rooms = morphologicalCores(free, std::max(1, minCells / 4), maxCells, markers);
        if (rooms > 0)
            growCores(markers, free, dist);
    }
    if (rooms == 0) { // too small to split: one room
        rooms = 1;
        for (size_t i = 0; i < out.size(); ++i)
            out[i] = freeCells[i] ? 1 : 0;
        return out;
    }
    bool unreached = false;
    for (size_t i = 0; i < out.size(); ++i) {
        if (!freeCells[i])
            continue;
        out[i] =
            std::max(markers.at<int>(static_cast<int>(i / width), static_cast<int>(i % width)), 0);
        unreached = unreached || out[i] == 0;
    }
    // A free cell no core reached (a part without a core) takes the nearest room.
    if (unreached) {
        const std::vector<std::int32_t> nearest = labelTerritories(out, width, height);
        for (size_t i = 0; i < out.size(); ++i)
            if (freeCells[i] && out[i] == 0)
                out[i] = nearest[i];
    }
    if (options.maxDoorWidth > 0)
        rooms = mergeAcrossWideBorders(out, free, rooms, options.maxDoorWidth / resolution,
                                       options.mergeAcrossNarrowings, resolution);
    return out;
}

std::vector<std::int32_t> labelTerritories(const std::vector<std::int32_t>& labels, int width,
                                           int height) {
    cv::Mat source(height, width, CV_8U), distance, indices;
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c)
            source.at<unsigned char>(r, c) =
                labels[static_cast<size_t>(r) * width + c] > 0 ? 0 : 255;
    cv::distanceTransform(source, distance, indices, cv::DIST_L2, 5, cv::DIST_LABEL_PIXEL);
    std::vector<std::int32_t> labelOfIndex(static_cast<size_t>(width) * height + 2, 0);
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c)
            if (source.at<unsigned char>(r, c) == 0)
                labelOfIndex[indices.at<int>(r, c)] = labels[static_cast<size_t>(r) * width + c];
    std::vector<std::int32_t> out(labels.size());
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c)
            out[static_cast<size_t>(r) * width + c] = labelOfIndex[indices.at<int>(r, c)];
    return out;
}

} // namespace fc::importing
