// `floorcover-cli plan SITE` (or `--building all`): every building of a GeoJSON site planned
// in one run, one path file per building ("site-building-2.csv" for --out site.csv) and one JSON
// line: the site's totals, then each building's metrics under "buildings". The robot is
// carried between buildings, so no transit joins them.
#include "CliCommon.h"
#include "formats/FileIO.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

namespace fc::cli {

namespace {

// "site.csv" -> "site-building-2.csv".
std::string buildingFile(const std::string& out, int building) {
    const std::filesystem::path p(out);
    return (p.parent_path() /
            (p.stem().string() + "-building-" + std::to_string(building) + p.extension().string()))
        .string();
}

// The site's metrics: sums, and the coverage of the summed areas.
Metrics siteTotals(const std::vector<Metrics>& parts) {
    Metrics total;
    total.lowerBound = 0.0;
    for (const Metrics& m : parts) {
        total.length += m.length;
        total.ideal += m.ideal;
        total.extra += m.extra;
        total.turns += m.turns;
        total.time += m.time;
        total.cells += m.cells;
        total.graphCost += m.graphCost;
        total.seconds += m.seconds;
        total.requiredArea += m.requiredArea;
        total.sweepableArea += m.sweepableArea;
        total.coveredArea += m.coveredArea;
        total.uncoveredArea += m.uncoveredArea;
        total.unreachableArea += m.unreachableArea;
        total.lowerBound =
            total.lowerBound >= 0.0 && m.lowerBound > 0.0 ? total.lowerBound + m.lowerBound : -1.0;
    }
    total.coverage = total.sweepableArea > 0.0 ? total.coveredArea / total.sweepableArea : 1.0;
    return total;
}

} // namespace

int commandPlanSite(const Arguments& args, int count) {
    const std::string& path = planPath(args);
    std::vector<Project> buildings;
    for (int k = 1; k <= count; ++k) {
        buildings.push_back(
            loadProjectFile(path, count > 1 ? std::optional<int>(k) : std::nullopt));
        if (k == 1) // the same notes for every building: said once
            for (const std::string& note : buildings.back().notes)
                std::cerr << "floorcover-cli: note: " << path << ": " << note << "\n";
    }
    // Rooms, start and end go to the building that holds them; each must be in one.
    const std::vector<std::string> asked = args.list("--rooms");
    for (const std::string& name : asked)
        if (std::none_of(buildings.begin(), buildings.end(), [&](const Project& b) {
                return std::any_of(b.plan.rooms.begin(), b.plan.rooms.end(),
                                   [&](const Room& r) { return r.name == name; });
            }))
            throw InputError(path + ": no building of the site has a room named \"" + name + "\"");
    for (const char* option : {"--start", "--end"})
        if (const auto p = args.point(option);
            p && std::none_of(buildings.begin(), buildings.end(),
                              [&](const Project& b) { return pointInRing(b.plan.boundary, *p); }))
            throw InputError(path + ": " + option + " lies in no building of the site");

    std::vector<Metrics> planned;
    std::vector<std::string> lines;
    std::string solver;
    bool loss = false;
    for (int k = 1; k <= count; ++k) {
        const Project& project = buildings[static_cast<size_t>(k - 1)];
        Arguments own = args.with("--building", std::nullopt);
        if (!asked.empty()) {
            std::string mine;
            for (const std::string& name : asked)
                for (const Room& room : project.plan.rooms)
                    if (room.name == name)
                        mine += (mine.empty() ? "" : ",") + name;
            if (mine.empty())
                continue; // none of the rooms asked for is here
            own = own.with("--rooms", mine);
        }
        for (const char* option : {"--start", "--end"})
            if (const auto p = args.point(option); p && !pointInRing(project.plan.boundary, *p))
                own = own.with(option, std::nullopt);
        PlanRequest request;
        const std::string label = path + " (building " + std::to_string(k) + ")";
        const PlanResult result = planFromArguments(label, project, own, request);
        if (auto out = args.text("--out"))
            writeFileAtomically(
                buildingFile(*out, k),
                pathToFormat(*out, result.path, exportInfoFor(project, request, result)));
        solver = result.solution.solver;
        planned.push_back(result.metrics);
        const std::string line = metricsJsonLine(solver, result.metrics);
        lines.push_back("{\"building\":" + std::to_string(k) + "," + line.substr(1));
        loss = loss || !coverageLossWarnings(result.metrics).empty();
    }
    std::string line = metricsJsonLine(solver, siteTotals(planned));
    line.pop_back(); // the closing brace
    line += ",\"buildings\":[";
    for (size_t i = 0; i < lines.size(); ++i)
        line += (i ? "," : "") + lines[i];
    std::cout << line << "]}" << std::endl;
    if (args.has("--strict") && loss) {
        std::cerr << "floorcover-cli: error: " << path
                  << ": coverage loss above 0.5% of the selected floor in a building (--strict)\n";
        return 3;
    }
    return 0;
}

} // namespace fc::cli
