// Cleaning a SLAM occupancy grid before it is traced (issue 15), with OpenCV's connected
// components and morphology: sensor speckle, stray pixels and ragged wall edges would
// otherwise each become an obstacle the coverage path has to zigzag around.
#include "importers/OccupancyGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace fc::importing {

namespace {

double cellArea(const OccupancyGrid& grid) {
    return grid.resolution * grid.resolution;
}

// A connected component of a mask: its cells, and whether it touches the image border.
struct Component {
    int area = 0;
    bool border = false;
};

// The components of `mask` (255) that `drop(labels, components)` marks (a flag per label,
// 0 the background) are set to `fill`. Returns their count and their cells.
template <typename Drop>
std::pair<int, long long> dropComponents(cv::Mat& mask, int connectivity, unsigned char fill,
                                         Drop drop) {
    cv::Mat labels, stats, centroids;
    const int n =
        cv::connectedComponentsWithStats(mask, labels, stats, centroids, connectivity, CV_32S);
    std::vector<Component> parts(n);
    for (int i = 1; i < n; ++i) {
        const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
        const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
        parts[i] = {stats.at<int>(i, cv::CC_STAT_AREA),
                    x == 0 || y == 0 || x + w == mask.cols || y + h == mask.rows};
    }
    const std::vector<char> dropped = drop(labels, parts);
    int count = 0;
    long long cells = 0;
    for (int i = 1; i < n; ++i)
        if (dropped[i]) {
            ++count;
            cells += parts[i].area;
        }
    if (count > 0)
        for (int r = 0; r < mask.rows; ++r) {
            const int* label = labels.ptr<int>(r);
            unsigned char* m = mask.ptr<unsigned char>(r);
            for (int c = 0; c < mask.cols; ++c)
                if (dropped[label[c]])
                    m[c] = fill;
        }
    return {count, cells};
}

// Components of `mask` (255) smaller than `minCells` are set to `fill`; components touching
// the image border are kept when `keepBorder` (the world outside the map). Returns the
// count and the number of cells changed.
std::pair<int, long long> removeSmallComponents(cv::Mat& mask, int minCells, bool keepBorder,
                                                unsigned char fill, int connectivity) {
    if (minCells <= 1)
        return {0, 0};
    return dropComponents(
        mask, connectivity, fill, [&](const cv::Mat&, const std::vector<Component>& parts) {
            std::vector<char> drop(parts.size(), 0);
            for (size_t i = 1; i < parts.size(); ++i)
                drop[i] = parts[i].area < minCells && !(keepBorder && parts[i].border);
            return drop;
        });
}

// Unknown patches no laser return borders are floor up to this many times the gap area.
constexpr int kUnobservedGapFactor = 4;
// Returns (m of cells, 8-connected) that make an unknown patch they border a thing's inside.
constexpr double kMinThingReturns = 0.25;

// Unknown gaps inside the mapped floor (4-connected components of `unknown` off the image
// border) become floor: those smaller than minCells, and those up to kUnobservedGapFactor
// times that which touch no occupied cell (8-neighbourhood; `occupied` without lone
// returns). A gap with returns on its edge may be a thing's inside; one with none is floor
// no scan reached (blind spots run together), where the rays passed on every side.
// Returns the count and the cells filled.
std::pair<int, long long> fillUnknownGaps(cv::Mat& unknown, const cv::Mat& occupied, int minCells) {
    if (minCells <= 1)
        return {0, 0};
    return dropComponents(
        unknown, 4, 0, [&](const cv::Mat& labels, const std::vector<Component>& parts) {
            cv::Mat nearHit;
            cv::dilate(occupied, nearHit,
                       cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)));
            std::vector<char> hit(parts.size(), 0), fill(parts.size(), 0);
            for (int r = 0; r < labels.rows; ++r) {
                const int* label = labels.ptr<int>(r);
                const unsigned char* near = nearHit.ptr<unsigned char>(r);
                for (int c = 0; c < labels.cols; ++c)
                    if (label[c] > 0 && near[c])
                        hit[label[c]] = 1;
            }
            for (size_t i = 1; i < parts.size(); ++i)
                fill[i] = !parts[i].border &&
                          (parts[i].area < minCells ||
                           (!hit[i] && parts[i].area < kUnobservedGapFactor * minCells));
            return fill;
        });
}

// A disc of at most `radiusCells` (whole cells), so that no step reaches further than asked.
cv::Mat disc(double radiusCells) {
    const int r = static_cast<int>(std::floor(radiusCells + 1e-9));
    return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1));
}

int cellsOf(double area, const OccupancyGrid& grid) {
    return static_cast<int>(std::ceil(std::max(area, 0.0) / cellArea(grid) - 1e-9));
}

} // namespace

std::vector<unsigned char> cleanOccupancyGrid(const OccupancyGrid& grid,
                                              const MapCleaningOptions& options,
                                              double robotDiameter, MapCleaningReport& report) {
    for (const auto& [radius, what] :
         {std::pair{options.openingRadius, "opening"}, std::pair{options.closingRadius, "closing"}})
        if (!(radius <= MapCleaningOptions::kMaxMorphologyRadius)) {
            char text[128];
            std::snprintf(text, sizeof text, "the %s radius must be at most %g m (got %g m)", what,
                          MapCleaningOptions::kMaxMorphologyRadius, radius);
            throw InputError(text);
        }
    report.width = grid.width;
    report.height = grid.height;
    report.resolution = grid.resolution;
    cv::Mat free(grid.height, grid.width, CV_8U);
    long long freeCells = 0;
    for (int r = 0; r < grid.height; ++r) {
        unsigned char* row = free.ptr<unsigned char>(r);
        for (int c = 0; c < grid.width; ++c) {
            const unsigned char cell = grid.cells[static_cast<size_t>(r) * grid.width + c];
            report.unknownCells += cell == kUnknown;
            const bool isFree = cell == kFree || (cell == kUnknown && options.unknownIsFree);
            row[c] = isFree ? 255 : 0;
            freeCells += isFree;
        }
    }
    report.freeAreaBefore = freeCells * cellArea(grid);
    if (options.enabled && !options.unknownIsFree) {
        // Unknown gaps inside the mapped floor (a blind spot behind a chair leg, a missed
        // scan): small ones become floor, as they would otherwise stand as teeth on the
        // walls they touch. The unknown world around the map touches the image border.
        cv::Mat unknown(grid.height, grid.width, CV_8U), occupied(grid.height, grid.width, CV_8U);
        for (int r = 0; r < grid.height; ++r) {
            unsigned char* row = unknown.ptr<unsigned char>(r);
            unsigned char* hit = occupied.ptr<unsigned char>(r);
            for (int c = 0; c < grid.width; ++c) {
                const unsigned char cell = grid.cells[static_cast<size_t>(r) * grid.width + c];
                row[c] = cell == kUnknown ? 255 : 0;
                hit[c] = cell == kOccupied ? 255 : 0;
            }
        }
        // A return or two beside a gap is speckle; a thing seen from one side is a line of
        // them (kMinThingReturns long). Only a line makes the gap the inside of a thing:
        // counting area instead, a 0.6 m box seen on two sides is speckle too.
        removeSmallComponents(
            occupied, static_cast<int>(std::ceil(kMinThingReturns / grid.resolution - 1e-9)), true,
            0, 8);
        const cv::Mat before = unknown.clone();
        const auto gaps = fillUnknownGaps(unknown, occupied, cellsOf(options.unknownGapArea, grid));
        report.gapsFilled = gaps.first;
        report.gapArea = gaps.second * cellArea(grid);
        free.setTo(255, before - unknown);
    }
    if (options.enabled) {
        // Obstacle specks (8-connected, as a speck touching at a corner is one speck).
        cv::Mat blocked = 255 - free;
        const auto specks =
            removeSmallComponents(blocked, cellsOf(options.speckleArea, grid), true, 0, 8);
        report.specksRemoved = specks.first;
        report.speckArea = specks.second * cellArea(grid);
        free = 255 - blocked;
        // Ragged wall edges: a 3 x 3 majority (median) vote flips lone cells both ways, so
        // the notches and the bumps of a wall cancel out instead of biasing the area; a wall
        // two cells thick survives it. Only on fine maps, where one cell is sensor noise and
        // not a feature the robot has to respect.
        if (options.smoothEdges && grid.resolution <= robotDiameter / 6.0) {
            const int before = cv::countNonZero(free);
            cv::medianBlur(free, free, 3);
            report.smoothedArea = (cv::countNonZero(free) - before) * cellArea(grid);
        }
        if (options.closingRadius / grid.resolution >= 1.0) {
            const int before = cv::countNonZero(free);
            cv::morphologyEx(free, free, cv::MORPH_CLOSE,
                             disc(options.closingRadius / grid.resolution));
            report.closedArea = (cv::countNonZero(free) - before) * cellArea(grid);
        }
        const double opening =
            options.openingRadius >= 0 ? options.openingRadius : robotDiameter / 2.0;
        // Opening by at most the robot's radius removes only what its body cannot enter (its
        // footprint is the opening by its radius); the swath, W/2 from its centre, could
        // reach a little into what is filled, which the report counts.
        if (opening / grid.resolution >= 1.0) {
            const int before = cv::countNonZero(free);
            cv::morphologyEx(free, free, cv::MORPH_OPEN, disc(opening / grid.resolution));
            report.openedArea = (before - cv::countNonZero(free)) * cellArea(grid);
        }
        // Free islands (4-connected, as the tracer joins cells through edges only).
        const auto fragments =
            removeSmallComponents(free, cellsOf(options.fragmentArea, grid), false, 0, 4);
        report.fragmentsDropped = fragments.first;
        report.fragmentArea = fragments.second * cellArea(grid);
    }
    report.freeAreaAfter = cv::countNonZero(free) * cellArea(grid);
    const cv::Mat ones = free / 255; // continuous: a new matrix
    return std::vector<unsigned char>(ones.datastart, ones.dataend);
}

} // namespace fc::importing
