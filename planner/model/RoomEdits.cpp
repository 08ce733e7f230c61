#include "model/RoomEdits.h"

#include "geometry/BoostGeometry.h"
#include "model/Plan.h"

#include <algorithm>
#include <cmath>

namespace fc {
namespace {

using namespace bgeo;

Ring toRing(const BPolygon& polygon, Vec2 origin) {
    Ring out;
    const auto& outer = polygon.outer();
    for (size_t i = 0; i + 1 < outer.size(); ++i)
        out.push_back({outer[i].x() + origin.x, outer[i].y() + origin.y});
    // Vertices the union left on a straight line (where the rooms' borders met).
    for (size_t i = 0; out.size() > 3 && i < out.size();) {
        const Vec2 a = out[(i + out.size() - 1) % out.size()], b = out[i],
                   c = out[(i + 1) % out.size()];
        if (std::abs(cross(b - a, c - b)) <=
                1e-12 * (norm(b - a) + norm(c - b)) * (norm(b - a) + norm(c - b)) &&
            dot(b - a, c - b) > 0)
            out.erase(out.begin() + static_cast<long>(i));
        else
            ++i;
    }
    return out;
}

BMulti merged(const BPolygon& a, const BPolygon& b) {
    BMulti out;
    bg::union_(a, b, out);
    return out;
}

} // namespace

Ring mergedRoomOutline(const Ring& first, const Ring& second) {
    if (first.size() < 3 || second.size() < 3)
        throw InputError("a room to merge has fewer than 3 corners");
    const Vec2 origin = first.front();
    const BPolygon a = toPolygon(first, origin), b = toPolygon(second, origin);
    // Rooms drawn or traced side by side share a wall within a few millimetres, not
    // exactly: each is grown by 5 mm for the test and the union.
    const double grow = 0.005;
    BMulti grownA, grownB;
    const bg::strategy::buffer::distance_symmetric<double> by(grow);
    const bg::strategy::buffer::side_straight side;
    const bg::strategy::buffer::join_miter join;
    const bg::strategy::buffer::end_flat end;
    const bg::strategy::buffer::point_square point;
    bg::buffer(a, grownA, by, side, join, end, point);
    bg::buffer(b, grownB, by, side, join, end, point);
    BMulti overlap;
    bg::intersection(grownA, grownB, overlap);
    // Touching along a border makes a strip 2 * grow wide; a border at least 10 cm long.
    if (bg::area(overlap) < 2 * grow * 0.1)
        throw InputError("the rooms do not share a border; merge rooms that meet along a "
                         "wall or a doorway");
    BMulti exact = merged(a, b);
    if (exact.size() != 1) {
        // Apart by less than the growth: join through the grown shapes, then shrink back.
        BMulti joined;
        bg::union_(grownA, grownB, joined);
        const bg::strategy::buffer::distance_symmetric<double> back(-grow);
        exact.clear();
        bg::buffer(joined, exact, back, side, join, end, point);
    }
    if (exact.size() != 1)
        throw InputError("the merged room would be in several pieces");
    // Slivers between borders that nearly meet are not holes.
    auto& inners = exact.front().inners();
    inners.erase(std::remove_if(inners.begin(), inners.end(),
                                [](const auto& inner) { return std::abs(bg::area(inner)) < 0.05; }),
                 inners.end());
    if (!inners.empty())
        throw InputError("the merged room would enclose a hole; merge the room inside it too");
    return toRing(exact.front(), origin);
}

std::pair<Ring, Ring> splitRoomOutline(const Ring& outline, Vec2 from, Vec2 to) {
    if (outline.size() < 3)
        throw InputError("the room has fewer than 3 corners");
    const double length = distance(from, to);
    if (!(length > 1e-6) || !std::isfinite(length))
        throw InputError("draw the cut as a line across the room");
    // Clipped by hand, not by a library: both parts must share the cut's two points exactly,
    // or a sliver between them would belong to no room.
    const Vec2 u = (to - from) * (1.0 / length);
    const size_t n = outline.size();
    std::vector<double> side(n);
    for (size_t i = 0; i < n; ++i)
        side[i] = cross(u, outline[i] - from); // > 0: left of the cut
    auto left = [&](size_t i) { return side[i] > 0; };
    int crossings = 0;
    for (size_t i = 0; i < n; ++i)
        crossings += left(i) != left((i + 1) % n);
    if (crossings == 0)
        throw InputError("the cut does not cross the room");
    if (crossings > 2)
        throw InputError("the cut crosses the room more than once; draw it where one straight "
                         "line divides the room in two");
    std::pair<Ring, Ring> out;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        (left(i) ? out.first : out.second).push_back(outline[i]);
        if (left(i) != left(j)) {
            const double t = side[i] / (side[i] - side[j]);
            const Vec2 cut = outline[i] + (outline[j] - outline[i]) * t;
            out.first.push_back(cut);
            out.second.push_back(cut);
        }
    }
    const double whole = ringArea(outline);
    for (Ring* part : {&out.first, &out.second}) {
        part->erase(std::unique(part->begin(), part->end(),
                                [](Vec2 a, Vec2 b) { return distance(a, b) < 1e-12; }),
                    part->end());
        const double area = part->size() >= 3 ? ringArea(*part) : 0.0;
        if (area < 0.01 * whole && area < 0.05)
            throw InputError("the cut would leave a sliver of the room; draw it across the room");
    }
    return out;
}

} // namespace fc
