// Exports for robot vendors and GIS (issue 5): one entry point for the CLI's `export`
// command and the editor's File > Export menu. Every format states its units and frame;
// docs/formats.md, section "Exporting", lists the specifications followed.
#pragma once

#include "formats/PathIO.h"
#include "model/Plan.h"

#include <optional>
#include <string>
#include <vector>

namespace fc {

enum class ExportFormat {
    GeoJson,      // the plan's own frame (local metres marked as such)
    Wgs84GeoJson, // RFC 7946: reprojected to EPSG:4326 with PROJ when the plan has an EPSG
    Csv,
    Json,
    RosPath,      // nav_msgs/Path YAML
    Nav2,         // nav2_msgs/action/FollowWaypoints goal YAML
    Fields2Cover, // Fields2Cover 2.x path text
    Vda5050,      // VDA 5050 2.0.0 order JSON
    Zones,        // simple zone JSON: name, polygon, area, units
    Svg,          // plan + path drawing
    Pdf,          // plan + path drawing
    Wkt,
};

// What a file holds: the coverage path, the floor plan, or its rooms as zones.
enum class ExportSubject { Path, Plan, Zones };

// "geojson", "wgs84-geojson", "csv", "json", "ros-path", "nav2", "fields2cover", "vda5050",
// "zones", "svg", "pdf", "wkt".
const std::vector<std::string>& exportFormatNames();
std::string exportFormatName(ExportFormat format);
ExportFormat exportFormatNamed(const std::string& name); // throws InputError
// The format a file extension implies when it is unambiguous (.geojson .csv .json .yaml
// .yml .svg .pdf .wkt); nullopt otherwise.
std::optional<ExportFormat> exportFormatForExtension(const std::string& fileName);
// "path", "plan", "zones"; throws InputError for another word.
ExportSubject exportSubjectNamed(const std::string& name);
// What a format writes when no subject is asked for; whether it can write `subject`.
ExportSubject defaultExportSubject(ExportFormat format);
bool exportSupports(ExportFormat format, ExportSubject subject);
// Whether the export needs a planned path: the path subject does (SVG and PDF of "path" draw
// the plan with the path, of "plan" the plan alone).
bool exportNeedsPath(ExportSubject subject);

// Writes `format` for `subject`; `path` may be empty when exportNeedsPath is false.
// Throws InputError for an unsupported combination or a failed reprojection.
std::string exportToFormat(ExportFormat format, ExportSubject subject, const Plan& plan,
                           const CoveragePath& path, const PathExportInfo& info);

// Zones for vendors that take areas rather than paths: the rooms, or the whole floor
// (boundary with the obstacles as holes) when the plan has none.
std::string zonesToJson(const Plan& plan);    // {"units","frame","zones":[{name,polygon,area}]}
std::string zonesToGeoJson(const Plan& plan); // one Polygon feature per zone
// The plan in its own frame as GeoJSON; a plan without EPSG is marked "local metres".
std::string planToLocalGeoJson(const Plan& plan);
// OGC WKT: POLYGON (floor with holes), or GEOMETRYCOLLECTION (floor, then one POLYGON per
// room in plan order) when the plan has rooms.
std::string planToWkt(const Plan& plan);
std::string zonesToWkt(const Plan& plan); // MULTIPOLYGON of the zones

// RFC 7946 GeoJSON: `localGeoJson` (any FloorCover GeoJSON export in the plan's frame) with
// every coordinate reprojected from EPSG:`epsg` to WGS84 longitude/latitude with PROJ.
// Throws InputError when PROJ does not know the code or cannot transform a point.
std::string reprojectGeoJsonToWgs84(const std::string& localGeoJson, int epsg);
// Lon/lat (degrees) of points given in EPSG:`epsg`; throws InputError on failure.
std::vector<Vec2> toWgs84(const std::vector<Vec2>& points, int epsg);
// Whether PROJ knows EPSG:`epsg` as a geographic (longitude/latitude) CRS.
bool isGeographicCrs(int epsg);
// Web Mercator (EPSG:3857 and its older codes): "metres" that are 1/cos(latitude) of the
// ground's (1.5x at 48 degrees), what web maps and GIS tools drawing on them use.
bool isWebMercator(int epsg);
// A plan in longitude/latitude (EPSG:`sourceEpsg`, longitude first as in GeoJSON) or in Web
// Mercator, in true metres: WGS84 / UTM in the zone of its centre (EPSG:326zz north, 327zz
// south), which becomes its EPSG. Throws InputError when the centre is not on the globe or
// PROJ fails.
Plan projectedToUtm(const Plan& plan, int sourceEpsg);
// The plan in metres (projectedToUtm) where its EPSG is geographic or Web Mercator, or where
// `guessedLonLat` (no EPSG, coordinates that can only be degrees); returns the line that
// says what was done, nothing where the plan stays as it is.
std::optional<std::string> reprojectToMetres(Plan& plan, bool guessedLonLat);

// Drawings of the plan with the path (may be empty): obstacles, rooms with names, the path
// by segment kind and the overlap segments (path over area already swept) in blue.
std::string planToSvg(const Plan& plan, const CoveragePath& path, const PathExportInfo& info);
std::string planToPdf(const Plan& plan, const CoveragePath& path, const PathExportInfo& info);

} // namespace fc
