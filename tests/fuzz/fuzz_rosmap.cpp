// libFuzzer: ROS occupancy maps. One input holds the map YAML, a line "%%", then the image
// bytes, written as both map.pgm and map.png next to map.yaml: the YAML's image: key picks
// the reader (the PGM reader here, or GDAL's PNG driver).
#include "FuzzSupport.h"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string yaml = fc::fuzz::scratchPath("map.yaml");
    static const std::string pgm = fc::fuzz::scratchPath("map.pgm");
    static const std::string png = fc::fuzz::scratchPath("map.png");
    const char* text = reinterpret_cast<const char*>(data);
    const char* separator = static_cast<const char*>(memmem(text, size, "\n%%\n", 4));
    const size_t yamlSize = separator ? static_cast<size_t>(separator - text) + 1 : size;
    const size_t imageStart = separator ? yamlSize + 3 : size;
    fc::fuzz::writeBytes(yaml, data, yamlSize);
    fc::fuzz::writeBytes(pgm, data + imageStart, size - imageStart);
    fc::fuzz::writeBytes(png, data + imageStart, size - imageStart);
    fc::fuzz::importExpectingOnlyInputErrors(yaml);
    return 0;
}
