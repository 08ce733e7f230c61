// The tiling robot: energy model against hand-computed cases, the shapes on the lattice,
// the free cells of a plan, and tilings that are complete and non-overlapping.
#include "TestPlans.h"
#include "formats/PlanIO.h"
#include "tiling/Polyabolo.h"
#include "tiling/Tiling.h"
#include "tiling/TilingRobot.h"
#include "tiling/TriangleGrid.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>

using namespace fc;
using namespace fc::tiling;

namespace {

constexpr double kPi = 3.14159265358979323846;

TilingRobotProfile unitMasses() {
    TilingRobotProfile robot;
    robot.blockMass = {1.0, 2.0, 3.0, 4.0}; // total 10 kg
    return robot;
}

Pose poseAt(Shape shape, double heading, Vec2 offset) {
    Pose pose;
    pose.shape = shape;
    pose.heading = heading;
    for (int b = 0; b < kBlockCount; ++b)
        pose.blocks[b] = offset + Vec2(0.1 * b, 0.05 * b);
    return pose;
}

Plan rectanglePlan(double w, double h) {
    Plan plan;
    plan.boundary = test::rectangle(0, 0, w, h);
    return plan;
}

Plan samplePlan(const std::string& name) {
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

// Every tile on free cells, no cell twice, and tiles + unreachable + untiled = free cells.
void expectCompleteAndDisjoint(const TriangleGrid& grid, const TilingResult& result) {
    std::vector<int> uses(grid.cellCount(), 0);
    for (const Tile& tile : result.tiles)
        for (int cell : tile.cells) {
            ASSERT_TRUE(grid.isFree(cell));
            ++uses[cell];
        }
    for (int cell : result.unreachable)
        ++uses[cell];
    for (int cell : result.untiled)
        ++uses[cell];
    for (int cell = 0; cell < grid.cellCount(); ++cell)
        ASSERT_EQ(uses[cell], grid.isFree(cell) ? 1 : 0) << "cell " << cell;
}

} // namespace

TEST(TilingRobot, LeversFollowTheBlockGeometry) {
    TilingRobotProfile robot;                            // leg 0.21 m
    EXPECT_NEAR(robot.firstLever(), 0.156524758, 1e-9);  // 0.21 * sqrt(5) / 3
    EXPECT_NEAR(robot.secondLever(), 0.098994949, 1e-9); // 0.21 * sqrt(2) / 3
}

TEST(TilingRobot, TranslationIsMassTimesDistance) {
    const TilingRobotProfile robot = unitMasses();
    const EnergyTerms e = transitionEnergy(robot, poseAt(Shape::Square, 0, {0, 0}),
                                           poseAt(Shape::Square, 0, {0.3, 0.4}));
    EXPECT_NEAR(e.translation, 10 * 0.5, 1e-12); // every block moves 0.5 m
    EXPECT_EQ(e.transformation, 0.0);
    EXPECT_EQ(e.orientation, 0.0);
    EXPECT_NEAR(e.total(), 5.0, 1e-12);
}

TEST(TilingRobot, ShapeChangeRectangleToParallelogramTurnsTheEndBlocks) {
    // Table 1: B1 and B4 turn pi about their first hinge: (m1 + m4) * pi * l1.
    const EnergyTerms e = transitionEnergy(unitMasses(), poseAt(Shape::Rectangle, 0, {}),
                                           poseAt(Shape::Parallelogram, 0, {}));
    EXPECT_NEAR(e.transformation, 2.4586851559, 1e-9);
    EXPECT_EQ(e.translation, 0.0);
}

TEST(TilingRobot, ShapeChangeSquareToRectangleUsesBothLevers) {
    // B3: 7pi/4 with l1; B4: pi with l1 then 7pi/4 with l2.
    // 3 * 7pi/4 * l1 + 4 * (pi * l1 + 7pi/4 * l2) = 2.581530 + 4.144050.
    const EnergyTerms e = transitionEnergy(unitMasses(), poseAt(Shape::Square, 0, {}),
                                           poseAt(Shape::Rectangle, 0, {}));
    EXPECT_NEAR(e.transformation, 6.7255801780, 1e-9);
}

TEST(TilingRobot, HeadingChangeTakesTheShortWayRound) {
    // 10 kg * pi/2 * (l1 + l2), for a quarter turn either way.
    const TilingRobotProfile robot = unitMasses();
    const Pose start = poseAt(Shape::Curve, 0, {});
    const EnergyTerms left = transitionEnergy(robot, start, poseAt(Shape::Curve, kPi / 2, {}));
    const EnergyTerms right = transitionEnergy(robot, start, poseAt(Shape::Curve, 3 * kPi / 2, {}));
    EXPECT_NEAR(left.orientation, 4.0136941842, 1e-9);
    EXPECT_NEAR(right.orientation, left.orientation, 1e-12);
    EXPECT_NEAR(headingDifference(0.1, 2 * kPi - 0.1), 0.2, 1e-12);
}

TEST(TilingRobot, TableIsSymmetricWithNothingToDoForTheSameShape) {
    for (int a = 0; a < kShapeCount; ++a)
        for (int b = 0; b < kShapeCount; ++b)
            for (int k = 0; k < kBlockCount; ++k) {
                const BlockRotation ab = blockRotation(Shape(a), Shape(b), k);
                const BlockRotation ba = blockRotation(Shape(b), Shape(a), k);
                EXPECT_EQ(ab.first, ba.first);
                EXPECT_EQ(ab.second, ba.second);
                if (a == b) {
                    EXPECT_EQ(ab.first + ab.second, 0.0);
                }
            }
    EXPECT_TRUE(shapeFromName("curve") == Shape::Curve);
    EXPECT_FALSE(shapeFromName("hexagon"));
}

TEST(TilingRobot, ProfileRejectsNonPositiveValues) {
    TilingRobotProfile robot;
    robot.blockMass[2] = 0.0;
    EXPECT_THROW(robot.validate(), InputError);
    robot = TilingRobotProfile();
    robot.blockLeg = -1;
    EXPECT_THROW(robot.validate(), InputError);
}

TEST(Polyabolo, EveryOrientationIsFourDistinctLatticeTriangles) {
    for (const ShapeOrientation& o : allOrientations()) {
        std::set<std::pair<int, int>> cells; // (square, half) must be distinct
        for (const LatticeTriangle& t : o.blocks) {
            EXPECT_TRUE(translated(t, o.translationParity, 0).fitsLattice());
            cells.insert({t.squareJ() * 16 + t.squareI(), t.half()});
        }
        EXPECT_EQ(cells.size(), 4u) << shapeName(o.shape);
    }
    // Symmetric shapes have fewer distinct orientations (the square sits only around the
    // lattice points where four right angles meet); none has more than eight.
    for (int s = 0; s < kShapeCount; ++s) {
        const auto orientations = shapeOrientations(Shape(s));
        EXPECT_GE(orientations.size(), Shape(s) == Shape::Square ? 1u : 2u) << s;
        EXPECT_LE(orientations.size(), 8u);
    }
}

TEST(TriangleGrid, RectangleFloorIsAllFree) {
    const TriangleGrid grid = buildTriangleGrid(rectanglePlan(2.1, 1.05), 0.21);
    EXPECT_EQ(grid.nx(), 10);
    EXPECT_EQ(grid.ny(), 5);
    EXPECT_EQ(grid.freeCount(), 100);
    for (int cell = 0; cell < grid.cellCount(); ++cell) {
        EXPECT_TRUE(grid.triangle(cell).fitsLattice());
        EXPECT_EQ(grid.cellId(grid.triangle(cell)), cell);
    }
}

TEST(TriangleGrid, CellsCutByAnObstacleAreNotFree) {
    Plan plan = rectanglePlan(2.0, 2.0);
    plan.obstacles.push_back(test::rectangle(0.5, 0.5, 1.5, 1.5));
    const TriangleGrid grid = buildTriangleGrid(plan, 0.25);
    // Walls on grid lines: the 4 x 4 squares inside the obstacle go, the rest stays.
    EXPECT_EQ(grid.freeCount(), 2 * (64 - 16));
    Plan slanted = rectanglePlan(2.0, 2.0);
    slanted.obstacles.push_back({{1.0, 0.4}, {1.6, 1.0}, {1.0, 1.6}, {0.4, 1.0}});
    const TriangleGrid cut = buildTriangleGrid(slanted, 0.25);
    for (int cell = 0; cell < cut.cellCount(); ++cell) {
        if (!cut.isFree(cell))
            continue;
        for (Vec2 v : cut.vertices(cell)) // no free cell reaches into the diamond
            EXPECT_GE(std::abs(v.x - 1.0) + std::abs(v.y - 1.0), 0.6 - 1e-9);
    }
}

TEST(Tiling, RectangleIsTiledExactly) {
    const TriangleGrid grid = buildTriangleGrid(rectanglePlan(2.1, 1.05), 0.21);
    const TilingResult result = tileFreeSpace(grid);
    EXPECT_EQ(result.tiles.size(), 25u);
    EXPECT_TRUE(result.unreachable.empty());
    EXPECT_TRUE(result.untiled.empty());
    EXPECT_EQ(result.piecesTiledExactly, result.pieces);
    expectCompleteAndDisjoint(grid, result);
}

TEST(Tiling, IsolatedCellsAreReportedUnreachable) {
    TriangleGrid grid({0, 0}, 1.0, 6, 2);
    for (int cell = 0; cell < grid.cellCount(); ++cell)
        grid.setFree(cell, true);
    // (5, 1, 1) is a corner triangle; without its hypotenuse neighbour it has no free
    // neighbour, and every shape is edge-connected.
    grid.setFree(grid.cellId(5, 1, 0), false);
    const TilingResult result = tileFreeSpace(grid);
    EXPECT_EQ(result.unreachable, std::vector<int>{grid.cellId(5, 1, 1)});
    expectCompleteAndDisjoint(grid, result);
}

TEST(Tiling, GreedyFillWhenTheBudgetRunsOut) {
    const TriangleGrid grid = buildTriangleGrid(rectanglePlan(2.1, 1.05), 0.21);
    TilingOptions options;
    options.nodeBudget = 0; // no backtracking at all
    const TilingResult result = tileFreeSpace(grid, options);
    EXPECT_EQ(result.piecesTiledExactly, 0);
    expectCompleteAndDisjoint(grid, result);
    EXPECT_GE(result.tiles.size(), 20u);
}

TEST(Tiling, LocalRepairLeavesFewerCellsThanTheGreedyFill) {
    // ward's slanted walls defeat the exact search within its budget; the greedy fill leaves
    // pockets, and re-tiling the patches around them exactly closes some.
    const TriangleGrid grid = buildTriangleGrid(samplePlan("ward"), 0.21);
    TilingOptions greedyOnly;
    greedyOnly.nodeBudget = 0;
    greedyOnly.repairBudget = 0;
    TilingOptions repaired;
    repaired.nodeBudget = 0;
    const TilingResult before = tileFreeSpace(grid, greedyOnly);
    const TilingResult after = tileFreeSpace(grid, repaired);
    expectCompleteAndDisjoint(grid, before);
    expectCompleteAndDisjoint(grid, after);
    EXPECT_LT(after.untiled.size(), before.untiled.size());
    EXPECT_EQ(after.untiled.size() % 4, before.untiled.size() % 4) << "four cells a tile";
}

class SamplePlanTiling : public ::testing::TestWithParam<std::string> {};

TEST_P(SamplePlanTiling, CompleteAndNonOverlapping) {
    const TriangleGrid grid = buildTriangleGrid(samplePlan(GetParam()), 0.21);
    const TilingResult result = tileFreeSpace(grid);
    expectCompleteAndDisjoint(grid, result);
    // The fallback may leave a few cells; it must stay a small share of the floor.
    EXPECT_LE(result.untiled.size() + result.unreachable.size(), 0.01 * result.freeCells)
        << result.untiled.size() << " untiled, " << result.unreachable.size() << " unreachable, "
        << result.piecesTiledExactly << "/" << result.pieces << " pieces exact, " << result.nodes
        << " nodes, " << result.freeCells << " free cells";
}

INSTANTIATE_TEST_SUITE_P(Plans, SamplePlanTiling,
                         ::testing::Values("simple", "simple-diamond", "room-obstacle",
                                           "room-notches", "office", "ward"));
