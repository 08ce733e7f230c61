// The 3D importer's entry points: choose the storey, slice, turn the section into a plan.
#include "importers/BuildingModelImport.h"

#include "importers/BuildingModel.h"
#include "importers/SectionArrangement.h"
#include "model/Validation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <new>

namespace fc {

using namespace building;
namespace fs = std::filesystem;

namespace {

std::string extensionOf(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    if (!extension.empty())
        extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::string metres(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g m", value);
    return text;
}

std::string withoutSpaces(std::string s) {
    s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }),
            s.end());
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// Layer entries name a node, its owning element or its label; "Prefix*" matches by prefix.
bool listed(const std::vector<std::string>& names, const Part& part) {
    return std::any_of(names.begin(), names.end(), [&](const std::string& name) {
        if (!name.empty() && name.back() == '*') {
            const std::string prefix = name.substr(0, name.size() - 1);
            return part.node.rfind(prefix, 0) == 0 || part.owner.rfind(prefix, 0) == 0;
        }
        return name == part.node || name == part.owner || name == part.label;
    });
}

double unitScale(const ImportOptions& options) {
    const double scale = options.metresPerUnit.value_or(1.0);
    if (!std::isfinite(scale) || scale <= 0)
        throw InputError("metres per unit must be a positive number");
    return scale;
}

size_t pickStorey(const BuildingModel& model, const std::string& wanted) {
    if (wanted.empty())
        return 0;
    for (size_t i = 0; i < model.storeys.size(); ++i)
        if (withoutSpaces(model.storeys[i].name) == withoutSpaces(wanted))
            return i;
    std::string known;
    for (const Storey& storey : model.storeys)
        known += (known.empty() ? "" : ", ") + ("\"" + storey.name + "\"");
    throw InputError("no storey \"" + wanted + "\" (the model has " + known + ")");
}

struct SlicedSpace {
    std::string name;
    std::vector<SectionSegment> segments;
};

void addRooms(Plan& plan, const std::vector<SlicedSpace>& spaces, ImportResult& result) {
    for (const SlicedSpace& space : spaces) {
        const std::vector<Ring> outlines = solidOutlines(space.segments);
        if (outlines.empty()) {
            result.warnings.push_back("space \"" + space.name + "\" has no closed section");
            continue;
        }
        std::string name = space.name.empty() ? "space" : space.name;
        for (int k = 2; std::any_of(plan.rooms.begin(), plan.rooms.end(),
                                    [&](const Room& r) { return r.name == name; });
             ++k)
            name = space.name + " (" + std::to_string(k) + ")";
        Plan candidate = plan;
        candidate.rooms.push_back({name, outlines.front()});
        try {
            candidate = normalizedPlan(candidate);
            validatePlan(candidate, RobotProfile{});
            plan = std::move(candidate);
        } catch (const InputError& e) {
            result.warnings.push_back("room \"" + name + "\" left out: " + e.what());
        }
    }
}

ImportResult sliceModel(const BuildingModel& model, const ImportOptions& options,
                        const std::string& planName) {
    if (!std::isfinite(options.sliceHeight) || options.sliceHeight <= 0)
        throw InputError("the slice height must be a positive number of metres");
    const size_t storey = pickStorey(model, options.storey);
    const double height = model.storeys[storey].elevation + options.sliceHeight;
    const std::string where = "at height " + metres(height) + " (storey \"" +
                              model.storeys[storey].name + "\" floor + " +
                              metres(options.sliceHeight) + ")";
    std::vector<SectionSegment> segments;
    std::vector<bool> isDoor;
    std::vector<SlicedSpace> spaces;
    for (const Part& part : model.parts) {
        if (part.storey != static_cast<int>(storey) || listed(options.layers.ignored, part))
            continue;
        const PartKind kind = listed(options.layers.rooms, part) ? PartKind::Space : part.kind;
        std::vector<Segment> cut = slicePart(part, height);
        closeOpenChains(cut);
        if (cut.empty())
            continue;
        if (kind == PartKind::Space) {
            spaces.push_back({part.label, {}});
            for (const Segment& s : cut)
                spaces.back().segments.push_back({s, 0});
            continue;
        }
        const int id = static_cast<int>(isDoor.size());
        isDoor.push_back(kind == PartKind::DoorLeaf);
        for (const Segment& s : cut)
            segments.push_back({s, id});
        if (segments.size() > kMaxSectionSegments)
            throw InputError("the section " + where + " has more than " +
                             std::to_string(kMaxSectionSegments) + " segments");
    }
    if (segments.empty())
        throw InputError("no section " + where + ": the plane cuts no wall");
    ImportResult result;
    FreeSpace free;
    try {
        free = enclosedFreeSpace(segments, isDoor, options.ignoreDoorLeaves);
    } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + " " + where);
    }
    Plan plan;
    plan.name = planName;
    plan.epsg = options.epsg;
    plan.boundary = free.region.outer;
    plan.obstacles = free.region.holes;
    if (free.otherRegions > 0)
        result.warnings.push_back(std::to_string(free.otherRegions) +
                                  " smaller enclosed region(s) left out (" +
                                  metres(free.otherRegionsArea) + "^2 in all)");
    try {
        plan = normalizedPlan(plan);
        validatePlan(plan, RobotProfile{});
    } catch (const InputError& e) {
        throw InputError("the section " + where + " is not a valid plan: " + e.what());
    }
    addRooms(plan, spaces, result);
    result.project.plan = std::move(plan);
    return result;
}

std::string rethrowMessage(const std::string& prefix) {
    try {
        throw;
    } catch (const std::bad_alloc&) {
        return prefix + "out of memory while reading the model";
    } catch (const std::exception& e) {
        return prefix + e.what();
    }
}

void checkFile(const std::string& path) {
    std::error_code error;
    const auto size = fs::file_size(path, error);
    if (error)
        throw InputError("cannot read the file (" + error.message() + ")");
    if (size == 0)
        throw InputError("the file is empty");
    if (size > kMaxBuildingModelBytes)
        throw InputError("the file is larger than " + std::to_string(kMaxBuildingModelBytes >> 20) +
                         " MiB");
}

} // namespace

std::vector<std::string> buildingModelExtensions() {
    return {"ifc", "obj", "gltf", "glb", "stl"};
}

ImportResult importBuildingModel(const std::string& path, const ImportOptions& options,
                                 const BuildingModelSettings& settings) {
    try {
        checkFile(path);
        const BuildingModel model = loadBuildingModel({nullptr, 0, path, extensionOf(path)},
                                                      settings.up, unitScale(options));
        return sliceModel(model, options, fs::path(path).stem().string());
    } catch (...) {
        throw InputError(rethrowMessage(path + ": "));
    }
}

ImportResult importBuildingModelFromMemory(const void* data, std::size_t size,
                                           const std::string& extension,
                                           const ImportOptions& options,
                                           const BuildingModelSettings& settings) {
    try {
        if (size == 0)
            throw InputError("the file is empty");
        if (size > kMaxBuildingModelBytes)
            throw InputError("the model is too large");
        const BuildingModel model =
            loadBuildingModel({data, size, "", extension}, settings.up, unitScale(options));
        return sliceModel(model, options, "model");
    } catch (...) {
        throw InputError(rethrowMessage(""));
    }
}

ImportPreview previewBuildingModel(const std::string& path, const BuildingModelSettings& settings) {
    try {
        checkFile(path);
        const BuildingModel model =
            loadBuildingModel({nullptr, 0, path, extensionOf(path)}, settings.up, 1.0);
        ImportPreview preview;
        preview.format = model.format;
        preview.layers = model.nodes;
        for (const Storey& storey : model.storeys)
            preview.storeys.push_back(storey.name);
        if (!model.unitless)
            preview.metresPerUnit = 1.0;
        return preview;
    } catch (...) {
        throw InputError(rethrowMessage(path + ": "));
    }
}

} // namespace fc
