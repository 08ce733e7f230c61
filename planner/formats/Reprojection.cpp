// WGS84 GeoJSON (RFC 7946) with PROJ: the only file that includes PROJ's headers.
#include "formats/Export.h"
#include "formats/WriterSupport.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
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

bool isGeographicCrs(int epsg) {
    std::unique_ptr<PJ_CONTEXT, ContextDeleter> context(proj_context_create());
    proj_log_level(context.get(), PJ_LOG_NONE);
    const std::string code = "EPSG:" + std::to_string(epsg);
    std::unique_ptr<PJ, TransformDeleter> crs(proj_create(context.get(), code.c_str()));
    if (!crs)
        return false;
    const PJ_TYPE type = proj_get_type(crs.get());
    return type == PJ_TYPE_GEOGRAPHIC_2D_CRS || type == PJ_TYPE_GEOGRAPHIC_3D_CRS ||
           type == PJ_TYPE_GEOGRAPHIC_CRS;
}

bool isWebMercator(int epsg) {
    return epsg == 3857 || epsg == 3785 || epsg == 900913 || epsg == 102100 || epsg == 102113;
}

Plan projectedToUtm(const Plan& plan, int sourceEpsg) {
    const BoundingBox box = plan.bounds();
    const Vec2 centre{0.5 * (box.minX + box.maxX), 0.5 * (box.minY + box.maxY)};
    const bool geographic = isGeographicCrs(sourceEpsg);
    const Vec2 lonLat = geographic ? centre : toWgs84({centre}, sourceEpsg).front();
    const double lon = lonLat.x, lat = lonLat.y;
    if (!(std::abs(lon) <= 180.0 && std::abs(lat) <= 90.0))
        throw InputError("coordinates in EPSG:" + std::to_string(sourceEpsg) +
                         (geographic ? " are longitude/latitude, but the plan's centre ("
                                     : ": the plan's centre (") +
                         formats::fixedNumber(centre.x, 6) + ", " +
                         formats::fixedNumber(centre.y, 6) + ") is not on the globe");
    const int zone = std::clamp(static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1, 1, 60);
    const int target = (lat >= 0.0 ? 32600 : 32700) + zone;
    std::unique_ptr<PJ_CONTEXT, ContextDeleter> context(proj_context_create());
    proj_log_level(context.get(), PJ_LOG_NONE);
    const std::string source = "EPSG:" + std::to_string(sourceEpsg);
    const std::string destination = "EPSG:" + std::to_string(target);
    std::unique_ptr<PJ, TransformDeleter> raw(
        proj_create_crs_to_crs(context.get(), source.c_str(), destination.c_str(), nullptr));
    // Normalised: GeoJSON's longitude first in, easting first out.
    std::unique_ptr<PJ, TransformDeleter> transform(
        raw ? proj_normalize_for_visualization(context.get(), raw.get()) : nullptr);
    if (!transform)
        throw InputError("cannot reproject from " + source + " to " + destination + ": " +
                         projError(context.get()));
    // Every point on the globe, not only the centre (Web Mercator's square is +-20,037,508 m
    // each way; beyond it the projection wraps or clamps, and the rings collapse).
    constexpr double kMercatorExtent = 20037508.35;
    const bool mercator = isWebMercator(sourceEpsg);
    auto project = [&](Ring& ring) {
        for (Vec2& p : ring) {
            const bool onGlobe =
                geographic ? std::abs(p.x) <= 360.0 && std::abs(p.y) <= 90.0
                : mercator ? std::abs(p.x) <= kMercatorExtent && std::abs(p.y) <= kMercatorExtent
                           : true;
            if (!onGlobe)
                throw InputError("point (" + formats::fixedNumber(p.x, 6) + ", " +
                                 formats::fixedNumber(p.y, 6) + ") in " + source +
                                 " is not on the globe");
            const PJ_COORD out = proj_trans(transform.get(), PJ_FWD, proj_coord(p.x, p.y, 0, 0));
            if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y))
                throw InputError("cannot reproject point (" + formats::fixedNumber(p.x, 9) + ", " +
                                 formats::fixedNumber(p.y, 9) + ") from " + source + " to " +
                                 destination);
            p = {out.xy.x, out.xy.y};
        }
    };
    Plan out = plan;
    project(out.boundary);
    for (Ring& obstacle : out.obstacles)
        project(obstacle);
    for (Room& room : out.rooms)
        project(room.outline);
    out.epsg = target;
    return out;
}

std::optional<std::string> reprojectToMetres(Plan& plan, bool guessedLonLat) {
    const bool geographic = plan.epsg && isGeographicCrs(*plan.epsg);
    const bool webMercator = plan.epsg && isWebMercator(*plan.epsg);
    if (!guessedLonLat && !geographic && !webMercator)
        return std::nullopt;
    const int source = guessedLonLat ? 4326 : *plan.epsg;
    plan = projectedToUtm(plan, source);
    const std::string utm = "metres in WGS84 / UTM zone " + std::to_string(*plan.epsg % 100) +
                            (*plan.epsg < 32700 ? "N" : "S") +
                            " (EPSG:" + std::to_string(*plan.epsg) + ")";
    const std::string code = "EPSG:" + std::to_string(source);
    if (guessedLonLat)
        return "no crs, and coordinates that only make sense as degrees (the plan spans "
               "less than 0.05): read as WGS84 longitude/latitude (GeoJSON's default) and "
               "reprojected to " +
               utm;
    if (webMercator)
        return "Web Mercator (" + code + "), whose metres are not the ground's, reprojected to " +
               utm;
    return "longitude/latitude (" + code + ") reprojected to " + utm;
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
