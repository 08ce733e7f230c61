// `floorcover-cli plan SITE` (or `--building all`): every building of a GeoJSON site planned
// in one run, one path file per building ("site-building-2.csv" for --out site.csv) and one JSON
// line: the site's totals, then each building's metrics under "buildings". The robot is
// carried between buildings, so no transit joins them. A building that cannot be read or
// planned (a shed smaller than the robot, a self-crossing outline) is left out with a warning
// and a "skipped" entry: the rest of the site is still planned, and nothing goes missing
// without a word.
#include "CliCommon.h"
#include "formats/FileIO.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <utility>

namespace fc::cli {

std::string buildingFile(const std::string& out, int building) {
    const std::filesystem::path p(out);
    return (p.parent_path() /
            (p.stem().string() + "-building-" + std::to_string(building) + p.extension().string()))
        .string();
}

namespace {

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

// A building left out: why, and its outline's area (m^2; the site's error carries them).
struct Skipped {
    std::string why;
    double area = 0;
};

std::string skippedEntry(int building, const Skipped& skipped) {
    char area[32];
    std::snprintf(area, sizeof area, "%.3f", skipped.area);
    return "{\"building\":" + std::to_string(building) +
           ",\"skipped\":" + nlohmann::json(skipped.why).dump() + ",\"boundary_area\":" + area +
           "}";
}

void warnSkipped(const std::string& path, int building, const Skipped& skipped) {
    // A self-crossing outline's shoelace area means nothing (a bowtie's is 0): no figure then.
    char area[48] = "";
    if (skipped.area >= 0.01)
        std::snprintf(area, sizeof area, " (an outline of %.2f m^2)", skipped.area);
    std::fprintf(stderr,
                 "floorcover-cli: warning: %s: building %d%s not planned, left out of the site's "
                 "paths and totals: %s\n",
                 path.c_str(), building, area, skipped.why.c_str());
}

// The message of a building's error without the "FILE (building K): " it was given.
std::string reasonOf(const std::string& message, const std::string& label) {
    return message.rfind(label + ": ", 0) == 0 ? message.substr(label.size() + 2) : message;
}

} // namespace

int commandPlanSite(const Arguments& args, const std::vector<double>& areas) {
    const std::string& path = planPath(args);
    const int count = std::max(1, static_cast<int>(areas.size()));
    auto areaOf = [&](int k) { return k <= static_cast<int>(areas.size()) ? areas[k - 1] : 0.0; };
    std::vector<std::optional<Project>> buildings;
    std::vector<std::optional<Skipped>> skipped(static_cast<size_t>(count));
    std::optional<InputError> firstError;
    bool notesSaid = false; // the same notes for every building: said once
    for (int k = 1; k <= count; ++k) {
        try {
            buildings.push_back(
                loadProjectFile(path, count > 1 ? std::optional<int>(k) : std::nullopt));
        } catch (const InputError& e) {
            if (count == 1)
                throw;
            firstError = firstError.value_or(e);
            buildings.push_back(std::nullopt);
            skipped[k - 1] = Skipped{reasonOf(e.what(), path), areaOf(k)};
            continue;
        }
        if (!std::exchange(notesSaid, true))
            for (const std::string& note : buildings.back()->notes)
                std::cerr << "floorcover-cli: note: " << path << ": " << note << "\n";
    }
    auto holds = [](const std::optional<Project>& b, auto&& test) { return b && test(*b); };
    auto hasRoom = [](const Project& b, const std::string& name) {
        return std::any_of(b.plan.rooms.begin(), b.plan.rooms.end(),
                           [&](const Room& r) { return r.name == name; });
    };
    const std::string unread =
        firstError
            ? " (a building of it could not be read: " + std::string(firstError->what()) + ")"
            : "";
    // Rooms, start and end go to the building that holds them; each must be in one.
    const std::vector<std::string> asked = args.list("--rooms");
    for (const std::string& name : asked)
        if (std::none_of(buildings.begin(), buildings.end(), [&](const auto& b) {
                return holds(b, [&](const Project& p) { return hasRoom(p, name); });
            }))
            throw InputError(path + ": no building of the site has a room named \"" + name + "\"" +
                             unread);
    for (const char* option : {"--start", "--end"})
        if (const auto p = args.point(option);
            p && std::none_of(buildings.begin(), buildings.end(), [&](const auto& b) {
                return holds(b, [&](const Project& q) { return pointInRing(q.plan.boundary, *p); });
            }))
            throw InputError(path + ": " + option + " lies in no building of the site" + unread);

    std::vector<Metrics> planned;
    std::vector<std::string> lines;
    std::string solver;
    bool loss = false;
    for (int k = 1; k <= count; ++k) {
        const std::string label = path + " (building " + std::to_string(k) + ")";
        if (!buildings[k - 1]) {
            warnSkipped(path, k, *skipped[k - 1]);
            lines.push_back(skippedEntry(k, *skipped[k - 1]));
            continue;
        }
        const Project& project = *buildings[static_cast<size_t>(k - 1)];
        Arguments own = args.with("--building", std::nullopt);
        bool askedHere = false; // rooms, start or end in this building: its error is the run's
        if (!asked.empty()) {
            std::string mine;
            for (const std::string& name : asked)
                if (hasRoom(project, name))
                    mine += (mine.empty() ? "" : ",") + name;
            if (mine.empty())
                continue; // none of the rooms asked for is here
            own = own.with("--rooms", mine);
            askedHere = true;
        }
        for (const char* option : {"--start", "--end"})
            if (const auto p = args.point(option); p) {
                if (!pointInRing(project.plan.boundary, *p))
                    own = own.with(option, std::nullopt);
                else
                    askedHere = true;
            }
        PlanRequest request;
        PlanResult result;
        try {
            result = planFromArguments(label, project, own, request);
        } catch (const InputError& e) {
            if (askedHere || count == 1)
                throw;
            firstError = firstError.value_or(e);
            skipped[k - 1] = Skipped{reasonOf(e.what(), label), areaOf(k)};
            warnSkipped(path, k, *skipped[k - 1]);
            lines.push_back(skippedEntry(k, *skipped[k - 1]));
            continue;
        }
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
    if (planned.empty()) {
        if (firstError)
            throw *firstError; // no building could be planned: the first one's reason
        throw InputError(path + ": no building of the site was planned");
    }
    const auto left =
        std::count_if(skipped.begin(), skipped.end(), [](const auto& s) { return s; });
    double leftArea = 0;
    for (const auto& s : skipped)
        leftArea += s ? s->area : 0.0;
    std::string line = metricsJsonLine(solver, siteTotals(planned));
    line.pop_back(); // the closing brace
    if (left > 0) {
        char text[96];
        std::snprintf(text, sizeof text, ",\"skipped_buildings\":%d,\"skipped_area\":%.3f",
                      static_cast<int>(left), leftArea);
        line += text;
    }
    line += ",\"buildings\":[";
    for (size_t i = 0; i < lines.size(); ++i)
        line += (i ? "," : "") + lines[i];
    std::cout << line << "]}" << std::endl;
    if (args.has("--strict") && (loss || left > 0)) {
        std::cerr << "floorcover-cli: error: " << path
                  << (left > 0 ? ": a building was not planned (--strict)\n"
                               : ": coverage loss above 0.5% of the selected floor in a building "
                                 "(--strict)\n");
        return 3;
    }
    return 0;
}

} // namespace fc::cli
