#include "path/PathBuilder.h"

#include "geometry/Clearance.h"
#include "path/ExcursionPruning.h"

namespace fc {
namespace {

SegmentKind kindOf(EdgeKind kind) {
    switch (kind) {
    case EdgeKind::Coverage:
        return SegmentKind::Stripe;
    case EdgeKind::Contour:
        return SegmentKind::Contour;
    case EdgeKind::Inter:
        break;
    }
    return SegmentKind::Transit;
}

// Appends a piece, skipping repeated points; returns each piece point's index in the path.
std::vector<int> append(CoveragePath& path, const Polyline& piece, SegmentKind kind) {
    std::vector<int> index;
    index.reserve(piece.size());
    for (const Vec2& p : piece) {
        if (path.points.empty() || distance(path.points.back(), p) >= 1e-9) {
            if (!path.points.empty())
                path.kinds.push_back(kind);
            path.points.push_back(p);
        }
        index.push_back(static_cast<int>(path.points.size()) - 1);
    }
    return index;
}

Polyline joinFreePoint(const ClearanceField& field, Vec2 from, Vec2 to, const char* what) {
    if (distance(from, to) < 1e-9)
        return {from};
    Polyline line = field.findPath(from, to);
    if (line.empty())
        throw SolverError(std::string("the ") + what +
                          " point cannot be joined to the corner graph without collision");
    return line;
}

} // namespace

CoveragePath buildCoveragePath(const Decomposition& dec, const CornerGraph& graph, const Walk& walk,
                               std::optional<Vec2> startPoint, std::optional<Vec2> endPoint) {
    CoveragePath local;
    const ClearanceField field(dec.freeSpace, 0.5 * dec.coverageWidth);
    if (walk.nodes.empty())
        return local;
    const Vec2 first = graph.nodes[walk.nodes.front()].position;
    if (startPoint)
        append(local, joinFreePoint(field, dec.frame.toLocal(*startPoint), first, "start"),
               SegmentKind::Transit);
    else
        append(local, {first}, SegmentKind::Transit);
    std::vector<detail::PathExcursion> excursions;
    for (size_t i = 0; i < walk.edges.size(); ++i) {
        const GraphEdge& e = graph.edges[walk.edges[i]];
        const bool reversed = e.u != walk.nodes[i];
        Polyline piece = e.geometry;
        if (reversed)
            piece.assign(e.geometry.rbegin(), e.geometry.rend());
        const std::vector<int> index = append(local, piece, kindOf(e.kind));
        const int last = static_cast<int>(piece.size()) - 1;
        for (const Excursion& x : e.excursions) {
            const int b = reversed ? last - x.end : x.begin;
            const int en = reversed ? last - x.begin : x.end;
            excursions.push_back({index[b], index[en], x.towardsCeiling});
        }
    }
    if (endPoint)
        append(local,
               joinFreePoint(field, graph.nodes[walk.nodes.back()].position,
                             dec.frame.toLocal(*endPoint), "end"),
               SegmentKind::Transit);

    // Drop the seal excursions whose margin the rest of the path already sweeps.
    const std::vector<char> keep =
        detail::prunableExcursions(local.points, excursions, dec.coverageWidth);
    CoveragePath world;
    for (size_t i = 0; i < local.points.size(); ++i) {
        if (!keep[i])
            continue;
        const Vec2 p = dec.frame.toWorld(local.points[i]);
        if (!world.points.empty()) {
            if (distance(world.points.back(), p) < 1e-9)
                continue;
            world.kinds.push_back(local.kinds[i - 1]);
        }
        world.points.push_back(p);
    }
    return world;
}

} // namespace fc
