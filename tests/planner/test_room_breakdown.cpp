// The report's room table: rows that add up to the path's metrics, in visit order.
#include "formats/PlanIO.h"
#include "geometry/Geometry.h"
#include "metrics/RoomBreakdown.h"
#include "pipeline/Planner.h"

#include <gtest/gtest.h>
#include <set>

namespace fc {
namespace {

TEST(RoomBreakdown, RowsAddUpToThePathsMetrics) {
    PlanRequest request =
        planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/office.geojson"));
    request.solver = "greedy";
    request.rooms = {"N03", "S05", "Corridor"};
    const PlanResult result = planCoverage(request, {});
    const auto rows =
        roomBreakdown(request.plan, result.path, request.robot, &result.prepared.decomposition);
    double length = 0, time = 0, area = 0;
    int turns = 0;
    std::set<int> orders;
    for (const RoomVisit& row : rows) {
        length += row.length;
        time += row.time;
        turns += row.turns;
        area += row.area;
        if (row.order > 0) {
            EXPECT_TRUE(orders.insert(row.order).second) << row.room;
        }
    }
    EXPECT_NEAR(length, result.metrics.length, 1e-6);
    EXPECT_EQ(turns, result.metrics.turns);
    EXPECT_NEAR(time, result.metrics.time, 1e-6);
    // Every room of the plan has a row; the swept ones come first, numbered 1, 2, 3...
    ASSERT_GE(rows.size(), request.plan.rooms.size());
    for (int k = 0; k < static_cast<int>(orders.size()); ++k)
        EXPECT_EQ(rows[k].order, k + 1);
    for (const std::string& room : request.rooms) {
        const auto row = std::find_if(rows.begin(), rows.end(),
                                      [&](const RoomVisit& r) { return r.room == room; });
        ASSERT_NE(row, rows.end()) << room;
        EXPECT_GT(row->order, 0) << room << " is planned, so it is swept";
        EXPECT_GT(row->length, 5.0) << room;
        EXPECT_GT(row->area, 5.0) << room;
    }
    // Areas are the rooms' free floor (with the doorway the decomposition gives them): about
    // their outlines, never much more.
    for (const RoomVisit& row : rows)
        for (const Room& room : request.plan.rooms)
            if (room.name == row.room) {
                EXPECT_LE(row.area, 1.02 * ringArea(room.outline) + 0.5) << row.room;
                EXPECT_GE(row.area, 0.8 * ringArea(room.outline)) << row.room;
            }
}

TEST(RoomBreakdown, SplitsAMoveThroughADoorAndKeepsTheOutside) {
    Plan plan;
    plan.boundary = {{0, 0}, {20, 0}, {20, 4}, {0, 4}};
    plan.rooms = {{"West", {{0, 0}, {8, 0}, {8, 4}, {0, 4}}},
                  {"East", {{10, 0}, {20, 0}, {20, 4}, {10, 4}}}};
    RobotProfile robot;
    robot.speed = 0.5;
    robot.turnTime = 2.0;
    CoveragePath path;
    // Sweep East first, then travel west through the gap (outside both rooms) and turn.
    path.points = {{12, 1}, {18, 1}, {2, 1}, {2, 3}};
    path.kinds = {SegmentKind::Stripe, SegmentKind::Transit, SegmentKind::Stripe};
    const auto rows = roomBreakdown(plan, path, robot, nullptr);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].room, "East");
    EXPECT_EQ(rows[0].order, 1);
    EXPECT_NEAR(rows[0].length, 6 + 8, 0.3);
    EXPECT_EQ(rows[0].turns, 1); // the reversal at x = 18
    EXPECT_EQ(rows[1].room, "West");
    EXPECT_EQ(rows[1].order, 2);
    EXPECT_NEAR(rows[1].length, 6 + 2, 0.3);
    EXPECT_EQ(rows[1].turns, 1);
    EXPECT_EQ(rows[2].room, "");
    EXPECT_NEAR(rows[2].length, 2, 0.3);
    EXPECT_NEAR(rows[2].time, rows[2].length / 0.5, 1e-9);
}

} // namespace
} // namespace fc
