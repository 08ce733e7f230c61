#include "geometry/RingOverlap.h"

#include "geometry/BoostGeometry.h"

namespace fc {

double ringOverlapArea(const Ring& a, const Ring& b) {
    if (a.size() < 3 || b.size() < 3)
        return 0.0;
    const BoundingBox ba = boundsOf(a), bb = boundsOf(b);
    if (ba.maxX <= bb.minX || bb.maxX <= ba.minX || ba.maxY <= bb.minY || bb.maxY <= ba.minY)
        return 0.0;
    const Vec2 origin{ba.minX, ba.minY};
    const bgeo::BPolygon pa = bgeo::toPolygon(a, origin), pb = bgeo::toPolygon(b, origin);
    if (!bgeo::bg::is_valid(pa) || !bgeo::bg::is_valid(pb))
        return 0.0;
    try {
        bgeo::BMulti shared;
        bgeo::bg::intersection(pa, pb, shared);
        return bgeo::bg::area(shared);
    } catch (const std::exception&) {
        return 0.0; // Boost.Geometry's overlay gave up: no claim of an overlap
    }
}

} // namespace fc
