// A coarse, conservative map of where a disc's centre can travel among walls: a grid cell is
// open when its centre is within half a cell diagonal of being clear (distance to walls >=
// r - h*sqrt(2)/2). Any clear point lies in an open cell (distance is 1-Lipschitz) and a
// clear path passes through 8-adjacent open cells, so two clear points in different open
// regions cannot be joined and the expensive visibility search can be skipped (on a SLAM
// map with many pockets it would otherwise explore every corner of the floor for each
// pocket). Points in one region may still be apart: the grid only proves separation.
#pragma once

#include "geometry/SegmentIndex.h"

#include <functional>
#include <vector>

namespace fc {

class OpenRegions {
public:
    // How grid nodes are found open: Pruned decides whole blocks far from the threshold with
    // one distance query (what the planner uses); EveryNode tests each node (the reference
    // the tests compare Pruned with).
    enum class Classification { Pruned, EveryNode };

    // The grid over `extent` grown by r, cells of r/6 (coarser on very large floors).
    OpenRegions(const SegmentIndex& walls, BoundingBox extent, double r,
                Classification classification = Classification::Pruned);

    // The open region holding p; -1 outside the grid or in a closed cell (never for a
    // clear point inside the extent).
    int regionOf(Vec2 p) const;
    // False when no clear path from a to b stays inside `window` (proved on the grid: such a
    // path passes through 8-adjacent open nodes within one node of the window); true when
    // one may. A visibility search in a window that holds no path tests every pair of its
    // corners before it gives up: on an uncleaned map most of the search time went there.
    bool mayJoinWithin(Vec2 a, Vec2 b, const BoundingBox& window) const;
    // A clear path from a to b inside `window` over surely clear nodes (at least r + h*sqrt(2)/2
    // from every wall, so the straight piece between 8-adjacent ones is clear as well),
    // pulled tight; empty when the grid holds none. `sees` tests a straight piece against the
    // walls (the hops from a and b onto the grid, and the shortcuts of the pulling). Costs
    // one grid search where a visibility search among thousands of wall corners (an
    // uncleaned map) spends its whole test budget; slightly longer than the shortest path,
    // and blind to gaps less than a node wider than the robot.
    Polyline clearRoute(Vec2 a, Vec2 b, const BoundingBox& window,
                        const std::function<bool(Vec2, Vec2)>& sees) const;
    // The grid's labels, row by row (-1: closed), for comparisons.
    const std::vector<int>& labels() const { return label_; }

    // A clear point in a gap too tight for surely clear nodes (a traced doorway a little
    // wider than the robot), and the unit direction through it.
    struct Portal {
        Vec2 middle, along;
    };
    // Lets clearRoute pass through the portals that join surely clear nodes of different
    // components: on each side, the first such node along the gap within a few radii that
    // the middle sees (`sees`, as in clearRoute). Call once, before any clearRoute.
    void addPortals(const std::vector<Portal>& portals,
                    const std::function<bool(Vec2, Vec2)>& sees);

private:
    size_t index(int i, int j) const { return static_cast<size_t>(j) * nx_ + i; }
    BoundingBox box_;
    double h_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<int> label_;
    std::vector<char> surelyClear_;
    std::vector<int> clearLabel_; // components of the surely clear nodes
    double r_ = 0;
    // Portals that join two surely clear nodes of different components: the nodes and the
    // way between them (beside `from`, the gap's middle, beside `to`).
    struct Bridge {
        size_t from, to;
        Polyline way;
    };
    std::vector<Bridge> bridges_;
    Vec2 nodePosition(size_t k) const {
        return {box_.minX + static_cast<double>(k % nx_) * h_,
                box_.minY + static_cast<double>(k / nx_) * h_};
    }
};

} // namespace fc
