// 3D building models (issue 5, item 2): IFC2x3, OBJ, glTF/GLB and STL read with assimp, cut by
// a horizontal plane a little above a storey's floor. The section becomes a plan:
//  - boundary  = the outline of the free floor space of the storey (the inner side of the
//                outer walls, i.e. the largest region enclosed by the section),
//  - obstacles = wall, column and furniture cross-sections inside that region,
//  - rooms     = sections of IfcSpace volumes, named by their IFC LongName (else Name).
// The section is an exact CGAL arrangement of the cut segments (see SectionArrangement.h).
// Non-IFC models have one storey, "whole model", whose floor is the model's lowest point.
#pragma once

#include "importers/Import.h"

#include <cstddef>
#include <string>

namespace fc {

// Which model axis points up. Automatic: IFC (assimp turns it to Y-up), glTF/GLB and OBJ are
// taken as Y-up, STL (CAD, 3D printing) as Z-up.
enum class UpAxis { Automatic, Y, Z };

struct BuildingModelSettings {
    UpAxis up = UpAxis::Automatic;
};

// The formats importBuildingModel reads (lower case, without the dot).
std::vector<std::string> buildingModelExtensions();

// Throws InputError("FILE: problem") for unreadable, corrupt, empty or oversized files,
// an unknown storey, and a plane that cuts nothing ("no section at height H m ...").
ImportResult importBuildingModel(const std::string& path, const ImportOptions& options,
                                 const BuildingModelSettings& settings = {});
// Storeys (lowest first) and the names of the nodes holding geometry.
ImportPreview previewBuildingModel(const std::string& path,
                                   const BuildingModelSettings& settings = {});

// The same from bytes already in memory; `extension` ("obj", "stl", ...) picks the reader.
// Used by the fuzzer. Messages carry no file name.
ImportResult importBuildingModelFromMemory(const void* data, std::size_t size,
                                           const std::string& extension,
                                           const ImportOptions& options,
                                           const BuildingModelSettings& settings = {});

// Limits that keep hostile files from exhausting memory or time.
constexpr std::size_t kMaxBuildingModelBytes = 512u << 20; // 512 MiB
constexpr std::size_t kMaxBuildingModelTriangles = 20'000'000;
constexpr std::size_t kMaxSectionSegments = 400'000;

} // namespace fc
