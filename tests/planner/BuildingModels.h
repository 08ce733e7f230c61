// Small 3D building models written by the tests (and the fuzzer's seeds): cuboids saved as
// Wavefront OBJ (Y-up, one group per cuboid), ASCII STL (Z-up) or binary glTF (Y-up).
#pragma once

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fc::test {

struct Cuboid {
    std::string name;
    double x0, y0, h0, x1, y1, h1; // plan x, plan y, height
};

// A 10 m x 6 m room (inside) with 0.2 m walls 2.5 m high, a 0.5 m square pillar in the middle,
// and a room volume "kitchen" (its last cuboid): free area 60 - 0.25 = 59.75 m^2.
inline std::vector<Cuboid> pillarRoom() {
    return {{"wall-south", -0.2, -0.2, 0, 10.2, 0, 2.5}, {"wall-north", -0.2, 6, 0, 10.2, 6.2, 2.5},
            {"wall-west", -0.2, 0, 0, 0, 6, 2.5},        {"wall-east", 10, 0, 0, 10.2, 6, 2.5},
            {"pillar", 4.75, 2.75, 0, 5.25, 3.25, 2.5},  {"kitchen", 0, 0, 0, 10, 6, 2.5}};
}

// The 8 corners (plan x, plan y, height) and 12 outward-facing triangles of a cuboid.
inline std::vector<std::vector<double>> cuboidCorners(const Cuboid& c) {
    std::vector<std::vector<double>> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back({i & 1 ? c.x1 : c.x0, i & 2 ? c.y1 : c.y0, i & 4 ? c.h1 : c.h0});
    return corners;
}
constexpr int kCuboidTriangles[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                         {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                         {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};

inline std::string objText(const std::vector<Cuboid>& cuboids) {
    std::ostringstream out;
    int base = 1;
    for (const Cuboid& c : cuboids) {
        out << "o " << c.name << "\n";
        for (const auto& p : cuboidCorners(c)) // Y-up: (x, height, -y)
            out << "v " << p[0] << " " << p[2] << " " << -p[1] << "\n";
        for (const auto& t : kCuboidTriangles)
            out << "f " << base + t[0] << " " << base + t[1] << " " << base + t[2] << "\n";
        base += 8;
    }
    return out.str();
}

inline std::string stlText(const std::vector<Cuboid>& cuboids) {
    std::ostringstream out;
    out << "solid building\n";
    for (const Cuboid& c : cuboids) {
        const auto corners = cuboidCorners(c);
        for (const auto& t : kCuboidTriangles) {
            out << "facet normal 0 0 0\nouter loop\n";
            for (int k : t)
                out << "vertex " << corners[k][0] << " " << corners[k][1] << " " << corners[k][2]
                    << "\n";
            out << "endloop\nendfacet\n";
        }
    }
    out << "endsolid building\n";
    return out.str();
}

// Binary glTF 2 (Y-up): one node and mesh per cuboid, float positions, uint32 indices.
inline std::string glbBytes(const std::vector<Cuboid>& cuboids) {
    std::string bin;
    auto put = [&bin](const void* data, size_t size) {
        bin.append(static_cast<const char*>(data), size);
    };
    std::ostringstream nodes, meshes, accessors, views;
    for (size_t i = 0; i < cuboids.size(); ++i) {
        const auto corners = cuboidCorners(cuboids[i]);
        const size_t positions = bin.size();
        float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
        for (const auto& p : corners) {
            const float v[3] = {float(p[0]), float(p[2]), float(-p[1])};
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], v[k]);
                hi[k] = std::max(hi[k], v[k]);
            }
            put(v, sizeof v);
        }
        const size_t indices = bin.size();
        for (const auto& t : kCuboidTriangles)
            for (int k : t) {
                const uint32_t index = uint32_t(k);
                put(&index, sizeof index);
            }
        const char* sep = i ? "," : "";
        nodes << sep << "{\"name\":\"" << cuboids[i].name << "\",\"mesh\":" << i << "}";
        meshes << sep << "{\"primitives\":[{\"attributes\":{\"POSITION\":" << 2 * i
               << "},\"indices\":" << 2 * i + 1 << "}]}";
        accessors << sep << "{\"bufferView\":" << 2 * i
                  << ",\"componentType\":5126,\"count\":8,\"type\":\"VEC3\",\"min\":[" << lo[0]
                  << "," << lo[1] << "," << lo[2] << "],\"max\":[" << hi[0] << "," << hi[1] << ","
                  << hi[2] << "]},{\"bufferView\":" << 2 * i + 1
                  << ",\"componentType\":5125,\"count\":36,\"type\":\"SCALAR\"}";
        views << sep << "{\"buffer\":0,\"byteOffset\":" << positions
              << ",\"byteLength\":96},{\"buffer\":0,\"byteOffset\":" << indices
              << ",\"byteLength\":144}";
    }
    std::ostringstream json;
    json << "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[";
    for (size_t i = 0; i < cuboids.size(); ++i)
        json << (i ? "," : "") << i;
    json << "]}],\"nodes\":[" << nodes.str() << "],\"meshes\":[" << meshes.str()
         << "],\"accessors\":[" << accessors.str() << "],\"bufferViews\":[" << views.str()
         << "],\"buffers\":[{\"byteLength\":" << bin.size() << "}]}";
    std::string text = json.str();
    text.append((4 - text.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string glb;
    auto word = [&glb](uint32_t value) { glb.append(reinterpret_cast<const char*>(&value), 4); };
    word(0x46546C67); // "glTF"
    word(2);
    word(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    word(uint32_t(text.size()));
    word(0x4E4F534A); // "JSON"
    glb += text;
    word(uint32_t(bin.size()));
    word(0x004E4942); // "BIN"
    glb += bin;
    return glb;
}

inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

} // namespace fc::test
