// Room segmentation of a cleaned occupancy grid (issue 15), after ipa_room_segmentation's
// distance-transform and morphological variants: room cores are found where the free space
// is wide, then grown back over all free cells with OpenCV's watershed, whose flooding from
// the wide middle of each room towards the walls meets other rooms in the doorways.
#include "importers/OccupancyGrid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <opencv2/imgproc.hpp>

namespace fc::importing {

namespace {

// Labels (1..n) of the components of `mask` of at least `minCells` cells; the rest 0.
int labelLargeComponents(const cv::Mat& mask, int minCells, cv::Mat& labels) {
    cv::Mat stats, centroids;
    const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
    std::vector<int> relabel(n, 0);
    int kept = 0;
    for (int i = 1; i < n; ++i)
        if (stats.at<int>(i, cv::CC_STAT_AREA) >= minCells)
            relabel[i] = ++kept;
    for (int r = 0; r < labels.rows; ++r) {
        int* row = labels.ptr<int>(r);
        for (int c = 0; c < labels.cols; ++c)
            row[c] = relabel[row[c]];
    }
    return kept;
}

// Distance variant: the threshold on the distance to the nearest wall that splits the free
// space into the most cores of at least `minCells` (ties: the lowest threshold).
int distanceCores(const cv::Mat& dist, int minCells, double step, cv::Mat& markers) {
    double maxDistance = 0;
    cv::minMaxLoc(dist, nullptr, &maxDistance);
    int best = 0;
    for (double t = step; t < maxDistance; t += step) {
        cv::Mat labels;
        const int count = labelLargeComponents(dist > t, minCells, labels);
        if (count > best) {
            best = count;
            markers = labels;
        }
    }
    return best;
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

// Rooms that meet along more than a doorway's width are one room cut at a wide place (a
// hall around a pillar, a corridor's bend): merged, and the labels renumbered 1..n.
int mergeAcrossWideBorders(std::vector<std::int32_t>& labels, int width, int height, int rooms,
                           double maxDoorCells) {
    std::map<std::pair<int, int>, int> border; // cell edges between two rooms
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const int a = labels[static_cast<size_t>(r) * width + c];
            if (a <= 0)
                continue;
            for (const auto& [dr, dc] : {std::pair{0, 1}, std::pair{1, 0}}) {
                if (r + dr >= height || c + dc >= width)
                    continue;
                const int b = labels[static_cast<size_t>(r + dr) * width + c + dc];
                if (b > 0 && b != a)
                    ++border[{std::min(a, b), std::max(a, b)}];
            }
        }
    std::vector<int> parent(rooms + 1);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const auto& [pair, cells] : border)
        if (cells > maxDoorCells)
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
    const cv::Mat free =
        cv::Mat(height, width, CV_8U, const_cast<unsigned char*>(freeCells.data())) != 0;
    const double cellArea = resolution * resolution;
    const int minCells = std::max(1, static_cast<int>(options.minRoomArea / cellArea));
    cv::Mat dist;
    cv::distanceTransform(free, dist, cv::DIST_L2, 5);
    cv::Mat markers;
    if (options.method == RoomSegmentationMethod::Distance) {
        // Cores of a quarter of the smallest room's area: a room of that size keeps that much
        // of its middle at the threshold where its doorway has closed.
        rooms = distanceCores(dist, std::max(1, minCells / 4), std::max(1.0, 0.1 / resolution),
                              markers);
    } else {
        const int maxCells = std::max(minCells, static_cast<int>(60.0 / cellArea));
        rooms = morphologicalCores(free, std::max(1, minCells / 4), maxCells, markers);
    }
    if (rooms == 0) { // too small to split: one room
        rooms = 1;
        for (size_t i = 0; i < out.size(); ++i)
            out[i] = freeCells[i] ? 1 : 0;
        return out;
    }
    // Flood from the cores: watershed floods the darkest pixels first, so the free space is
    // drawn darker the farther it is from a wall and the walls white (flooded last).
    double maxDistance = 1;
    cv::minMaxLoc(dist, nullptr, &maxDistance);
    cv::Mat relief(height, width, CV_8U);
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const float d = dist.at<float>(r, c);
            relief.at<unsigned char>(r, c) =
                d <= 0 ? 255
                       : static_cast<unsigned char>(254 - std::lround(253.0 * d / maxDistance));
        }
    cv::Mat relief3;
    cv::cvtColor(relief, relief3, cv::COLOR_GRAY2BGR);
    cv::watershed(relief3, markers);
    // Watershed lines (-1) and any free cell left unlabelled take the nearest labelled cell's
    // room.
    cv::Mat unlabelled(height, width, CV_8U), nearest, indices;
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c)
            unlabelled.at<unsigned char>(r, c) =
                free.at<unsigned char>(r, c) && markers.at<int>(r, c) <= 0 ? 255 : 0;
    const bool anyUnlabelled = cv::countNonZero(unlabelled) > 0;
    std::vector<int> labelOfIndex;
    if (anyUnlabelled) {
        cv::Mat source = ~unlabelled; // zero where labelled or wall: restrict to labelled free
        for (int r = 0; r < height; ++r)
            for (int c = 0; c < width; ++c)
                if (!free.at<unsigned char>(r, c))
                    source.at<unsigned char>(r, c) = 255;
        cv::distanceTransform(source, nearest, indices, cv::DIST_L2, 5, cv::DIST_LABEL_PIXEL);
        labelOfIndex.assign(static_cast<size_t>(width) * height + 2, 0);
        for (int r = 0; r < height; ++r)
            for (int c = 0; c < width; ++c)
                if (source.at<unsigned char>(r, c) == 0)
                    labelOfIndex[indices.at<int>(r, c)] = markers.at<int>(r, c);
    }
    for (int r = 0; r < height; ++r)
        for (int c = 0; c < width; ++c) {
            const size_t i = static_cast<size_t>(r) * width + c;
            if (!freeCells[i])
                continue;
            const int label = markers.at<int>(r, c);
            out[i] = label > 0 ? label : labelOfIndex[indices.at<int>(r, c)];
        }
    if (options.maxDoorWidth > 0)
        rooms =
            mergeAcrossWideBorders(out, width, height, rooms, options.maxDoorWidth / resolution);
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
