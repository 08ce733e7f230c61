#include "pipeline/RestPieces.h"

#include "pipeline/EdgePass.h"
#include "pipeline/LayoutOffers.h"
#include "pipeline/PerRoomSweep.h"

#include <cmath>
#include <string>

namespace fc::detail {
namespace {

// How close to kDenseAutoSaving a piece's pick of its layout is planned both ways.
constexpr double kPieceLayoutMargin = 0.1;

void throwIfStopped(const SolveControl& control) {
    if (control.cancelled && control.cancelled())
        throw SolverError("wall loop: cancelled");
}

// The stripe angle the user fixed for a piece of the rest: the whole floor's (`--angle DEG`,
// the editor's fixed sweep angle) or that of the piece's room (the editor's per-room "Fixed");
// none where the angle is the planner's to choose.
std::optional<double> fixedAngleOfPiece(const PlanRequest& request, int room) {
    const SweepOptions& sweep = request.sweep;
    if (sweep.automatic)
        return std::nullopt;
    if (!sweep.perRoom)
        return sweep.angleDeg;
    const std::string name =
        room >= 0 ? request.plan.rooms[static_cast<size_t>(room)].name
                  : (request.plan.rooms.empty() ? std::string("Floor") : std::string());
    if (auto it = sweep.roomAngles.find(name); !name.empty() && it != sweep.roomAngles.end())
        return it->second;
    return std::nullopt;
}

} // namespace

PieceLayouts::PieceLayouts(const Plan& plan, const RobotProfile& robot, bool transitionCells) {
    for (auto [layout, mode] : {std::pair{&automatic, LatticeMode::Auto},
                                {&dense, LatticeMode::Dense},
                                {&own, LatticeMode::Own}})
        *layout = std::make_unique<PreparedPlans>(plan, robot, transitionCells, nullptr, mode);
}

const PreparedPlans* PieceLayouts::alternative(const Decomposition& chosen) const {
    if (std::abs(chosen.denseSaving - kDenseAutoSaving) > kPieceLayoutMargin ||
        !chosen.denseLatticeAvailable)
        return nullptr;
    return chosen.layout == LatticeMode::Dense ? own.get() : dense.get();
}

std::vector<PreparedPiece> preparedPieces(const PlanRequest& request, const WallLoop& walls) {
    const double width = request.robot.coverageWidth, radius = 0.5 * request.robot.robotDiameter;
    std::vector<PreparedPiece> pieces(walls.rest.size());
    for (size_t index = 0; index < walls.rest.size(); ++index) {
        PreparedPiece& prepared = pieces[index];
        PlanRequest& piece = prepared.request;
        piece.plan.boundary = walls.rest[index];
        piece.plan.obstacles = walls.restHoles[index];
        prepared.islands = islandDetours(piece.plan.boundary, piece.plan.obstacles, radius,
                                         kEdgeIslandInWidths2 * width * width);
        piece.plan.name = request.plan.name;
        piece.robot = request.robot;
        piece.sweep = request.sweep;
        piece.sweep.roomAngles.clear();
        piece.solver = request.solver;
        piece.seed = request.seed;
        piece.modelPath = request.modelPath;
        piece.transitionCells = request.transitionCells;
        piece.wallLoop = false;
        if (!prepared.islands.zones.empty()) {
            Plan open = piece.plan;
            open.obstacles = prepared.islands.keptHoles;
            prepared.open =
                std::make_unique<PieceLayouts>(open, piece.robot, piece.transitionCells);
        }
        prepared.full =
            std::make_unique<PieceLayouts>(piece.plan, piece.robot, piece.transitionCells);
    }
    return pieces;
}

std::optional<PlanResult> planPiece(const PlanRequest& request, const WallLoop& walls,
                                    const PreparedPiece& prepared, size_t index, Vec2 from,
                                    Vec2 towards, const SolveControl& control) {
    PlanRequest piece = prepared.request;
    piece.secondFamilies = false; // PlanRequest::secondFamilies
    const double radius = 0.5 * request.robot.robotDiameter;
    piece.start = clearPointNear(piece.plan.boundary, piece.plan.obstacles, radius, from);
    piece.end = clearPointNear(piece.plan.boundary, piece.plan.obstacles, radius, towards);
    if (!piece.start || !piece.end)
        return std::nullopt;
    const std::optional<double> fixed = fixedAngleOfPiece(request, walls.restRoom[index]);
    auto plan = [&](const PlanRequest& floor, const PreparedPlans& plans) {
        return fixed ? planOneAngle(floor, *fixed, control, &plans)
                     : planPerRoom(floor, control, &plans);
    };
    // The plan in Auto's layout and, where its pick was close, in the other one: the better.
    // `finish` makes a plan the piece's path (nullopt: it cannot be).
    auto planBoth = [&](const PlanRequest& floor, const PieceLayouts& layouts, auto finish) {
        PlanResult planned = plan(floor, *layouts.automatic);
        // Not at an angle the user fixed: there the other layout's plan, faster by the
        // estimate, swept a traced hall with 84% of its stripes at that angle, against 93%.
        const PreparedPlans* other =
            fixed ? nullptr : layouts.alternative(planned.prepared.decomposition);
        std::optional<PlanResult> best = finish(std::move(planned));
        if (other) {
            std::optional<PlanResult> again = finish(plan(floor, *other));
            if (again && (!best || betterPlanChoice(again->metrics, best->metrics)))
                best = std::move(again);
        }
        return best;
    };
    try {
        // Small islands (traced furniture) out of the way of the stripes, which then drive
        // round them; where that cannot be (a path that would start beside one), the piece
        // is planned with every hole.
        if (prepared.open) {
            PlanRequest open = piece;
            open.plan.obstacles = prepared.islands.keptHoles;
            std::optional<PlanResult> planned =
                planBoth(open, *prepared.open, [&](PlanResult p) -> std::optional<PlanResult> {
                    std::optional<CoveragePath> round =
                        detouredPath(p.path, prepared.islands.zones);
                    if (!round || round->empty())
                        return std::nullopt;
                    p.path = std::move(*round);
                    return p;
                });
            if (planned)
                return planned;
        }
        return planBoth(piece, *prepared.full, [](PlanResult p) -> std::optional<PlanResult> {
            if (p.path.empty())
                return std::nullopt;
            return p;
        });
    } catch (const InputError&) {
        // Smaller than a coverage square, or a pocket the robot cannot turn in: left to the
        // touch-ups, and measured with the whole path.
        return std::nullopt;
    } catch (const SolverError&) {
        throwIfStopped(control);
        return std::nullopt;
    }
}
} // namespace fc::detail
