#include "path/PathBuilder.h"

#include "geometry/Clearance.h"

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

void append(CoveragePath& path, const Polyline& piece, SegmentKind kind) {
    for (const Vec2& p : piece) {
        if (!path.points.empty() && distance(path.points.back(), p) < 1e-9)
            continue;
        if (!path.points.empty())
            path.kinds.push_back(kind);
        path.points.push_back(p);
    }
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

CoveragePath buildCoveragePath(const Decomposition& dec, const CornerGraph& graph,
                               const Walk& walk, std::optional<Vec2> startPoint,
                               std::optional<Vec2> endPoint) {
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
    for (size_t i = 0; i < walk.edges.size(); ++i) {
        const GraphEdge& e = graph.edges[walk.edges[i]];
        Polyline piece = e.geometry;
        if (e.u != walk.nodes[i])
            piece.assign(e.geometry.rbegin(), e.geometry.rend());
        append(local, piece, kindOf(e.kind));
    }
    if (endPoint)
        append(local,
               joinFreePoint(field, graph.nodes[walk.nodes.back()].position,
                             dec.frame.toLocal(*endPoint), "end"),
               SegmentKind::Transit);
    CoveragePath world;
    world.points = dec.frame.toWorld(local.points);
    world.kinds = std::move(local.kinds);
    return world;
}

} // namespace fc
