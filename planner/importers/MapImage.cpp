// Occupancy-map images at any common bit depth: 1-, 8- and 16-bit greyscale, palette and
// colour PNG/BMP/TIFF through GDAL, each scaled to 0..255 so that map_server's thresholds
// apply unchanged (a 1-bit map's white is 255, not 1).
#include "formats/FileIO.h"
#include "importers/OgrSupport.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace fc::importing {

namespace {

// The largest value of the band's bit depth: its NBITS when the driver reports one
// (1-bit PNG), otherwise the data type's.
double fullScale(GDALRasterBand* band) {
    if (const char* bits = band->GetMetadataItem("NBITS", "IMAGE_STRUCTURE")) {
        const int n = std::atoi(bits);
        if (n >= 1 && n <= 16)
            return std::pow(2.0, n) - 1.0;
    }
    switch (band->GetRasterDataType()) {
    case GDT_Byte:
        return 255.0;
    case GDT_UInt16:
        return 65535.0;
    default:
        throw InputError("map image pixels are " +
                         std::string(GDALGetDataTypeName(band->GetRasterDataType())) +
                         " (expected 1- to 16-bit unsigned grey or colour)");
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
    std::vector<double> row(pixels), sum(pixels, 0.0);
    int colours = 0;
    for (int b = 1; b <= bands; ++b) {
        GDALRasterBand* band = dataset->GetRasterBand(b);
        const double scale = 255.0 / fullScale(band);
        if (band->RasterIO(GF_Read, 0, 0, image.width, image.height, row.data(), image.width,
                           image.height, GDT_Float64, 0, 0, nullptr) != CE_None)
            throw InputError(std::string("map image unreadable: ") + CPLGetLastErrorMsg());
        if (band->GetColorInterpretation() == GCI_AlphaBand) {
            image.alpha.resize(pixels);
            for (size_t i = 0; i < pixels; ++i)
                image.alpha[i] = static_cast<unsigned char>(std::lround(row[i] * scale));
            continue;
        }
        const GDALColorTable* palette = band->GetColorTable();
        if (band->GetColorInterpretation() == GCI_PaletteIndex && palette) {
            // Palette entries to grey (the mean of R, G, B); a transparent entry is unknown.
            image.alpha.assign(pixels, 255);
            for (size_t i = 0; i < pixels; ++i) {
                const GDALColorEntry* e = palette->GetColorEntry(static_cast<int>(row[i]));
                if (!e)
                    throw InputError("map image uses a colour missing from its palette");
                sum[i] += (e->c1 + e->c2 + e->c3) / 3.0;
                image.alpha[i] = static_cast<unsigned char>(e->c4);
            }
            ++colours;
            continue;
        }
        ++colours;
        for (size_t i = 0; i < pixels; ++i)
            sum[i] += std::clamp(row[i] * scale, 0.0, 255.0);
    }
    image.grey.resize(pixels);
    for (size_t i = 0; i < pixels; ++i)
        image.grey[i] = static_cast<unsigned char>(std::lround(sum[i] / std::max(colours, 1)));
    return image;
}

GreyImage readMapImage(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& ch : extension)
        ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (extension == ".pgm" || extension == ".pbm" || extension == ".pnm")
        return readPgm(readFile(path));
    return readImageWithGdal(path);
}

} // namespace fc::importing
