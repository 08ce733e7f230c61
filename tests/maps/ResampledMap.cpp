#include "ResampledMap.h"

#include "importers/ImportSupport.h"
#include "model/Plan.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

namespace fc::test {

std::string resampledMap(const std::string& yamlPath, Resample how, const std::string& folder) {
    std::ifstream yamlIn(yamlPath);
    std::string imageName;
    double resolution = 0.0;
    for (std::string line; std::getline(yamlIn, line);) {
        if (line.rfind("image:", 0) == 0)
            imageName = line.substr(line.find_first_not_of(' ', 6));
        else if (line.rfind("resolution:", 0) == 0)
            resolution = std::atof(line.c_str() + 11);
    }
    if (imageName.empty() || !(resolution > 0.0))
        throw InputError(yamlPath + ": no image or resolution");
    const std::filesystem::path source = std::filesystem::path(yamlPath).parent_path() / imageName;
    const importing::GreyImage image = importing::readMapImage(source.string());
    auto at = [&](int x, int y) -> int {
        if (x < 0 || y < 0 || x >= image.width || y >= image.height)
            return 205;
        const unsigned char v = image.grey[static_cast<size_t>(y) * image.width + x];
        return v >= 250 ? 254 : v <= 50 ? 0 : 205;
    };
    int w = image.width, h = image.height;
    double scale = 1.0;
    const double turn = 30.0 * M_PI / 180.0, c = std::cos(turn), s = std::sin(turn);
    if (how == Resample::Finer) {
        w *= 2, h *= 2, scale = 0.5;
    } else if (how == Resample::Coarser) {
        w /= 2, h /= 2, scale = 2.0;
    } else {
        w = static_cast<int>(image.width * c + image.height * s) + 1;
        h = static_cast<int>(image.width * s + image.height * c) + 1;
    }
    std::vector<unsigned char> out(static_cast<size_t>(w) * h, 205);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int v = 205;
            if (how == Resample::Finer) {
                v = at(x / 2, y / 2);
            } else if (how == Resample::Coarser) {
                bool occupied = false, free = false;
                for (int k = 0; k < 4; ++k) {
                    const int u = at(2 * x + k % 2, 2 * y + k / 2);
                    occupied |= u == 0;
                    free |= u == 254;
                }
                v = occupied ? 0 : free ? 254 : 205;
            } else {
                // The output cell's centre, turned back about the centre onto the input.
                const double ox = x + 0.5 - 0.5 * w, oy = y + 0.5 - 0.5 * h;
                v = at(static_cast<int>(std::floor(c * ox + s * oy + 0.5 * image.width)),
                       static_cast<int>(std::floor(-s * ox + c * oy + 0.5 * image.height)));
            }
            out[static_cast<size_t>(y) * w + x] = static_cast<unsigned char>(v);
        }
    const char* tag = how == Resample::Finer     ? "-finer"
                      : how == Resample::Coarser ? "-coarser"
                                                 : "-turned";
    const std::string stem = source.stem().string() + tag;
    std::filesystem::create_directories(folder);
    const std::filesystem::path dir(folder);
    std::ofstream pgm(dir / (stem + ".pgm"), std::ios::binary);
    pgm << "P5\n" << w << " " << h << "\n255\n";
    pgm.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
    const std::filesystem::path yaml = dir / (stem + ".yaml");
    std::ofstream(yaml) << "image: " << stem
                        << ".pgm\nmode: trinary\nresolution: " << resolution * scale
                        << "\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
                           "free_thresh: 0.196\n";
    return yaml.string();
}

} // namespace fc::test
