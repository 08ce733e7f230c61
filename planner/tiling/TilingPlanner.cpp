#include "tiling/TilingPlanner.h"

#include "model/Validation.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fc::tiling {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

double headingDegrees(const Pose& pose) {
    return pose.heading * 180.0 / 3.14159265358979323846;
}

constexpr double kMaxTiles = 200000.0;

} // namespace

TilingPlan tilePlan(const TilingRequest& request) {
    request.robot.validate();
    const Plan plan = normalizedPlan(request.plan);
    RobotProfile footprint; // the plan checks need a robot; one block's size is enough
    footprint.robotDiameter = footprint.cleaningDiameter = footprint.coverageWidth =
        request.robot.blockLeg;
    validatePlan(plan, footprint);
    // Each tile is four blocks of leg^2 / 2: a leg of 4 mm made 2.9 million waypoints and
    // 4.3 GB for a 92 m^2 floor.
    const double tiles = freeAreaOf(plan) / (2.0 * request.robot.blockLeg * request.robot.blockLeg);
    if (tiles > kMaxTiles) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "the floor needs about %.0f tiles of a %g m block leg, more than %.0f: "
                      "choose a longer block leg",
                      tiles, request.robot.blockLeg, kMaxTiles);
        throw InputError(text);
    }
    TilingPlan result;
    const auto start = std::chrono::steady_clock::now();
    result.grid = buildTriangleGrid(plan, request.robot.blockLeg);
    result.tiling = tileFreeSpace(result.grid, request.tiling);
    result.tilingSeconds = secondsSince(start);
    result.problem.robot = request.robot;
    for (const Tile& tile : result.tiling.tiles)
        result.problem.poses.push_back(poseOf(result.grid, tile));
    return result;
}

void orderTiles(TilingPlan& plan, const std::string& solver, std::uint64_t seed,
                const std::function<bool()>& cancelled) {
    if (cancelled && cancelled())
        throw OrderingCancelled();
    const auto start = std::chrono::steady_clock::now();
    plan.tour = solveOrdering(solver, plan.problem, seed, cancelled);
    plan.orderingSeconds = secondsSince(start);
    plan.solver = solver;
    plan.energy = tourEnergy(plan.problem, plan.tour);
    plan.length = tourLength(plan.problem, plan.tour);
    plan.shapeChanges = tourShapeChanges(plan.problem, plan.tour);
}

TilingPlan planTiling(const TilingRequest& request) {
    TilingPlan plan = tilePlan(request);
    orderTiles(plan, request.solver, request.seed, request.cancelled);
    return plan;
}

std::string tilingMetricsJson(const TilingPlan& plan) {
    nlohmann::ordered_json j;
    j["energy"] = plan.energy.total();
    j["length"] = plan.length;
    j["shape_changes"] = plan.shapeChanges;
    j["waypoints"] = plan.tour.size();
    j["seconds"] = plan.orderingSeconds;
    j["solver"] = plan.solver;
    j["translation"] = plan.energy.translation;
    j["transformation"] = plan.energy.transformation;
    j["orientation"] = plan.energy.orientation;
    j["free_cells"] = plan.tiling.freeCells;
    j["unreachable_cells"] = plan.tiling.unreachable.size();
    j["untiled_cells"] = plan.tiling.untiled.size();
    j["tiling_seconds"] = plan.tilingSeconds;
    return j.dump();
}

std::string waypointsToFormat(const std::string& path, const TilingPlan& plan) {
    if (endsWith(path, ".csv")) {
        std::ostringstream out;
        out.precision(10);
        out << "x,y,shape,heading\n";
        for (int w : plan.tour) {
            const Pose& pose = plan.problem.poses[w];
            out << pose.waypoint().x << ',' << pose.waypoint().y << ',' << shapeName(pose.shape)
                << ',' << headingDegrees(pose) << '\n';
        }
        return out.str();
    }
    if (endsWith(path, ".json")) {
        nlohmann::ordered_json j;
        j["solver"] = plan.solver;
        j["block_leg"] = plan.problem.robot.blockLeg;
        j["energy"] = plan.energy.total();
        nlohmann::json list = nlohmann::json::array();
        for (int w : plan.tour) {
            const Pose& pose = plan.problem.poses[w];
            list.push_back({{"x", pose.waypoint().x},
                            {"y", pose.waypoint().y},
                            {"shape", shapeName(pose.shape)},
                            {"heading", headingDegrees(pose)}});
        }
        j["waypoints"] = list;
        // Where the robot cannot clean: centres of the cells no shape reaches or left untiled.
        auto centres = [&plan](const std::vector<int>& cells) {
            nlohmann::json points = nlohmann::json::array();
            for (int cell : cells) {
                const Vec2 c = plan.grid.centroid(cell);
                points.push_back({c.x, c.y});
            }
            return points;
        };
        j["unreachable_cells"] = centres(plan.tiling.unreachable);
        j["untiled_cells"] = centres(plan.tiling.untiled);
        return j.dump(1) + "\n";
    }
    throw InputError("unsupported waypoint file \"" + path + "\" (use .csv or .json)");
}

} // namespace fc::tiling
