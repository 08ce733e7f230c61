// The import dispatcher: picks the importer by extension, names the file in every error and
// validates the result with the planner's own validation.
#include "importers/Import.h"

#include "formats/Export.h"
#include "formats/FileIO.h"
#include "importers/BuildingModelImport.h"
#include "importers/ImportSupport.h"
#include "model/Validation.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fc {

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string extensionOf(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    return lower(extension.empty() ? extension : extension.substr(1));
}

bool isBuildingModel(const std::string& extension) {
    static const std::vector<std::string> models = buildingModelExtensions();
    return std::find(models.begin(), models.end(), extension) != models.end();
}

bool contains(const std::string& name, const std::vector<std::string>& words) {
    return std::any_of(words.begin(), words.end(),
                       [&](const std::string& w) { return name.find(w) != std::string::npos; });
}

ImportResult importByExtension(const std::string& path, const std::string& extension,
                               const ImportOptions& options) {
    const bool geoJson = extension == "geojson" || extension == "json" || extension == "fcproj";
    if (options.building && *options.building != 1 && !geoJson)
        throw InputError("choosing a building other than the largest applies to GeoJSON plans; "
                         "a ." +
                         extension +
                         " import keeps its largest part and names what it "
                         "leaves out");
    if (extension == "dxf")
        return importing::importDxf(path, options);
    if (extension == "yaml" || extension == "yml")
        return importing::importRosMap(path, options);
    if (extension == "wkt")
        return importing::importWkt(withoutByteOrderMark(readFile(path)), options);
    if (extension == "geojson" || extension == "json" || extension == "fcproj") {
        ImportResult result;
        result.project = loadProjectFile(path, options.building);
        // Longitude/latitude reprojected: said where the importers' other findings are.
        result.warnings = result.project.notes;
        return result;
    }

    if (isBuildingModel(extension))
        return importBuildingModel(path, options);
    throw InputError("unknown plan format \"." + extension + "\" (importable: dxf, yaml, wkt, " +
                     "geojson, json, fcproj, ifc, obj, gltf, glb, stl)");
}

} // namespace

std::vector<std::string> importableExtensions() {
    std::vector<std::string> extensions{"dxf", "yaml", "yml", "wkt", "geojson", "json", "fcproj"};
    for (const std::string& model : buildingModelExtensions())
        extensions.push_back(model);
    return extensions;
}

std::string guessLayerRole(const std::string& layer) {
    const std::string name = lower(layer);
    // Checked in this order: "ROOM_TEXT" is ignored rather than a room, "WALL_COLUMN" an
    // obstacle rather than the boundary.
    if (contains(name, {"dim", "text", "anno", "grid", "axis", "hidden", "defpoints", "title",
                        "frame", "viewport", "door", "window"}))
        return "ignored";
    if (contains(name, {"obst", "column", "pillar", "furn", "equip", "desk", "fixture", "shelf",
                        "rack", "stair", "shaft"}))
        return "obstacles";
    if (contains(name, {"room", "space", "zone", "raum"}))
        return "rooms";
    if (contains(name, {"wall", "boundary", "outline", "border", "floor", "mauer", "wand"}))
        return "boundary";
    return "";
}

constexpr int kMaxEpsgCode = 999999;

ImportResult importPlanFile(const std::string& path, const ImportOptions& options) {
    const std::string extension = extensionOf(path);
    try {
        if (!std::filesystem::is_regular_file(path))
            throw InputError("no such file");
        if (std::filesystem::file_size(path) > importing::kMaxSourceBytes)
            throw InputError("file larger than 256 MiB");
        if (options.metresPerUnit && !(*options.metresPerUnit > 0 && *options.metresPerUnit < 1e6))
            throw InputError("the unit must be a positive number of metres below 1,000,000 "
                             "(metres per drawing unit: 0.001 for millimetres)");
        if (!(options.gapTolerance >= 0 && options.gapTolerance < 1e3))
            throw InputError("the gap tolerance must be between 0 and 1000 m");
        ImportResult result = importByExtension(path, extension, options);
        Plan& plan = result.project.plan;
        if (plan.name.empty())
            plan.name = std::filesystem::path(path).stem().string();
        if (options.epsg)
            plan.epsg = options.epsg;
        // A project must load again (ProjectFile refuses what is not a positive code).
        if (plan.epsg && !(*plan.epsg >= 1 && *plan.epsg <= kMaxEpsgCode))
            throw InputError("EPSG code " + std::to_string(*plan.epsg) +
                             " is not valid (codes run from 1 to " + std::to_string(kMaxEpsgCode) +
                             ")");
        // Degrees or Web Mercator (a WKT's SRID=4326, --epsg 4326): planned in metres.
        if (std::optional<std::string> note = reprojectToMetres(plan, false))
            result.warnings.push_back(*note);
        plan = normalizedPlan(plan);
        try {
            validatePlan(plan, result.project.robot);
        } catch (const InputError& e) {
            if (!options.keepInvalid || plan.boundary.size() < 3)
                throw;
            result.warnings.push_back(std::string("the plan needs repair: ") + e.what());
        }
        if (result.robotStartPose) {
            const Vec2 start = *result.robotStartPose;
            const bool free = pointInRing(plan.boundary, start) &&
                              std::none_of(plan.obstacles.begin(), plan.obstacles.end(),
                                           [&](const Ring& o) { return pointInRing(o, start); });
            if (free) {
                result.project.hasStart = true;
                result.project.start = start;
            } else {
                result.warnings.push_back("the start pose (" + std::to_string(start.x) + ", " +
                                          std::to_string(start.y) +
                                          ") is not in the free space; not used");
            }
        }
        return result;
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.rfind(path + ": ", 0) == 0) // loadProjectFile names the file itself
            throw;
        throw InputError(path + ": " + message);
    } catch (const std::filesystem::filesystem_error& e) {
        throw InputError(path + ": " + e.code().message());
    }
}

ImportPreview previewImport(const std::string& path) {
    const std::string extension = extensionOf(path);
    try {
        if (!std::filesystem::is_regular_file(path))
            throw InputError("no such file");
        if (extension == "dxf")
            return importing::previewDxf(path);
        ImportPreview preview;
        if (extension == "yaml" || extension == "yml")
            preview.format = "ros-map";
        else if (extension == "wkt" || extension == "geojson" || extension == "json" ||
                 extension == "fcproj")
            preview.format = extension == "json" ? "geojson" : extension;
        else if (isBuildingModel(extension))
            return previewBuildingModel(path); // names the file in its own messages
        else
            throw InputError("unknown plan format \"." + extension + "\"");
        return preview;
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.rfind(path + ": ", 0) == 0)
            throw;
        throw InputError(path + ": " + message);
    }
}

} // namespace fc
