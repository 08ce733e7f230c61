// The planning pipeline as one call, and its steps for clients that show intermediate
// results (the editor updates cells and graph overlays without planning a path).
#pragma once

#include "decomposition/Decomposition.h"
#include "graph/CornerGraph.h"
#include "graph/PreparedPlan.h"
#include "metrics/Metrics.h"
#include "model/CoveragePath.h"
#include "model/Plan.h"
#include "model/Project.h"
#include "pipeline/WallFamilies.h"
#include "solvers/Solver.h"
#include "solvers/SolverRegistry.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fc {

struct PlanRequest {
    Plan plan;
    RobotProfile robot;
    SweepOptions sweep;
    std::string solver = "heuristic";
    std::vector<std::string> rooms; // names; empty = every room
    std::optional<Vec2> start, end; // world frame; default start: defaultStartNode;
                                    // default end: the start
    std::uint64_t seed = 1;
    std::string modelPath; // for learnt solvers
    bool transitionCells = true;
    // planCoverage also plans with stripes on a shared lattice where wide cells meet at an
    // obstacle's corner (DecompositionOptions::stripeLattice) and, on small floors, with
    // headlands along the walls (DecompositionOptions::headland), keeping the better path.
    bool stripeLattice = true;
    // planCoverage also offers a loop along the outer walls first, then stripes over what it
    // left (pipeline/EdgePass.h), where that is estimated shorter: ragged traced walls.
    bool wallLoop = true;
    // planCoverage also offers loops along the walls, each W further in than the last
    // (pipeline/RingsOffer.h), on floors where the wall loop is allowed too.
    bool rings = true;
    // A per-room plan (planPerRoom) plans only its best screened candidate with the solver,
    // not the family and the two best as well. planCoverage sets it for its first plan on
    // floors of more than kSingleFinalistMinArea where it drafts a wall loop beside it.
    bool singleFinalist = false;
    // A per-room plan also screens rooms whose walls run two ways along their second family
    // (roomSecondAngles). The wall loop's pieces leave it off: their outlines follow a traced
    // floor's band, and an uncleaned map's pixel staircases outvote its walls (the faculty map
    // imported without cleaning: 81 m shorter, 1.3% slower by the estimate, 1 s more to plan).
    bool secondFamilies = true;
    // planCoverage also plans the floor with its wall teeth cut back (a pilaster, a traced
    // wall's speck; model/WallTeeth.h) and keeps that plan where its path clears the teeth
    // and is better (pipeline/ShavedTeethOffer.h). Off for that plan itself.
    bool shaveTeeth = true;
    // The path planned before the last edits (world frame; empty: none): the query's
    // orderHint follows it. The editor gives it to live replanning's quick draft, which then
    // keeps the last plan's order where that is cheaper than greedy's.
    CoveragePath previousPath;
    // The rooms' angles in that plan (roomAnglesOf), when it was of the same floor: the
    // draft plans at them, so that its cells are the plan's and the order maps one to one.
    std::map<std::string, double> previousAngles;
};

// The request a project file describes (its plan, robot, sweep, solver, rooms, start, end).
PlanRequest planRequestFor(const Project& project);

// One group of rooms planned at one sweep angle (per-room sweeps plan several in turn).
struct PlanPart {
    double stripeAngleDeg = 90.0;
    PreparedPlan prepared; // the whole floor at this angle
    Query query;           // only this group's rooms are required
    Solution solution;
    CoveragePath path;              // world frame, from the previous part's end
    std::vector<std::string> rooms; // decomposition room names this part covers
};

struct PlanResult {
    PreparedPlan prepared; // of the first part
    Query query;
    Solution solution;
    CoveragePath path; // the whole path, world frame
    Metrics metrics;   // of the whole path over every required room
    std::vector<std::string> warnings;
    double stripeAngleDeg = 90.0;
    // Set when rooms were swept at different angles (per-room); empty for one angle.
    std::vector<PlanPart> parts;
    bool touchedUp = false; // applyTouchUps has run (it runs once per plan)
    // Wall teeth cut back for this plan (pipeline/ShavedTeethOffer.h): its cells are those
    // of the floor without them; its path keeps L/2 from them and its metrics are the
    // floor's as drawn. 0: planned on the floor as drawn.
    int shavedTeeth = 0;
    double shavedToothDepth = 0.0; // m: how deep a tooth may have been
    // Planned as loops inside the wall loop, W apart (pipeline/RingsOffer.h).
    bool rings = false;
};

// Validates (throws InputError) and builds decomposition and graph for one sweep angle
// (graph/PreparedPlan.h); with classicStages also PreparedPlan::classic.
// floorCache (optional): what earlier preparations of the same free space built
// (DecompositionOptions::floorCache). stripeLattice, headland: DecompositionOptions'.
PreparedPlan preparePlan(const Plan& plan, const RobotProfile& robot, double stripeAngleDeg,
                         bool transitionCells = true, bool classicStages = false,
                         const std::shared_ptr<FloorCache>& floorCache = nullptr,
                         LatticeMode stripeLattice = LatticeMode::Own,
                         Headland headland = Headland::None);

// The stripe layout of a request's first plan (PreparedPlans): the dense lattice where it
// saves a quarter of the stripes (LatticeMode::Auto) for the solvers that plan any corner
// graph and where request.stripeLattice allows; the learnt and baseline solvers keep the
// plain layout their models and definitions assume.
LatticeMode firstLayoutFor(const PlanRequest& request);

// Whether the named solver plans on PreparedPlan::classic (false for unknown names).
bool solverNeedsClassicStages(const std::string& name);

// The start corner when none is given: in the part of the graph with the most required
// floor, the corner of a required cell farthest from the centre of the required area (the
// same corner at any rotation of the plan).
// inPart >= 0: only corners of that part of the graph (graphComponents' numbering).
int defaultStartNode(const PreparedPlan& prepared, const std::vector<char>& required,
                     int inPart = -1);

// The corner a point p (local frame) snaps to: the nearest one, of a cell the robot sweeps
// where there is one; where the straight way there is blocked, the nearest in p's open
// region (the nearest may lie across a wall from p while p's own part of the floor is
// beyond: on a speck-ridden map a corner 0.8 m away through a thin wall, which the path
// could never join). components/only: only corners of that part of the graph.
int joinableNode(const PreparedPlan& prepared, Vec2 p, const std::vector<int>* components = nullptr,
                 int only = -1);

// Required cells from room names, start/end snapped to the nearest corners. Cells that
// cannot be reached from the start are left out with a warning. Throws InputError for
// unknown rooms or an end that cannot be reached. For points the planner chose itself (where
// one room's part hands over to the next), mainRegionAt names a point of the floor's main
// part: the start snaps to the nearest corner of the graph's part holding it, and the end
// (endMayMove) to the nearest corner the start reaches.
// Query::orderHint from a path planned before (world frame): a cell's rank is the first
// covering segment of `previous` whose midpoint lies in it; a cell it did not sweep (a room
// just ticked, a cell a wall edit made) comes right after the nearest cell it did. Empty
// when `previous` sweeps no cell of this decomposition.
std::vector<double> orderHintFrom(const PreparedPlan& prepared, const CoveragePath& previous);

Query makeQuery(const PreparedPlan& prepared, const std::vector<std::string>& rooms,
                std::optional<Vec2> start, std::optional<Vec2> end, std::uint64_t seed,
                std::vector<std::string>& warnings, std::optional<Vec2> mainRegionAt = {},
                bool endMayMove = false);

// Solver names accepted by runSolver, in the order the CLI lists them (the registry's:
// solvers/SolverRegistry.h).
std::vector<std::string> solverNames();
// Looks the solver up in the registry (InputError listing the registered names when unknown);
// prepares PreparedPlan::classic on a copy when the solver needs it and it is missing.
Solution runSolver(const std::string& name, const PreparedPlan& prepared, const Query& query,
                   const std::string& modelPath = {}, const SolveControl& control = {});

// Losses above this fraction of the selected floor are reported (CLI stderr, GUI, --strict).
inline constexpr double kReportedLossFraction = 0.005;

// Whether `candidate` is the better of two plans of one request: a plan that covers
// everything reachable (uncovered at most kReportedLossFraction of the floor) beats one
// that does not; plans that do not are ranked by coverage in steps of that fraction; within
// a step, the shorter estimated time, then the shorter path. A shorter path never buys
// less coverage.
bool betterPlanChoice(const Metrics& candidate, const Metrics& best);

// Estimated times this close (a share) count as equal when several plans of one request are
// weighed (choosePlan).
inline constexpr double kTimeTie = 0.01;

// Free area (in W^2) above which the first plan beside a wall loop (ragged traced walls)
// plans a single per-room finalist (PlanRequest::singleFinalist): on such floors the loop
// usually wins, and the finalists took two thirds of planning a 4,650 m^2 map; on small ones
// they take under a second and the first plan wins more often (with one finalist 5 of 250
// generated floors planned up to 9% slower, 2 up to 3% faster).
inline constexpr double kSingleFinalistMinArea = 500.0;

// Which of several plans of one request to keep: the best by betterPlanChoice, unless another
// that covers as much is within kTimeTie of its time and shorter (the time's turn model is
// rough; at the same time the path metres shorter is the better one); the first of equals.
size_t choosePlan(const std::vector<const Metrics*>& candidates);
size_t choosePlan(const std::vector<PlanResult>& plans);
// Drops the plans choosePlan can no longer take, whatever plans come next: those that lose
// to the best so far by more than a tie. The first of equals stays first.
void keepContenders(std::vector<PlanResult>& plans);
// Whether a plan covers everything reachable: uncovered at most kReportedLossFraction.
bool completePlan(const Metrics& metrics);

// One warning per kind of loss above kReportedLossFraction of the required area: area
// the path misses (uncovered) and area no robot position can sweep (unreachable).
std::vector<std::string> coverageLossWarnings(const Metrics& metrics);

class PreparedPlans;

// Plans the request at one sweep angle for the whole floor. `prepared`: plans of
// request.plan and request.robot already built (or to be shared) per angle.
PlanResult planAtAngle(const PlanRequest& request, double angleDeg,
                       const SolveControl& control = {}, const PreparedPlans* prepared = nullptr);

// The metrics of a path over the required rooms (by decomposition room name; empty: all),
// for ranking candidate paths: without Metrics::overlaps (see withOverlaps).
Metrics measurePath(const PreparedPlan& prepared, const std::vector<std::string>& requiredRooms,
                    const CoveragePath& path);

// Fills result.metrics.overlaps for the path chosen. Every plan the planner hands out has
// them (planCoverage, planAtAngle, draftCoverage).
void withOverlaps(PlanResult& result);

// Wall touch-ups (path/CoverageRepair.h) for the floor `metrics` found unswept, within this
// many coverage widths of the path; path and metrics are replaced when coverage improves.
inline constexpr double kTouchUpReachInWidths = 4.0;
inline constexpr int kTouchUpRounds = 3;
// Touch-ups start where the plan misses more than this fraction of the floor: below the
// reported kReportedLossFraction by a margin, since the planner's raster measure and an
// exact one differ by up to about 0.1% of the floor (tests/checker).
inline constexpr double kTouchUpFraction = 0.0035;
// What the touch-ups aim for (path/CoverageRepair.h TouchUpBudget): the best-paying strokes
// until the plan misses at most this share of kTouchUpFraction (a margin, as their sweep is
// estimated), and beyond that only strokes that sweep at least this share of what a stripe
// sweeps per second (W times the speed).
inline constexpr double kTouchUpKeepShare = 0.5;
inline constexpr double kTouchUpMinRateShare = 0.05;
void touchUpCoverage(const PreparedPlan& prepared, const std::vector<std::string>& requiredRooms,
                     CoveragePath& path, Metrics& metrics);

// touchUpCoverage on a plan that misses more than kTouchUpFraction of its floor; warnings
// and metrics follow. Candidate plans are compared after it: what they leave is what it
// cannot reach.
void applyTouchUps(const PlanRequest& request, PlanResult& result);

// Per-room (the default), auto or fixed sweep angle, as request.sweep says. `prepared`
// (optional): cells and graphs of request.plan and request.robot built by earlier requests
// (pipeline/PreparedPlans.h); the caller keeps it for as long as plan and robot stay.
PlanResult planCoverage(const PlanRequest& request, const SolveControl& control = {},
                        const PreparedPlans* prepared = nullptr);

// A quick plan of the request for the editor's live replanning, shown while planCoverage
// refines it: the greedy solver at the family angles (per-room; a room of
// request.previousAngles at its angle there) or at the first candidate angle ("auto"),
// without the angle search and the wall touch-ups; with request.previousPath greedy also
// walks that path's order (Query::orderHint) and the faster path is kept. Same warnings.
PlanResult draftCoverage(const PlanRequest& request, const PreparedPlans& prepared,
                         const SolveControl& control = {});

} // namespace fc
