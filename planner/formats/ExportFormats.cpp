// The export dispatch (CLI `export`, File > Export) and the plan/zone writers: zone JSON
// and GeoJSON, the plan's own-frame GeoJSON and WKT.
#include "formats/Export.h"
#include "formats/JsonSupport.h"
#include "formats/PlanIO.h"
#include "formats/WriterSupport.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>

namespace fc {

using nlohmann::ordered_json;

namespace {

constexpr std::array<const char*, 12> kNames = {
    "geojson",      "wgs84-geojson", "csv",   "json", "ros-path", "nav2",
    "fields2cover", "vda5050",       "zones", "svg",  "pdf",      "wkt"};

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

struct Zone {
    std::string name;
    Ring outline;
    std::vector<Ring> holes;
};

std::vector<Zone> zonesOf(const Plan& plan) {
    std::vector<Zone> zones;
    for (const Room& room : plan.rooms)
        zones.push_back({room.name, room.outline, {}});
    if (zones.empty())
        zones.push_back({plan.name.empty() ? "floor" : plan.name, plan.boundary, plan.obstacles});
    return zones;
}

double zoneArea(const Zone& zone) {
    double area = formats::ringArea(zone.outline);
    for (const Ring& hole : zone.holes)
        area -= formats::ringArea(hole);
    return area;
}

ordered_json zoneRings(const Zone& zone) {
    ordered_json rings = ordered_json::array();
    rings.push_back(formats::ringToJson(formats::orientedRing(zone.outline, true), true));
    for (const Ring& hole : zone.holes)
        rings.push_back(formats::ringToJson(formats::orientedRing(hole, false), true));
    return rings;
}

// Top-level members stating the frame of a GeoJSON in the plan's own coordinates.
void markFrame(ordered_json& root, const std::optional<int>& epsg) {
    if (epsg)
        root["crs"] = {
            {"type", "name"},
            {"properties", {{"name", "urn:ogc:def:crs:EPSG::" + std::to_string(*epsg)}}}};
    else
        root["floorcover:crs"] = "local metres";
    root["units"] = "m";
}

// ((x y, x y, ...), (...)) with the closing vertex repeated.
std::string wktRings(const std::vector<Ring>& rings) {
    std::string text = "(";
    for (size_t r = 0; r < rings.size(); ++r) {
        text += r ? ", (" : "(";
        for (size_t i = 0; i <= rings[r].size(); ++i) {
            const Vec2 p = rings[r][i % rings[r].size()];
            text +=
                (i ? ", " : "") + formats::fixedNumber(p.x, 6) + " " + formats::fixedNumber(p.y, 6);
        }
        text += ")";
    }
    return text + ")";
}

std::vector<Ring> floorRings(const Plan& plan) {
    std::vector<Ring> rings{formats::orientedRing(plan.boundary, true)};
    for (const Ring& obstacle : plan.obstacles)
        rings.push_back(formats::orientedRing(obstacle, false));
    return rings;
}

std::string geoJsonFor(ExportSubject subject, const Plan& plan, const CoveragePath& path,
                       const PathExportInfo& info) {
    if (subject == ExportSubject::Plan)
        return planToLocalGeoJson(plan);
    if (subject == ExportSubject::Zones)
        return zonesToGeoJson(plan);
    ordered_json root = ordered_json::parse(pathToGeoJson(path, info));
    if (!plan.epsg)
        root["floorcover:crs"] = "local metres";
    return formats::dumped(root, -1) + "\n";
}

} // namespace

const std::vector<std::string>& exportFormatNames() {
    static const std::vector<std::string> names(kNames.begin(), kNames.end());
    return names;
}

std::string exportFormatName(ExportFormat format) {
    return kNames[static_cast<size_t>(format)];
}

ExportFormat exportFormatNamed(const std::string& name) {
    for (size_t i = 0; i < kNames.size(); ++i)
        if (lowerCase(name) == kNames[i])
            return static_cast<ExportFormat>(i);
    std::string known;
    for (const char* n : kNames)
        known += (known.empty() ? "" : ", ") + std::string(n);
    throw InputError("unknown export format \"" + name + "\" (expected " + known + ")");
}

std::optional<ExportFormat> exportFormatForExtension(const std::string& fileName) {
    const std::string extension = lowerCase(std::filesystem::path(fileName).extension().string());
    if (extension == ".geojson")
        return ExportFormat::GeoJson;
    if (extension == ".csv")
        return ExportFormat::Csv;
    if (extension == ".json")
        return ExportFormat::Json;
    if (extension == ".yaml" || extension == ".yml")
        return ExportFormat::RosPath;
    if (extension == ".svg")
        return ExportFormat::Svg;
    if (extension == ".pdf")
        return ExportFormat::Pdf;
    if (extension == ".wkt")
        return ExportFormat::Wkt;
    return std::nullopt;
}

ExportSubject exportSubjectNamed(const std::string& name) {
    const std::string lower = lowerCase(name);
    if (lower == "path")
        return ExportSubject::Path;
    if (lower == "plan")
        return ExportSubject::Plan;
    if (lower == "zones")
        return ExportSubject::Zones;
    throw InputError("unknown export subject \"" + name + "\" (expected path, plan or zones)");
}

ExportSubject defaultExportSubject(ExportFormat format) {
    switch (format) {
    case ExportFormat::Wgs84GeoJson:
    case ExportFormat::Wkt:
        return ExportSubject::Plan;
    case ExportFormat::Zones:
        return ExportSubject::Zones;
    default:
        return ExportSubject::Path;
    }
}

bool exportSupports(ExportFormat format, ExportSubject subject) {
    switch (format) {
    case ExportFormat::GeoJson:
    case ExportFormat::Wgs84GeoJson:
    case ExportFormat::Wkt:
        return true;
    case ExportFormat::Zones:
        return subject == ExportSubject::Zones;
    case ExportFormat::Svg:
    case ExportFormat::Pdf: // "path": the plan with the path; "plan": the plan alone
        return subject != ExportSubject::Zones;
    default:
        return subject == ExportSubject::Path;
    }
}

bool exportNeedsPath(ExportSubject subject) {
    return subject == ExportSubject::Path;
}

std::string exportToFormat(ExportFormat format, ExportSubject subject, const Plan& plan,
                           const CoveragePath& path, const PathExportInfo& pathInfo) {
    PathExportInfo info = pathInfo;
    info.epsg = plan.epsg; // one frame for every file
    if (!exportSupports(format, subject))
        throw InputError("format " + exportFormatName(format) + " cannot hold the " +
                         (subject == ExportSubject::Path   ? "path"
                          : subject == ExportSubject::Plan ? "plan"
                                                           : "zones"));
    switch (format) {
    case ExportFormat::GeoJson:
        return geoJsonFor(subject, plan, path, info);
    case ExportFormat::Wgs84GeoJson: {
        const std::string local = geoJsonFor(subject, plan, path, info);
        return plan.epsg ? reprojectGeoJsonToWgs84(local, *plan.epsg) : local;
    }
    case ExportFormat::Csv:
        return pathToCsv(path, info);
    case ExportFormat::Json:
        return pathToJson(path, info);
    case ExportFormat::RosPath:
        return pathToRosYaml(path, info);
    case ExportFormat::Nav2:
        return pathToNav2Yaml(path, info);
    case ExportFormat::Fields2Cover:
        return pathToFields2Cover(path, info);
    case ExportFormat::Vda5050:
        return pathToVda5050(path, info);
    case ExportFormat::Zones:
        return zonesToJson(plan);
    case ExportFormat::Svg:
        return planToSvg(plan, path, info);
    case ExportFormat::Pdf:
        return planToPdf(plan, path, info);
    case ExportFormat::Wkt:
        return subject == ExportSubject::Path   ? pathToWkt(path)
               : subject == ExportSubject::Plan ? planToWkt(plan)
                                                : zonesToWkt(plan);
    }
    throw InputError("unknown export format");
}

std::string zonesToJson(const Plan& plan) {
    ordered_json zones = ordered_json::array();
    for (const Zone& zone : zonesOf(plan)) {
        ordered_json item;
        item["name"] = zone.name;
        item["polygon"] = formats::ringToJson(formats::orientedRing(zone.outline, true), false);
        if (!zone.holes.empty()) {
            item["holes"] = ordered_json::array();
            for (const Ring& hole : zone.holes)
                item["holes"].push_back(
                    formats::ringToJson(formats::orientedRing(hole, false), false));
        }
        item["area"] = formats::rounded(zoneArea(zone), 4);
        zones.push_back(std::move(item));
    }
    ordered_json root;
    root["units"] = "m";
    root["area_units"] = "m2";
    root["frame"] = formats::frameDescription(plan.epsg);
    root["zones"] = std::move(zones);
    return formats::dumped(root, 1) + "\n";
}

std::string zonesToGeoJson(const Plan& plan) {
    ordered_json root;
    root["type"] = "FeatureCollection";
    root["name"] = "zones";
    markFrame(root, plan.epsg);
    ordered_json features = ordered_json::array();
    for (const Zone& zone : zonesOf(plan)) {
        ordered_json feature;
        feature["type"] = "Feature";
        feature["properties"] = {
            {"name", zone.name}, {"area", formats::rounded(zoneArea(zone), 4)}, {"units", "m"}};
        feature["geometry"] = {{"type", "Polygon"}, {"coordinates", zoneRings(zone)}};
        features.push_back(std::move(feature));
    }
    root["features"] = std::move(features);
    return formats::dumped(root, 1) + "\n";
}

std::string planToLocalGeoJson(const Plan& plan) {
    ordered_json source = ordered_json::parse(writeGeoJsonPlan(plan));
    ordered_json root;
    root["type"] = "FeatureCollection";
    if (source.contains("name"))
        root["name"] = source["name"];
    markFrame(root, plan.epsg);
    for (ordered_json& feature : source["features"])
        feature["properties"]["units"] = "m";
    root["features"] = std::move(source["features"]);
    return formats::dumped(root, 1) + "\n";
}

std::string planToWkt(const Plan& plan) {
    const std::string floor = "POLYGON " + wktRings(floorRings(plan));
    if (plan.rooms.empty())
        return floor + "\n";
    std::string text = "GEOMETRYCOLLECTION (" + floor;
    for (const Room& room : plan.rooms)
        text += ", POLYGON " + wktRings({formats::orientedRing(room.outline, true)});
    return text + ")\n";
}

std::string zonesToWkt(const Plan& plan) {
    std::string text = "MULTIPOLYGON (";
    const std::vector<Zone> zones = zonesOf(plan);
    for (size_t i = 0; i < zones.size(); ++i) {
        std::vector<Ring> rings{formats::orientedRing(zones[i].outline, true)};
        for (const Ring& hole : zones[i].holes)
            rings.push_back(formats::orientedRing(hole, false));
        text += (i ? ", " : "") + wktRings(rings);
    }
    return text + ")\n";
}

} // namespace fc
