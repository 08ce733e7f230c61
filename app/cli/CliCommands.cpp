#include "CliCommands.h"

#include "Arguments.h"
#include "CliCommon.h"
#include "formats/FileIO.h"
#include "formats/PathIO.h"
#include "formats/PlanIO.h"
#include "model/RobotPlacement.h"
#include "model/Validation.h"
#include "pipeline/Comparison.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fc::cli {
namespace {

const char* kUsage = R"(usage: floorcover-cli COMMAND PLAN [options]

commands:
  plan PLAN     plan a coverage path; prints one JSON line of metrics
                [--width W] [--robot-diameter L] [--cleaning-diameter D] [--speed V]
                [--turn-time S] [--angle per-room|auto|DEG] [--rooms A,B] [--start X,Y] [--end X,Y]
                [--solver exact|heuristic|greedy|dqn|dqn-search|reeb-cpp|adjacency-ga|
                adjacency-ga-centres] [--model FILE]
                [--seed N] [--out FILE] [--strict] [--no-wall-loop] [--no-rings]
                (--no-wall-loop: never drive once along the outer walls first; by default
                that is planned beside the stripes where it is estimated shorter, on ragged
                traced walls, and kept when it is faster; it also turns off the rings)
                (--no-rings: stripes only; by default floors up to 1,000 m^2 are also
                planned as loops along the walls, each W further in than the last, kept
                where faster: curved corridors, round and slanted rooms)
                (--robot-diameter L, default 0.6: the robot is a disc; its centre keeps L/2
                from walls, so passages at least L wide are driven and swept; a --start
                or --end inside an obstacle or outside the floor is refused, one closer
                than L/2 to a wall moves to where the robot fits, with a note)
                (--angle per-room, the default: each room's stripes follow its own walls;
                --angle auto: the shortest estimated time among the angles that cover
                everything reachable, or within 1% of it the shortest path; losses above
                0.5% of the floor are warned on stderr,
                and with --strict the exit code is 3)
                (dqn without --model uses the built-in generalist model, trained on
                generated floors; with --model FILE, a file written by train, it plans
                at that model's sweep angle; dqn-search: the same model guides a
                search for 2 s per query, better than heuristic on large floors)
                (--out format by extension: .geojson .csv .json .yaml)
  graph PLAN    write the corner graph: [--width W] [--angle DEG] --out FILE.json
  compare PLAN  run several solvers on the same query: [--solvers a,b,..] [--json]
                and the plan options above;
                then the paper's ratios: our best solver's extra distance and turns
                divided by each baseline's (reeb-cpp, adjacency-ga)
  train PLAN    train the Double-DQN planner for this plan: --out MODEL
                [--episodes N] [--seconds S] (default 300 s when neither is given)
                [--seed N] [--setting graph|improved|paper] [--resume] [--evaluate-every N]
                (graph is the default; it starts from the built-in generalist model
                unless --from-scratch) and the robot and --angle options above;
                prints progress; Ctrl-C stops after the current episode and saves
                what was learnt
  tile PLAN     tiling robot: tile the floor with its five shapes and order the tiles by
                energy; prints one JSON line (energy, length, shape_changes, waypoints,
                seconds); [--solver zigzag|spiral|greedy|aco|aco+2opt|ga|exact|
                ppo-policy|ppo] [--seed N] [--block-leg M] [--block-masses M1,M2,M3,M4]
                [--out FILE.csv|FILE.json]; ppo trains first (about 50 s) unless
                --model FILE; [--train-seconds S] [--save-model FILE]
  import FILE   import a DXF drawing, a ROS occupancy map (.yaml), WKT, GeoJSON or a 3D
                building model (.ifc .obj .gltf .glb .stl, cut at --height above --storey):
                --out PLAN.geojson|PLAN.fcproj [--boundary-layers A,B] [--obstacle-layers C]
                [--room-layers D] [--ignore-layers E] [--units M_PER_UNIT] [--gap M]
                [--simplify M] [--epsg N] [--storey S] [--height H] [--repair: a plan
                with self-intersections, obstacles across the wall or overlapping rooms
                is made valid (GEOS) instead of refused; what changed on stderr]
                [--building K: a GeoJSON site of several buildings (boundary polygons) is
                imported one building at a time, 1 = the largest; its obstacles and rooms
                come with it]; warnings on stderr,
                one JSON line (areas, obstacles, rooms, warnings, start) on stdout;
                occupancy maps are cleaned (what was removed under "cleaning"):
                [--unknown wall|free] [--unknown-gap M2 (0.15): smaller unknown patches inside
                the map are floor, and up to 4 times that where no laser returns border them]
                [--speckle M2 (0.15)] [--smooth on|off] [--fragment M2 (0.5)]
                [--opening M (robot diameter / 2)] [--closing M (0)] [--robot-diameter L]
                [--straighten on|off: walls fitted as lines along the map's two dominant
                directions] [--wall-band CELLS (1): how far a wall may move] [--notch M (0.1):
                shallower notches in a straightened wall are filled]
                [--no-cleaning] and split into rooms at doorways:
                [--segment-rooms distance|morphological|none] [--min-room M2 (1)]
                [--max-door M (1.6): rooms meeting along more are merged]
  export PLAN   write the path, the plan or its zones for robots and GIS: --out FILE
                [--format geojson|wgs84-geojson|csv|json|ros-path|nav2|fields2cover|
                vda5050|zones|svg|pdf|wkt] (default from the extension: .geojson .csv
                .json .yaml .svg .pdf .wkt) [--what path|plan|zones] (default path; plan
                for wgs84-geojson and wkt; zones for zones), the plan options above when
                the path is exported; ros-path/nav2: [--frame-id ID]; vda5050:
                [--manufacturer M] [--serial-number S] [--order-id O] [--map-id ID]

PLAN is a GeoJSON floor plan (.geojson) or a FloorCover project (.fcproj). A GeoJSON site
of several buildings (boundary polygons) is planned one building at a time: --building K,
1 = the largest (plan, graph, train, compare, tile, export); its obstacles and rooms come
with it. plan without --building (or with --building all) plans every building: a path
file each (--out site.csv writes site-building-K.csv), one JSON line of the site's totals
with each building's metrics under "buildings"; --rooms, --start and --end apply to the
building that holds them. A building that cannot be planned is left out with a warning
and a "skipped" entry (with --strict: exit 3). export without --building (or with
--building all) writes every building the same way, a file each (one VDA 5050 order
each), and one JSON line listing them.
Exit codes: 0 success, 2 bad input (one line on stderr), 3 coverage loss with --strict,
1 internal error.
)";

} // namespace

const std::vector<std::string> kPlanOptions{
    "--width",        "--robot-diameter", "--cleaning-diameter",
    "--speed",        "--turn-time",      "--angle",
    "--rooms",        "--start",          "--end",
    "--solver",       "--model",          "--seed",
    "--out",          "--strict",         "--no-transition-cells",
    "--no-wall-loop", "--no-rings",       "--building"};

// A request from the project file's settings, overridden by command-line options.
PlanRequest requestFrom(const Project& project, const Arguments& args) {
    PlanRequest r = planRequestFor(project);
    if (auto w = args.number("--width")) {
        r.robot.coverageWidth = *w;
        // Keep L <= W <= D when only W is given; explicit values are validated as given.
        if (!args.has("--cleaning-diameter") && r.robot.cleaningDiameter < *w)
            r.robot.cleaningDiameter = *w;
        if (!args.has("--robot-diameter") && r.robot.robotDiameter > *w)
            r.robot.robotDiameter = *w;
    }
    if (auto v = args.number("--robot-diameter"))
        r.robot.robotDiameter = *v;
    if (auto v = args.number("--cleaning-diameter"))
        r.robot.cleaningDiameter = *v;
    if (auto v = args.number("--speed"))
        r.robot.speed = *v;
    if (auto v = args.number("--turn-time"))
        r.robot.turnTime = *v;
    if (auto a = args.text("--angle")) {
        if (*a == "auto") {
            r.sweep.automatic = true;
        } else if (*a == "per-room") {
            r.sweep.automatic = false;
            r.sweep.perRoom = true;
        } else {
            r.sweep.automatic = false;
            r.sweep.perRoom = false;
            r.sweep.angleDeg = *args.number("--angle");
        }
    }
    if (args.has("--rooms"))
        r.rooms = args.list("--rooms");
    if (auto p = args.point("--start"))
        r.start = *p;
    if (auto p = args.point("--end"))
        r.end = *p;
    if (auto s = args.text("--solver"))
        r.solver = *s;
    if (auto m = args.text("--model"))
        r.modelPath = *m;
    if (auto s = args.integer("--seed"))
        r.seed = static_cast<std::uint64_t>(*s);
    r.transitionCells = !args.has("--no-transition-cells");
    r.wallLoop = !args.has("--no-wall-loop");
    r.rings = !args.has("--no-rings");
    r.robot.validate();
    return r;
}

namespace {

// A start or end point where the robot cannot stand is refused with its reason; one beside a
// wall moves to where the robot fits, with a note (as the editor's Place tools do): planning
// from it failed with "cannot be joined to the corner graph without collision".
void placeEndpoint(const std::string& path, const PlanRequest& request, std::optional<Vec2>& point,
                   const char* what) {
    if (!point)
        return;
    const double diameter = request.robot.robotDiameter > 0.0 ? request.robot.robotDiameter
                                                              : request.robot.coverageWidth;
    const RobotPlacement placed = placeRobot(request.plan, *point, diameter);
    char at[96], size[32];
    // Millimetres for any plan's coordinates (UTM included); absurd ones in short form.
    const bool absurd = std::max(std::abs(point->x), std::abs(point->y)) >= 1e9;
    std::snprintf(at, sizeof at, absurd ? "(%.6g, %.6g)" : "(%.3f, %.3f)", point->x, point->y);
    std::snprintf(size, sizeof size, "%.2f m", diameter);
    switch (placed.problem) {
    case PlacementProblem::OutsideFloor:
        throw InputError(std::string("the ") + what + " point " + at + " lies outside the floor");
    case PlacementProblem::InsideObstacle:
        throw InputError(std::string("the ") + what + " point " + at + " lies inside an obstacle");
    case PlacementProblem::NoRoom:
        throw InputError(std::string("the robot (") + size +
                         " across) does not fit at or near the " + what + " point " + at);
    case PlacementProblem::None:
        break;
    }
    if (placed.moved > 0.0) {
        char to[96];
        std::snprintf(to, sizeof to, "%.2f m to (%.3f, %.3f)", placed.moved, placed.position.x,
                      placed.position.y);
        std::cerr << "floorcover-cli: note: " << path << ": the " << what << " point " << at
                  << " is closer to a wall than the robot allows; moved " << to
                  << ", where the robot (" << size << " across) fits\n";
        point = placed.position;
    }
}

} // namespace

void rethrowInFile(const std::string& path, const InputError& e) {
    if (dynamic_cast<const RepairablePlanError*>(&e))
        throw RepairablePlanError(path + ": " + e.what());
    throw InputError(path + ": " + e.what());
}

PlanResult planFromArguments(const std::string& path, const Project& project, const Arguments& args,
                             PlanRequest& request) {
    PlanResult result;
    try {
        request = requestFrom(project, args);
        placeEndpoint(path, request, request.start, "start");
        placeEndpoint(path, request, request.end, "end");
        result = planCoverage(request);
    } catch (const InputError& e) {
        rethrowInFile(path, e);
    } catch (const SolverError& e) {
        throw InputError(path + ": " + e.what());
    }
    for (const std::string& w : result.warnings)
        std::cerr << "floorcover-cli: warning: " << path << ": " << w << "\n";
    if (result.shavedTeeth > 0) {
        char depth[32];
        std::snprintf(depth, sizeof depth, "%.2f", result.shavedToothDepth);
        std::cerr << "floorcover-cli: note: " << path << ": planned with " << result.shavedTeeth
                  << " wall teeth (bumps up to " << depth
                  << " m deep) cut back to their walls; the path keeps L/2 from them\n";
    }
    if (result.rings)
        std::cerr << "floorcover-cli: note: " << path
                  << ": planned as loops along the walls, each W further in than the last "
                     "(estimated faster than stripes here)\n";
    if (request.sweep.automatic)
        std::cerr << "floorcover-cli: note: " << path << ": sweep angle " << result.stripeAngleDeg
                  << " degrees chosen (shortest estimated time among the plans that cover "
                     "everything reachable, or within 1% of it the shortest path)\n";
    return result;
}

PathExportInfo exportInfoFor(const Project& project, const PlanRequest& request,
                             const PlanResult& result) {
    PathExportInfo info;
    info.solver = result.solution.solver;
    info.robot = request.robot;
    info.metrics = result.metrics;
    info.epsg = project.plan.epsg;
    return info;
}

const std::string& planPath(const Arguments& args) {
    if (args.positional().size() != 1)
        throw InputError("expected exactly one PLAN file (see floorcover-cli --help)");
    return args.positional()[0];
}

Project loadProject(const std::string& path, const Arguments& args) {
    std::optional<int> building;
    if (args.text("--building") == "all")
        throw InputError(path + ": --building all: only `plan` plans every building of a site; " +
                         "choose one with --building K");
    if (const auto k = args.integer("--building")) {
        if (*k < 1 || *k > 1'000'000)
            throw InputError(path + ": --building " + std::to_string(*k) +
                             ": buildings are numbered from 1, the largest");
        building = static_cast<int>(*k);
    }
    Project project = loadProjectFile(path, building);
    for (const std::string& note : project.notes)
        std::cerr << "floorcover-cli: note: " << path << ": " << note << "\n";
    return project;
}

namespace {

constexpr int kExitCoverageLoss = 3;

int commandPlan(const Arguments& args) {
    args.allowOnly(kPlanOptions);
    const std::string& path = planPath(args);
    if (args.text("--building") == "all") {
        std::vector<double> areas; // none: a plan of one building is a site of one
        try {
            loadProjectFile(path);
        } catch (const SiteError& e) {
            areas = e.buildingAreas();
        }
        return commandPlanSite(args.with("--building", std::nullopt), areas);
    }
    Project project;
    try {
        project = loadProject(path, args);
    } catch (const SiteError& e) {
        // A site without --building: every building, each on its own (what a user handing
        // over the site's file wants), and said so.
        std::cerr << "floorcover-cli: note: " << path << ": " << e.buildingAreas().size()
                  << " buildings, each planned on its own (--building K plans one)"
                  << (args.has("--out") ? "; a path file each, NAME-building-K" : "") << "\n";
        return commandPlanSite(args, e.buildingAreas());
    }
    if (auto out = args.text("--out"))
        requirePathFormat(*out);
    PlanRequest request;
    const PlanResult result = planFromArguments(path, project, args, request);
    if (auto out = args.text("--out"))
        writeFileAtomically(
            *out, pathToFormat(*out, result.path, exportInfoFor(project, request, result)));
    std::cout << metricsJsonLine(result.solution.solver, result.metrics) << std::endl;
    // --strict: any reported loss of coverage fails the run (the path is still written).
    if (args.has("--strict") && !coverageLossWarnings(result.metrics).empty()) {
        std::cerr << "floorcover-cli: error: " << path
                  << ": coverage loss above 0.5% of the selected floor (--strict)\n";
        return kExitCoverageLoss;
    }
    return 0;
}

int commandGraph(const Arguments& args) {
    args.allowOnly(
        {"--width", "--angle", "--out", "--robot-diameter", "--no-transition-cells", "--building"});
    const std::string& path = planPath(args);
    const auto out = args.text("--out");
    if (!out)
        throw InputError("graph needs --out FILE.json");
    const Project project = loadProject(path, args);
    try {
        PlanRequest request = requestFrom(project, args);
        if (request.sweep.automatic)
            throw InputError("graph needs a fixed --angle (not auto)");
        const PreparedPlan prepared = preparePlan(request.plan, request.robot,
                                                  request.sweep.angleDeg, request.transitionCells);
        writeFileAtomically(*out, graphToJson(prepared.graph, prepared.decomposition));
        std::cout << "{\"nodes\":" << prepared.graph.nodes.size()
                  << ",\"edges\":" << prepared.graph.edges.size()
                  << ",\"cells\":" << prepared.graph.cells.size() << "}" << std::endl;
    } catch (const InputError& e) {
        rethrowInFile(path, e);
    }
    return 0;
}

// Under the table: the paper's ratios; with --json one more line {"ratios":[...]}.
void printRatios(const std::vector<BaselineRatio>& ratios, bool json) {
    if (ratios.empty())
        return;
    if (json) {
        std::ostringstream line;
        line << "{\"ratios\":[";
        for (size_t i = 0; i < ratios.size(); ++i) {
            const BaselineRatio& r = ratios[i];
            auto number = [](double v) { return std::isfinite(v) ? std::to_string(v) : "null"; };
            line << (i ? "," : "") << "{\"baseline\":\"" << r.baseline << "\",\"ours\":\"" << r.ours
                 << "\",\"extra_ratio\":" << number(r.extraRatio)
                 << ",\"turns_ratio\":" << number(r.turnsRatio) << "}";
        }
        std::cout << line.str() << "]}" << std::endl;
        return;
    }
    std::printf("\nthe paper's ratios (ours = %s, the least extra distance):\n",
                ratios.front().ours.c_str());
    for (const BaselineRatio& r : ratios)
        std::printf("  vs %-20s extra %6.1f%%  turns %6.1f%%   (paper: %s)\n", r.baseline.c_str(),
                    100.0 * r.extraRatio, 100.0 * r.turnsRatio,
                    paperRatiosText(r.baseline).c_str());
}

int commandCompare(const Arguments& args) {
    std::vector<std::string> allowed = kPlanOptions;
    allowed.push_back("--solvers");
    allowed.push_back("--json");
    args.allowOnly(allowed);
    const std::string& path = planPath(args);
    const Project project = loadProject(path, args);
    std::vector<std::string> solvers = args.list("--solvers");
    if (solvers.empty())
        solvers = solverNames(); // dqn without --model: the built-in generalist
    const bool json = args.has("--json");
    PlanRequest request;
    try {
        request = requestFrom(project, args);
    } catch (const InputError& e) {
        rethrowInFile(path, e);
    }
    if (!json)
        std::printf("%-20s %10s %10s %10s %6s %9s %10s %11s %9s\n", "solver", "length_m", "ideal_m",
                    "extra_m", "turns", "coverage", "time_s", "graph_cost", "seconds");
    int failures = 0;
    std::vector<std::pair<std::string, Metrics>> answered;
    for (const std::string& solver : solvers) {
        request.solver = solver;
        try {
            const PlanResult r = planCoverage(request);
            const Metrics& m = r.metrics;
            answered.push_back({solver, m});
            if (json)
                std::cout << metricsJsonLine(solver, m) << std::endl;
            else
                std::printf("%-20s %10.2f %10.2f %10.2f %6d %8.2f%% %10.1f %11.3f %9.3f\n",
                            solver.c_str(), m.length, m.ideal, m.extra, m.turns, 100.0 * m.coverage,
                            m.time, m.graphCost, m.seconds);
        } catch (const SolverError& e) {
            ++failures;
            if (json)
                std::cout << "{\"solver\":\"" << solver << "\",\"error\":\"" << e.what() << "\"}"
                          << std::endl;
            else
                std::printf("%-20s refused: %s\n", solver.c_str(), e.what());
        } catch (const InputError& e) {
            rethrowInFile(path, e);
        }
    }
    printRatios(baselineRatios(answered), json);
    return failures == static_cast<int>(solvers.size()) ? 2 : 0;
}

} // namespace

int run(int argc, char** argv) {
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
        std::cout << kUsage;
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    try {
        const Arguments args(argc, argv, 2,
                             {"--json", "--no-transition-cells", "--no-wall-loop", "--no-rings",
                              "--help", "--resume", "--strict", "--no-cleaning", "--repair",
                              "--from-scratch"});
        if (args.has("--help")) {
            std::cout << kUsage;
            return 0;
        }
        if (command == "plan")
            return commandPlan(args);
        if (command == "graph")
            return commandGraph(args);
        if (command == "compare")
            return commandCompare(args);
        if (command == "train")
            return commandTrain(args);
        if (command == "tile")
            return commandTile(args);
        if (command == "import")
            return commandImport(args);
        if (command == "export")
            return commandExport(args);
        throw InputError("unknown command \"" + command +
                         "\" (plan, graph, compare, train, tile, import, export)");
    } catch (const RepairablePlanError& e) {
        // The plan is the first argument after the command (its options come after it).
        const std::filesystem::path plan = argc > 2 ? argv[2] : "PLAN";
        const std::string repaired =
            (plan.parent_path() / (plan.stem().string() + "-repaired.fcproj")).string();
        // One line, as every error: the problem, then how to mend it.
        std::cerr << "floorcover-cli: error: " << e.what()
                  << " (to repair it: floorcover-cli import " << plan.string() << " --repair --out "
                  << repaired << ", which says what it changed; in the editor: Plan > Repair Plan)"
                  << std::endl;
        return 2;
    } catch (const InputError& e) {
        std::cerr << "floorcover-cli: error: " << e.what() << std::endl;
        return 2;
    } catch (const SolverError& e) {
        std::cerr << "floorcover-cli: error: " << e.what() << std::endl;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "floorcover-cli: internal error: " << e.what() << std::endl;
        return 1;
    }
}

} // namespace fc::cli
