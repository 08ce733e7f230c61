#include "model/SyntheticPlans.h"

#include "geometry/BoostGeometry.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace fc {
namespace {

using namespace bgeo;

BPolygon box(double x0, double y0, double x1, double y1) {
    BPolygon p;
    bg::convert(bg::model::box<BPoint>(BPoint(x0, y0), BPoint(x1, y1)), p);
    bg::correct(p);
    return p;
}

// Boost's union_ must not write into one of its inputs.
template <typename Geometry> void unite(BMulti& acc, const Geometry& g) {
    BMulti out;
    bg::union_(acc, g, out);
    acc.swap(out);
}

Ring toRing(const bg::model::ring<BPoint>& r) {
    Ring out;
    for (size_t i = 0; i + 1 < r.size(); ++i) // Boost rings repeat the first point
        out.push_back({r[i].x(), r[i].y()});
    return out;
}

Ring rect(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

} // namespace

Plan generateOfficeFloor(int rooms, std::uint64_t seed) {
    const double roomW = 5.0, roomD = 8.0, wall = 0.2, corridor = 2.0, door = 1.2;
    const double spine = 2.5;
    const int perSide = std::max(1, static_cast<int>(std::ceil(std::sqrt(rooms / 2.0))));
    const int wings = std::max(1, static_cast<int>(std::ceil(rooms / (2.0 * perSide))));
    const double wingH = 2 * roomD + 2 * wall + corridor;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);

    Plan plan;
    plan.name = "office-" + std::to_string(rooms);
    BMulti free;
    unite(free, box(0, 0, spine, wings * wingH + (wings - 1) * wall));
    int made = 0;
    for (int w = 0; w < wings; ++w) {
        const double y0 = w * (wingH + wall);
        const double yc = y0 + roomD + wall; // corridor bottom
        BMulti wing;
        unite(wing, box(spine, yc, spine + perSide * (roomW + wall), yc + corridor));
        plan.rooms.push_back({"W" + std::to_string(w + 1) + "-Corridor",
                              rect(spine, yc, spine + perSide * (roomW + wall), yc + corridor)});
        for (int i = 0; i < perSide; ++i) {
            const double x0 = spine + wall + i * (roomW + wall);
            for (int side = 0; side < 2 && made < rooms; ++side, ++made) {
                const double ry0 = side == 0 ? y0 : yc + corridor + wall;
                const double ry1 = ry0 + roomD;
                unite(wing, box(x0, ry0, x0 + roomW, ry1));
                // The door: a gap in the wall between room and corridor.
                const double dx = x0 + 0.5 + unit(rng) * (roomW - door - 1.0);
                const double dy0 = side == 0 ? ry1 - 0.01 : yc + corridor - 0.01;
                unite(wing, box(dx, dy0, dx + door, dy0 + wall + 0.02));
                const std::string name =
                    "W" + std::to_string(w + 1) + (side ? "-N" : "-S") + std::to_string(i + 1);
                plan.rooms.push_back({name, rect(x0, ry0, x0 + roomW, ry1)});
                // Furniture: a desk block in most rooms, away from walls and the door.
                if (unit(rng) < 0.7) {
                    const double fw = 1.0 + unit(rng) * 1.0, fh = 1.0 + unit(rng) * 2.0;
                    const double fx = x0 + 1.2 + unit(rng) * (roomW - 2.4 - fw);
                    const double fy = ry0 + 1.5 + unit(rng) * (roomD - 3.0 - fh);
                    plan.obstacles.push_back(rect(fx, fy, fx + fw, fy + fh));
                }
            }
        }
        unite(free, wing);
        unite(free, box(spine - 0.01, yc, spine + 0.01, yc + corridor));
    }
    plan.rooms.push_back({"Spine", rect(0, 0, spine, wings * wingH + (wings - 1) * wall)});
    bg::correct(free);
    if (free.size() != 1)
        throw std::logic_error("office generator produced a disconnected floor");
    plan.boundary = toRing(free.front().outer());
    for (const auto& inner : free.front().inners())
        plan.obstacles.push_back(toRing(inner));
    return plan;
}

Plan generateHallWithObstacles(double width, double height, int obstacles, std::uint64_t seed) {
    Plan plan;
    plan.name = "hall";
    plan.boundary = rect(0, 0, width, height);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<BoundingBox> placed;
    int attempts = 0;
    while (static_cast<int>(placed.size()) < obstacles && attempts++ < 10000) {
        const double w = 2 + unit(rng) * 10, h = 2 + unit(rng) * 10;
        const double x = 3 + unit(rng) * (width - w - 6), y = 3 + unit(rng) * (height - h - 6);
        BoundingBox b;
        b.add({x, y});
        b.add({x + w, y + h});
        bool clear = true;
        for (const BoundingBox& o : placed) // keep 3 m between obstacles
            if (b.minX < o.maxX + 3 && o.minX < b.maxX + 3 && b.minY < o.maxY + 3 &&
                o.minY < b.maxY + 3)
                clear = false;
        if (!clear)
            continue;
        placed.push_back(b);
        if (unit(rng) < 0.5) {
            plan.obstacles.push_back(rect(x, y, x + w, y + h));
        } else { // a rotated box for slanted walls
            const double a = unit(rng) * M_PI / 2, cx = x + w / 2, cy = y + h / 2;
            const double r = 0.5 * std::min(w, h);
            Ring ring;
            for (int k = 0; k < 4; ++k)
                ring.push_back(
                    {cx + r * std::cos(a + k * M_PI / 2), cy + r * std::sin(a + k * M_PI / 2)});
            plan.obstacles.push_back(ring);
        }
    }
    return plan;
}

} // namespace fc
