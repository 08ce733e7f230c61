#include "model/OverlapArea.h"

#include <algorithm>
#include <cmath>

namespace fc::overlap {

namespace {

struct SharedRun {
    double from, to; // parameters along the edge being split
    bool sameDirection;
};

// The edges of one region bucketed in a uniform grid by their boxes, so that splitting an
// edge looks only at the edges near it: a room traced from a laser map meets tens of
// thousands of speckle edges, and testing every pair made validation seconds long.
class EdgeGrid {
public:
    explicit EdgeGrid(const std::vector<DirectedEdge>& edges) : edges_(edges) {
        for (const DirectedEdge& e : edges)
            box_.add(e.a), box_.add(e.b);
        const double side = std::ceil(std::sqrt(static_cast<double>(edges.size())));
        columns_ = rows_ = std::clamp(static_cast<int>(side), 1, 1024);
        cellW_ = std::max(box_.width() / columns_, 1e-12);
        cellH_ = std::max(box_.height() / rows_, 1e-12);
        cells_.resize(static_cast<size_t>(columns_) * rows_);
        for (size_t i = 0; i < edges.size(); ++i)
            forCells(boxOf(edges[i], 0.0),
                     [&](size_t c) { cells_[c].push_back(static_cast<int>(i)); });
        stamp_.assign(edges.size(), 0);
    }

    // Indices of the edges whose boxes may meet `box`, each once, in increasing order.
    const std::vector<int>& near(const BoundingBox& box) {
        found_.clear();
        ++visit_;
        forCells(box, [&](size_t c) {
            for (int i : cells_[c])
                if (stamp_[i] != visit_)
                    stamp_[i] = visit_, found_.push_back(i);
        });
        std::sort(found_.begin(), found_.end()); // the order of a full scan
        return found_;
    }

    const std::vector<DirectedEdge>& edges() const { return edges_; }

    static BoundingBox boxOf(const DirectedEdge& e, double grow) {
        BoundingBox b;
        b.add(e.a), b.add(e.b);
        b.minX -= grow, b.minY -= grow, b.maxX += grow, b.maxY += grow;
        return b;
    }

private:
    template <typename Visit> void forCells(const BoundingBox& b, Visit visit) const {
        if (edges_.empty() || b.maxX < box_.minX || b.minX > box_.maxX || b.maxY < box_.minY ||
            b.minY > box_.maxY)
            return;
        auto column = [&](double x) {
            return std::clamp(static_cast<int>(std::floor((x - box_.minX) / cellW_)), 0,
                              columns_ - 1);
        };
        auto row = [&](double y) {
            return std::clamp(static_cast<int>(std::floor((y - box_.minY) / cellH_)), 0, rows_ - 1);
        };
        for (int j = row(b.minY); j <= row(b.maxY); ++j)
            for (int i = column(b.minX); i <= column(b.maxX); ++i)
                visit(static_cast<size_t>(j) * columns_ + i);
    }

    const std::vector<DirectedEdge>& edges_;
    BoundingBox box_;
    int columns_ = 1, rows_ = 1;
    double cellW_ = 1, cellH_ = 1;
    std::vector<std::vector<int>> cells_;
    std::vector<unsigned> stamp_;
    unsigned visit_ = 0;
    std::vector<int> found_;
};

// Parameters along `e` where it meets the other region's edges, and the runs it shares.
void splitEdge(const DirectedEdge& e, EdgeGrid& others, double tolerance, std::vector<double>& cuts,
               std::vector<SharedRun>& shared) {
    const Vec2 d = e.b - e.a;
    const double length2 = dot(d, d);
    const double length = std::sqrt(length2);
    const double slack = tolerance / length;
    const double minX = std::min(e.a.x, e.b.x) - tolerance;
    const double maxX = std::max(e.a.x, e.b.x) + tolerance;
    const double minY = std::min(e.a.y, e.b.y) - tolerance;
    const double maxY = std::max(e.a.y, e.b.y) + tolerance;
    auto parameterOf = [&](Vec2 p) { return dot(p - e.a, d) / length2; };
    // |cross| / length is the distance from the line; comparing cross products avoids
    // a division (and hypot) per test.
    auto nearLineOfE = [&](Vec2 p) { return std::abs(cross(d, p - e.a)) <= tolerance * length; };
    for (int index : others.near(EdgeGrid::boxOf(e, tolerance))) {
        const DirectedEdge& g = others.edges()[index];
        if (std::max(g.a.x, g.b.x) < minX || std::min(g.a.x, g.b.x) > maxX ||
            std::max(g.a.y, g.b.y) < minY || std::min(g.a.y, g.b.y) > maxY)
            continue;
        const Vec2 dg = g.b - g.a;
        const double lengthG = std::sqrt(dot(dg, dg));
        if (lengthG == 0.0)
            continue;
        // Edges that run along each other, checked both ways so that a long and a short
        // edge agree whichever of them is being split.
        const bool alongE = nearLineOfE(g.a) && nearLineOfE(g.b);
        const bool alongG = std::abs(cross(dg, e.a - g.a)) <= tolerance * lengthG &&
                            std::abs(cross(dg, e.b - g.a)) <= tolerance * lengthG;
        if (alongE || alongG) {
            const double t0 = parameterOf(g.a), t1 = parameterOf(g.b);
            const double from = std::max(0.0, std::min(t0, t1));
            const double to = std::min(1.0, std::max(t0, t1));
            if (to > from) {
                cuts.push_back(from);
                cuts.push_back(to);
                shared.push_back({from, to, dot(d, dg) > 0.0});
            }
            continue;
        }
        const double denominator = cross(d, dg);
        if (denominator != 0.0) {
            const Vec2 offset = g.a - e.a;
            const double t = cross(offset, dg) / denominator;
            const double u = cross(offset, d) / denominator;
            const double uSlack = tolerance / lengthG;
            if (t >= -slack && t <= 1.0 + slack && u >= -uSlack && u <= 1.0 + uSlack)
                cuts.push_back(std::clamp(t, 0.0, 1.0));
        }
        // T-junctions: an endpoint of g lying on e.
        for (Vec2 p : {g.a, g.b}) {
            const double t = parameterOf(p);
            if (t >= -slack && t <= 1.0 + slack && nearLineOfE(p))
                cuts.push_back(std::clamp(t, 0.0, 1.0));
        }
    }
}

// Adds the contribution of the pieces of `e` that bound A ∩ B to `result`.
void addBoundaryPieces(const DirectedEdge& e, EdgeGrid& others,
                       const std::function<bool(Vec2)>& insideOther, bool countSharedRuns,
                       Vec2 origin, double tolerance, OverlapResult& result) {
    if (e.a == e.b)
        return;
    std::vector<double> cuts{0.0, 1.0};
    std::vector<SharedRun> shared;
    splitEdge(e, others, tolerance, cuts, shared);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const Vec2 d = e.b - e.a;
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double middle = 0.5 * (cuts[k] + cuts[k + 1]);
        bool onShared = false, sameDirection = false;
        for (const SharedRun& run : shared) {
            if (middle >= run.from && middle <= run.to) {
                onShared = true;
                sameDirection = sameDirection || run.sameDirection;
            }
        }
        const Vec2 midpoint = e.a + d * middle;
        bool include = false;
        if (onShared)
            include = countSharedRuns && sameDirection;
        else
            include = insideOther(midpoint);
        if (!include)
            continue;
        const Vec2 p = e.a + d * cuts[k] - origin, q = e.a + d * cuts[k + 1] - origin;
        result.area += 0.5 * cross(p, q);
        if (!result.hasSample && !onShared) {
            result.sample = midpoint;
            result.hasSample = true;
        }
    }
}

} // namespace

std::vector<DirectedEdge> edgesOf(const Ring& ring, bool interiorOnLeft) {
    std::vector<DirectedEdge> edges;
    const size_t n = ring.size();
    const bool reverse = (signedArea(ring) > 0.0) != interiorOnLeft;
    edges.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % n];
        edges.push_back(reverse ? DirectedEdge{b, a} : DirectedEdge{a, b});
    }
    return edges;
}

EvenOddIndex::EvenOddIndex(const std::vector<DirectedEdge>& edges) {
    for (const DirectedEdge& e : edges) {
        if (e.a.y != e.b.y) // horizontal edges never cross a horizontal ray
            edges_.push_back(e);
    }
    if (edges_.empty())
        return;
    minY_ = INFINITY;
    maxY_ = -INFINITY;
    for (const DirectedEdge& e : edges_) {
        minY_ = std::min({minY_, e.a.y, e.b.y});
        maxY_ = std::max({maxY_, e.a.y, e.b.y});
    }
    const size_t bandCount = std::clamp<size_t>(edges_.size() / 2, 1, 4096);
    bandHeight_ = (maxY_ - minY_) / static_cast<double>(bandCount);
    if (!(bandHeight_ > 0.0))
        bandHeight_ = 1.0;
    bands_.resize(bandCount);
    auto bandOf = [&](double y) {
        const double index = std::floor((y - minY_) / bandHeight_);
        return static_cast<size_t>(std::clamp(index, 0.0, static_cast<double>(bandCount - 1)));
    };
    for (size_t i = 0; i < edges_.size(); ++i) {
        const DirectedEdge& e = edges_[i];
        const size_t first = bandOf(std::min(e.a.y, e.b.y));
        const size_t last = bandOf(std::max(e.a.y, e.b.y));
        for (size_t band = first; band <= last; ++band)
            bands_[band].push_back(static_cast<int>(i));
    }
}

bool EvenOddIndex::contains(Vec2 p) const {
    if (bands_.empty() || p.y < minY_ || p.y > maxY_)
        return false;
    const double index = std::floor((p.y - minY_) / bandHeight_);
    const size_t band =
        static_cast<size_t>(std::clamp(index, 0.0, static_cast<double>(bands_.size() - 1)));
    bool inside = false;
    for (int i : bands_[band]) {
        const DirectedEdge& e = edges_[i];
        if ((e.a.y > p.y) != (e.b.y > p.y)) {
            const double xCross = e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
            if (p.x < xCross)
                inside = !inside;
        }
    }
    return inside;
}

OverlapResult overlapArea(const std::vector<DirectedEdge>& edgesA,
                          const std::function<bool(Vec2)>& insideA,
                          const std::vector<DirectedEdge>& edgesB,
                          const std::function<bool(Vec2)>& insideB, Vec2 origin, double tolerance) {
    // The boundary of A ∩ B: A's pieces inside B, B's pieces inside A, and the runs where
    // both boundaries coincide with the same direction (counted once, from A's side).
    OverlapResult result;
    EdgeGrid gridA(edgesA), gridB(edgesB);
    for (const DirectedEdge& e : edgesA)
        addBoundaryPieces(e, gridB, insideB, true, origin, tolerance, result);
    for (const DirectedEdge& g : edgesB)
        addBoundaryPieces(g, gridA, insideA, false, origin, tolerance, result);
    return result;
}

} // namespace fc::overlap
