#include "pipeline/ShavedTeethOffer.h"

#include "geometry/Clearance.h"
#include "model/WallTeeth.h"
#include "pipeline/EdgePass.h"
#include "pipeline/LayoutOffers.h"

#include <algorithm>

namespace fc::detail {

std::optional<ShavedTeethRequest> shavedTeethRequest(const PlanRequest& request) {
    const RobotProfile& robot = request.robot;
    const double depth = kToothDepthShare * (robot.coverageWidth - robot.robotDiameter) / 2.0;
    if (!request.shaveTeeth || !(depth > 0) || !plansAnyGraph(request.solver))
        return std::nullopt;
    // Ragged traced walls (a laser map) are driven round at L/2 by the wall loop, which
    // grazes every tooth: their shaved plans never passed (lab and faculty maps, 2.4-2.8 s
    // spent for nothing).
    if (averageWallPiece(request.plan) < kEdgeRaggedWallInWidths * robot.coverageWidth)
        return std::nullopt;
    ShavedTeeth shaved =
        shaveWallTeeth(request.plan, depth, kToothSpanInWidths * robot.coverageWidth);
    if (shaved.teeth == 0)
        return std::nullopt;
    ShavedTeethRequest flat{request, shaved.teeth, depth};
    flat.request.plan = std::move(shaved.plan);
    flat.request.shaveTeeth = false;
    // The wall loop runs L/2 from every wall, so past every tooth cut: never kept.
    flat.request.wallLoop = false;
    return flat;
}

std::optional<PlanResult> planShavedTeeth(const ShavedTeethRequest& flat,
                                          const SolveControl& control) {
    try {
        PlanResult result = planCoverage(flat.request, control);
        result.shavedTeeth = flat.teeth;
        result.shavedToothDepth = flat.depth;
        return result;
    } catch (const InputError&) {
        return std::nullopt; // an offer: where it cannot be planned, the first plan stands
    } catch (const SolverError&) {
        if (control.cancelled && control.cancelled())
            throw;
        return std::nullopt;
    }
}

bool keepShavedTeethPlan(const PlanRequest& request, const PlanResult& first, PlanResult& shaved) {
    std::vector<Ring> walls{request.plan.boundary};
    walls.insert(walls.end(), request.plan.obstacles.begin(), request.plan.obstacles.end());
    const ClearanceField drawn(walls, request.robot.robotDiameter / 2.0);
    if (!drawn.polylineIsClear(shaved.path.points))
        return false;
    std::vector<std::string> required = request.rooms;
    if (required.empty())
        required = first.prepared.decomposition.roomNames;
    Metrics measured = measurePath(first.prepared, required, shaved.path);
    measured.graphCost = shaved.metrics.graphCost;
    measured.lowerBound = shaved.metrics.lowerBound;
    measured.cells = shaved.metrics.cells;
    measured.seconds = shaved.metrics.seconds;
    const std::vector<std::string> shavedLosses = coverageLossWarnings(shaved.metrics);
    auto& warnings = shaved.warnings;
    warnings.erase(std::remove_if(warnings.begin(), warnings.end(),
                                  [&](const std::string& w) {
                                      return std::find(shavedLosses.begin(), shavedLosses.end(),
                                                       w) != shavedLosses.end();
                                  }),
                   warnings.end());
    for (const std::string& loss : coverageLossWarnings(measured))
        warnings.push_back(loss);
    shaved.metrics = std::move(measured);
    return true;
}

} // namespace fc::detail
