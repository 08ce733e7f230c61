#include "geometry/SwathReach.h"

#include "geometry/BoostGeometry.h"

#include <exception>

namespace fc {

SwathLeftovers swathLeftovers(const Ring& outline, const std::vector<Ring>& holes,
                              const Polyline& line, double reach, double minPartArea) {
    SwathLeftovers leftovers;
    if (outline.size() < 3 || line.size() < 2)
        return leftovers;
    const Vec2 origin = outline.front();
    bgeo::BPolygon floor = bgeo::toPolygon(outline, origin);
    for (const Ring& hole : holes) {
        floor.inners().emplace_back();
        bgeo::appendRing(hole, origin, floor.inners().back());
    }
    bgeo::bg::correct(floor);
    bgeo::BLine swathLine;
    for (const Vec2& p : line)
        swathLine.push_back(bgeo::BPoint(p.x - origin.x, p.y - origin.y));
    try {
        const bgeo::BMulti swath = bgeo::roundBuffer(swathLine, reach);
        bgeo::BMulti left;
        bgeo::bg::difference(floor, swath, left);
        leftovers.area = bgeo::bg::area(left);
        for (const bgeo::BPolygon& part : left) {
            if (bgeo::bg::area(part) < minPartArea)
                continue;
            FloorPart kept{bgeo::toRing(part.outer(), origin), {}};
            for (const bgeo::BRing& inner : part.inners())
                kept.holes.push_back(bgeo::toRing(inner, origin));
            leftovers.parts.push_back(std::move(kept));
        }
    } catch (const std::exception&) {
        leftovers.parts.clear();
        leftovers.area = -1.0;
    }
    return leftovers;
}

} // namespace fc
