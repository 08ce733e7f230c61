#include "PlanGenerator.h"

#include "model/SyntheticPlans.h"
#include "model/Validation.h"

// Boost.Geometry's envelope code trips GCC 12's -Wmaybe-uninitialized (a false positive
// inside the library).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

namespace fcgen {
namespace {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;
using BMulti = bg::model::multi_polygon<BPolygon>;

using fc::Plan;
using fc::Ring;
using fc::Vec2;

constexpr double kPi = 3.14159265358979323846;

class Rng {
public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(engine_);
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }
    std::uint64_t next() { return engine_(); }

private:
    std::mt19937_64 engine_;
};

BPolygon toPolygon(const Ring& ring) {
    BPolygon p;
    for (const Vec2& v : ring)
        p.outer().push_back(BPoint(v.x, v.y));
    p.outer().push_back(p.outer().front());
    bg::correct(p);
    return p;
}

Ring toRing(const bg::model::ring<BPoint>& r) {
    Ring out;
    for (std::size_t i = 0; i + 1 < r.size(); ++i) // Boost rings repeat the first point
        out.push_back({r[i].x(), r[i].y()});
    return out;
}

Ring rect(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

template <typename Geometry> void unite(BMulti& acc, const Geometry& g) {
    BMulti out;
    bg::union_(acc, g, out);
    acc.swap(out);
}

template <typename Geometry> void subtract(BMulti& acc, const Geometry& g) {
    BMulti out;
    bg::difference(acc, g, out);
    acc.swap(out);
}

// A free space built as a Boost region becomes the plan's boundary and holes; a region in
// several pieces is a failed draw.
bool setFreeSpace(Plan& plan, BMulti free) {
    bg::correct(free);
    if (free.size() != 1)
        return false;
    plan.boundary = toRing(free.front().outer());
    for (const auto& inner : free.front().inners())
        plan.obstacles.push_back(toRing(inner));
    return true;
}

Ring regularPolygon(Vec2 centre, double radius, int sides, double phase) {
    Ring r;
    for (int k = 0; k < sides; ++k) {
        const double a = phase + 2.0 * kPi * k / sides;
        r.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    }
    return r;
}

// A random convex polygon: the hull of 5-8 points in a disc of the given radius.
Ring convexBlob(Rng& rng, Vec2 centre, double radius) {
    bg::model::multi_point<BPoint> points;
    const int n = rng.integer(5, 8);
    for (int i = 0; i < n; ++i) {
        const double a = rng.uniform(0.0, 2.0 * kPi), r = radius * std::sqrt(rng.uniform(0.2, 1.0));
        bg::append(points, BPoint(centre.x + r * std::cos(a), centre.y + r * std::sin(a)));
    }
    BPolygon hull;
    bg::convex_hull(points, hull);
    return toRing(hull.outer());
}

// Places obstacles inside `free` (a polygon) at a random gap from walls and from each
// other; returns the obstacles placed. `make` draws one obstacle around a centre.
template <typename Make>
std::vector<Ring> placeObstacles(Rng& rng, const BPolygon& free, int count, Make make,
                                 double minGap = 0.2) {
    bg::model::box<BPoint> box;
    bg::envelope(free, box);
    std::vector<Ring> placed;
    std::vector<BPolygon> shapes;
    const bg::model::linestring<BPoint> walls(free.outer().begin(), free.outer().end());
    for (int tries = 0; static_cast<int>(placed.size()) < count && tries < 200; ++tries) {
        const Vec2 c{rng.uniform(box.min_corner().x(), box.max_corner().x()),
                     rng.uniform(box.min_corner().y(), box.max_corner().y())};
        const Ring ring = make(c);
        const BPolygon shape = toPolygon(ring);
        const double gap = rng.uniform(minGap, std::max(minGap, 1.5));
        if (!bg::within(shape, free) || bg::distance(shape, walls) < gap)
            continue;
        bool clear = true;
        for (const BPolygon& other : shapes)
            clear = clear && bg::distance(shape, other) >= gap;
        for (const auto& inner : free.inners())
            clear = clear && bg::distance(shape, inner) >= gap;
        if (!clear)
            continue;
        placed.push_back(ring);
        shapes.push_back(shape);
    }
    return placed;
}

Ring roundPillar(Rng& rng, Vec2 c) {
    return regularPolygon(c, rng.uniform(0.15, 0.5), rng.integer(24, 48), rng.uniform(0, kPi));
}

Ring slantedBox(Rng& rng, Vec2 c) {
    const double w = rng.uniform(0.4, 1.6), h = rng.uniform(0.4, 1.2), a = rng.uniform(0, kPi);
    Ring r;
    for (const Vec2& corner : {Vec2{-w, -h}, Vec2{w, -h}, Vec2{w, h}, Vec2{-w, h}})
        r.push_back({c.x + 0.5 * (corner.x * std::cos(a) - corner.y * std::sin(a)),
                     c.y + 0.5 * (corner.x * std::sin(a) + corner.y * std::cos(a))});
    return r;
}

double doorWidth(Rng& rng, const fc::RobotProfile& robot) {
    return rng.uniform(1.05 * robot.robotDiameter, 2.0 * robot.coverageWidth);
}

// 2-4 rooms in a row, joined by one door per wall.
bool drawDoorRooms(Rng& rng, const fc::RobotProfile& robot, Plan& plan, std::string& what) {
    const int rooms = rng.integer(2, 4);
    const double height = rng.uniform(3.0, 6.0);
    BMulti free;
    std::ostringstream doors;
    doors.precision(3);
    double x = 0.0;
    std::vector<BPolygon> openings;
    for (int i = 0; i < rooms; ++i) {
        const double width = rng.uniform(3.0, 6.0);
        unite(free, toPolygon(rect(x, 0, x + width, height)));
        plan.rooms.push_back({"R" + std::to_string(i + 1), rect(x, 0, x + width, height)});
        if (rng.chance(0.5)) { // a desk
            const double w = rng.uniform(0.6, 1.5), h = rng.uniform(0.6, 1.5);
            const double gx = rng.uniform(0.15, 1.2), gy = rng.uniform(0.15, 1.2);
            if (w + 2 * gx < width && h + 2 * gy < height) {
                const double dx = x + gx + rng.uniform(0, width - w - 2 * gx);
                const double dy = gy + rng.uniform(0, height - h - 2 * gy);
                plan.obstacles.push_back(rect(dx, dy, dx + w, dy + h));
            }
        }
        x += width;
        if (i + 1 < rooms) {
            const double wall = rng.uniform(0.1, 0.25);
            const double door = std::min(doorWidth(rng, robot), height);
            // Flush with a corner in a fifth of the walls.
            const double y0 = rng.chance(0.2) ? (rng.chance(0.5) ? 0.0 : height - door)
                                              : rng.uniform(0.0, height - door);
            openings.push_back(toPolygon(rect(x - 0.01, y0, x + wall + 0.01, y0 + door)));
            unite(free, openings.back());
            doors << (i ? "," : "") << door;
            x += wall;
        }
    }
    // A desk closer to a door than the robot is wide shuts the room behind it (seed 105: a
    // desk 0.4 m from a 0.8 m door's jamb left 17.7 m^2 unreachable); the doors are what this
    // family tests, so such a desk is left out (the other draws are unchanged).
    plan.obstacles.erase(
        std::remove_if(plan.obstacles.begin(), plan.obstacles.end(),
                       [&](const Ring& desk) {
                           const BPolygon shape = toPolygon(desk);
                           return std::any_of(
                               openings.begin(), openings.end(), [&](const BPolygon& opening) {
                                   return bg::distance(shape, opening) < 1.05 * robot.robotDiameter;
                               });
                       }),
        plan.obstacles.end());
    what = std::to_string(rooms) + " rooms, doors " + doors.str() + " m";
    return setFreeSpace(plan, free);
}

// A convex polygon split by a slanted wall with a door.
bool drawSlantedRooms(Rng& rng, const fc::RobotProfile& robot, Plan& plan, std::string& what) {
    const double rx = rng.uniform(4.0, 8.0), ry = rng.uniform(3.0, 6.0);
    bg::model::multi_point<BPoint> points;
    const int n = rng.integer(5, 9);
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * kPi * (i + rng.uniform(0.0, 0.8)) / n;
        bg::append(points, BPoint(rx * std::cos(a), ry * std::sin(a)));
    }
    BPolygon hull;
    bg::convex_hull(points, hull);
    // The wall: a strip through a point near the centre, at an angle that is not a
    // multiple of 90 degrees of anything in particular.
    const double angle = rng.uniform(0.0, kPi), thickness = rng.uniform(0.1, 0.3);
    const Vec2 dir{std::cos(angle), std::sin(angle)}, normal{-dir.y, dir.x};
    const Vec2 centre{rng.uniform(-0.3, 0.3) * rx, rng.uniform(-0.3, 0.3) * ry};
    const double reach = 4.0 * (rx + ry);
    auto strip = [&](double from, double to, double halfWidth) {
        Ring r;
        for (const Vec2& p :
             {centre + dir * from - normal * halfWidth, centre + dir * to - normal * halfWidth,
              centre + dir * to + normal * halfWidth, centre + dir * from + normal * halfWidth})
            r.push_back(p);
        return toPolygon(r);
    };
    // The chord of the hull along the wall line: where the door can go.
    bg::model::linestring<BPoint> line{BPoint((centre - dir * reach).x, (centre - dir * reach).y),
                                       BPoint((centre + dir * reach).x, (centre + dir * reach).y)};
    bg::model::multi_linestring<bg::model::linestring<BPoint>> chord;
    bg::intersection(line, hull, chord);
    if (chord.size() != 1 || chord.front().size() < 2)
        return false;
    const Vec2 a{chord.front().front().x(), chord.front().front().y()};
    const Vec2 b{chord.front().back().x(), chord.front().back().y()};
    const double t0 = fc::dot(a - centre, dir), t1 = fc::dot(b - centre, dir);
    const double lo = std::min(t0, t1), hi = std::max(t0, t1);
    const double door = doorWidth(rng, robot);
    if (hi - lo < door + 1.0)
        return false;
    const double doorStart = rng.uniform(lo + 0.5, hi - 0.5 - door);
    BMulti free{hull};
    subtract(free, strip(-reach, doorStart, 0.5 * thickness));
    subtract(free, strip(doorStart + door, reach, 0.5 * thickness));
    // Rooms: the two sides of the wall line.
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? 1.0 : -1.0;
        Ring half;
        for (const Vec2& p : {centre - dir * reach, centre + dir * reach,
                              centre + dir * reach + normal * (s * reach),
                              centre - dir * reach + normal * (s * reach)})
            half.push_back(p);
        BMulti part;
        bg::intersection(hull, toPolygon(half), part);
        if (part.size() != 1)
            return false;
        plan.rooms.push_back({side == 0 ? "Left" : "Right", toRing(part.front().outer())});
    }
    if (!setFreeSpace(plan, free))
        return false;
    if (rng.chance(0.6)) {
        const BPolygon room = toPolygon(plan.boundary);
        for (Ring& r : placeObstacles(
                 rng, room, 1, [&](Vec2 c) { return convexBlob(rng, c, rng.uniform(0.4, 1.2)); }))
            plan.obstacles.push_back(r);
    }
    std::ostringstream s;
    s.precision(3);
    s << n << "-gon, wall " << angle * 180.0 / kPi << " deg, door " << door << " m";
    what = s.str();
    return true;
}

bool drawStarRoom(Rng& rng, Plan& plan, std::string& what) {
    const int n = rng.integer(7, 14);
    const double radius = rng.uniform(5.0, 8.0);
    Ring boundary;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * kPi * (k + rng.uniform(-0.3, 0.3)) / n;
        const double r = radius * rng.uniform(0.55, 1.0);
        boundary.push_back({r * std::cos(a), r * std::sin(a)});
    }
    plan.boundary = boundary;
    const BPolygon room = toPolygon(boundary);
    if (!bg::is_valid(room))
        return false;
    const int blobs = rng.integer(1, 3), pillars = rng.integer(1, 3);
    for (Ring& r : placeObstacles(
             rng, room, blobs, [&](Vec2 c) { return convexBlob(rng, c, rng.uniform(0.4, 1.2)); }))
        plan.obstacles.push_back(r);
    BPolygon withHoles = room;
    for (const Ring& o : plan.obstacles)
        withHoles.inners().push_back(toPolygon(o).outer());
    bg::correct(withHoles);
    for (Ring& r :
         placeObstacles(rng, withHoles, pillars, [&](Vec2 c) { return roundPillar(rng, c); }))
        plan.obstacles.push_back(r);
    what =
        std::to_string(n) + "-point star, " + std::to_string(plan.obstacles.size()) + " obstacles";
    return true;
}

bool drawPillarHall(Rng& rng, Plan& plan, std::string& what) {
    const double w = rng.uniform(8.0, 16.0), h = rng.uniform(6.0, 12.0);
    plan.boundary = rect(0, 0, w, h);
    BPolygon hall = toPolygon(plan.boundary);
    const int count = rng.integer(2, 6);
    for (int i = 0; i < count; ++i) {
        const int kind = rng.integer(0, 2);
        for (Ring& r : placeObstacles(rng, hall, 1, [&](Vec2 c) {
                 return kind == 0   ? roundPillar(rng, c)
                        : kind == 1 ? convexBlob(rng, c, rng.uniform(0.4, 1.2))
                                    : slantedBox(rng, c);
             })) {
            plan.obstacles.push_back(r);
            hall.inners().push_back(toPolygon(r).outer());
            bg::correct(hall);
        }
    }
    std::ostringstream s;
    s.precision(3);
    s << w << " x " << h << " m hall, " << plan.obstacles.size() << " obstacles";
    what = s.str();
    return true;
}

// Points on an arc from angle a0 to a1 (radians, either direction), both ends included, at
// most `segment` metres apart: CAD exports write arcs from 5 cm to 1 m per segment.
std::vector<Vec2> arcPoints(Vec2 centre, double radius, double a0, double a1, double segment) {
    const int steps =
        std::max(2, static_cast<int>(std::ceil(std::abs(a1 - a0) * radius / segment)));
    std::vector<Vec2> out;
    for (int k = 0; k <= steps; ++k) {
        const double a = a0 + (a1 - a0) * k / steps;
        out.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    }
    return out;
}

Ring circle(Vec2 centre, double radius, double segment) {
    Ring r = arcPoints(centre, radius, 0.0, 2.0 * kPi, segment);
    r.pop_back(); // the first point again
    return r;
}

// A rectangle [0,w] x [0,h] whose corners are rounded by the given radii (0 = sharp),
// counter-clockwise from the lower left.
Ring roundedRect(double w, double h, const double (&radius)[4], double segment) {
    const Vec2 corners[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
    const Vec2 inward[4] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    const double start[4] = {kPi, 1.5 * kPi, 0.0, 0.5 * kPi};
    Ring r;
    for (int i = 0; i < 4; ++i) {
        if (radius[i] <= 0.0) {
            r.push_back(corners[i]);
            continue;
        }
        const Vec2 c = corners[i] + inward[i] * radius[i];
        for (const Vec2& p : arcPoints(c, radius[i], start[i], start[i] + 0.5 * kPi, segment))
            r.push_back(p);
    }
    return r;
}

// Round and curved walls, drawn as CAD exports write them (arcs as chains of 5 cm to 1 m
// segments): a rotunda with an annex, a curved corridor with rooms off it, a hall with
// rounded corners and an apse, or a hall whose corner is a concave quarter circle.
bool drawRoundWalls(Rng& rng, const fc::RobotProfile& robot, Plan& plan, std::string& what) {
    const double segment = std::exp(rng.uniform(std::log(0.05), std::log(1.0)));
    const int variant = rng.integer(0, 3);
    std::ostringstream s;
    s.precision(3);
    BMulti free;
    if (variant == 0) { // rotunda + annex through a door
        const double radius = rng.uniform(3.5, 8.0), wall = rng.uniform(0.1, 0.3);
        const Ring hall = circle({0, 0}, radius, segment);
        unite(free, toPolygon(hall));
        plan.rooms.push_back({"Rotunda", hall});
        const double aw = rng.uniform(3.0, 6.0), ad = rng.uniform(3.0, 5.0);
        const double door = std::min(doorWidth(rng, robot), aw - 0.2);
        const Ring annex = rect(radius + wall, -0.5 * aw, radius + wall + ad, 0.5 * aw);
        unite(free, toPolygon(annex));
        plan.rooms.push_back({"Annex", annex});
        const double y0 = rng.uniform(-0.5 * aw, 0.5 * aw - door);
        unite(free, toPolygon(rect(radius - 0.5, y0, radius + wall + 0.01, y0 + door)));
        if (rng.chance(0.5)) // a central column, round and finely drawn
            plan.obstacles.push_back(
                circle({rng.uniform(-1, 1), rng.uniform(-1, 1)}, rng.uniform(0.3, 1.5), segment));
        s << "rotunda r " << radius << " m, door " << door << " m";
    } else if (variant == 1) { // curved corridor with rooms on its outer side
        const double inner = rng.uniform(3.0, 8.0), width = rng.uniform(1.2, 3.0);
        const double sweep = rng.uniform(kPi / 3.0, 1.1 * kPi), wall = rng.uniform(0.1, 0.25);
        Ring corridor = arcPoints({0, 0}, inner + width, 0.0, sweep, segment);
        for (const Vec2& p : arcPoints({0, 0}, inner, sweep, 0.0, segment))
            corridor.push_back(p);
        unite(free, toPolygon(corridor));
        plan.rooms.push_back({"Corridor", corridor});
        const int rooms = rng.integer(1, 3);
        for (int i = 0; i < rooms; ++i) {
            const double a = sweep * (i + 0.5) / rooms, rw = rng.uniform(2.5, 4.5);
            const double rd = rng.uniform(2.5, 4.0), r0 = inner + width + wall;
            if (rw > 0.9 * (inner + width) * sweep / rooms)
                continue; // rooms would overlap
            const Vec2 u{std::cos(a), std::sin(a)}, t{-u.y, u.x};
            auto box = [&](double from, double to, double half) {
                return Ring{u * from - t * half, u * to - t * half, u * to + t * half,
                            u * from + t * half};
            };
            const Ring room = box(r0, r0 + rd, 0.5 * rw);
            unite(free, toPolygon(room));
            plan.rooms.push_back({"Room " + std::to_string(i + 1), room});
            const double door = std::min(doorWidth(rng, robot), rw - 0.2);
            const double off = rng.uniform(-0.5 * rw, 0.5 * rw - door) + 0.5 * door;
            Ring d = box(inner + width - 0.3, r0 + 0.01, 0.5 * door);
            for (Vec2& p : d)
                p = p + t * off;
            unite(free, toPolygon(d));
        }
        s << "curved corridor r " << inner << "-" << inner + width << " m over "
          << sweep * 180.0 / kPi << " deg";
    } else if (variant == 2) { // rounded corners, an apse on one side
        const double w = rng.uniform(6.0, 14.0), h = rng.uniform(5.0, 10.0);
        double radii[4];
        for (double& r : radii)
            r = rng.chance(0.3) ? 0.0 : rng.uniform(0.3, std::min(3.0, 0.4 * h));
        unite(free, toPolygon(roundedRect(w, h, radii, segment)));
        const double apse = rng.uniform(1.0, 0.45 * h);
        if (rng.chance(0.6)) {
            Ring half = arcPoints({w, 0.5 * h}, apse, -0.5 * kPi, 0.5 * kPi, segment);
            half.push_back({w - 0.5, 0.5 * h + apse});
            half.push_back({w - 0.5, 0.5 * h - apse});
            unite(free, toPolygon(half));
            s << "apse r " << apse << " m, ";
        }
        s << w << " x " << h << " m hall, rounded corners";
    } else { // a concave quarter circle at a corner, a round stair well near a wall
        const double w = rng.uniform(7.0, 14.0), h = rng.uniform(6.0, 10.0);
        unite(free, toPolygon(rect(0, 0, w, h)));
        const double cut = rng.uniform(1.0, 0.6 * h);
        Ring quarter = arcPoints({w, h}, cut, kPi, 1.5 * kPi, segment);
        quarter.push_back({w + 1, h - cut});
        quarter.push_back({w + 1, h + 1});
        quarter.push_back({w - cut, h + 1});
        subtract(free, toPolygon(quarter));
        s << w << " x " << h << " m hall, concave corner r " << cut << " m";
    }
    if (!setFreeSpace(plan, free))
        return false;
    // A round stair well or pillars, at 1.05 L to 1.5 m from the walls and each other: never
    // across a door or a corridor (a room behind a pillar is another test's pocket).
    BPolygon withHoles = toPolygon(plan.boundary);
    for (const Ring& o : plan.obstacles)
        withHoles.inners().push_back(toPolygon(o).outer());
    bg::correct(withHoles);
    const int pillars = rng.integer(0, 2);
    for (Ring& r : placeObstacles(
             rng, withHoles, pillars,
             [&](Vec2 c) { return circle(c, rng.uniform(0.2, 1.8), segment); },
             1.05 * robot.robotDiameter))
        plan.obstacles.push_back(r);
    s << ", arcs of " << segment << " m segments, " << plan.obstacles.size() << " obstacles";
    what = s.str();
    return true;
}

// One draw of the family's shape (not yet rotated or shifted); false = draw again.
bool drawShape(Family family, Rng& rng, const fc::RobotProfile& robot, Plan& plan,
               std::string& what) {
    switch (family) {
    case Family::RotatedOffice: {
        const int rooms = rng.integer(2, 6);
        plan = fc::generateOfficeFloor(rooms, rng.next());
        what = std::to_string(rooms) + "-room office";
        return true;
    }
    case Family::DoorRooms:
        return drawDoorRooms(rng, robot, plan, what);
    case Family::SlantedRooms:
        return drawSlantedRooms(rng, robot, plan, what);
    case Family::StarRoom:
        return drawStarRoom(rng, plan, what);
    case Family::PillarHall:
        return drawPillarHall(rng, plan, what);
    case Family::RoundWalls:
        return drawRoundWalls(rng, robot, plan, what);
    }
    return false;
}

} // namespace

std::vector<Family> allFamilies() {
    return {Family::RotatedOffice, Family::DoorRooms,  Family::SlantedRooms,
            Family::StarRoom,      Family::PillarHall, Family::RoundWalls};
}

const char* familyName(Family family) {
    switch (family) {
    case Family::RotatedOffice:
        return "rotated-office";
    case Family::DoorRooms:
        return "door-rooms";
    case Family::SlantedRooms:
        return "slanted-rooms";
    case Family::StarRoom:
        return "star-room";
    case Family::PillarHall:
        return "pillar-hall";
    case Family::RoundWalls:
        return "round-walls";
    }
    return "?";
}

fc::Plan transformPlan(const fc::Plan& plan, double angleDeg, fc::Vec2 offset) {
    const double a = angleDeg * kPi / 180.0, c = std::cos(a), s = std::sin(a);
    auto move = [&](Ring& ring) {
        for (Vec2& p : ring)
            p = Vec2{c * p.x - s * p.y + offset.x, s * p.x + c * p.y + offset.y};
    };
    fc::Plan out = plan;
    move(out.boundary);
    for (Ring& o : out.obstacles)
        move(o);
    for (fc::Room& r : out.rooms)
        move(r.outline);
    return out;
}

GeneratedPlan generatePlan(Family family, std::uint64_t seed, const fc::RobotProfile& robot) {
    // The case seed and the family pick the stream; each failed draw moves on in it.
    Rng rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(family) * 0x51ED27ULL + 7);
    std::string lastError;
    for (int attempt = 1; attempt <= 100; ++attempt) {
        Plan shape;
        std::string what;
        const bool drawn = drawShape(family, rng, robot, shape, what);
        const double angle = rng.uniform(0.0, 360.0);
        const bool utm = rng.chance(0.5);
        const Vec2 offset = utm ? Vec2{5e5 + rng.uniform(0.0, 1e5), 5.4e6 + rng.uniform(0.0, 1e5)}
                                : Vec2{rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0)};
        if (!drawn)
            continue;
        GeneratedPlan g;
        g.plan = transformPlan(shape, angle, offset);
        g.plan.name = std::string(familyName(family)) + "-" + std::to_string(seed);
        try {
            fc::validatePlan(fc::normalizedPlan(g.plan), robot);
        } catch (const fc::InputError& e) {
            lastError = e.what();
            continue;
        }
        g.family = family;
        g.seed = seed;
        g.rotationDeg = angle;
        g.offset = offset;
        g.attempts = attempt;
        std::ostringstream d;
        d.precision(10);
        d << familyName(family) << " seed " << seed << ": " << what << ", rotated ";
        d.precision(4);
        d << angle << " deg, offset (";
        d.precision(10);
        d << offset.x << ", " << offset.y << ")";
        g.description = d.str();
        return g;
    }
    throw std::runtime_error(std::string("plan generator: ") + familyName(family) + " seed " +
                             std::to_string(seed) +
                             " failed validation 100 times (last: " + lastError + ")");
}

std::vector<double> oddAngles(std::uint64_t seed, int count) {
    Rng rng(seed);
    std::vector<double> out;
    while (static_cast<int>(out.size()) < count) {
        const double a = std::round(rng.uniform(0.0, 360.0) * 10.0) / 10.0;
        const double offAxis = std::fmod(a, 45.0);
        if (offAxis > 1.0 && offAxis < 44.0)
            out.push_back(a);
    }
    return out;
}

fccheck::FreeSpace freeSpaceOf(const fc::Plan& plan) {
    auto ringOf = [](const Ring& r) {
        fccheck::RingXY out;
        for (const Vec2& p : r)
            out.push_back({p.x, p.y});
        return out;
    };
    fccheck::FreeSpace free;
    free.outer = ringOf(plan.boundary);
    for (const Ring& o : plan.obstacles)
        free.holes.push_back(ringOf(o));
    return free;
}

fccheck::PolylineXY polylineOf(const fc::Polyline& path) {
    fccheck::PolylineXY out;
    for (const Vec2& p : path)
        out.push_back({p.x, p.y});
    return out;
}

} // namespace fcgen
