// Boost.Geometry as the planner's .cpp files use it (boolean operations, buffers): its
// headers and the types they share. Include it from .cpp files only: it is heavy, and it
// silences GCC 12's -Wmaybe-uninitialized for the rest of the file (a false positive inside
// the library's envelope code).
#pragma once

#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "geometry/Geometry.h"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

namespace fc::bgeo {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;
using BMulti = bg::model::multi_polygon<BPolygon>;
using BLine = bg::model::linestring<BPoint>;
using BRing = bg::model::ring<BPoint>;

// Coordinates relative to `origin`: a plan in UTM coordinates loses its digits otherwise.
inline void appendRing(const Ring& ring, Vec2 origin, BRing& out) {
    for (const Vec2& p : ring)
        out.push_back(BPoint(p.x - origin.x, p.y - origin.y));
    if (!ring.empty())
        out.push_back(out.front());
}

// A simple ring as a polygon, relative to `origin`, oriented as Boost.Geometry expects.
inline BPolygon toPolygon(const Ring& ring, Vec2 origin) {
    BPolygon out;
    appendRing(ring, origin, out.outer());
    bg::correct(out);
    return out;
}

inline Ring toRing(const BRing& ring, Vec2 origin) {
    Ring out;
    for (size_t i = 0; i + 1 < ring.size(); ++i)
        out.push_back({ring[i].x() + origin.x, ring[i].y() + origin.y});
    return out;
}

// `geometry` grown (distance > 0) or shrunk by `distance` with round joins of
// `circlePoints` per full circle (32: a chord of a 0.3 m arc cuts it by 1.4 mm).
template <typename Geometry>
BMulti roundBuffer(const Geometry& geometry, double distance, int circlePoints = 32) {
    BMulti out;
    bg::buffer(geometry, out, bg::strategy::buffer::distance_symmetric<double>(distance),
               bg::strategy::buffer::side_straight(),
               bg::strategy::buffer::join_round(circlePoints),
               bg::strategy::buffer::end_round(circlePoints),
               bg::strategy::buffer::point_circle(circlePoints));
    return out;
}

} // namespace fc::bgeo
