// floorcover-cli import: a DXF drawing, a ROS occupancy map, WKT or GeoJSON to a plan or
// project file. Warnings on stderr, one JSON summary line on stdout.
#include "CliCommon.h"
#include "formats/FileIO.h"
#include "importers/Import.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fc::cli {

namespace {

std::string summaryLine(const std::string& format, const ImportResult& r) {
    const Plan& plan = r.project.plan;
    char areas[128];
    std::snprintf(areas, sizeof areas, "\"boundary_area\":%.3f,\"free_area\":%.3f",
                  ringArea(plan.boundary), freeAreaOf(plan));
    std::ostringstream line;
    line << "{\"format\":\"" << format << "\"," << areas
         << ",\"obstacles\":" << plan.obstacles.size() << ",\"rooms\":" << plan.rooms.size()
         << ",\"warnings\":" << r.warnings.size() << ",\"start\":";
    if (r.robotStartPose)
        line << "[" << r.robotStartPose->x << "," << r.robotStartPose->y << "]";
    else
        line << "null";
    line << "}";
    return line.str();
}

ImportOptions optionsFrom(const Arguments& args) {
    ImportOptions options;
    options.layers.boundary = args.list("--boundary-layers");
    options.layers.obstacles = args.list("--obstacle-layers");
    options.layers.rooms = args.list("--room-layers");
    options.layers.ignored = args.list("--ignore-layers");
    if (auto units = args.number("--units")) {
        if (!(*units > 0))
            throw InputError("--units must be a positive number of metres per drawing unit");
        options.metresPerUnit = *units;
    }
    if (auto gap = args.number("--gap"))
        options.gapTolerance = *gap;
    if (auto simplify = args.number("--simplify"))
        options.simplifyTolerance = *simplify;
    if (auto epsg = args.integer("--epsg"))
        options.epsg = static_cast<int>(*epsg);
    if (auto storey = args.text("--storey"))
        options.storey = *storey;
    if (auto height = args.number("--height")) {
        if (!(*height > 0))
            throw InputError("--height must be a positive height in metres");
        options.sliceHeight = *height;
    }
    return options;
}

} // namespace

int commandImport(const Arguments& args) {
    args.allowOnly({"--out", "--boundary-layers", "--obstacle-layers", "--room-layers",
                    "--ignore-layers", "--units", "--gap", "--simplify", "--epsg", "--storey",
                    "--height"});
    if (args.positional().size() != 1)
        throw InputError("import needs exactly one FILE (see floorcover-cli --help)");
    const std::string& path = args.positional()[0];
    const auto out = args.text("--out");
    if (!out)
        throw InputError("import needs --out PLAN.geojson or PLAN.fcproj");
    const std::string extension = std::filesystem::path(*out).extension().string();
    if (extension != ".geojson" && extension != ".fcproj")
        throw InputError("--out " + *out + ": expected a .geojson plan or a .fcproj project");
    const ImportOptions options = optionsFrom(args);
    const ImportPreview preview = previewImport(path);
    const ImportResult result = importPlanFile(path, options);
    for (const std::string& w : result.warnings)
        std::cerr << "floorcover-cli: warning: " << path << ": " << w << "\n";
    if (extension == ".geojson") {
        if (result.robotStartPose)
            std::cerr << "floorcover-cli: note: " << path
                      << ": the start pose is kept only in a .fcproj project\n";
        writeFileAtomically(*out, writeGeoJsonPlan(result.project.plan));
    } else {
        writeFileAtomically(*out, writeProject(result.project));
    }
    std::cout << summaryLine(preview.format, result) << std::endl;
    return 0;
}

} // namespace fc::cli
