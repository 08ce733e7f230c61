// ROS map_server occupancy maps: the free pixels traced into polygons with GDAL's
// polygonizer, opened by a twentieth of a pixel (so that obstacles touching the wall at a corner
// become part of it), simplified (Douglas-Peucker, topology kept) and placed in map
// coordinates (origin + resolution, y up, rotated by the origin's yaw).
#include "formats/FileIO.h"
#include "importers/OgrSupport.h"

#include <cmath>
#include <filesystem>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <memory>
#include <ogrsf_frmts.h>

namespace fc::importing {

namespace {

constexpr long long kMaxTracedPolygons = 200000;
constexpr double kOpening = 0.05; // pixels

// map_server's rule: p = (255 - grey) / 255 (or grey / 255 with negate); free below
// free_thresh (trinary, scale; scale also needs an opaque pixel); raw: free where grey is 0.
std::vector<unsigned char> freeMask(const GreyImage& image, const RosMapInfo& info) {
    std::vector<unsigned char> mask(image.grey.size(), 0);
    for (size_t i = 0; i < mask.size(); ++i) {
        const double grey = image.grey[i];
        if (info.mode == "raw") {
            mask[i] = grey == 0;
            continue;
        }
        const double p = info.negate ? grey / 255.0 : (255.0 - grey) / 255.0;
        const bool transparent = !image.alpha.empty() && image.alpha[i] < 255;
        mask[i] = p < info.freeThresh && !(info.mode == "scale" && transparent);
    }
    return mask;
}

int cancelWhenHuge(double, const char*, void* layer) {
    return static_cast<OGRLayer*>(layer)->GetFeatureCount(FALSE) < kMaxTracedPolygons;
}

// The free pixels as one (multi)polygon in pixel units (x right, y down).
GeometryPtr traceFree(const GreyImage& image, const std::vector<unsigned char>& mask) {
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("Memory");
    if (!mem || !memory)
        throw InputError("GDAL lacks its in-memory drivers");
    DatasetPtr raster(mem->Create("", image.width, image.height, 1, GDT_Byte, nullptr));
    GDALRasterBand* band = raster->GetRasterBand(1);
    if (band->RasterIO(GF_Write, 0, 0, image.width, image.height,
                       const_cast<unsigned char*>(mask.data()), image.width, image.height, GDT_Byte,
                       0, 0, nullptr) != CE_None)
        throw InputError("cannot hold the map image in memory");
    DatasetPtr vector(memory->Create("", 0, 0, 0, GDT_Unknown, nullptr));
    OGRLayer* layer = vector->CreateLayer("free", nullptr, wkbPolygon, nullptr);
    OGRFieldDefn field("free", OFTInteger);
    layer->CreateField(&field);
    if (GDALPolygonize(band, band, layer, 0, nullptr, cancelWhenHuge, layer) != CE_None)
        throw InputError(layer->GetFeatureCount(FALSE) >= kMaxTracedPolygons
                             ? "the free space is split into more than 200000 pieces"
                             : std::string("tracing the free space failed: ") +
                                   CPLGetLastErrorMsg());
    auto all = std::make_unique<OGRMultiPolygon>();
    layer->ResetReading();
    while (std::unique_ptr<OGRFeature> feature{layer->GetNextFeature()})
        if (OGRGeometry* g = feature->StealGeometry())
            all->addGeometryDirectly(g);
    if (all->IsEmpty())
        throw InputError("the map has no free space");
    return all;
}

void toMapFrame(std::vector<Polygon2>& polygons, const GreyImage& image, const RosMapInfo& info) {
    const double c = std::cos(info.yaw), s = std::sin(info.yaw);
    auto place = [&](Vec2& p) {
        const double x = p.x * info.resolution, y = (image.height - p.y) * info.resolution;
        p = {info.origin.x + c * x - s * y, info.origin.y + s * x + c * y};
    };
    for (Polygon2& polygon : polygons) {
        for (Vec2& p : polygon.shell)
            place(p);
        for (Ring& hole : polygon.holes)
            for (Vec2& p : hole)
                place(p);
    }
}

} // namespace

GreyImage readImageWithGdal(const std::string& path) {
    ensureGdal();
    const char* const drivers[] = {"PNG", "BMP", "GTiff", "PNM", nullptr};
    DatasetPtr dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, drivers,
                                         nullptr, nullptr));
    if (!dataset)
        throw InputError("map image " + std::filesystem::path(path).filename().string() +
                         " is not a readable PNG/PGM/BMP/TIFF");
    GreyImage image;
    image.width = dataset->GetRasterXSize();
    image.height = dataset->GetRasterYSize();
    const int bands = dataset->GetRasterCount();
    if (image.width < 1 || image.height < 1 || bands < 1)
        throw InputError("map image is empty");
    if (static_cast<long long>(image.width) * image.height > kMaxMapPixels)
        throw InputError("map image larger than " + std::to_string(kMaxMapPixels) + " pixels");
    const size_t pixels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    std::vector<unsigned char> row(pixels);
    std::vector<double> sum(pixels, 0.0);
    int colours = 0;
    for (int b = 1; b <= bands; ++b) {
        GDALRasterBand* band = dataset->GetRasterBand(b);
        if (band->RasterIO(GF_Read, 0, 0, image.width, image.height, row.data(), image.width,
                           image.height, GDT_Byte, 0, 0, nullptr) != CE_None)
            throw InputError(std::string("map image unreadable: ") + CPLGetLastErrorMsg());
        if (band->GetColorInterpretation() == GCI_AlphaBand) {
            image.alpha = row;
            continue;
        }
        ++colours;
        for (size_t i = 0; i < pixels; ++i)
            sum[i] += row[i];
    }
    image.grey.resize(pixels);
    for (size_t i = 0; i < pixels; ++i)
        image.grey[i] = static_cast<unsigned char>(std::lround(sum[i] / std::max(colours, 1)));
    return image;
}

ImportResult importRosMap(const std::string& yamlPath, const ImportOptions& options) {
    ensureGdal();
    const RosMapInfo info = parseRosMapYaml(readFile(yamlPath));
    const std::filesystem::path imagePath =
        std::filesystem::path(yamlPath).parent_path() / info.image;
    std::string extension = imagePath.extension().string();
    for (char& ch : extension)
        ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (!std::filesystem::is_regular_file(imagePath))
        throw InputError("map image " + info.image + " not found");
    const GreyImage image = extension == ".pgm" ? readPgm(readFile(imagePath.string()))
                                                : readImageWithGdal(imagePath.string());
    GeometryPtr free = traceFree(image, freeMask(image, info));
    // Douglas-Peucker on the pixel staircase (its corners exact), keeping the topology.
    const double tolerance = std::max(options.simplifyTolerance, 0.0) / info.resolution;
    if (tolerance > 0)
        free.reset(free->SimplifyPreserveTopology(tolerance));
    if (!free)
        throw InputError("simplifying the free space failed");
    // Opening by a twentieth of a pixel: a hole touching the outline at a pixel corner joins
    // it (the plan validation refuses rings that touch); convex corners are cut by 0.05
    // pixel, a negligible area.
    GeometryPtr simple(free->Buffer(-kOpening, 1));
    if (simple)
        simple.reset(simple->Buffer(kOpening, 1));
    if (!simple || simple->IsEmpty())
        throw InputError("the free space is thinner than a pixel everywhere");
    std::vector<Polygon2> polygons;
    collectPolygons(simple.get(), polygons);
    toMapFrame(polygons, image, info);
    ImportResult result;
    result.project.plan = planFromPolygons(std::move(polygons), "free space", result.warnings);
    result.robotStartPose = info.start;
    return result;
}

} // namespace fc::importing
