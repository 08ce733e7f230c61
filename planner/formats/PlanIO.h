// Reading and writing floor plans: GeoJSON (SPEC sect. 7) and the native project file.
#pragma once

#include "model/Plan.h"
#include "model/Project.h"

#include <optional>
#include <string>
#include <vector>

namespace fc {

// GeoJSON FeatureCollection of Polygon features with properties.role =
// boundary | obstacle | room and properties.name for rooms. Polygon interior rings of the
// boundary become obstacles. Several boundary polygons (features or MultiPolygon parts) are
// the buildings of a site; a plan holds one: `building` K = 1, 2, ... (largest first) picks
// it with the obstacles and rooms inside it, and without it such a file is refused with the
// buildings' areas. Throws InputError (message without the file name).
// Longitude/latitude (a geographic `crs`, or none and an extent below kLonLatExtent degrees
// inside the globe's ranges, RFC 7946's default) is reprojected to metres in its UTM zone,
// which becomes the plan's EPSG; `notes` (when given) gets a line saying so.
inline constexpr double kLonLatExtent = 0.05; // degrees, about 5 km: no building in metres

// A site of several buildings read without `building`: the message lists their areas and
// the option; buildingAreas() (m^2, largest first, building K at K - 1) lets an editor ask.
class SiteError : public InputError {
public:
    SiteError(const std::string& message, std::vector<double> buildingAreas)
        : InputError(message), areas_(std::move(buildingAreas)) {}
    const std::vector<double>& buildingAreas() const { return areas_; }

private:
    std::vector<double> areas_;
};

Plan readGeoJsonPlan(const std::string& text, std::optional<int> building = std::nullopt,
                     std::vector<std::string>* notes = nullptr);
std::string writeGeoJsonPlan(const Plan& plan);

// The native project file: a versioned JSON document holding the plan, robot profile,
// sweep options and the planning selection (model/Project.h).
constexpr int kProjectFormatVersion = 1;
Project readProject(const std::string& text);
std::string writeProject(const Project& project);

// Reads a plan or project file by extension (.geojson/.json with a FeatureCollection,
// .fcproj), throwing InputError("FILE: problem") on any failure. `building`: as in
// readGeoJsonPlan (a project holds one building already: refused with one). The project's
// notes say what was done to read it (coordinates reprojected).
Project loadProjectFile(const std::string& path, std::optional<int> building = std::nullopt);

} // namespace fc
