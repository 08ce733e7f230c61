// The native project file: a versioned JSON document with the plan, the robot profile,
// the sweep options and the planning selection.
#include "formats/JsonSupport.h"
#include "formats/PlanIO.h"

#include <algorithm>
#include <cmath>

namespace fc {

using nlohmann::json;
using nlohmann::ordered_json;

namespace {

constexpr const char* kProjectFormatName = "floorcover-project";

const json* memberOf(const json& object, const char* key) {
    if (!object.contains(key) || object[key].is_null())
        return nullptr;
    return &object[key];
}

// Overwrites `value` when the member is present; it must then be a finite number.
void readNumber(const json& object, const char* key, const std::string& where, double& value) {
    const json* member = memberOf(object, key);
    if (!member)
        return;
    if (!member->is_number() || !std::isfinite(member->get<double>()))
        throw InputError(where + "." + key + " must be a finite number (got " +
                         formats::describeJsonValue(*member) + ")");
    value = member->get<double>();
}

const json& objectMember(const json& object, const char* key, const std::string& where) {
    static const json kEmpty = json::object();
    const json* member = memberOf(object, key);
    if (!member)
        return kEmpty;
    if (!member->is_object())
        throw InputError(where + "." + key + " must be an object");
    return *member;
}

bool readPoint(const json& object, const char* key, Vec2& point) {
    const json* member = memberOf(object, key);
    if (!member)
        return false;
    if (!member->is_array() || member->size() != 2 || !(*member)[0].is_number() ||
        !(*member)[1].is_number())
        throw InputError(std::string(key) + " must be [x, y] or null (got " +
                         formats::describeJsonValue(*member) + ")");
    point = {(*member)[0].get<double>(), (*member)[1].get<double>()};
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
        throw InputError(std::string(key) + " has a non-finite coordinate");
    return true;
}

Plan readPlanObject(const json& planJson) {
    Plan plan;
    if (!planJson.contains("boundary"))
        throw InputError("plan has no boundary");
    plan.boundary = formats::ringFromJson(planJson["boundary"], "boundary");
    if (const json* obstacles = memberOf(planJson, "obstacles")) {
        if (!obstacles->is_array())
            throw InputError("plan.obstacles must be an array of rings");
        for (const json& ring : *obstacles) {
            const std::string what = "obstacle " + std::to_string(plan.obstacles.size() + 1);
            plan.obstacles.push_back(formats::ringFromJson(ring, what));
        }
    }
    if (const json* rooms = memberOf(planJson, "rooms")) {
        if (!rooms->is_array())
            throw InputError("plan.rooms must be an array");
        for (size_t i = 0; i < rooms->size(); ++i) {
            const json& room = (*rooms)[i];
            const std::string label = "room " + std::to_string(i + 1);
            if (!room.is_object() || !room.contains("name") || !room["name"].is_string() ||
                room["name"].get<std::string>().empty())
                throw InputError(label + " has no name");
            const std::string name = room["name"].get<std::string>();
            const bool duplicate = std::any_of(plan.rooms.begin(), plan.rooms.end(),
                                               [&](const Room& r) { return r.name == name; });
            if (duplicate)
                throw InputError("duplicate room name \"" + name + "\"");
            if (!room.contains("outline"))
                throw InputError("room \"" + name + "\" has no outline");
            plan.rooms.push_back(
                Room{name, formats::ringFromJson(room["outline"], "room \"" + name + "\"")});
        }
    }
    if (const json* name = memberOf(planJson, "name"); name && name->is_string())
        plan.name = name->get<std::string>();
    if (const json* epsg = memberOf(planJson, "epsg")) {
        if (!epsg->is_number_integer() || epsg->get<long long>() <= 0 ||
            epsg->get<long long>() > 999999999)
            throw InputError("plan.epsg must be a positive integer EPSG code (got " +
                             formats::describeJsonValue(*epsg) + ")");
        plan.epsg = static_cast<int>(epsg->get<long long>());
    }
    return plan;
}

ordered_json pointOrNull(bool present, Vec2 point) {
    return present ? ordered_json::array({point.x, point.y}) : ordered_json();
}

} // namespace

Project readProject(const std::string& text) {
    const json root = formats::parseJsonDocument(text);
    if (!root.is_object() || !root.contains("format"))
        throw InputError("not a FloorCover project (no \"format\" member)");
    if (!root["format"].is_string() || root["format"].get<std::string>() != kProjectFormatName)
        throw InputError("not a FloorCover project (format is " +
                         formats::describeJsonValue(root["format"]) + ", expected \"" +
                         kProjectFormatName + "\")");
    if (!root.contains("version") || !root["version"].is_number_integer())
        throw InputError("project has no integer \"version\"");
    const long long version = root["version"].get<long long>();
    if (version > kProjectFormatVersion)
        throw InputError("project format version " + std::to_string(version) +
                         " is newer than this FloorCover supports (" +
                         std::to_string(kProjectFormatVersion) + "); update FloorCover");
    if (version < 1)
        throw InputError("project format version " + std::to_string(version) + " is invalid");

    Project project;
    if (!root.contains("plan") || !root["plan"].is_object())
        throw InputError("project has no \"plan\" object");
    project.plan = readPlanObject(root["plan"]);

    const json& robot = objectMember(root, "robot", "project");
    readNumber(robot, "robot_diameter", "robot", project.robot.robotDiameter);
    readNumber(robot, "cleaning_diameter", "robot", project.robot.cleaningDiameter);
    readNumber(robot, "coverage_width", "robot", project.robot.coverageWidth);
    readNumber(robot, "speed", "robot", project.robot.speed);
    readNumber(robot, "turn_time", "robot", project.robot.turnTime);

    const json& sweep = objectMember(root, "sweep", "project");
    readNumber(sweep, "angle_deg", "sweep", project.sweep.angleDeg);
    if (const json* automatic = memberOf(sweep, "automatic")) {
        if (!automatic->is_boolean())
            throw InputError("sweep.automatic must be true or false");
        project.sweep.automatic = automatic->get<bool>();
    }
    // Files written before per-room sweeps fixed their angle: without the key they keep it.
    project.sweep.perRoom = false;
    if (const json* perRoom = memberOf(sweep, "per_room")) {
        if (!perRoom->is_boolean())
            throw InputError("sweep.per_room must be true or false");
        project.sweep.perRoom = perRoom->get<bool>();
    }
    if (const json* angles = memberOf(sweep, "room_angles")) {
        if (!angles->is_object())
            throw InputError("sweep.room_angles must map room names to angles in degrees");
        for (const auto& [name, value] : angles->items()) {
            if (!value.is_number() || !std::isfinite(value.get<double>()))
                throw InputError("sweep.room_angles[\"" + name +
                                 "\"] must be a finite number of degrees (got " +
                                 formats::describeJsonValue(value) + ")");
            project.sweep.roomAngles[name] = value.get<double>();
        }
    }

    if (const json* solver = memberOf(root, "solver")) {
        if (!solver->is_string())
            throw InputError("solver must be a string (got " + formats::describeJsonValue(*solver) +
                             ")");
        project.solver = solver->get<std::string>();
    }
    if (const json* selected = memberOf(root, "selectedRooms")) {
        if (!selected->is_array())
            throw InputError("selectedRooms must be an array of room names");
        for (const json& name : *selected) {
            if (!name.is_string())
                throw InputError("selectedRooms must hold room names (got " +
                                 formats::describeJsonValue(name) + ")");
            project.selectedRooms.push_back(name.get<std::string>());
        }
    }
    project.hasStart = readPoint(root, "start", project.start);
    project.hasEnd = readPoint(root, "end", project.end);
    return project;
}

std::string writeProject(const Project& project) {
    const Plan& plan = project.plan;
    ordered_json planJson;
    planJson["name"] = plan.name;
    planJson["epsg"] = plan.epsg ? ordered_json(*plan.epsg) : ordered_json();
    planJson["boundary"] = formats::ringToJson(plan.boundary, false);
    planJson["obstacles"] = ordered_json::array();
    for (const Ring& obstacle : plan.obstacles)
        planJson["obstacles"].push_back(formats::ringToJson(obstacle, false));
    planJson["rooms"] = ordered_json::array();
    for (const Room& room : plan.rooms)
        planJson["rooms"].push_back(
            {{"name", room.name}, {"outline", formats::ringToJson(room.outline, false)}});

    const RobotProfile& robot = project.robot;
    ordered_json root;
    root["format"] = kProjectFormatName;
    root["version"] = kProjectFormatVersion;
    root["plan"] = std::move(planJson);
    root["robot"] = {{"robot_diameter", robot.robotDiameter},
                     {"cleaning_diameter", robot.cleaningDiameter},
                     {"coverage_width", robot.coverageWidth},
                     {"speed", robot.speed},
                     {"turn_time", robot.turnTime}};
    ordered_json roomAngles = ordered_json::object();
    for (const auto& [name, angle] : project.sweep.roomAngles)
        roomAngles[name] = angle;
    root["sweep"] = {{"angle_deg", project.sweep.angleDeg},
                     {"automatic", project.sweep.automatic},
                     {"per_room", project.sweep.perRoom},
                     {"room_angles", std::move(roomAngles)}};
    root["solver"] = project.solver;
    root["selectedRooms"] = project.selectedRooms;
    root["start"] = pointOrNull(project.hasStart, project.start);
    root["end"] = pointOrNull(project.hasEnd, project.end);
    return root.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

} // namespace fc
