// Reading and writing floor plans: GeoJSON (SPEC sect. 7) and the native project file.
#pragma once

#include "model/Plan.h"

#include <string>

namespace fc {

// GeoJSON FeatureCollection of Polygon features with properties.role =
// boundary | obstacle | room and properties.name for rooms. Polygon interior rings of the
// boundary become obstacles. Throws InputError (message without the file name).
Plan readGeoJsonPlan(const std::string& text);
std::string writeGeoJsonPlan(const Plan& plan);

// The native project: a versioned JSON document holding the plan, robot profile,
// sweep options and the planning selection.
struct Project {
    Plan plan;
    RobotProfile robot;
    SweepOptions sweep;
    std::string solver = "heuristic";
    std::vector<std::string> selectedRooms; // empty = all
    bool hasStart = false, hasEnd = false;
    Vec2 start, end;
};
constexpr int kProjectFormatVersion = 1;
Project readProject(const std::string& text);
std::string writeProject(const Project& project);

// Reads a plan or project file by extension (.geojson/.json with a FeatureCollection,
// .fcproj), throwing InputError("FILE: problem") on any failure.
Project loadProjectFile(const std::string& path);
// Atomic write (temporary file + rename). Throws InputError on failure.
void writeFileAtomically(const std::string& path, const std::string& contents);
std::string readFile(const std::string& path); // throws InputError

} // namespace fc
