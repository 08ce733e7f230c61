// Where the robot centre may be: at least r from every wall (r = L/2, the robot disc's
// radius). Stripes prefer to keep a larger inset (W/2) from a cell's limits where the
// walls allow (see detail::spanAt). Answers the two questions the decomposition and graph ask:
// which part of a vertical line is clear, and a short collision-free path between two clear points.
#pragma once

#include "geometry/OpenRegions.h"
#include "geometry/SegmentIndex.h"

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fc {

// Corner waypoints are built lazily, once, on the first path search (thread-safe: one field
// is shared by every copy of a decomposition). Neither copyable nor movable.
class ClearanceField {
public:
    // rings: the free space (boundary and holes) in the frame used for queries.
    // inset: how far stripes prefer to keep from a cell's floor and ceiling (W/2); never
    // less than radius.
    ClearanceField(const std::vector<Ring>& rings, double radius, double inset = 0.0);

    double radius() const { return radius_; }
    double inset() const { return inset_; }
    const SegmentIndex& walls() const { return walls_; }

    // Clear pieces of the vertical segment x = const, y in [yLow, yHigh], bottom to top,
    // keeping radius + margin from every wall.
    std::vector<Interval> clearPieces(double x, double yLow, double yHigh,
                                      double margin = 0.0) const;

    // Paths count as clear down to radius - acceptance(): traced contours are polylines
    // through points on the exact offset curve, whose chords may cut it by this much.
    double acceptance() const { return acceptance_; }

    bool isClear(Vec2 p) const;
    bool segmentIsClear(Vec2 a, Vec2 b) const;
    bool polylineIsClear(const Polyline& line) const;

    // Shortest path found over a visibility graph of the clear points next to convex wall
    // corners, searched in a window around a and b that grows when needed. Empty when a
    // and b are not connected within the largest window.
    // hints: extra clear waypoints worth trying (e.g. points inside a tight doorway).
    // maxMargin bounds how far beyond the box of a and b the search may look; maxChecks
    // (0: none) bounds the segment tests of all windows together, after which the search
    // gives up (empty): a search that fails covers the whole plan, n^2 tests on a big map.
    Polyline findPath(Vec2 a, Vec2 b, const std::vector<Vec2>& hints = {},
                      double maxMargin = INFINITY, std::size_t maxChecks = 0) const;

    // The open region (see OpenRegions) of p, built on first use (thread-safe); two clear
    // points in different regions cannot be joined. -1: p is in no open cell.
    int openRegionOf(Vec2 p) const;

private:
    Polyline searchPath(Vec2 a, Vec2 b, const std::vector<Vec2>& hints, double maxMargin,
                        std::size_t maxChecks) const;
    std::size_t cornersIn(const BoundingBox& window) const;
    // OpenRegions::clearRoute within the window; the grid must exist.
    Polyline gridRoute(Vec2 a, Vec2 b, const BoundingBox& window) const;
    Polyline searchWindow(Vec2 a, Vec2 b, const BoundingBox& window, const std::vector<Vec2>& hints,
                          std::size_t& checksLeft) const;

    SegmentIndex walls_;
    double radius_;
    double inset_;
    double tolerance_;
    double acceptance_;
    const std::vector<Vec2>& cornerPoints() const; // built on first use
    void buildCornerPoints() const;
    void addGapMiddle(Vec2 corner, Vec2 away) const; // part of buildCornerPoints
    std::vector<Ring> rings_;
    mutable std::once_flag cornersBuilt_;
    mutable std::vector<Vec2> cornerPoints_;           // clear points hugging wall corners
    mutable std::vector<OpenRegions::Portal> portals_; // tight gaps, for the grid's routes
    // cornerPoints_ by square bucket (indices ascending): a window's points without a scan
    // of all of them (an uncleaned map has thousands, and every search round asks).
    mutable std::vector<std::vector<int>> cornerBuckets_;
    mutable int bucketColumns_ = 0, bucketRows_ = 0;
    mutable double bucketSize_ = 1;
    void bucketCornerPoints() const; // part of buildCornerPoints
    // Calls visit(bucket, fullyInside) for every bucket the window meets.
    template <class Visit> void forBucketsIn(const BoundingBox& window, Visit&& visit) const;
    std::vector<int> cornerIndicesIn(const BoundingBox& window) const; // ascending
    BoundingBox extent_;
    mutable std::once_flag regionsBuilt_;
    mutable std::unique_ptr<OpenRegions> regions_;
    mutable std::atomic<bool> regionsReady_{false}; // regions_ built
    // Searches already made, by their arguments: the graphs of one floor (the whole plan's,
    // each room's, each strategy's) ask many of the same, and on an uncleaned map the
    // repeats of failing ones were half of all search time.
    struct SearchKey {
        double ax, ay, bx, by, maxMargin;
        std::size_t maxChecks, hints;
        bool operator==(const SearchKey& o) const;
    };
    struct SearchKeyHash {
        std::size_t operator()(const SearchKey& k) const;
    };
    mutable std::mutex searchesMutex_;
    mutable std::unordered_map<SearchKey, Polyline, SearchKeyHash> searches_;
};

} // namespace fc
