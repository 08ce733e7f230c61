#include "geometry/Geometry.h"
#include "geometry/SegmentIndex.h"

#include <gtest/gtest.h>

using namespace fc;

TEST(Geometry, AreaAndOrientation) {
    Ring sq{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_DOUBLE_EQ(signedArea(sq), 4.0);
    Ring cw(sq.rbegin(), sq.rend());
    EXPECT_DOUBLE_EQ(signedArea(cw), -4.0);
}

TEST(Geometry, AreaKeepsPrecisionAtUtmOffsets) {
    const double ox = 500000.0, oy = 5000000.0;
    Ring sq{{ox, oy}, {ox + 0.5, oy}, {ox + 0.5, oy + 0.5}, {ox, oy + 0.5}};
    EXPECT_NEAR(ringArea(sq), 0.25, 1e-9);
}

TEST(Geometry, FrameRoundTripAndExactQuarterTurns) {
    Frame f({10, 20}, 0.0); // horizontal stripes: world x maps onto local y
    const Vec2 l = f.toLocal({13, 20});
    EXPECT_DOUBLE_EQ(l.x, 0.0);
    EXPECT_DOUBLE_EQ(l.y, 3.0);
    Frame g({5, 5}, 37.0);
    const Vec2 w = g.toWorld(g.toLocal({1.25, -7.5}));
    EXPECT_NEAR(w.x, 1.25, 1e-12);
    EXPECT_NEAR(w.y, -7.5, 1e-12);
}

TEST(Geometry, SegmentIndexClearance) {
    SegmentIndex idx({Ring{{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
    EXPECT_NEAR(idx.distanceToWalls({3, 4}), 3.0, 1e-12);
    EXPECT_NEAR(idx.segmentClearance({2, 5}, {8, 5}), 2.0, 1e-12);
    EXPECT_NEAR(idx.polylineClearance({{1, 1}, {5, 5}, {9, 9}}), 1.0, 1e-12);
}
