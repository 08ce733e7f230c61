// Path exports for robot software: Nav2 FollowWaypoints YAML, Fields2Cover path text,
// VDA 5050 orders and WKT. Coordinates stay in the plan's frame, in metres.
#include "formats/PathIO.h"
#include "formats/WriterSupport.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <sstream>

namespace fc {

using formats::dumped;
using formats::fixedNumber;
using nlohmann::ordered_json;

namespace {

// The path without consecutive repeated points; kinds[i] belongs to the segment i -> i+1.
CoveragePath withoutRepeats(const CoveragePath& path) {
    CoveragePath result;
    for (size_t i = 0; i < path.points.size(); ++i) {
        if (!result.points.empty() && result.points.back() == path.points[i])
            continue;
        if (!result.points.empty())
            result.kinds.push_back(path.kinds.empty()
                                       ? SegmentKind::Transit
                                       : path.kinds[std::min(i - 1, path.kinds.size() - 1)]);
        result.points.push_back(path.points[i]);
    }
    return result;
}

std::string utcNow() {
    const auto now = std::chrono::system_clock::now();
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    const auto millis =
        std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() %
        1000;
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char buffer[40];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%S", &utc);
    char text[48];
    std::snprintf(text, sizeof text, "%s.%03dZ", buffer, static_cast<int>(millis));
    return text;
}

} // namespace

std::string pathToNav2Yaml(const CoveragePath& input, const PathExportInfo& info) {
    const CoveragePath path = withoutRepeats(input);
    const std::string frameId = dumped(ordered_json(info.frameId), -1);
    const std::vector<double> headings = formats::headingsOf(path.points);
    std::ostringstream out;
    out << "# nav2_msgs/action/FollowWaypoints goal (send to /follow_waypoints): "
        << path.points.size() << " robot-centre waypoints\n"
        << "# units: metres; frame: " << formats::frameDescription(info.epsg)
        << "; orientation: quaternion x, y, z, w (geometry_msgs/Quaternion) about +z\n";
    if (path.points.empty())
        return out.str() + "poses: []\n";
    out << "poses:\n";
    for (size_t i = 0; i < path.points.size(); ++i) {
        const Vec2 p = path.points[i];
        const double half = headings[i] / 2.0;
        out << "  - header:\n      stamp: {sec: 0, nanosec: 0}\n      frame_id: " << frameId
            << "\n    pose:\n"
            << "      position: {x: " << fixedNumber(p.x, 6) << ", y: " << fixedNumber(p.y, 6)
            << ", z: 0.0}\n"
            << "      orientation: {x: 0.0, y: 0.0, z: " << fixedNumber(std::sin(half), 9)
            << ", w: " << fixedNumber(std::cos(half), 9) << "}\n";
    }
    return out.str();
}

std::string pathToFields2Cover(const CoveragePath& input, const PathExportInfo& info) {
    const CoveragePath path = withoutRepeats(input);
    const double speed = info.robot.speed;
    std::ostringstream out;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) {
        const Vec2 a = path.points[i], b = path.points[i + 1];
        double angle = std::atan2(b.y - a.y, b.x - a.x);
        if (angle < 0)
            angle += 2.0 * M_PI; // Fields2Cover keeps angles in [0, 2 pi)
        const int type = path.kinds[i] == SegmentKind::Transit ? 2 : 1; // TURN : SWATH
        out << fixedNumber(a.x, 6) << ' ' << fixedNumber(a.y, 6) << " 0.0 " << fixedNumber(angle, 9)
            << ' ' << fixedNumber(speed, 6) << ' '
            << fixedNumber(std::hypot(b.x - a.x, b.y - a.y), 6) << " 1 " << type << '\n';
    }
    // Fields2Cover's reader stops at the first line that is not eight numbers, so the
    // units line goes last.
    out << "# Fields2Cover path (x y z angle velocity len dir type): metres, radians, m/s; "
           "frame "
        << formats::frameDescription(info.epsg) << "\n";
    return out.str();
}

std::string pathToVda5050(const CoveragePath& input, const PathExportInfo& info) {
    const CoveragePath path = withoutRepeats(input);
    const std::vector<double> headings = formats::headingsOf(path.points);
    const std::string mapDescription = "FloorCover coverage path: x, y in metres, theta in "
                                       "radians; frame " +
                                       formats::frameDescription(info.epsg);
    ordered_json nodes = ordered_json::array(), edges = ordered_json::array();
    for (size_t i = 0; i < path.points.size(); ++i) {
        ordered_json position;
        position["x"] = path.points[i].x;
        position["y"] = path.points[i].y;
        position["theta"] = headings[i];
        position["mapId"] = info.mapId;
        if (i == 0)
            position["mapDescription"] = mapDescription;
        ordered_json node;
        node["nodeId"] = "node-" + std::to_string(i);
        node["sequenceId"] = 2 * i;
        node["released"] = true;
        node["nodePosition"] = std::move(position);
        node["actions"] = ordered_json::array();
        nodes.push_back(std::move(node));
        if (i + 1 == path.points.size())
            continue;
        const Vec2 a = path.points[i], b = path.points[i + 1];
        ordered_json edge;
        edge["edgeId"] = "edge-" + std::to_string(i);
        edge["sequenceId"] = 2 * i + 1;
        edge["edgeDescription"] = segmentKindName(path.kinds[i]);
        edge["released"] = true;
        edge["startNodeId"] = "node-" + std::to_string(i);
        edge["endNodeId"] = "node-" + std::to_string(i + 1);
        edge["maxSpeed"] = info.robot.speed;
        edge["length"] = std::hypot(b.x - a.x, b.y - a.y);
        edge["actions"] = ordered_json::array();
        edges.push_back(std::move(edge));
    }
    ordered_json order;
    order["headerId"] = 0;
    order["timestamp"] = info.timestamp.empty() ? utcNow() : info.timestamp;
    order["version"] = "2.0.0";
    order["manufacturer"] = info.manufacturer;
    order["serialNumber"] = info.serialNumber;
    order["orderId"] = info.orderId;
    order["orderUpdateId"] = 0;
    order["nodes"] = std::move(nodes);
    order["edges"] = std::move(edges);
    return dumped(order, 1) + "\n";
}

std::string pathToWkt(const CoveragePath& input) {
    const CoveragePath path = withoutRepeats(input);
    if (path.points.size() < 2)
        return "LINESTRING EMPTY\n";
    std::string text = "LINESTRING (";
    for (size_t i = 0; i < path.points.size(); ++i)
        text += (i ? ", " : "") + fixedNumber(path.points[i].x, 6) + " " +
                fixedNumber(path.points[i].y, 6);
    return text + ")\n";
}

} // namespace fc
