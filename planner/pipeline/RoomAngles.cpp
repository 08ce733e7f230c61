#include "pipeline/RoomAngles.h"

#include "geometry/Geometry.h"
#include "pipeline/WallFamilies.h"

#include <algorithm>
#include <cmath>

namespace fc {

double normalizedAngle(double deg) {
    return std::fmod(std::fmod(deg, 180.0) + 180.0, 180.0);
}

double angleDistance(double a, double b) {
    const double d = std::abs(normalizedAngle(a) - normalizedAngle(b));
    return std::min(d, 180.0 - d);
}

namespace {

// A room whose second wall family is at least this share of its first (by wall length) is
// also tried at the second: a trapezoid's slanted sides, a room whose door wall runs across
// its long walls. Rectilinear rooms have one family and are not.
constexpr double kSecondFamilyShare = 0.5;

// Stripes along the longer extent of `outline` in the frame of wall family `family`
// (degrees in [0, 90)): fewer, longer stripes and so fewer turns.
double alongLongerExtent(const Ring& outline, double family) {
    const double rad = family * M_PI / 180.0;
    const Vec2 u{std::cos(rad), std::sin(rad)}, v{-std::sin(rad), std::cos(rad)};
    double uMin = INFINITY, uMax = -INFINITY, vMin = INFINITY, vMax = -INFINITY;
    for (const Vec2& p : outline) {
        uMin = std::min(uMin, dot(p, u)), uMax = std::max(uMax, dot(p, u));
        vMin = std::min(vMin, dot(p, v)), vMax = std::max(vMax, dot(p, v));
    }
    // A near-square room keeps the family's own direction, whichever way it is drawn.
    const bool alongU = uMax - uMin >= (vMax - vMin) * (1.0 - 1e-6);
    return normalizedAngle(alongU ? family : family + 90.0);
}

double angleFromWalls(const Plan& walls, const Ring& outline) {
    const std::vector<double> families = dominantWallAngles(walls, 1);
    return alongLongerExtent(outline, families.empty() ? 0.0 : families.front());
}

// A room's own walls: its outline and the obstacles inside it.
Plan roomWalls(const Plan& plan, const Room& room) {
    Plan walls;
    walls.boundary = room.outline;
    for (const Ring& obstacle : plan.obstacles)
        if (!obstacle.empty() && pointInRing(room.outline, obstacle.front()))
            walls.obstacles.push_back(obstacle);
    return walls;
}

} // namespace

std::map<std::string, double> roomSweepAngles(const Plan& plan, const SweepOptions& sweep) {
    std::map<std::string, double> out;
    out[""] = angleFromWalls(plan, plan.boundary);
    for (const Room& room : plan.rooms) {
        if (auto it = sweep.roomAngles.find(room.name); it != sweep.roomAngles.end()) {
            out[room.name] = normalizedAngle(it->second);
            continue;
        }
        out[room.name] = angleFromWalls(roomWalls(plan, room), room.outline);
    }
    if (auto it = sweep.roomAngles.find("Floor");
        it != sweep.roomAngles.end() && plan.rooms.empty())
        out[""] = normalizedAngle(it->second);
    return out;
}

double sweepAngleOfRoom(const std::map<std::string, double>& angles, const std::string& room) {
    auto it = angles.find(room);
    return it != angles.end() ? it->second : angles.at("");
}

// The groups of the rooms' own angles, the one with the most rooms first.
std::vector<std::pair<double, int>> angleGroups(const std::map<std::string, double>& walls) {
    std::vector<std::pair<double, int>> groups; // angle, rooms
    for (const auto& entry : walls) {
        auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
            return angleDistance(g.first, entry.second) < 0.5;
        });
        if (it == groups.end())
            groups.push_back({entry.second, 1});
        else
            ++it->second;
    }
    std::stable_sort(groups.begin(), groups.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    return groups;
}

std::map<std::string, double> roomAnglesOf(const PlanResult& result, const Plan& plan) {
    std::map<std::string, double> angles;
    if (result.rings) // loops along the walls: no room swept at an angle
        return angles;
    auto add = [&](const std::string& room, double angle) {
        const bool named = std::any_of(plan.rooms.begin(), plan.rooms.end(),
                                       [&](const Room& r) { return r.name == room; });
        angles[named ? room : std::string()] = angle;
    };
    if (result.parts.empty()) {
        for (const std::string& room : result.prepared.decomposition.roomNames)
            add(room, result.stripeAngleDeg);
    }
    for (const PlanPart& part : result.parts)
        for (const std::string& room : part.rooms)
            add(room, part.stripeAngleDeg);
    return angles;
}

std::map<std::string, double> familyAngles(const Plan& plan, const SweepOptions& sweep) {
    const std::map<std::string, double> walls = roomSweepAngles(plan, sweep);
    const std::vector<std::pair<double, int>> groups = angleGroups(walls);
    // Every room of the main group's wall family (along or across it) at the main group's
    // angle: sweeping a family in two passes crosses the building twice (offices, then their
    // corridors). Fixed angles stay.
    std::map<std::string, double> family = walls;
    for (auto& [room, angle] : family) {
        const double d = angleDistance(angle, groups.front().first);
        if (sweep.roomAngles.count(room) == 0 && (d < 0.5 || std::abs(d - 90.0) < 0.5))
            angle = groups.front().first;
    }
    return family;
}

std::map<std::string, double> roomSecondAngles(const Plan& plan, const SweepOptions& sweep) {
    std::map<std::string, double> out;
    // `walls`' second family where it is strong enough, stripes along `outline`'s longer
    // extent in its frame.
    auto addSecond = [&out](const std::string& key, const Plan& walls, const Ring& outline) {
        const std::vector<WallFamily> families = wallFamilies(walls, 2);
        if (families.size() == 2 && families[1].length >= kSecondFamilyShare * families[0].length)
            out[key] = alongLongerExtent(outline, families[1].angleDeg);
    };
    for (const Room& room : plan.rooms)
        if (sweep.roomAngles.count(room.name) == 0)
            addSecond(room.name, roomWalls(plan, room), room.outline);
    if (plan.rooms.empty() && sweep.roomAngles.count("Floor") == 0) // one room, "Floor"
        addSecond("", plan, plan.boundary);
    return out;
}

} // namespace fc
