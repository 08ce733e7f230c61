// WGS84 GeoJSON (RFC 7946) with PROJ: the only file that includes PROJ's headers.
#include "formats/Export.h"
#include "formats/WriterSupport.h"

#include <cmath>
#include <memory>
#include <proj.h>

namespace fc {

using nlohmann::ordered_json;

namespace {

struct ContextDeleter {
    void operator()(PJ_CONTEXT* context) const { proj_context_destroy(context); }
};
struct TransformDeleter {
    void operator()(PJ* transform) const { proj_destroy(transform); }
};

std::string projError(PJ_CONTEXT* context) {
    const int code = proj_context_errno(context);
    return code ? proj_context_errno_string(context, code) : "unknown PROJ error";
}

// Replaces every [x, y] position under `value` (a GeoJSON "coordinates" member).
void collectPositions(ordered_json& value, std::vector<ordered_json*>& positions) {
    if (!value.is_array())
        return;
    if (value.size() >= 2 && value[0].is_number() && value[1].is_number()) {
        positions.push_back(&value);
        return;
    }
    for (ordered_json& item : value)
        collectPositions(item, positions);
}

} // namespace

std::vector<Vec2> toWgs84(const std::vector<Vec2>& points, int epsg) {
    std::unique_ptr<PJ_CONTEXT, ContextDeleter> context(proj_context_create());
    proj_log_level(context.get(), PJ_LOG_NONE);
    const std::string source = "EPSG:" + std::to_string(epsg);
    std::unique_ptr<PJ, TransformDeleter> raw(
        proj_create_crs_to_crs(context.get(), source.c_str(), "EPSG:4326", nullptr));
    if (!raw)
        throw InputError("cannot reproject from " + source +
                         " to WGS84: " + projError(context.get()));
    // EPSG:4326 is latitude-first; normalising gives the longitude, latitude of GeoJSON.
    std::unique_ptr<PJ, TransformDeleter> transform(
        proj_normalize_for_visualization(context.get(), raw.get()));
    if (!transform)
        throw InputError("cannot reproject from " + source +
                         " to WGS84: " + projError(context.get()));
    std::vector<Vec2> result;
    result.reserve(points.size());
    for (const Vec2& p : points) {
        const PJ_COORD out = proj_trans(transform.get(), PJ_FWD, proj_coord(p.x, p.y, 0, 0));
        if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y))
            throw InputError("cannot reproject point (" + formats::fixedNumber(p.x, 3) + ", " +
                             formats::fixedNumber(p.y, 3) + ") from " + source + " to WGS84");
        result.push_back({out.lp.lam, out.lp.phi});
    }
    return result;
}

std::string reprojectGeoJsonToWgs84(const std::string& localGeoJson, int epsg) {
    ordered_json root = ordered_json::parse(localGeoJson);
    std::vector<ordered_json*> positions;
    for (ordered_json& feature : root["features"])
        if (feature.contains("geometry") && feature["geometry"].is_object() &&
            feature["geometry"].contains("coordinates"))
            collectPositions(feature["geometry"]["coordinates"], positions);
    std::vector<Vec2> points;
    points.reserve(positions.size());
    for (const ordered_json* position : positions)
        points.push_back({(*position)[0].get<double>(), (*position)[1].get<double>()});
    const std::vector<Vec2> lonLat = toWgs84(points, epsg);
    for (size_t i = 0; i < positions.size(); ++i)
        *positions[i] = {formats::rounded(lonLat[i].x, 9), formats::rounded(lonLat[i].y, 9)};

    // RFC 7946 has no "crs" member: WGS84 longitude, latitude is implied.
    ordered_json result;
    for (auto& item : root.items()) {
        if (item.key() == "crs")
            continue;
        if (item.key() == "units") {
            result["units"] = "degrees (coordinates); metres (lengths and areas in properties)";
            continue;
        }
        if (item.key() == "features") {
            result["floorcover:coordinates"] = "WGS84 longitude, latitude in degrees (RFC 7946)";
            result["floorcover:source_crs"] = "EPSG:" + std::to_string(epsg);
        }
        result[item.key()] = std::move(item.value());
    }
    return formats::dumped(result, 1) + "\n";
}

} // namespace fc
