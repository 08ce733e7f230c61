// Boost.Geometry as the planner's .cpp files use it (boolean operations, buffers): its
// headers and the types they share. Include it from .cpp files only: it is heavy, and it
// silences GCC 12's -Wmaybe-uninitialized for the rest of the file (a false positive inside
// the library's envelope code).
#pragma once

#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

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

} // namespace fc::bgeo
