// floorcover-cli import: a DXF drawing, a ROS occupancy map, WKT or GeoJSON to a plan or
// project file. Warnings on stderr, one JSON summary line on stdout.
#include "CliCommon.h"
#include "formats/FileIO.h"
#include "importers/Import.h"
#include "model/Validation.h"

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
    if (r.cleaning) {
        const MapCleaningReport& c = *r.cleaning;
        char walls[200] = "";
        if (c.wallAngle)
            std::snprintf(walls, sizeof walls,
                          ",\"wall_angle\":%.3f,\"walls_straightened\":%d,\"notches_filled\":%d,"
                          "\"straightened_added\":%.3f,\"straightened_removed\":%.3f,"
                          "\"doorways_aligned\":%d",
                          *c.wallAngle, c.wallsStraightened, c.notchesFilled, c.straightenedAdded,
                          c.straightenedRemoved, c.doorwaysAligned);
        char cleaning[768];
        std::snprintf(cleaning, sizeof cleaning,
                      ",\"cleaning\":{\"cells\":[%d,%d],\"resolution\":%g,\"unknown_cells\":%lld,"
                      "\"gaps_filled\":%d,\"gap_area\":%.3f,\"specks_removed\":%d,\"speck_area\":%."
                      "3f,\"fragments_dropped\":%d,"
                      "\"fragment_area\":%.3f,\"smoothed_area\":%.3f,\"opened_area\":%.3f,\"closed_"
                      "area\":%.3f,\"obstacles_joined\":%d,\"passage_area\":%.3f,"
                      "\"free_area_before\":%.3f,\"free_area_after\":%.3f,"
                      "\"vertices_traced\":%d,\"vertices_kept\":%d%s}",
                      c.width, c.height, c.resolution, c.unknownCells, c.gapsFilled, c.gapArea,
                      c.specksRemoved, c.speckArea, c.fragmentsDropped, c.fragmentArea,
                      c.smoothedArea, c.openedArea, c.closedArea, c.obstaclesJoined, c.passageArea,
                      c.freeAreaBefore, c.freeAreaAfter, c.verticesTraced, c.verticesKept, walls);
        line << cleaning;
    }
    line << "}";
    return line.str();
}

double nonNegative(const Arguments& args, const std::string& name, double fallback) {
    const auto value = args.number(name);
    if (!value)
        return fallback;
    if (!(*value >= 0))
        throw InputError(name + " must be 0 or a positive number");
    return *value;
}

// Occupancy-map cleaning and room segmentation (issue 15).
void mapOptionsFrom(const Arguments& args, ImportOptions& options) {
    MapCleaningOptions& c = options.cleaning;
    c.enabled = !args.has("--no-cleaning");
    if (auto smooth = args.text("--smooth")) {
        if (*smooth != "on" && *smooth != "off")
            throw InputError("--smooth " + *smooth + ": expected on or off");
        c.smoothEdges = *smooth == "on";
    }
    if (auto unknown = args.text("--unknown")) {
        if (*unknown != "wall" && *unknown != "free")
            throw InputError("--unknown " + *unknown + ": expected wall or free");
        c.unknownIsFree = *unknown == "free";
    }
    if (auto straighten = args.text("--straighten")) {
        if (*straighten != "on" && *straighten != "off")
            throw InputError("--straighten " + *straighten + ": expected on or off");
        c.straightenWalls = *straighten == "on";
    }
    c.wallBand = nonNegative(args, "--wall-band", c.wallBand);
    c.notchDepth = nonNegative(args, "--notch", c.notchDepth);
    c.unknownGapArea = nonNegative(args, "--unknown-gap", c.unknownGapArea);
    c.speckleArea = nonNegative(args, "--speckle", c.speckleArea);
    c.fragmentArea = nonNegative(args, "--fragment", c.fragmentArea);
    c.openingRadius = nonNegative(args, "--opening", c.openingRadius);
    c.closingRadius = nonNegative(args, "--closing", c.closingRadius);
    for (const auto& [radius, name] :
         {std::pair{c.openingRadius, "--opening"}, std::pair{c.closingRadius, "--closing"}})
        if (radius > MapCleaningOptions::kMaxMorphologyRadius)
            throw InputError(std::string(name) + " must be at most 5 m (a radius in metres)");
    if (auto diameter = args.number("--robot-diameter")) {
        if (!(*diameter > 0 && *diameter < 100))
            throw InputError("--robot-diameter must be a positive size in metres");
        options.robotDiameter = *diameter;
    }
    if (auto rooms = args.text("--segment-rooms")) {
        if (*rooms == "none")
            options.roomSegmentation.method = RoomSegmentationMethod::None;
        else if (*rooms == "distance")
            options.roomSegmentation.method = RoomSegmentationMethod::Distance;
        else if (*rooms == "morphological")
            options.roomSegmentation.method = RoomSegmentationMethod::Morphological;
        else
            throw InputError("--segment-rooms " + *rooms +
                             ": expected distance, morphological or none");
    }
    options.roomSegmentation.minRoomArea =
        nonNegative(args, "--min-room", options.roomSegmentation.minRoomArea);
    options.roomSegmentation.maxDoorWidth =
        nonNegative(args, "--max-door", options.roomSegmentation.maxDoorWidth);
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
    options.simplifyTolerance = nonNegative(args, "--simplify", options.simplifyTolerance);
    mapOptionsFrom(args, options);
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
    args.allowOnly({"--out",
                    "--boundary-layers",
                    "--obstacle-layers",
                    "--room-layers",
                    "--ignore-layers",
                    "--units",
                    "--gap",
                    "--simplify",
                    "--epsg",
                    "--storey",
                    "--height",
                    "--no-cleaning",
                    "--unknown",
                    "--speckle",
                    "--fragment",
                    "--smooth",
                    "--opening",
                    "--closing",
                    "--robot-diameter",
                    "--segment-rooms",
                    "--min-room",
                    "--max-door",
                    "--straighten",
                    "--wall-band",
                    "--notch",
                    "--unknown-gap",
                    "--repair",
                    "--building"});
    if (args.positional().size() != 1)
        throw InputError("import needs exactly one FILE (see floorcover-cli --help)");
    const std::string& path = args.positional()[0];
    const auto out = args.text("--out");
    if (!out)
        throw InputError("import needs --out PLAN.geojson or PLAN.fcproj");
    const std::string extension = std::filesystem::path(*out).extension().string();
    if (extension != ".geojson" && extension != ".fcproj")
        throw InputError("--out " + *out + ": expected a .geojson plan or a .fcproj project");
    ImportOptions options = optionsFrom(args);
    options.keepInvalid = args.has("--repair");
    if (const auto building = args.integer("--building")) {
        if (*building < 1 || *building > 1'000'000)
            throw InputError("--building " + std::to_string(*building) +
                             ": expected 1 (the largest building), 2, ...");
        options.building = static_cast<int>(*building);
    }
    const ImportPreview preview = previewImport(path);
    ImportResult result = importPlanFile(path, options);
    for (const std::string& w : result.warnings)
        std::cerr << "floorcover-cli: warning: " << path << ": " << w << "\n";
    if (options.keepInvalid && !planProblems(result.project.plan, result.project.robot).empty()) {
        std::vector<std::string> notes;
        try {
            result.project.plan = normalizedPlan(repairPlan(result.project.plan, notes));
            validatePlan(result.project.plan, result.project.robot); // still broken: refused
        } catch (const InputError& e) {
            // Plain InputError: the CLI's advice for a repairable plan is this very command.
            throw InputError(path + ": --repair could not make the plan valid: " + e.what() +
                             "; it needs mending by hand");
        }
        for (const std::string& note : notes)
            std::cerr << "floorcover-cli: repaired: " << path << ": " << note << "\n";
    }
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
