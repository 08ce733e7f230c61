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

// The path under construction in the sweep frame, and the seal excursions it contains.
struct LocalPath {
    CoveragePath path;
    std::vector<detail::PathExcursion> excursions;
};

void joinStart(LocalPath& local, const ClearanceField& field, const Decomposition& dec,
               std::optional<Vec2> startPoint, Vec2 first) {
    if (startPoint)
        append(local.path, joinFreePoint(field, dec.frame.toLocal(*startPoint), first, "start"),
               SegmentKind::Transit);
    else
        append(local.path, {first}, SegmentKind::Transit);
}

// A fold runs a transit straight to a seal's far end, along the wall: a seal whose margin
// only that transit sweeps could not be dropped before it (noisy room-obstacle: two seals at
// one stripe end). The pruning runs again on the folded path.
void pruneAgainAfterFolding(const LocalPath& local, double width, std::vector<char>& keep) {
    const Polyline& pts = local.path.points;
    std::vector<int> compactIndex(pts.size(), -1), original;
    Polyline compact;
    for (size_t i = 0; i < pts.size(); ++i)
        if (keep[i]) {
            compactIndex[i] = static_cast<int>(compact.size());
            original.push_back(static_cast<int>(i));
            compact.push_back(pts[i]);
        }
    std::vector<detail::PathExcursion> whole;
    for (const detail::PathExcursion& ex : local.excursions) {
        bool kept = true;
        for (int k = ex.begin; k <= ex.end; ++k)
            kept = kept && keep[k];
        if (kept)
            whole.push_back({compactIndex[ex.begin], compactIndex[ex.end], ex.towardsCeiling});
    }
    if (whole.empty())
        return;
    const std::vector<char> again = detail::prunableExcursions(compact, whole, width);
    for (size_t i = 0; i < compact.size(); ++i)
        if (!again[i])
            keep[original[i]] = 0;
}

// Joins the end point, drops the seal excursions whose margin the rest of the path already
// sweeps, and converts to the world frame.
CoveragePath finish(LocalPath& local, const ClearanceField& field, const Decomposition& dec,
                    std::optional<Vec2> endPoint) {
    if (endPoint && !local.path.points.empty())
        append(local.path,
               joinFreePoint(field, local.path.points.back(), dec.frame.toLocal(*endPoint), "end"),
               SegmentKind::Transit);
    std::vector<char> keep =
        detail::prunableExcursions(local.path.points, local.excursions, dec.coverageWidth());
    std::vector<SegmentKind> arriving(local.path.points.size(), SegmentKind::Transit);
    for (size_t i = 1; i < arriving.size(); ++i)
        arriving[i] = local.path.kinds[i - 1];
    detail::foldExcursionsIntoTransits(local.path.points, local.excursions, field, dec.robot, keep,
                                       arriving);
    pruneAgainAfterFolding(local, dec.coverageWidth(), keep);
    CoveragePath world;
    for (size_t i = 0; i < local.path.points.size(); ++i) {
        if (!keep[i])
            continue;
        const Vec2 p = dec.frame.toWorld(local.path.points[i]);
        if (!world.points.empty()) {
            if (distance(world.points.back(), p) < 1e-9)
                continue;
            world.kinds.push_back(arriving[i]);
        }
        world.points.push_back(p);
    }
    return world;
}

} // namespace

CoveragePath buildCoveragePath(const Decomposition& dec, const CornerGraph& graph, const Walk& walk,
                               std::optional<Vec2> startPoint, std::optional<Vec2> endPoint) {
    const ClearanceField& field = dec.clearance();
    if (walk.nodes.empty())
        return {};
    LocalPath local;
    joinStart(local, field, dec, startPoint, graph.nodes[walk.nodes.front()].position);
    for (size_t i = 0; i < walk.edges.size(); ++i) {
        const GraphEdge& e = graph.edges[walk.edges[i]];
        const bool reversed = e.u != walk.nodes[i];
        Polyline piece = e.geometry;
        if (reversed)
            piece.assign(e.geometry.rbegin(), e.geometry.rend());
        // Between two pieces of a headland band the step sweeps the band.
        const bool alongBand = e.kind == EdgeKind::Inter &&
                               dec.cells[graph.nodes[e.u].cell].headland &&
                               dec.cells[graph.nodes[e.v].cell].headland;
        const std::vector<int> index =
            append(local.path, piece, alongBand ? SegmentKind::Stripe : kindOf(e.kind));
        const int last = static_cast<int>(piece.size()) - 1;
        for (const Excursion& x : e.excursions) {
            const int b = reversed ? last - x.end : x.begin;
            const int en = reversed ? last - x.begin : x.end;
            local.excursions.push_back({index[b], index[en], x.towardsCeiling});
        }
    }
    return finish(local, field, dec, endPoint);
}

CoveragePath buildCoveragePath(const Decomposition& dec, const DirectPath& direct,
                               std::optional<Vec2> startPoint, std::optional<Vec2> endPoint) {
    const ClearanceField& field = dec.clearance();
    const Polyline& points = direct.path.points;
    if (points.empty())
        return {};
    LocalPath local;
    joinStart(local, field, dec, startPoint, points.front());
    std::vector<int> index{static_cast<int>(local.path.points.size()) - 1};
    for (size_t i = 1; i < points.size(); ++i)
        index.push_back(append(local.path, {points[i]}, direct.path.kinds[i - 1]).back());
    for (const Excursion& x : direct.excursions)
        local.excursions.push_back({index[x.begin], index[x.end], x.towardsCeiling});
    return finish(local, field, dec, endPoint);
}

CoveragePath buildCoveragePath(const Decomposition& dec, const CornerGraph& graph,
                               const Solution& solution, std::optional<Vec2> startPoint,
                               std::optional<Vec2> endPoint) {
    if (solution.directPath)
        return buildCoveragePath(dec, *solution.directPath, startPoint, endPoint);
    return buildCoveragePath(dec, graph, solution.walk, startPoint, endPoint);
}

} // namespace fc
