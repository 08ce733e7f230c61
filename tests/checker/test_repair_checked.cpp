// fc::repairPlan (GEOS through OGR) checked by an independent library (Boost.Geometry) on
// generated floors of every family, rotated and offset, broken on purpose: an obstacle
// across a wall corner and one overlapping another. The repaired plan must pass the
// planner's validation (CGAL), and its floor must be the largest part of the boundary
// minus the union of all obstacles, as Boost.Geometry computes it.
// Boost.Geometry's envelope code trips GCC 12's -Wmaybe-uninitialized (a false positive,
// as in PlanGenerator.cpp).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "importers/Import.h"
#include "model/Validation.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <gtest/gtest.h>

namespace fcgen {
namespace {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
using Polygon = bg::model::polygon<Point>;
using MultiPolygon = bg::model::multi_polygon<Polygon>;

Polygon polygonOf(const fc::Ring& ring) {
    Polygon polygon;
    for (const fc::Vec2& p : ring)
        bg::append(polygon.outer(), Point(p.x, p.y));
    bg::correct(polygon);
    return polygon;
}

fc::Ring square(fc::Vec2 centre, double half) {
    return {{centre.x - half, centre.y - half},
            {centre.x + half, centre.y - half},
            {centre.x + half, centre.y + half},
            {centre.x - half, centre.y + half}};
}

// The largest part of boundary minus the union of the obstacles, m^2.
double expectedFloor(const fc::Plan& plan) {
    MultiPolygon obstacles;
    for (const fc::Ring& ring : plan.obstacles) {
        MultiPolygon merged;
        bg::union_(obstacles, polygonOf(ring), merged);
        obstacles = merged;
    }
    MultiPolygon free;
    bg::difference(polygonOf(plan.boundary), obstacles, free);
    double largest = 0;
    for (const Polygon& part : free)
        largest = std::max(largest, bg::area(part));
    return largest;
}

TEST(RepairChecked, BrokenFloorsComeOutValidWithTheFloorBoostGeometryExpects) {
    int checked = 0;
    for (Family family : allFamilies()) {
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            const GeneratedPlan generated = generatePlan(family, seed);
            fc::Plan broken = generated.plan;
            broken.rooms.clear(); // the floor is what is compared
            // Across a corner of the wall, and over a copy of an obstacle moved by 0.3 m.
            broken.obstacles.push_back(square(broken.boundary[0], 0.8));
            if (!generated.plan.obstacles.empty()) {
                fc::Ring moved = generated.plan.obstacles.front();
                for (fc::Vec2& p : moved)
                    p = p + fc::Vec2(0.3, 0.3);
                broken.obstacles.push_back(moved);
            }
            ASSERT_FALSE(fc::planProblems(broken, fc::RobotProfile{}).empty())
                << generated.description;
            std::vector<std::string> notes;
            fc::Plan repaired;
            try {
                repaired = fc::normalizedPlan(fc::repairPlan(broken, notes));
            } catch (const fc::InputError& e) {
                ADD_FAILURE() << generated.description << ": " << e.what();
                continue;
            }
            EXPECT_NO_THROW(fc::validatePlan(repaired, fc::RobotProfile{}))
                << generated.description;
            const double expected = expectedFloor(broken);
            const double got = fccheck::floorArea(freeSpaceOf(repaired), {});
            EXPECT_NEAR(got, expected, 1e-3 * expected + 1e-3) << generated.description;
            ++checked;
        }
    }
    EXPECT_GE(checked, 8);
}

} // namespace
} // namespace fcgen
