// Transits of the Tung & Liu model: shortest paths on a visibility graph (Boost.Graph's
// Dijkstra) whose nodes sit just outside the walls' corners, grown by the clearance, so that
// a path bends around a corner at the clearance, as around the grown obstacles of their
// implementation.
#include "baselines/BaselineModel.h"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <cmath>

namespace fc::baselines::detail {

struct Transits::Graph {
    using Type =
        boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                              boost::property<boost::edge_weight_t, double>>;
    Type g;
};

namespace {

// Corners are passed this much farther out than the clearance, so that a path touching one
// stays clear despite rounding.
constexpr double kNodeMargin = 1.002;
constexpr double kClearTolerance = 1e-9;

bool boxesNear(Vec2 a, Vec2 b, const Segment& w, double r) {
    return std::max(a.x, b.x) + r >= std::min(w.a.x, w.b.x) &&
           std::min(a.x, b.x) - r <= std::max(w.a.x, w.b.x) &&
           std::max(a.y, b.y) + r >= std::min(w.a.y, w.b.y) &&
           std::min(a.y, b.y) - r <= std::max(w.a.y, w.b.y);
}

Vec2 unit(Vec2 v) {
    const double n = norm(v);
    return n > 0 ? v * (1.0 / n) : Vec2{};
}

} // namespace

Transits::Transits(std::vector<Segment> walls, double clearance, std::function<bool()> cancelled)
    : walls_(std::move(walls)), clearance_(clearance), cancelled_(std::move(cancelled)),
      graph_(std::make_unique<Graph>()) {
    placeNodes();
    const int n = static_cast<int>(nodes_.size());
    graph_->g = Graph::Type(n + 1); // the last vertex: the source of each point's search
    for (int i = 0; i < n; ++i) {
        throwIfCancelled();
        for (int j = i + 1; j < n; ++j)
            if (clear(nodes_[i], nodes_[j]))
                boost::add_edge(i, j, fc::distance(nodes_[i], nodes_[j]), graph_->g);
    }
}

void Transits::throwIfCancelled() const {
    if (cancelled_ && cancelled_())
        throw TourError("cancelled");
}

Transits::~Transits() = default;

bool Transits::clear(Vec2 p) const {
    return clear(p, p);
}

bool Transits::clear(Vec2 p, Vec2 q) const {
    const double r = clearance_ * (1.0 - kClearTolerance);
    for (const Segment& w : walls_)
        if (boxesNear(p, q, w, r) && segmentSegmentDistance(p, q, w.a, w.b) < r)
            return false;
    return true;
}

// Around every corner the free space wraps (where a path can bend), nodes on a polygon
// circumscribing the clearance arc: one at a right angle, more around sharper corners.
void Transits::placeNodes() {
    // Walls arrive ring by ring, each ring's segments in order and closed: a segment's
    // successor is the next one, or its ring's first one after the ring's last.
    std::size_t ringStart = 0;
    for (std::size_t i = 0; i < walls_.size(); ++i) {
        if (i > 0 && fc::distance(walls_[i - 1].b, walls_[i].a) > 1e-12)
            ringStart = i;
        const Segment& in = walls_[i];
        const bool ringGoesOn =
            i + 1 < walls_.size() && fc::distance(walls_[i + 1].a, in.b) <= 1e-12;
        const std::size_t k = ringGoesOn ? i + 1 : ringStart;
        if (k == i || fc::distance(walls_[k].a, in.b) > 1e-12)
            continue;
        const Segment& out = walls_[k];
        {
            const Vec2 corner = in.b;
            const Vec2 d1 = unit(in.b - in.a), d2 = unit(out.b - out.a);
            // The two sides' normals; a node is needed on whichever side the corner is
            // convex (the other side is a reflex corner no shortest path touches).
            for (const double side : {1.0, -1.0}) {
                const Vec2 n1 = Vec2{-d1.y, d1.x} * side, n2 = Vec2{-d2.y, d2.x} * side;
                if (cross(d1, d2) * side > 1e-12)
                    continue; // turning towards this side: reflex here
                const double turn = std::acos(std::clamp(dot(n1, n2), -1.0, 1.0));
                if (turn < 1e-9)
                    continue; // a straight vertex is no corner
                const int pieces = turn <= 0.5 * M_PI + 1e-9
                                       ? 1
                                       : static_cast<int>(std::ceil(turn / (0.25 * M_PI)));
                const double step = turn / pieces;
                const double a1 = std::atan2(n1.y, n1.x);
                const double sign = cross(n1, n2) >= 0 ? 1.0 : -1.0;
                // One node on the bisector of a corner up to a right angle; around sharper
                // ones, the vertices of a polygon whose edges touch the clearance arc.
                const int count = pieces == 1 ? 1 : pieces + 1;
                for (int p = 0; p < count; ++p) {
                    const double angle =
                        pieces == 1 ? a1 + sign * 0.5 * turn : a1 + sign * step * p;
                    const double r =
                        clearance_ * kNodeMargin / std::cos(pieces == 1 ? 0.5 * turn : 0.5 * step);
                    const Vec2 node = corner + Vec2{std::cos(angle), std::sin(angle)} * r;
                    if (clear(node))
                        nodes_.push_back(node);
                }
            }
        }
    }
}

std::vector<std::pair<int, double>> Transits::visibleNodes(Vec2 p) const {
    std::vector<std::pair<int, double>> seen;
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i)
        if (clear(p, nodes_[i]))
            seen.push_back({i, fc::distance(p, nodes_[i])});
    return seen;
}

int Transits::addPoint(Vec2 p) {
    points_.push_back(p);
    return static_cast<int>(points_.size()) - 1;
}

void Transits::solve() {
    const int n = static_cast<int>(nodes_.size()), count = static_cast<int>(points_.size());
    Graph::Type& g = graph_->g;
    std::vector<std::vector<std::pair<int, double>>> seen(count);
    nodeDistance_.assign(count, {});
    nodeParent_.assign(count, {});
    for (int i = 0; i < count; ++i) {
        throwIfCancelled();
        seen[i] = visibleNodes(points_[i]);
        boost::clear_vertex(n, g);
        for (const auto& [node, length] : seen[i])
            boost::add_edge(n, node, length, g);
        std::vector<double> dist(n + 1);
        std::vector<Graph::Type::vertex_descriptor> parent(n + 1);
        boost::dijkstra_shortest_paths(
            g, n, boost::predecessor_map(parent.data()).distance_map(dist.data()));
        nodeDistance_[i].assign(dist.begin(), dist.begin() + n);
        nodeParent_[i].resize(n);
        for (int v = 0; v < n; ++v)
            nodeParent_[i][v] =
                parent[v] == static_cast<std::size_t>(n) || parent[v] == static_cast<std::size_t>(v)
                    ? -1
                    : static_cast<int>(parent[v]);
    }
    boost::clear_vertex(n, g);
    distance_.assign(count, std::vector<double>(count, INFINITY));
    for (int i = 0; i < count; ++i) {
        throwIfCancelled();
        for (int j = 0; j < count; ++j) {
            if (i == j) {
                distance_[i][j] = 0;
                continue;
            }
            if (j < i) {
                distance_[i][j] = distance_[j][i];
                continue;
            }
            double best =
                clear(points_[i], points_[j]) ? fc::distance(points_[i], points_[j]) : INFINITY;
            for (const auto& [node, length] : seen[j])
                best = std::min(best, nodeDistance_[i][node] + length);
            distance_[i][j] = best;
        }
    }
}

double Transits::distance(int from, int to) const {
    return distance_[from][to];
}

Polyline Transits::path(int from, int to) const {
    const Vec2 p = points_[from], q = points_[to];
    if (from == to)
        return {p};
    if (clear(p, q))
        return {p, q};
    int best = -1;
    double bestCost = INFINITY;
    for (int node = 0; node < static_cast<int>(nodes_.size()); ++node) {
        const double cost = nodeDistance_[from][node] + fc::distance(nodes_[node], q);
        if (cost < bestCost && clear(nodes_[node], q))
            best = node, bestCost = cost;
    }
    if (best < 0)
        return {};
    Polyline reversed{q};
    for (int v = best; v >= 0; v = nodeParent_[from][v])
        reversed.push_back(nodes_[v]);
    reversed.push_back(p);
    return Polyline(reversed.rbegin(), reversed.rend());
}

Polyline Transits::route(Vec2 p, Vec2 q) const {
    if (clear(p, q))
        return {p, q};
    // A one-off search from the source vertex, wired to p for this search only (the graph is
    // not copied: on a large floor that cost more than the search); the registered points'
    // tables are not touched.
    const int n = static_cast<int>(nodes_.size());
    Graph::Type& g = graph_->g;
    for (const auto& [node, length] : visibleNodes(p))
        boost::add_edge(n, node, length, g);
    std::vector<double> dist(n + 1);
    std::vector<Graph::Type::vertex_descriptor> parent(n + 1);
    boost::dijkstra_shortest_paths(g, n,
                                   boost::predecessor_map(parent.data()).distance_map(dist.data()));
    boost::clear_vertex(n, g);
    int best = -1;
    double bestCost = INFINITY;
    for (const auto& [node, length] : visibleNodes(q))
        if (dist[node] + length < bestCost)
            best = node, bestCost = dist[node] + length;
    if (best < 0 || !(bestCost < INFINITY))
        return {};
    Polyline reversed{q};
    for (int v = best; v != n; v = static_cast<int>(parent[v])) {
        if (parent[v] == static_cast<std::size_t>(v))
            return {};
        reversed.push_back(nodes_[v]);
    }
    reversed.push_back(p);
    return Polyline(reversed.rbegin(), reversed.rend());
}

} // namespace fc::baselines::detail
