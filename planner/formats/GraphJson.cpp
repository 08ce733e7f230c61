// The corner graph as JSON (SPEC sect. 7), node coordinates in the world frame.
#include "formats/PathIO.h"

#include <nlohmann/json.hpp>

namespace fc {

using nlohmann::ordered_json;

namespace {

const char* cornerName(CornerKind corner) {
    switch (corner) {
    case CornerKind::LB:
        return "LB";
    case CornerKind::LT:
        return "LT";
    case CornerKind::RB:
        return "RB";
    case CornerKind::RT:
        return "RT";
    case CornerKind::Bottom:
        return "bottom";
    case CornerKind::Top:
        break;
    }
    return "top";
}

const char* edgeKindName(EdgeKind kind) {
    switch (kind) {
    case EdgeKind::Coverage:
        return "coverage";
    case EdgeKind::Contour:
        return "contour";
    case EdgeKind::Inter:
        break;
    }
    return "inter";
}

} // namespace

std::string graphToJson(const CornerGraph& graph, const Decomposition& decomposition) {
    ordered_json nodes = ordered_json::array();
    for (const GraphNode& node : graph.nodes) {
        const Vec2 world = decomposition.frame.toWorld(node.position);
        nodes.push_back({{"id", node.id},
                         {"x", world.x},
                         {"y", world.y},
                         {"cell", node.cell},
                         {"corner", cornerName(node.corner)}});
    }
    ordered_json cells = ordered_json::array();
    for (const GraphCell& cell : graph.cells) {
        const bool named =
            cell.room >= 0 && cell.room < static_cast<int>(decomposition.roomNames.size());
        cells.push_back({{"id", cell.id},
                         {"kind", cell.kind == CellKind::Primary ? "primary" : "transition"},
                         {"room", named ? decomposition.roomNames[cell.room] : std::string()},
                         {"coverage_edges", cell.coverageEdges},
                         {"reachable", cell.reachable}});
    }
    ordered_json edges = ordered_json::array();
    for (const GraphEdge& edge : graph.edges) {
        // The cost when the owning cell is still uncovered (SPEC sect. 3).
        edges.push_back({{"id", edge.id},
                         {"u", edge.u},
                         {"v", edge.v},
                         {"kind", edgeKindName(edge.kind)},
                         {"parallel", edge.parallel},
                         {"length", edge.length},
                         {"cost", edgeCost(edge, false)},
                         {"cell", edge.cell}});
    }
    ordered_json root;
    root["nodes"] = std::move(nodes);
    root["cells"] = std::move(cells);
    root["edges"] = std::move(edges);
    return root.dump(-1, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

} // namespace fc
