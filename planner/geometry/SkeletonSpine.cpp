#include "geometry/SkeletonSpine.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_straight_skeleton_2.h>
#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <exception>
#include <limits>
#include <map>
#include <vector>

namespace fc {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SkeletonGraph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                          boost::property<boost::edge_weight_t, double>>;

// Distances from `source` and each node's predecessor on the way (the skeleton is a tree:
// the path is the only one).
std::vector<double> distancesFrom(const SkeletonGraph& graph, std::size_t source,
                                  std::vector<std::size_t>& predecessor) {
    std::vector<double> distance(boost::num_vertices(graph));
    predecessor.assign(boost::num_vertices(graph), 0);
    boost::dijkstra_shortest_paths(
        graph, source, boost::predecessor_map(predecessor.data()).distance_map(distance.data()));
    return distance;
}

std::size_t farthest(const std::vector<double>& distance) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < distance.size(); ++i)
        if (distance[i] > distance[best] && distance[i] < std::numeric_limits<double>::max())
            best = i;
    return best;
}

} // namespace

Polyline skeletonSpine(const Ring& outline) {
    if (outline.size() < 4)
        return {};
    // Relative to the first corner: UTM-sized coordinates keep their digits.
    const Vec2 origin = outline.front();
    CGAL::Polygon_2<Kernel> polygon;
    for (const Vec2& p : outline)
        polygon.push_back(Kernel::Point_2(p.x - origin.x, p.y - origin.y));
    if (!polygon.is_simple())
        return {};
    if (polygon.is_clockwise_oriented())
        polygon.reverse_orientation();
    boost::shared_ptr<CGAL::Straight_skeleton_2<Kernel>> skeleton;
    try {
        skeleton = CGAL::create_interior_straight_skeleton_2(polygon.vertices_begin(),
                                                             polygon.vertices_end());
    } catch (const std::exception&) {
        return {}; // CGAL's own checks (its precondition exceptions) found the outline wanting
    }
    if (!skeleton)
        return {};

    std::map<int, std::size_t> nodeOf; // CGAL vertex id -> graph node
    std::vector<Vec2> points;
    SkeletonGraph graph;
    const auto node = [&](const auto& vertex) {
        const auto [it, added] = nodeOf.emplace(vertex->id(), points.size());
        if (added)
            points.push_back({CGAL::to_double(vertex->point().x()) + origin.x,
                              CGAL::to_double(vertex->point().y()) + origin.y});
        return it->second;
    };
    for (auto edge = skeleton->halfedges_begin(); edge != skeleton->halfedges_end(); ++edge) {
        // Each inner bisector once: both ends are skeleton nodes, not the outline's corners.
        if (!edge->is_inner_bisector() || edge->id() > edge->opposite()->id())
            continue;
        const std::size_t a = node(edge->vertex()), b = node(edge->opposite()->vertex());
        boost::add_edge(a, b, norm(points[a] - points[b]), graph);
    }
    if (points.size() < 2)
        return {};
    // The tree's longest path: the node farthest from any node is one of its ends.
    std::vector<std::size_t> predecessor;
    const std::size_t end = farthest(distancesFrom(graph, 0, predecessor));
    const std::size_t other = farthest(distancesFrom(graph, end, predecessor));
    Polyline spine{points[other]};
    for (std::size_t at = other; at != end && predecessor[at] != at;) {
        at = predecessor[at];
        spine.push_back(points[at]);
    }
    return spine.size() >= 2 ? spine : Polyline{};
}

} // namespace fc
