// floorcover-cli tile: the reconfigurable tiling robot (seeds/001). Tiles the floor with the
// robot's shapes, orders the tiles by energy and prints one JSON line of metrics.
#include "CliCommon.h"
#include "formats/FileIO.h"
#include "tiling/TilingPlanner.h"
#include "tiling/ppo/PpoOrdering.h"

#include <iostream>

namespace fc::cli {

int commandTile(const Arguments& args) {
    args.allowOnly({"--solver", "--out", "--seed", "--block-leg", "--block-masses", "--model",
                    "--train-seconds", "--save-model", "--building"});
    const std::string& path = planPath(args);
    const Project project = loadProject(path, args);
    tiling::TilingRequest request;
    request.plan = project.plan;
    request.solver = args.text("--solver").value_or("greedy");
    if (auto seed = args.integer("--seed"))
        request.seed = static_cast<std::uint64_t>(*seed);
    if (auto leg = args.number("--block-leg"))
        request.robot.blockLeg = *leg;
    if (args.has("--block-masses")) {
        const std::vector<std::string> masses = args.list("--block-masses");
        if (masses.size() != tiling::kBlockCount)
            throw InputError("--block-masses needs four masses M1,M2,M3,M4 (kg)");
        for (int b = 0; b < tiling::kBlockCount; ++b) {
            try {
                request.robot.blockMass[b] = std::stod(masses[b]);
            } catch (const std::exception&) {
                throw InputError("--block-masses: \"" + masses[b] + "\" is not a number");
            }
        }
    }
    PpoOrderingSettings ppo;
    ppo.modelPath = args.text("--model").value_or("");
    ppo.savePath = args.text("--save-model").value_or("");
    if (auto seconds = args.number("--train-seconds")) {
        if (!(*seconds > 0.0))
            throw InputError("--train-seconds must be positive");
        ppo.trainSeconds = *seconds;
    }
    configurePpoOrdering(ppo);
    tiling::TilingPlan plan;
    try {
        plan = tiling::planTiling(request);
        if (auto out = args.text("--out"))
            writeFileAtomically(*out, tiling::waypointsToFormat(*out, plan));
    } catch (const InputError& e) {
        rethrowInFile(path, e);
    }
    if (!plan.tiling.unreachable.empty() || !plan.tiling.untiled.empty())
        std::cerr << "floorcover-cli: warning: " << path << ": " << plan.tiling.unreachable.size()
                  << " free cells no shape can reach, " << plan.tiling.untiled.size()
                  << " left untiled\n";
    std::cout << tiling::tilingMetricsJson(plan) << std::endl;
    return 0;
}

} // namespace fc::cli
