// Shared by the importer tests: fixture locations, free area, files written on the fly.
#pragma once

#include "importers/Import.h"
#include "geometry/Geometry.h"

#include <filesystem>
#include <fstream>
#include <string>

namespace fc::test {

inline double freeArea(const Plan& plan) {
    return freeAreaOf(plan);
}

// A fresh folder under the system's temporary directory for one test.
inline std::filesystem::path scratchDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("fc-import-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string writeText(const std::filesystem::path& path, const std::string& contents) {
    std::ofstream(path, std::ios::binary) << contents;
    return path.string();
}

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The expected free area the fixture generator wrote for FILE (expected.txt).
inline double expectedArea(const std::string& file) {
    std::ifstream in(std::string(FC_IMPORT_FIXTURES_DIR) + "/expected.txt");
    std::string name;
    double area = 0;
    while (in >> name >> area)
        if (name == file)
            return area;
    return -1;
}

inline std::string fixture(const std::string& file) {
    return std::string(FC_IMPORT_FIXTURES_DIR) + "/" + file;
}

} // namespace fc::test
