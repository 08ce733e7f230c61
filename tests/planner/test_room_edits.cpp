// Merging and splitting room outlines (model/RoomEdits): the editor's merge and split
// commands rest on these.
#include "model/Plan.h"
#include "model/RoomEdits.h"

#include <gtest/gtest.h>

using namespace fc;

namespace {

Ring rect(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

} // namespace

TEST(RoomEdits, RoomsSharingAWallMergeIntoOneOutline) {
    const Ring merged = mergedRoomOutline(rect(0, 0, 4, 3), rect(4, 0, 7, 3));
    EXPECT_NEAR(ringArea(merged), 21.0, 1e-9);
    EXPECT_EQ(merged.size(), 4u); // the shared wall's ends are gone
}

TEST(RoomEdits, RoomsMeetingAtADoorwayMergeAndKeepTheirShape) {
    // An L: a corridor and an office meeting along a 1 m doorway at UTM coordinates.
    const Vec2 o{500000.0, 5400000.0};
    auto at = [&](Ring r) {
        for (Vec2& p : r)
            p = p + o;
        return r;
    };
    const Ring merged = mergedRoomOutline(at(rect(0, 0, 10, 2)), at(rect(2, 2, 3, 5)));
    EXPECT_NEAR(ringArea(merged), 23.0, 1e-6);
}

TEST(RoomEdits, TracedNeighboursAMillimetreApartStillMerge) {
    const Ring merged = mergedRoomOutline(rect(0, 0, 4, 3), rect(4.001, 0, 7, 3));
    EXPECT_NEAR(ringArea(merged), 21.0, 0.02);
}

TEST(RoomEdits, RoomsApartOrTouchingAtACornerAreRefused) {
    EXPECT_THROW(mergedRoomOutline(rect(0, 0, 4, 3), rect(5, 0, 7, 3)), InputError);
    EXPECT_THROW(mergedRoomOutline(rect(0, 0, 4, 3), rect(4, 3, 7, 6)), InputError);
}

TEST(RoomEdits, AMergeThatWouldEncloseAHoleIsRefused) {
    // A U-shaped room closed by a bar leaves a courtyard between them.
    const Ring u = {{0, 0}, {6, 0}, {6, 5}, {5, 5}, {5, 1}, {1, 1}, {1, 5}, {0, 5}};
    EXPECT_THROW(mergedRoomOutline(u, rect(0, 5, 6, 6)), InputError);
}

TEST(RoomEdits, ACutAcrossARoomSplitsItInTwo) {
    const auto [left, right] = splitRoomOutline(rect(0, 0, 10, 4), {6, -1}, {6, 5});
    // Left of the line looking from (6, -1) to (6, 5) is the west part.
    EXPECT_NEAR(ringArea(left), 24.0, 1e-9);
    EXPECT_NEAR(ringArea(right), 16.0, 1e-9);
    // A slanted cut inside the room (the line is extended across it).
    const auto [a, b] = splitRoomOutline(rect(0, 0, 10, 4), {4, 1}, {5, 3});
    EXPECT_NEAR(ringArea(a) + ringArea(b), 40.0, 1e-9);
}

TEST(RoomEdits, CutsThatMissCrossTwiceOrShaveAreRefused) {
    EXPECT_THROW(splitRoomOutline(rect(0, 0, 10, 4), {12, -1}, {12, 5}), InputError);
    EXPECT_THROW(splitRoomOutline(rect(0, 0, 10, 4), {3, 3}, {3, 3}), InputError);
    const Ring u = {{0, 0}, {6, 0}, {6, 5}, {5, 5}, {5, 1}, {1, 1}, {1, 5}, {0, 5}};
    EXPECT_THROW(splitRoomOutline(u, {-1, 3}, {7, 3}), InputError); // through both arms
    EXPECT_THROW(splitRoomOutline(rect(0, 0, 10, 4), {9.999, -1}, {9.999, 5}), InputError);
}
