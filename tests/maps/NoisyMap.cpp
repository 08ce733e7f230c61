#include "NoisyMap.h"

#include "geometry/SegmentIndex.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

namespace fc::test {

namespace {

constexpr unsigned char kFree = 254, kOccupied = 0, kUnknown = 205;

bool inFree(const Plan& plan, Vec2 p) {
    if (!pointInRing(plan.boundary, p))
        return false;
    return std::none_of(plan.obstacles.begin(), plan.obstacles.end(),
                        [&](const Ring& o) { return pointInRing(o, p); });
}

std::vector<Ring> wallsOf(const Plan& plan) {
    std::vector<Ring> rings{plan.boundary};
    rings.insert(rings.end(), plan.obstacles.begin(), plan.obstacles.end());
    return rings;
}

} // namespace

NoisyMap renderNoisyMap(const Plan& plan, const NoisyMapOptions& o) {
    NoisyMap map;
    map.resolution = o.resolution;
    const BoundingBox box = plan.bounds();
    const double margin = 5 * o.resolution + o.wallThickness;
    map.origin = {box.minX - margin, box.minY - margin};
    map.width = static_cast<int>(std::ceil((box.width() + 2 * margin) / o.resolution));
    map.height = static_cast<int>(std::ceil((box.height() + 2 * margin) / o.resolution));
    map.pixels.assign(static_cast<size_t>(map.width) * map.height, kUnknown);
    const SegmentIndex walls(wallsOf(plan));
    auto centre = [&](int x, int y) {
        return Vec2{map.origin.x + (x + 0.5) * o.resolution,
                    map.origin.y + (map.height - y - 0.5) * o.resolution};
    };
    auto at = [&](int x, int y) -> unsigned char& {
        return map.pixels[static_cast<size_t>(y) * map.width + x];
    };
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const Vec2 p = centre(x, y);
            if (inFree(plan, p))
                at(x, y) = kFree;
            else if (!walls.pointKeepsDistance(p, o.wallThickness))
                at(x, y) = kOccupied;
        }
    std::mt19937_64 rng(o.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < map.width && y < map.height; };
    // Ragged wall edges: cells where free meets occupied flip.
    std::vector<unsigned char> before = map.pixels;
    for (int y = 1; y + 1 < map.height; ++y)
        for (int x = 1; x + 1 < map.width; ++x) {
            const unsigned char v = before[static_cast<size_t>(y) * map.width + x];
            if (v == kUnknown)
                continue;
            bool edge = false;
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const unsigned char n = before[static_cast<size_t>(y + dy) * map.width + x + dx];
                edge |= (n == kFree) != (v == kFree) && n != kUnknown;
            }
            if (edge && unit(rng) < o.ragged)
                at(x, y) = v == kFree ? kOccupied : kFree;
        }
    // Speckle, missing patches, stray free returns.
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const unsigned char v = before[static_cast<size_t>(y) * map.width + x];
            if (v == kFree && unit(rng) < o.speckle) {
                const int size = 1 + static_cast<int>(unit(rng) * 2); // 1x1 or 2x2
                for (int dy = 0; dy < size; ++dy)
                    for (int dx = 0; dx < size; ++dx)
                        if (inside(x + dx, y + dy))
                            at(x + dx, y + dy) = kOccupied;
            } else if (v == kFree && unit(rng) < o.missing) {
                const int r = 1 + static_cast<int>(unit(rng) * 3);
                for (int dy = -r; dy <= r; ++dy)
                    for (int dx = -r; dx <= r; ++dx)
                        if (dx * dx + dy * dy <= r * r && inside(x + dx, y + dy) &&
                            map.pixels[static_cast<size_t>(y + dy) * map.width + x + dx] == kFree)
                            at(x + dx, y + dy) = kUnknown;
            } else if (v == kUnknown && unit(rng) < o.strayFree) {
                at(x, y) = kFree;
            }
        }
    return map;
}

std::string NoisyMap::write(const std::string& folder, const std::string& name) const {
    {
        std::ofstream pgm(folder + "/" + name + ".pgm", std::ios::binary);
        pgm << "P5\n" << width << " " << height << "\n255\n";
        pgm.write(reinterpret_cast<const char*>(pixels.data()),
                  static_cast<std::streamsize>(pixels.size()));
    }
    const std::string yaml = folder + "/" + name + ".yaml";
    std::ofstream out(yaml);
    out << "image: " << name << ".pgm\nresolution: " << resolution << "\norigin: [" << origin.x
        << ", " << origin.y << ", 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
    return yaml;
}

std::vector<double> roomIoUs(const Plan& truth, const std::vector<Room>& found, double resolution) {
    const BoundingBox box = truth.bounds();
    std::vector<std::vector<long long>> common(truth.rooms.size(),
                                               std::vector<long long>(found.size(), 0));
    std::vector<long long> trueCells(truth.rooms.size(), 0), foundCells(found.size(), 0);
    for (double y = box.minY + resolution / 2; y < box.maxY; y += resolution)
        for (double x = box.minX + resolution / 2; x < box.maxX; x += resolution) {
            const Vec2 p{x, y};
            if (!inFree(truth, p))
                continue;
            int t = -1, f = -1;
            for (size_t i = 0; i < truth.rooms.size() && t < 0; ++i)
                if (pointInRing(truth.rooms[i].outline, p))
                    t = static_cast<int>(i);
            for (size_t j = 0; j < found.size() && f < 0; ++j)
                if (pointInRing(found[j].outline, p))
                    f = static_cast<int>(j);
            if (t >= 0)
                ++trueCells[t];
            if (f >= 0)
                ++foundCells[f];
            if (t >= 0 && f >= 0)
                ++common[t][f];
        }
    std::vector<double> ious;
    for (size_t i = 0; i < truth.rooms.size(); ++i) {
        double best = 0;
        for (size_t j = 0; j < found.size(); ++j) {
            const double uni = static_cast<double>(trueCells[i] + foundCells[j] - common[i][j]);
            if (uni > 0)
                best = std::max(best, common[i][j] / uni);
        }
        ious.push_back(best);
    }
    return ious;
}

} // namespace fc::test
