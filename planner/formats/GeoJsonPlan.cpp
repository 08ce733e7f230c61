// GeoJSON floor plans (SPEC sect. 7): a FeatureCollection of Polygon features with
// properties.role = boundary | obstacle | room.
#include "formats/Export.h"
#include "formats/JsonSupport.h"
#include "formats/PlanIO.h"
#include "formats/WriterSupport.h"
#include "geometry/Geometry.h"
#include "geometry/RingOverlap.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <optional>

namespace fc {

using nlohmann::json;
using nlohmann::ordered_json;

namespace {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// "urn:ogc:def:crs:EPSG::32632", "EPSG:32632" and the GeoJSON default CRS84.
std::optional<int> epsgFromCrsName(const std::string& name) {
    const std::string lower = lowerCase(name);
    if (lower.find("crs84") != std::string::npos)
        return 4326;
    if (lower.find("epsg") == std::string::npos)
        return std::nullopt;
    size_t end = lower.size();
    size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(lower[begin - 1])))
        --begin;
    if (begin == end || end - begin > 9)
        return std::nullopt;
    return std::stoi(lower.substr(begin));
}

std::optional<int> epsgFromJson(const json& value) {
    if (value.is_number_integer() && value.get<long long>() > 0 &&
        value.get<long long>() < 1000000000)
        return static_cast<int>(value.get<long long>());
    if (value.is_string())
        return epsgFromCrsName(value.get<std::string>());
    return std::nullopt;
}

// The optional "crs" member (GeoJSON 2008, still written by GDAL), or an "epsg" member of
// the collection or of the boundary's properties.
std::optional<int> readEpsg(const json& root, const json& boundaryProperties) {
    if (root.contains("crs") && root["crs"].is_object()) {
        const json& crs = root["crs"];
        if (crs.contains("properties") && crs["properties"].is_object()) {
            const json& props = crs["properties"];
            for (const char* key : {"name", "code"}) {
                if (props.contains(key))
                    if (auto epsg = epsgFromJson(props[key]))
                        return epsg;
            }
        }
    }
    for (const json* holder : {&root, &boundaryProperties}) {
        if (holder->is_object() && holder->contains("epsg"))
            if (auto epsg = epsgFromJson((*holder)["epsg"]))
                return epsg;
    }
    return std::nullopt;
}

// The polygons of a Polygon or MultiPolygon geometry, each a list of rings.
std::vector<json> polygonsOf(const json& feature, const std::string& label) {
    if (!feature.contains("geometry") || feature["geometry"].is_null())
        throw InputError(label + " has no geometry");
    const json& geometry = feature["geometry"];
    if (!geometry.is_object() || !geometry.contains("type") || !geometry["type"].is_string())
        throw InputError(label + ": geometry has no type");
    const std::string type = geometry["type"].get<std::string>();
    if (type != "Polygon" && type != "MultiPolygon")
        throw InputError(label + ": geometry type \"" + type +
                         "\" is not supported (expected Polygon)");
    if (!geometry.contains("coordinates") || !geometry["coordinates"].is_array())
        throw InputError(label + ": " + type + " has no coordinates array");
    const json& coordinates = geometry["coordinates"];
    std::vector<json> polygons;
    if (type == "Polygon")
        polygons.push_back(coordinates);
    else
        polygons.assign(coordinates.begin(), coordinates.end());
    if (polygons.empty())
        throw InputError(label + ": " + type + " has no polygons");
    for (const json& polygon : polygons) {
        if (!polygon.is_array() || polygon.empty())
            throw InputError(label + ": polygon has no rings");
    }
    return polygons;
}

std::string roomNameOf(const json& properties, const std::string& label) {
    const json name = properties.contains("name") ? properties["name"] : json();
    std::string text;
    if (name.is_string())
        text = name.get<std::string>();
    else if (name.is_number())
        text = name.dump();
    else if (!name.is_null())
        throw InputError(label + ": properties.name must be a string (got " +
                         formats::describeJsonValue(name) + ")");
    if (text.find_first_not_of(" \t") == std::string::npos)
        throw InputError(label + " has no name (rooms need properties.name)");
    return text;
}

// One boundary polygon of the file: a building of a site when there are several.
struct BoundaryPart {
    Ring outline;
    std::vector<Ring> holes; // the polygon's interior rings: obstacles
    int featureNumber = 0;
    json properties;
};

struct PlanReader {
    Plan plan;
    std::vector<BoundaryPart> boundaries; // every boundary polygon, in file order
    json boundaryProperties;
    std::map<std::string, int> roomFeatures; // name -> feature number

    // Several boundary features, or a MultiPolygon boundary, are the buildings of a site:
    // collected here, one of them chosen after reading (selectBuilding).
    void addBoundary(const std::vector<json>& polygons, int featureNumber, const json& properties) {
        for (std::size_t part = 0; part < polygons.size(); ++part) {
            std::string label = "boundary (feature " + std::to_string(featureNumber);
            if (polygons.size() > 1)
                label += ", part " + std::to_string(part + 1);
            label += ")";
            const json& rings = polygons[part];
            BoundaryPart b;
            b.outline = formats::ringFromJson(rings[0], label);
            const std::string of = polygons.size() > 1
                                       ? "of the boundary, part " + std::to_string(part + 1)
                                       : "of the boundary";
            for (size_t k = 1; k < rings.size(); ++k)
                b.holes.push_back(
                    formats::ringFromJson(rings[k], "obstacle " + std::to_string(k) + " (hole " +
                                                        std::to_string(k) + " " + of + ")"));
            b.featureNumber = featureNumber;
            b.properties = properties;
            boundaries.push_back(std::move(b));
        }
    }

    // The building `building` (1 = the largest) or the only one; obstacles and rooms of the
    // other buildings are left out (the first vertex decides where one belongs).
    void selectBuilding(std::optional<int> building) {
        if (boundaries.empty())
            throw InputError("no boundary: one feature needs properties.role = \"boundary\"");
        std::stable_sort(boundaries.begin(), boundaries.end(),
                         [](const BoundaryPart& a, const BoundaryPart& b) {
                             return ringArea(a.outline) > ringArea(b.outline);
                         });
        const int count = static_cast<int>(boundaries.size());
        if (!building && count > 1) {
            std::string areas;
            std::vector<double> all;
            for (int i = 0; i < count; ++i)
                all.push_back(ringArea(boundaries[i].outline));
            for (int i = 0; i < count && i < 6; ++i)
                areas += (i > 0 ? ", " : "") + formatArea(all[i]);
            if (count > 6)
                areas += ", ...";
            throw SiteError(std::to_string(count) + " buildings (boundary polygons of " + areas +
                                " m2, largest first); a plan holds one building: choose one "
                                "with --building K, K = 1.." +
                                std::to_string(count) +
                                " (plan, graph, train, compare, tile, export, or `import FILE "
                                "--building K --out PLAN.fcproj` for a project of its own)",
                            std::move(all));
        }
        const int chosen = building.value_or(1);
        if (chosen < 1 || chosen > count)
            throw InputError("building " + std::to_string(chosen) +
                             " does not exist: the file has " + std::to_string(count) +
                             (count == 1 ? " building" : " buildings"));
        BoundaryPart& b = boundaries[static_cast<std::size_t>(chosen - 1)];
        plan.boundary = b.outline;
        boundaryProperties = b.properties;
        if (count > 1) {
            // Left out only when another building holds it: one in no building stays, so the
            // plan's checks name it (outside the boundary) instead of it vanishing.
            auto elsewhere = [&](const Ring& ring) {
                if (ring.empty() || pointInRing(plan.boundary, ring.front()))
                    return false;
                return std::any_of(boundaries.begin(), boundaries.end(),
                                   [&](const BoundaryPart& other) {
                                       return pointInRing(other.outline, ring.front());
                                   });
            };
            plan.obstacles.erase(std::remove_if(plan.obstacles.begin(), plan.obstacles.end(),
                                                [&](const Ring& r) { return elsewhere(r); }),
                                 plan.obstacles.end());
            plan.rooms.erase(std::remove_if(plan.rooms.begin(), plan.rooms.end(),
                                            [&](const Room& r) { return elsewhere(r.outline); }),
                             plan.rooms.end());
        }
        // Interior rings of the boundary are obstacles (holes in the free space).
        plan.obstacles.insert(plan.obstacles.begin(), b.holes.begin(), b.holes.end());
    }

    // Another building of the site whose outline shares floor with the chosen one: that
    // floor is planned, and counted, with both (a site of two outlines overlapping by 40 m^2
    // totalled 160 m^2 for 120 m^2 without a word).
    std::vector<std::string> overlapsOfChosen(int chosen) const {
        std::vector<std::string> out;
        const Ring& mine = boundaries[static_cast<std::size_t>(chosen - 1)].outline;
        for (std::size_t k = 0; k < boundaries.size(); ++k) {
            if (static_cast<int>(k) == chosen - 1)
                continue;
            const double shared = ringOverlapArea(mine, boundaries[k].outline);
            if (shared > 1e-6 * std::max(ringArea(mine), 1.0))
                out.push_back("building " + std::to_string(chosen) + " overlaps building " +
                              std::to_string(k + 1) + " by " + formatArea(shared) +
                              " m2: that floor is planned with both");
        }
        return out;
    }

    static std::string formatArea(double area) {
        char text[32];
        std::snprintf(text, sizeof text, "%.0f", area);
        return text;
    }

    void addObstacles(const std::vector<json>& polygons, int featureNumber) {
        for (const json& rings : polygons) {
            const std::string label = "obstacle " + std::to_string(plan.obstacles.size() + 1) +
                                      " (feature " + std::to_string(featureNumber) + ")";
            if (rings.size() > 1)
                throw InputError(label +
                                 " has a hole; free space inside an obstacle is not supported");
            plan.obstacles.push_back(formats::ringFromJson(rings[0], label));
        }
    }

    void addRoom(const std::vector<json>& polygons, int featureNumber, const json& properties) {
        const std::string feature = "feature " + std::to_string(featureNumber);
        const std::string name = roomNameOf(properties, "room (" + feature + ")");
        const std::string label = "room \"" + name + "\" (" + feature + ")";
        if (auto previous = roomFeatures.find(name); previous != roomFeatures.end())
            throw InputError("duplicate room name \"" + name + "\" (features " +
                             std::to_string(previous->second) + " and " +
                             std::to_string(featureNumber) + ")");
        if (polygons.size() > 1)
            throw InputError(label + " is a MultiPolygon with " + std::to_string(polygons.size()) +
                             " parts; split it into separately named rooms");
        if (polygons.front().size() > 1)
            throw InputError(label + " has a hole; model the hole as an obstacle instead");
        roomFeatures[name] = featureNumber;
        plan.rooms.push_back(Room{name, formats::ringFromJson(polygons.front()[0], label)});
    }
};

// Whether every vertex lies inside the globe's ranges within kLonLatExtent degrees.
bool looksLikeLonLat(const Plan& plan) {
    BoundingBox box = plan.bounds();
    for (const Ring& obstacle : plan.obstacles)
        for (const Vec2& p : obstacle)
            box.add(p);
    for (const Room& room : plan.rooms)
        for (const Vec2& p : room.outline)
            box.add(p);
    return box.minX >= -180.0 && box.maxX <= 180.0 && box.minY >= -90.0 && box.maxY <= 90.0 &&
           std::max(box.width(), box.height()) < kLonLatExtent;
}

// A plan in longitude/latitude is planned in metres (the robot's sizes are metres).
void inMetres(Plan& plan, std::vector<std::string>* notes) {
    const bool guessed = !plan.epsg && looksLikeLonLat(plan);
    if (std::optional<std::string> note = reprojectToMetres(plan, guessed); note && notes)
        notes->push_back(*note);
}

} // namespace

Plan readGeoJsonPlan(const std::string& text, std::optional<int> building,
                     std::vector<std::string>* notes) {
    const json root = formats::parseJsonDocument(text);
    if (!root.is_object())
        throw InputError("not a GeoJSON FeatureCollection (the document is " +
                         std::string(root.type_name()) + ")");
    if (!root.contains("type") || !root["type"].is_string())
        throw InputError("not a GeoJSON FeatureCollection (no \"type\" member)");
    const std::string type = root["type"].get<std::string>();
    if (type != "FeatureCollection")
        throw InputError("not a GeoJSON FeatureCollection (type is \"" + type + "\")");
    if (!root.contains("features") || !root["features"].is_array())
        throw InputError("the FeatureCollection has no \"features\" array");

    PlanReader reader;
    const json& features = root["features"];
    for (size_t i = 0; i < features.size(); ++i) {
        const int featureNumber = static_cast<int>(i) + 1;
        const std::string label = "feature " + std::to_string(featureNumber);
        const json& feature = features[i];
        if (!feature.is_object())
            throw InputError(label + " is not a GeoJSON Feature object");
        json properties = feature.contains("properties") ? feature["properties"] : json();
        if (properties.is_null())
            properties = json::object();
        if (!properties.is_object())
            throw InputError(label + ": properties must be an object");
        if (!properties.contains("role") || properties["role"].is_null())
            throw InputError(label +
                             " has no properties.role (expected boundary, obstacle or room)");
        if (!properties["role"].is_string())
            throw InputError(label + ": properties.role must be a string (got " +
                             formats::describeJsonValue(properties["role"]) + ")");
        const std::string role = lowerCase(properties["role"].get<std::string>());
        if (role != "boundary" && role != "obstacle" && role != "room")
            throw InputError(label + " has unknown role \"" +
                             properties["role"].get<std::string>() +
                             "\" (expected boundary, obstacle or room)");
        const std::vector<json> polygons = polygonsOf(feature, label + " (" + role + ")");
        if (role == "boundary")
            reader.addBoundary(polygons, featureNumber, properties);
        else if (role == "obstacle")
            reader.addObstacles(polygons, featureNumber);
        else
            reader.addRoom(polygons, featureNumber, properties);
    }
    reader.selectBuilding(building);
    if (notes)
        for (const std::string& note : reader.overlapsOfChosen(building.value_or(1)))
            notes->push_back(note);
    reader.plan.epsg = readEpsg(root, reader.boundaryProperties);
    inMetres(reader.plan, notes);
    if (root.contains("name") && root["name"].is_string())
        reader.plan.name = root["name"].get<std::string>();
    return reader.plan;
}

std::string writeGeoJsonPlan(const Plan& plan) {
    ordered_json root;
    root["type"] = "FeatureCollection";
    if (!plan.name.empty())
        root["name"] = plan.name;
    if (plan.epsg)
        root["crs"] = {
            {"type", "name"},
            {"properties", {{"name", "urn:ogc:def:crs:EPSG::" + std::to_string(*plan.epsg)}}}};
    auto polygonFeature = [](ordered_json properties, ordered_json rings) {
        ordered_json feature;
        feature["type"] = "Feature";
        feature["properties"] = std::move(properties);
        feature["geometry"] = {{"type", "Polygon"}, {"coordinates", std::move(rings)}};
        return feature;
    };
    // RFC 7946: exterior rings counter-clockwise, holes clockwise, closing vertex repeated.
    ordered_json boundaryRings = ordered_json::array();
    boundaryRings.push_back(formats::ringToJson(formats::orientedRing(plan.boundary, true), true));
    for (const Ring& obstacle : plan.obstacles)
        boundaryRings.push_back(formats::ringToJson(formats::orientedRing(obstacle, false), true));
    ordered_json features = ordered_json::array();
    features.push_back(polygonFeature({{"role", "boundary"}}, std::move(boundaryRings)));
    for (const Room& room : plan.rooms) {
        ordered_json rings = ordered_json::array();
        rings.push_back(formats::ringToJson(formats::orientedRing(room.outline, true), true));
        features.push_back(polygonFeature({{"role", "room"}, {"name", room.name}}, rings));
    }
    root["features"] = std::move(features);
    return root.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

} // namespace fc
