// 2D DXF through GDAL's OGR DXF driver (LWPOLYLINE, POLYLINE, LINE, ARC, CIRCLE, ELLIPSE,
// SPLINE, INSERT with its transform, HATCH, TEXT/MTEXT). OGR ignores $INSUNITS: the HEADER
// section is read here.
#include "importers/OgrSupport.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gdal_priv.h>
#include <map>
#include <memory>
#include <mutex>
#include <ogrsf_frmts.h>

namespace fc::importing {

namespace {

// $INSUNITS codes 1..20 in metres (AutoCAD's table); 0 = unitless.
double metresOfInsunits(int code) {
    static const double table[] = {0,       0.0254,  0.3048,   1609.344, 0.001,   0.01, 1.0, 1000.0,
                                   2.54e-8, 2.54e-5, 0.9144,   1e-10,    1e-9,    1e-6, 0.1, 10.0,
                                   100.0,   1e9,     1.496e11, 9.461e15, 3.086e16};
    return code >= 1 && code <= 20 ? table[code] : 0.0;
}

std::string trimmed(const std::string& line) {
    const size_t first = line.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
        return {};
    return line.substr(first, line.find_last_not_of(" \t\r\n") - first + 1);
}

// The header's $INSUNITS code, or -1 when absent. Reads group code / value pairs up to the
// end of the HEADER section (at most a few thousand lines).
int readInsunits(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string code, value;
    for (int pair = 0; pair < 20000 && std::getline(in, code) && std::getline(in, value); ++pair) {
        const std::string c = trimmed(code), v = trimmed(value);
        if (c == "0" && (v == "ENDSEC" || v == "EOF"))
            break;
        if (c == "9" && v == "$INSUNITS") {
            if (!std::getline(in, code) || !std::getline(in, value) || trimmed(code) != "70")
                return -1;
            try {
                return std::stoi(trimmed(value));
            } catch (const std::exception&) {
                return -1;
            }
        }
    }
    return -1;
}

DatasetPtr openDxf(const std::string& path) {
    ensureGdal();
    // One feature per block entity (not one merged collection per INSERT).
    CPLSetThreadLocalConfigOption("DXF_MERGE_BLOCK_GEOMETRIES", "FALSE");
    CPLSetThreadLocalConfigOption("DXF_INLINE_BLOCKS", "TRUE");
    CPLErrorReset();
    const char* const drivers[] = {"DXF", nullptr};
    DatasetPtr dataset(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers,
                                         nullptr, nullptr));
    if (!dataset || dataset->GetLayerCount() < 1) {
        const std::string why = CPLGetLastErrorMsg();
        throw InputError("not a readable DXF file" + (why.empty() ? "" : " (" + why + ")"));
    }
    return dataset;
}

struct Collected {
    std::vector<Outline> outlines;
    std::vector<Piece> pieces;
    std::vector<Label> labels;
    size_t vertices = 0;
    size_t skipped = 0; // points and empty geometries
};

class Collector {
public:
    Collector(double scale, Collected& out) : scale_(scale), out_(out) {}

    void add(const OGRGeometry* geometry, const std::string& layer) {
        if (!geometry || geometry->IsEmpty()) {
            ++out_.skipped;
            return;
        }
        if (geometry->hasCurveGeometry()) {
            std::unique_ptr<OGRGeometry> linear(geometry->getLinearGeometry());
            add(linear.get(), layer);
            return;
        }
        switch (wkbFlatten(geometry->getGeometryType())) {
        case wkbLineString:
        case wkbLinearRing:
            addLine(*geometry->toLineString(), layer, false);
            break;
        case wkbPolygon:
        case wkbTriangle: {
            const OGRPolygon& polygon = *geometry->toPolygon();
            if (const OGRLinearRing* shell = polygon.getExteriorRing())
                addLine(*shell, layer, true);
            for (int i = 0; i < polygon.getNumInteriorRings(); ++i) // hatch islands
                addLine(*polygon.getInteriorRing(i), layer, true);
            break;
        }
        case wkbMultiLineString:
        case wkbMultiCurve:
        case wkbMultiPolygon:
        case wkbGeometryCollection:
        case wkbPolyhedralSurface:
        case wkbTIN:
        case wkbMultiSurface: {
            const auto* collection = dynamic_cast<const OGRGeometryCollection*>(geometry);
            if (!collection) { // polyhedral surfaces and TINs are not collections in OGR
                ++out_.skipped;
                break;
            }
            for (int i = 0; i < collection->getNumGeometries(); ++i)
                add(collection->getGeometryRef(i), layer);
            break;
        }
        default:
            ++out_.skipped;
        }
    }

private:
    void addLine(const OGRSimpleCurve& curve, const std::string& layer, bool closed) {
        const int n = curve.getNumPoints();
        out_.vertices += static_cast<size_t>(std::max(n, 0));
        if (out_.vertices > kMaxVertices)
            throw InputError("more than " + std::to_string(kMaxVertices) + " vertices");
        Polyline line;
        line.reserve(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) {
            const Vec2 p{curve.getX(i) * scale_, curve.getY(i) * scale_};
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                throw InputError("a coordinate on layer \"" + layer + "\" is not finite");
            if (line.empty() || distance(line.back(), p) > 0)
                line.push_back(p);
        }
        if (line.size() < 2) {
            ++out_.skipped;
            return;
        }
        const bool ringClosed = line.size() >= 4 && line.front() == line.back();
        if (closed || ringClosed) {
            if (ringClosed)
                line.pop_back();
            if (line.size() >= 3)
                out_.outlines.push_back({std::move(line), layer});
            else
                ++out_.skipped;
            return;
        }
        if (out_.pieces.size() >= kMaxOpenPieces)
            throw InputError("more than " + std::to_string(kMaxOpenPieces) + " open lines");
        out_.pieces.push_back({std::move(line), layer});
    }

    double scale_;
    Collected& out_;
};

std::string layerOf(const OGRFeature& feature) {
    const int field = feature.GetFieldIndex("Layer");
    return field >= 0 ? feature.GetFieldAsString(field) : std::string();
}

// The unit: the option, else $INSUNITS, else metres with a warning.
double unitScale(const std::string& path, const ImportOptions& options,
                 std::vector<std::string>& warnings) {
    if (options.metresPerUnit)
        return *options.metresPerUnit;
    const int code = readInsunits(path);
    const double metres = metresOfInsunits(code);
    if (metres > 0)
        return metres;
    warnings.push_back(code < 0 ? "no $INSUNITS in the header: drawing units taken as metres"
                                : "$INSUNITS " + std::to_string(code) +
                                      " (unitless or unknown): drawing units taken as metres");
    return 1.0;
}

} // namespace

ImportResult importDxf(const std::string& path, const ImportOptions& options) {
    ImportResult result;
    const double scale = unitScale(path, options, result.warnings);
    DatasetPtr dataset = openDxf(path);
    Collected collected;
    Collector collector(scale, collected);
    OGRLayer* layer = dataset->GetLayer(0);
    layer->ResetReading();
    size_t entities = 0;
    std::map<std::string, size_t> ignored;
    while (std::unique_ptr<OGRFeature> feature{layer->GetNextFeature()}) {
        if (++entities > kMaxEntities)
            throw InputError("more than " + std::to_string(kMaxEntities) + " entities");
        const std::string name = layerOf(*feature);
        const OGRGeometry* geometry = feature->GetGeometryRef();
        const int textField = feature->GetFieldIndex("Text");
        if (geometry && wkbFlatten(geometry->getGeometryType()) == wkbPoint) {
            // Labels name rooms whatever their layer (text layers are usually "ignored").
            const std::string text = textField >= 0 ? feature->GetFieldAsString(textField) : "";
            const OGRPoint* p = geometry->toPoint();
            if (!text.empty())
                collected.labels.push_back({{p->getX() * scale, p->getY() * scale}, text});
            continue;
        }
        if (roleOfLayer(name, options.layers) == Role::Ignored)
            ++ignored[name];
        else
            collector.add(geometry, name);
    }
    if (entities == 0)
        throw InputError("the drawing has no entities");
    for (const auto& [name, count] : ignored)
        result.warnings.push_back("layer \"" + name + "\": " + std::to_string(count) +
                                  " entities ignored");
    if (collected.skipped > 0)
        result.warnings.push_back(std::to_string(collected.skipped) +
                                  " entities without usable 2D geometry skipped");
    std::vector<Outline> chained =
        closeChains(std::move(collected.pieces), options.gapTolerance, result.warnings);
    for (Outline& o : chained)
        collected.outlines.push_back(std::move(o));
    result.project.plan =
        assemblePlan(collected.outlines, collected.labels, options.layers, result.warnings);
    return result;
}

ImportPreview previewDxf(const std::string& path) {
    ImportPreview preview;
    preview.format = "dxf";
    const double metres = metresOfInsunits(readInsunits(path));
    if (metres > 0)
        preview.metresPerUnit = metres;
    DatasetPtr dataset = openDxf(path);
    OGRLayer* layer = dataset->GetLayer(0);
    layer->ResetReading();
    size_t entities = 0;
    while (std::unique_ptr<OGRFeature> feature{layer->GetNextFeature()}) {
        if (++entities > kMaxEntities)
            throw InputError("more than " + std::to_string(kMaxEntities) + " entities");
        const std::string name = layerOf(*feature);
        if (std::find(preview.layers.begin(), preview.layers.end(), name) == preview.layers.end())
            preview.layers.push_back(name);
    }
    return preview;
}

void ensureGdal() {
    static std::once_flag once;
    std::call_once(once, []() {
        GDALAllRegister();
        CPLSetErrorHandler(CPLQuietErrorHandler);
    });
}

} // namespace fc::importing
