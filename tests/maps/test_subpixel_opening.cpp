// The traced floor's sub-pixel opening (importers/SubpixelOpening.cpp): a polygon of many
// holes is opened in parts, and must come out as one buffer over all of it would.
#include "importers/MapTracing.h"

#include <cmath>
#include <gtest/gtest.h>
#include <ogr_geometry.h>

namespace fc::importing {
namespace {

OGRLinearRing* square(double x, double y, double side) {
    auto* ring = new OGRLinearRing;
    ring->addPoint(x, y);
    ring->addPoint(x + side, y);
    ring->addPoint(x + side, y + side);
    ring->addPoint(x, y + side);
    ring->closeRings();
    return ring;
}

OGRLinearRing* triangle(Vec2 a, Vec2 b, Vec2 c) {
    auto* ring = new OGRLinearRing;
    for (Vec2 p : {a, b, c})
        ring->addPoint(p.x, p.y);
    ring->closeRings();
    return ring;
}

// A 400 x 400 pixel floor with a grid of 225 specks of 1.5 pixels, two specks touching at a corner,
// a speck touching the outline at its corner, and two specks 0.05 pixel apart.
std::unique_ptr<OGRPolygon> speckledFloor() {
    auto floor = std::make_unique<OGRPolygon>();
    floor->addRingDirectly(square(0, 0, 400));
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j)
            floor->addRingDirectly(square(20 + 25 * i, 20 + 25 * j, 1.5));
    floor->addRingDirectly(square(5, 380, 2));
    floor->addRingDirectly(square(7, 382, 2));
    floor->addRingDirectly(triangle({398, 10}, {400, 11}, {398, 12}));
    floor->addRingDirectly(square(10, 5, 2));
    floor->addRingDirectly(square(12.05, 5, 2));
    return floor;
}

double area(const OGRGeometry& g) {
    if (const auto* surface = dynamic_cast<const OGRSurface*>(&g))
        return surface->get_Area();
    if (const auto* many = dynamic_cast<const OGRMultiSurface*>(&g))
        return many->get_Area();
    return 0.0;
}

int holes(const OGRGeometry& g) {
    if (const auto* polygon = dynamic_cast<const OGRPolygon*>(&g))
        return polygon->getNumInteriorRings();
    int n = 0;
    if (const auto* parts = dynamic_cast<const OGRGeometryCollection*>(&g))
        for (int i = 0; i < parts->getNumGeometries(); ++i)
            n += holes(*parts->getGeometryRef(i));
    return n;
}

// Turned about the origin: long slanted walls (the grid walks them a cell at a time).
void turn(OGRPolygon& polygon, double degrees) {
    const double c = std::cos(degrees * M_PI / 180.0), s = std::sin(degrees * M_PI / 180.0);
    auto turnRing = [&](OGRLinearRing* ring) {
        for (int i = 0; i < ring->getNumPoints(); ++i) {
            const double x = ring->getX(i), y = ring->getY(i);
            ring->setPoint(i, c * x - s * y, s * x + c * y);
        }
    };
    turnRing(polygon.getExteriorRing());
    for (int h = 0; h < polygon.getNumInteriorRings(); ++h)
        turnRing(polygon.getInteriorRing(h));
}

class SubpixelOpeningAt : public ::testing::TestWithParam<double> {};

TEST_P(SubpixelOpeningAt, ManyHolesOpenAsOneBufferWould) {
    const std::unique_ptr<OGRPolygon> floor = speckledFloor();
    turn(*floor, GetParam());
    ASSERT_GE(floor->getNumInteriorRings(), 200); // opened in parts
    const double radius = 0.05;
    std::unique_ptr<OGRGeometry> whole(floor->Buffer(-radius, 1));
    ASSERT_TRUE(whole);
    whole.reset(whole->Buffer(radius, 1));
    ASSERT_TRUE(whole);

    const GeometryPtr parts = openedPolygons(*floor, radius);
    ASSERT_TRUE(parts);
    EXPECT_TRUE(parts->IsValid());
    // The touching specks joined each other, and the one on the outline joined it: as many
    // holes as the single buffer leaves, and no area apart.
    EXPECT_EQ(holes(*parts), holes(*whole));
    EXPECT_LT(holes(*whole), floor->getNumInteriorRings());
    const std::unique_ptr<OGRGeometry> apart(parts->SymDifference(whole.get()));
    ASSERT_TRUE(apart);
    EXPECT_LT(area(*apart), 1e-9);
    EXPECT_NEAR(area(*parts), area(*whole), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Turned, SubpixelOpeningAt, ::testing::Values(0.0, 30.0));

TEST(SubpixelOpening, FewHolesAndSeparatePartsOpenAsBefore) {
    OGRMultiPolygon floors;
    for (double x : {0.0, 100.0}) {
        auto* polygon = new OGRPolygon;
        polygon->addRingDirectly(square(x, 0, 50));
        polygon->addRingDirectly(square(x + 10, 10, 3));
        floors.addGeometryDirectly(polygon);
    }
    const GeometryPtr opened = openedPolygons(floors, 0.05);
    ASSERT_TRUE(opened);
    EXPECT_EQ(holes(*opened), 2);
    EXPECT_NEAR(area(*opened), 2 * (50 * 50 - 3 * 3), 0.01);
}

} // namespace
} // namespace fc::importing
