// The wall loop (pipeline/EdgePass.h, issue 15) on traced maps: halls with niches along their
// walls rendered as noisy occupancy maps at any rotation and at UTM-sized offsets, the
// office's noisy map imported as one room, and the real corridor map. The independent
// checker (tests/checker, Boost.Geometry only) judges each path; the loop must pay where the
// walls are traced and leave drawn plans as they were.
#include "NoisyMap.h"
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "ResampledMap.h"
#include "formats/PlanIO.h"
#include "importers/Import.h"
#include "model/Validation.h"
#include "pipeline/EdgePass.h"
#include "pipeline/RestPieces.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <gtest/gtest.h>
#include <random>

namespace fc {
namespace {

// The default request without the rings (pipeline/RingsOffer.h): these tests measure the wall
// loop and its pieces. The rings win on the corridor map by time with longer paths (1,303 s
// and 423 m against the loop's 1,472 s and 405 m); test_rings_checked.cpp covers them.
PlanRequest loopRequest(const Plan& plan) {
    PlanRequest request = fcgen::defaultRequest(plan);
    request.rings = false;
    return request;
}

// One side of a hall from a to b (counter-clockwise, the floor on the left): straight runs
// with niches (into the wall, deep enough for the robot) and bumps (cupboards) between.
void raggedSide(Vec2 a, Vec2 b, std::mt19937_64& rng, Ring& out) {
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<>(lo, hi)(rng);
    };
    const double length = norm(b - a);
    const Vec2 along = (b - a) * (1.0 / length);
    const Vec2 inward{-along.y, along.x};
    double at = 0.0;
    out.push_back(a);
    while (true) {
        at += uniform(0.4, 1.6);
        const double width = uniform(0.7, 1.6);
        if (at + width > length - 0.4)
            break;
        const double depth = uniform(0, 1) < 0.6 ? -uniform(0.2, 0.9) : uniform(0.1, 0.3);
        const Vec2 p = a + along * at, q = a + along * (at + width);
        out.insert(out.end(), {p, p + inward * depth, q + inward * depth, q});
        at += width;
    }
}

Plan raggedOutline(double width, double depth, std::mt19937_64& rng) {
    const Vec2 corners[4] = {{0, 0}, {width, 0}, {width, depth}, {0, depth}};
    Plan plan;
    for (int side = 0; side < 4; ++side)
        raggedSide(corners[side], corners[(side + 1) % 4], rng, plan.boundary);
    return plan;
}

// Each seed's placement: an odd angle (degrees) and, for odd seeds, a UTM-sized offset.
struct Placement {
    double degrees;
    Vec2 offset;
};

Placement placementOf(std::uint64_t seed) {
    return {fcgen::oddAngles(seed, 1).front(),
            seed % 2 ? Vec2{512345.0, 5432109.0} : Vec2{-7.0, 3.0}};
}

Plan placed(const Plan& plan, std::uint64_t seed) {
    const Placement at = placementOf(seed);
    return fcgen::transformPlan(plan, at.degrees, at.offset);
}

// A point of the drawing placed as `placed` places the plan (forward), or back.
Vec2 placedPoint(Vec2 p, std::uint64_t seed, bool forward) {
    const Placement at = placementOf(seed);
    const double a = (forward ? 1.0 : -1.0) * at.degrees * M_PI / 180.0;
    const Vec2 q = forward ? p : p - at.offset;
    const Vec2 turned{std::cos(a) * q.x - std::sin(a) * q.y, std::sin(a) * q.x + std::cos(a) * q.y};
    return forward ? turned + at.offset : turned;
}

Plan raggedHall(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<>(lo, hi)(rng);
    };
    const double width = uniform(10, 18), depth = uniform(7, 12);
    return placed(raggedOutline(width, depth, rng), seed);
}

// A ragged hall with furniture standing free in it: tables, round bins and pillars from 0.3
// to 1.2 m across, at least 1.5 m from the walls and 1 m from each other.
Plan furnishedHall(std::uint64_t seed) {
    std::mt19937_64 rng(seed * 7919);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<>(lo, hi)(rng);
    };
    const double width = uniform(12, 18), depth = uniform(8, 12);
    Plan plan = raggedOutline(width, depth, rng);
    std::vector<std::pair<Vec2, Vec2>> boxes; // low, high
    for (int tries = 0; tries < 200 && boxes.size() < 8; ++tries) {
        const double w = uniform(0.3, 1.2), h = uniform(0.3, 1.2);
        const Vec2 low{uniform(1.5, width - 1.5 - w), uniform(1.5, depth - 1.5 - h)};
        const Vec2 high = low + Vec2{w, h};
        bool apart = true;
        for (const auto& [l, u] : boxes)
            apart = apart && (low.x > u.x + 1.0 || high.x < l.x - 1.0 || low.y > u.y + 1.0 ||
                              high.y < l.y - 1.0);
        if (!apart)
            continue;
        boxes.push_back({low, high});
        if (boxes.size() % 2) {
            plan.obstacles.push_back({low, {high.x, low.y}, high, {low.x, high.y}});
        } else { // a round pillar or bin
            const Vec2 centre = (low + high) * 0.5;
            const double radius = 0.5 * std::min(w, h);
            Ring round;
            for (int k = 0; k < 24; ++k)
                round.push_back(centre +
                                Vec2{std::cos(k * M_PI / 12), std::sin(k * M_PI / 12)} * radius);
            plan.obstacles.push_back(round);
        }
    }
    return placed(plan, seed + 10);
}

Plan traced(const Plan& plan, const std::string& name, std::uint64_t seed, bool rooms = true) {
    // One folder per test: ctest -j runs tests side by side, and two of them trace the same
    // hall (one removed the other's map while it was read).
    const auto dir = std::filesystem::temp_directory_path() /
                     ("fc-wall-loop-" +
                      std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) +
                      "-" + name + "-" + std::to_string(seed));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    test::NoisyMapOptions options;
    options.seed = seed;
    ImportOptions import;
    if (!rooms)
        import.roomSegmentation.method = RoomSegmentationMethod::None;
    return importPlanFile(test::renderNoisyMap(plan, options).write(dir.string(), name), import)
        .project.plan;
}

struct Pair {
    fcgen::Outcome with, without;
};

// Plans with and without the loop; the path kept is clear of the walls, covers what the
// checker can sweep, and is never slower (bar choosePlan's tie) or less complete.
Pair planBoth(const Plan& plan, const std::string& label) {
    PlanRequest request = loopRequest(plan);
    Pair out;
    out.with = fcgen::planAndCheck(request);
    request.wallLoop = false;
    out.without = fcgen::planAndCheck(request);
    std::printf("%s: %s\n  without the wall loop: %.1f m, %d turns, %.0f s\n", label.c_str(),
                out.with.summary().c_str(), out.without.metrics.length, out.without.metrics.turns,
                out.without.metrics.time);
    EXPECT_TRUE(out.with.planned && out.without.planned)
        << label << out.with.error << out.without.error;
    EXPECT_TRUE(out.with.collisionFree) << label << ": " << out.with.summary();
    EXPECT_TRUE(out.with.covers || out.with.reportsLoss) << label << ": " << out.with.summary();
    EXPECT_GE(out.with.check.coverage, fcgen::kRequiredCoverage)
        << label << ": " << out.with.summary();
    EXPECT_LE(out.with.metrics.time, out.without.metrics.time * (1 + kTimeTie)) << label;
    EXPECT_LE(out.with.metrics.uncoveredArea,
              out.without.metrics.uncoveredArea + 0.005 * out.with.metrics.requiredArea)
        << label;
    return out;
}

TEST(WallLoopMaps, TracedHallsAreSweptAlongTheirWallsFirst) {
    double with = 0.0, without = 0.0, withTime = 0.0, withoutTime = 0.0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const Pair pair = planBoth(traced(raggedHall(seed), "hall", seed),
                                   "traced hall seed " + std::to_string(seed));
        with += pair.with.metrics.length;
        without += pair.without.metrics.length;
        withTime += pair.with.metrics.time;
        withoutTime += pair.without.metrics.time;
    }
    std::printf("traced halls: %.1f m with the wall loop, %.1f m without; %.0f s, %.0f s\n", with,
                without, withTime, withoutTime);
    // The loop is kept on about half of them (where it is faster): 17% faster in all (2,474 s
    // against 2,983 s) and as short within 0.2% (838 m against 837 m). The plans without the
    // loop minimise time too, so their length moves with small changes: 877 m before the
    // touch-ups were priced (TouchUpBudget), 891 m before the clearance field kept the walls
    // as traced; the loop's plans were 859 m then. So the length is held within 2%.
    EXPECT_LT(withTime, 0.9 * withoutTime);
    EXPECT_LT(with, 1.02 * without);
}

// Free-standing furniture, traced: inside the loop the stripes drive round each piece
// (decomposition/IslandDetours.h) rather than parting into cells at it.
TEST(WallLoopMaps, TracedFurnitureIsDrivenRoundByTheStripes) {
    double with = 0.0, without = 0.0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const Pair pair = planBoth(traced(furnishedHall(seed), "furnished", seed, false),
                                   "traced furnished hall seed " + std::to_string(seed));
        with += pair.with.metrics.length;
        without += pair.without.metrics.length;
    }
    std::printf("traced furnished halls: %.1f m with the wall loop, %.1f m without\n", with,
                without);
    // 658 m against 860 m (square furniture only: 683 m against 894 m, and with it parting
    // the stripes, before the detours, the loop's plans were no shorter: 898 m).
    EXPECT_LT(with, 0.85 * without);
}

// A drawn hall of pillars 0.4-0.8 m across on a jittered grid, round (32-sided) or square.
// The stripes' plan parts into cells at every pillar; the loop's plan drives round each one
// (IslandDetours.h).
Plan pillarHall(std::uint64_t seed, int sides) {
    std::mt19937_64 rng(seed);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<>(lo, hi)(rng);
    };
    Plan plan;
    plan.boundary = {{0, 0}, {20, 0}, {20, 14}, {0, 14}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            const Vec2 centre{5.0 * i + 2.5 + uniform(-0.4, 0.4),
                              14.0 / 3 * (j + 0.5) + uniform(-0.4, 0.4)};
            const double radius = uniform(0.2, 0.4);
            Ring pillar;
            for (int k = 0; k < sides; ++k) {
                const double a = (k + 0.5) * 2 * M_PI / sides;
                pillar.push_back(centre + Vec2{std::cos(a), std::sin(a)} * radius);
            }
            plan.obstacles.push_back(pillar);
        }
    return plan;
}

// Round pillars' short sides make the hall's walls "ragged", so the loop is drafted. Its
// estimate (the rest's area over W, times 1.5) came to a little more than the first plan's
// length upright and a little less at 23 degrees, so the loop's plan was made only when
// turned: a 60 x 40 m hall of 96 pillars planned 9,078 s upright and 5,739 s turned (3,554 m
// estimated, 3,435 m and 3,556 m first plans); on these 20 x 14 m halls it was made at
// neither rotation (seed 1: 1,192 s kept). Against the first plan's time the loop is made
// at every rotation.
TEST(WallLoopMaps, DrawnHallsOfRoundPillarsGetTheLoopAtAnyRotation) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const Plan drawing = pillarHall(seed, 32);
        const Pair upright = planBoth(drawing, "pillar hall seed " + std::to_string(seed));
        const Pair turned =
            planBoth(placed(drawing, seed), "placed pillar hall seed " + std::to_string(seed));
        // Seed 1: 791 s with the loop, 1,192 s without (upright).
        EXPECT_LT(upright.with.metrics.time, 0.85 * upright.without.metrics.time) << seed;
        EXPECT_LT(turned.with.metrics.time, 0.85 * turned.without.metrics.time) << seed;
        EXPECT_NEAR(upright.with.metrics.time, turned.with.metrics.time,
                    0.05 * upright.with.metrics.time)
            << seed;
    }
}

// Square pillars have long sides: the walls are not ragged, and the loop used to be drafted
// only for those. A hall of small islands is drafted too, and squares plan as round ones do
// (seed 1: 787 s, 1,080 s without the loop; a 60 x 40 m hall of 96 square pillars:
// 9,448 s, now 5,819 s; round: 5,751 s).
TEST(WallLoopMaps, DrawnHallsOfSquarePillarsGetTheLoopToo) {
    const Plan square = pillarHall(1, 4), round = pillarHall(1, 32);
    for (const bool turn : {false, true}) {
        const std::string label = turn ? "placed square pillar hall" : "square pillar hall";
        const Pair pair = planBoth(turn ? placed(square, 1) : square, label);
        EXPECT_LT(pair.with.metrics.time, 0.85 * pair.without.metrics.time) << label;
    }
    PlanRequest request = loopRequest(round);
    const double roundTime = planCoverage(request).metrics.time;
    request.plan = square;
    EXPECT_LT(planCoverage(request).metrics.time, 1.05 * roundTime);
}

TEST(WallLoopMaps, TheRealCorridorMapIsSweptAlongItsWallsFirst) {
    const Plan corridor =
        importPlanFile(std::string(FC_REAL_MAPS_DIR) + "/localization-demo.yaml").project.plan;
    const Pair pair = planBoth(corridor, "localization-demo");
    // 397 m against 423 m (454 m until the rooms met the floor's corners exactly, which
    // spared the plan without the loop a cell at every doorway).
    EXPECT_LT(pair.with.metrics.length, 0.95 * pair.without.metrics.length);
}

// Every room picked (the editor's pick tool, `--rooms` naming them all) is the whole floor
// when the rooms cover it, as an imported map's do: planned as with none named, the loop
// included. The loop used to be drafted only with none named: the faculty map with both
// rooms named planned 1,929 m and 1,360 turns instead of 1,713 m and 907.
TEST(WallLoopMaps, EveryRoomPickedPlansAsNoneNamed) {
    const Plan corridor =
        importPlanFile(std::string(FC_REAL_MAPS_DIR) + "/localization-demo.yaml").project.plan;
    ASSERT_GE(corridor.rooms.size(), 2u);
    PlanRequest request = loopRequest(corridor);
    const PlanResult none = planCoverage(request);
    for (const Room& room : corridor.rooms)
        request.rooms.push_back(room.name);
    EXPECT_TRUE(detail::everyRoomAsked(request));
    const PlanResult every = planCoverage(request);
    EXPECT_NEAR(every.metrics.length, none.metrics.length, 1e-6);
    EXPECT_EQ(every.metrics.turns, none.metrics.turns);
    EXPECT_NEAR(every.metrics.coverage, none.metrics.coverage, 1e-9);
    // A name that is no room is refused, also beside every real one (it was dropped without
    // a word where the rooms sweep at several angles).
    PlanRequest unknown = request;
    unknown.rooms.push_back("No such room");
    EXPECT_THROW(planCoverage(unknown), InputError);
    // One room left out: a subset, which would need a loop round its own walls.
    request.rooms.pop_back();
    EXPECT_FALSE(detail::everyRoomAsked(request));
    EXPECT_FALSE(detail::wantsWallLoop(request));
    // Rooms that leave part of the floor out are not the whole floor.
    Plan partial = corridor;
    partial.rooms.resize(1);
    PlanRequest one = loopRequest(partial);
    one.rooms = {partial.rooms.front().name};
    EXPECT_FALSE(detail::everyRoomAsked(one));
}

// A ragged outline (5 cm jitter every 0.25 m, as a traced wall) through the given corners.
Ring jittered(const std::vector<Vec2>& corners, std::mt19937_64& rng) {
    Ring ring;
    std::uniform_real_distribution<> jitter(-0.025, 0.025);
    for (size_t i = 0; i < corners.size(); ++i) {
        const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
        const Vec2 along = b - a, inward = Vec2{-along.y, along.x} * (1.0 / norm(along));
        const int pieces = static_cast<int>(std::ceil(norm(along) / 0.25));
        for (int k = 0; k < pieces; ++k)
            ring.push_back(a + along * (static_cast<double>(k) / pieces) +
                           inward * (k == 0 ? 0.0 : jitter(rng)));
    }
    return ring;
}

// Length of the path's segments inside the box [x0, x1] x [y0, y1] (sampled every 1 cm).
double lengthInside(const Polyline& path, Vec2 low, Vec2 high) {
    double inside = 0.0;
    for (size_t i = 1; i < path.size(); ++i) {
        const Vec2 a = path[i - 1], b = path[i];
        const int steps = std::max(1, static_cast<int>(norm(b - a) / 0.01));
        for (int k = 0; k < steps; ++k) {
            const Vec2 p = a + (b - a) * ((k + 0.5) / steps);
            if (p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y)
                inside += norm(b - a) / steps;
        }
    }
    return inside;
}

// The start at the far end of a dead-end corridor (1.5 m wide, 8 m long) off a traced hall:
// the loop's two sides sweep the corridor whole, and the rest's tour leaves the loop where
// it enters the hall and comes back there, instead of driving the corridor twice more
// from the loop's end and back to the start.
TEST(WallLoopMaps, TheRestIsTouredFromWhereTheLoopEntersTheFloor) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        std::mt19937_64 rng(seed);
        Plan drawing;
        drawing.boundary =
            jittered({{0, 0}, {1, 0}, {1, -8}, {2.5, -8}, {2.5, 0}, {12, 0}, {12, 8}, {0, 8}}, rng);
        // At an odd angle and a UTM-sized offset; the far end moved with it.
        const Plan plan = placed(drawing, seed);
        PlanRequest request = loopRequest(plan);
        request.start = placedPoint({1.75, -7.5}, seed, true);
        ASSERT_TRUE(detail::wantsWallLoop(request));
        std::promise<double> estimate;
        const detail::WallLoopDraft draft = detail::draftWallLoop(request, {}, estimate);
        ASSERT_FALSE(draft.path.empty());
        const PlanResult result = planCoverage(request);
        EXPECT_GE(result.metrics.coverage, 0.99);
        // The corridor in the drawing's frame: the path's points moved back.
        Polyline back;
        for (const Vec2& p : draft.path.points)
            back.push_back(placedPoint(p, seed, false));
        const double corridor = lengthInside(back, {1.0, -8.0}, {2.5, -0.5});
        std::printf("seed %llu: the wall loop's draft %.1f m, %.1f m of it in the corridor (7.5 m "
                    "long); the plan kept %.1f m\n",
                    static_cast<unsigned long long>(seed), polylineLength(draft.path.points),
                    corridor, result.metrics.length);
        // Down and up once (the loop's two sides), not twice more.
        EXPECT_LT(corridor, 2.6 * 7.5) << "seed " << seed;
    }
}

// Length of the path's transits.
double transitLength(const CoveragePath& path) {
    double length = 0.0;
    for (size_t i = 1; i < path.points.size(); ++i)
        if (path.kinds[i - 1] == SegmentKind::Transit)
            length += norm(path.points[i] - path.points[i - 1]);
    return length;
}

// The corridor map with its end at the corridor's far end (the robot parked there): the
// rest's pieces are toured in an order by cheapest insertion, the room the corridor passes on
// the way included. Taking the nearest piece next swept the middle to the far end, drove 37 m
// back to that room and 42 m to the end again: 415 m with 108 m of transits (now 337 m, 40 m).
TEST(WallLoopMaps, APathEndedAtTheFarEndSweepsThePassedRoomOnTheWay) {
    const Plan corridor =
        importPlanFile(std::string(FC_REAL_MAPS_DIR) + "/localization-demo.yaml").project.plan;
    PlanRequest request = loopRequest(corridor);
    request.end = Vec2{-30.5, -12.0};
    const PlanResult open = planCoverage(request);
    EXPECT_GE(open.metrics.coverage, 0.99);
    EXPECT_LT(transitLength(open.path), 60.0);
    EXPECT_LT(open.metrics.length, 370.0);
}

// Two traced halls (8 x 8 m) at the ends of a corridor 1.6 m wide and 20 m long, the start in
// a far corner of one: each hall's middle is swept where the loop passes it, as an excursion
// from the loop and back, not toured from one point of the loop, which crossed the corridor
// between the halls by transit twice: 54 and 68 m of transits, against 5 and 14 m now.
TEST(WallLoopMaps, EachPieceOfTheRestIsAnExcursionFromTheLoopBesideIt) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        std::mt19937_64 rng(seed);
        Plan drawing;
        drawing.boundary = jittered({{0, 0},
                                     {8, 0},
                                     {8, 3.2},
                                     {28, 3.2},
                                     {28, 0},
                                     {36, 0},
                                     {36, 8},
                                     {28, 8},
                                     {28, 4.8},
                                     {8, 4.8},
                                     {8, 8},
                                     {0, 8}},
                                    rng);
        const Plan plan = placed(drawing, seed);
        PlanRequest request = loopRequest(plan);
        request.start = placedPoint({0.5, 0.5}, seed, true);
        ASSERT_TRUE(detail::wantsWallLoop(request));
        std::promise<double> estimate;
        const detail::WallLoopDraft draft = detail::draftWallLoop(request, {}, estimate);
        ASSERT_FALSE(draft.path.empty());
        const double transits = transitLength(draft.path);
        const PlanResult result = planCoverage(request);
        std::printf("seed %llu: the wall loop's draft %.1f m, %.1f m of transits; the plan kept "
                    "%.1f m, coverage %.4f\n",
                    static_cast<unsigned long long>(seed), polylineLength(draft.path.points),
                    transits, result.metrics.length, result.metrics.coverage);
        EXPECT_LT(transits, 20.0) << "seed " << seed;
        EXPECT_GE(result.metrics.coverage, 0.99) << "seed " << seed;
    }
}

// A store room inside a traced hall (walls jittered as a tracing leaves them) whose only door is
// 0.4 m wide, narrower than the robot: a piece of the rest that the loop cannot get to (on a map
// imported without cleaning, pockets behind specks are many). The draft leaves that piece out and
// plans the others; it used to give up on the whole loop there, after planning every piece before
// it.
TEST(WallLoopMaps, APieceBehindAGapTooNarrowIsLeftOutNotTheWholeLoop) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        std::mt19937_64 rng(seed);
        Plan drawing;
        drawing.boundary = jittered({{0, 0}, {14, 0}, {14, 10}, {0, 10}}, rng);
        // Walls 0.1 m thick round [5, 9] x [3, 7], the door in the west wall at y 4.8-5.2.
        drawing.obstacles.push_back(jittered({{5, 3},
                                              {9, 3},
                                              {9, 7},
                                              {5, 7},
                                              {5, 5.2},
                                              {5.1, 5.2},
                                              {5.1, 6.9},
                                              {8.9, 6.9},
                                              {8.9, 3.1},
                                              {5.1, 3.1},
                                              {5.1, 4.8},
                                              {5, 4.8}},
                                             rng));
        const Plan plan = placed(drawing, seed);
        PlanRequest request = loopRequest(plan);
        ASSERT_TRUE(detail::wantsWallLoop(request));
        std::promise<double> estimate;
        detail::WallLoopDraft draft;
        ASSERT_NO_THROW(draft = detail::draftWallLoop(request, {}, estimate)) << "seed " << seed;
        ASSERT_FALSE(draft.path.empty());
        Polyline back;
        for (const Vec2& p : draft.path.points)
            back.push_back(placedPoint(p, seed, false));
        EXPECT_EQ(lengthInside(back, {5.1, 3.1}, {8.9, 6.9}), 0.0) << "seed " << seed;
        // The independent checker: the draft is clear of every wall, and it sweeps the hall
        // round the store room.
        const fccheck::Clearance clearance = fccheck::minimumClearance(
            fcgen::freeSpaceOf(plan), fcgen::polylineOf(draft.path.points));
        EXPECT_TRUE(fccheck::isCollisionFree(clearance, request.robot.robotDiameter))
            << "seed " << seed << ": clearance " << clearance.minimum;
        const double storeRoom = 3.8 * 3.8;
        const PlanResult result = planCoverage(request);
        std::printf("seed %llu: the wall loop's draft %.1f m; the plan kept %.1f m, %.1f m^2 "
                    "unswept, %.1f m^2 out of reach (the store room: %.1f m^2)\n",
                    static_cast<unsigned long long>(seed), polylineLength(draft.path.points),
                    result.metrics.length, result.metrics.uncoveredArea,
                    result.metrics.unreachableArea, storeRoom);
        // The store room is measured unswept (a robot set down in it could sweep it), and
        // little else is.
        EXPECT_GT(result.metrics.uncoveredArea, 0.8 * storeRoom);
        EXPECT_LT(result.metrics.uncoveredArea, 0.01 * result.metrics.requiredArea + storeRoom);
    }
}

// `ring` with every side cut into pieces of at most `step` (a CAD export's polylines).
Ring cutEvery(const Ring& ring, double step) {
    Ring out;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        const int pieces = std::max(1, static_cast<int>(std::ceil(norm(b - a) / step)));
        for (int k = 0; k < pieces; ++k)
            out.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
    }
    return out;
}

// Walls drawn as straight runs cut into short segments are not ragged: the ward with every
// side cut every 0.2 m drafted a loop that never won (0.7 s of planning became 1.8 s).
TEST(WallLoopMaps, StraightWallsCutIntoShortSegmentsAreNotRagged) {
    for (const char* name : {"ward", "office", "room-obstacle"}) {
        Plan plan = loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
        plan.boundary = cutEvery(plan.boundary, 0.2);
        for (Ring& obstacle : plan.obstacles)
            obstacle = cutEvery(obstacle, 0.2);
        EXPECT_FALSE(detail::wantsWallLoop(loopRequest(plan))) << name;
    }
    // Round pillars are (their sides turn), and so is a hall of small square ones.
    EXPECT_TRUE(detail::wantsWallLoop(loopRequest(pillarHall(1, 32))));
    EXPECT_TRUE(detail::wantsWallLoop(loopRequest(pillarHall(1, 4))));
    Plan bare = pillarHall(1, 4);
    bare.obstacles.clear();
    EXPECT_FALSE(detail::wantsWallLoop(loopRequest(bare)));
}

// A real map's walls are ragged whatever its cells: the faculty map at 10 cm cells, traced
// and simplified within a cell, averaged 0.51 W pieces (0.33 W at 5 cm) and the lab's 0.58 W;
// under a bound of W/2 they drafted no loop and planned 19.5% and 11.3% slower than at their
// own cells. (A traced drawing of straight walls is not ragged: the importer straightens
// them, and the office's noisy maps average 1.1-1.6 m pieces.)
TEST(WallLoopMaps, RealMapsAreRaggedAtTwiceTheirCellSize) {
    const auto dir = std::filesystem::temp_directory_path() / "fc-wall-loop-cells";
    for (const char* name : {"telecom-faculty", "uwb-localization-demo", "localization-demo"}) {
        const std::string yaml = std::string(FC_REAL_MAPS_DIR) + "/" + name + ".yaml";
        for (const std::string& source :
             {yaml, test::resampledMap(yaml, test::Resample::Coarser, dir.string())}) {
            const Plan map = importPlanFile(source).project.plan;
            const double piece = detail::averageWallPiece(map);
            std::printf("%s: wall pieces average %.3f m\n", source.c_str(), piece);
            EXPECT_TRUE(detail::wantsWallLoop(loopRequest(map)))
                << source << ": wall pieces average " << piece << " m";
        }
    }
}

// The share of a path's stripe length (segments over 1 m) within a degree of `angle`.
double stripeShareAt(const CoveragePath& path, double angle) {
    double at = 0.0, all = 0.0;
    for (size_t i = 0; i < path.kinds.size(); ++i) {
        const Vec2 d = path.points[i + 1] - path.points[i];
        if (path.kinds[i] != SegmentKind::Stripe || norm(d) <= 1.0)
            continue;
        const double off =
            std::abs(std::fmod(std::atan2(d.y, d.x) * 180.0 / M_PI - angle + 360.0, 180.0));
        all += norm(d);
        at += std::min(off, 180.0 - off) < 1.0 ? norm(d) : 0.0;
    }
    return all > 0.0 ? at / all : 0.0;
}

// An angle the user fixed holds for the stripes over the wall loop's rest too: `--angle 30`
// on a traced map gave the loop's rest stripes along its walls (the faculty map: 97 degrees
// for --angle 45), and so did a room's fixed angle in the editor.
TEST(WallLoopMaps, AFixedAngleHoldsForTheStripesBesideTheLoop) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const Plan map = traced(raggedHall(seed), "hall", seed);
        ASSERT_TRUE(detail::wantsWallLoop(loopRequest(map))) << seed;
        PlanRequest whole = loopRequest(map);
        whole.sweep.perRoom = false;
        whole.sweep.angleDeg = 30.0;
        PlanRequest rooms = loopRequest(map);
        for (const Room& room : map.rooms)
            rooms.sweep.roomAngles[room.name] = 30.0;
        if (map.rooms.empty())
            rooms.sweep.roomAngles["Floor"] = 30.0;
        for (const PlanRequest& request : {whole, rooms}) {
            // A few stripes bend round traced furniture or end along a slanted wall.
            const double share = stripeShareAt(planCoverage(request).path, 30.0);
            std::printf("seed %d%s: %.1f%% of the stripes at 30 degrees\n", static_cast<int>(seed),
                        request.sweep.perRoom ? ", rooms' angles" : "", 100.0 * share);
            EXPECT_GT(share, 0.9) << "seed " << seed
                                  << (request.sweep.perRoom ? ", rooms' angles" : "");
        }
    }
}

// The same floor turned plans alike: the wall loop's pieces were simplified from wherever
// Boost started their rings, which moves with the turn. The faculty map's imported plan
// turned by 45 or 90 degrees planned 7% slower than upright (5,580 s and 5,557 s against
// 5,204 s); then within 1% at any of 12 turns. Since unknown patches without returns are
// floor (0.85 m^2 more of this map), the main piece of the rest comes out of Boost's overlays
// with 2-3 vertices more or less by the turn, and its dense lattice's estimated saving falls
// on either side of the 25% at which it is laid out (27.1% upright, 24.8% turned by 180
// degrees): 4 of 12 turns planned 3.6-3.9% slower. Pieces near that threshold are now planned
// in both layouts, and those turns plan 3.4-4.3% faster than upright (a better dense plan of
// their outline). Not stable yet; the bound is 4%.
TEST(WallLoopMaps, ATurnedMapPlansAsUpright) {
    const Plan upright =
        importPlanFile(std::string(FC_REAL_MAPS_DIR) + "/telecom-faculty.yaml").project.plan;
    auto turned = [&](double degrees) {
        const double a = degrees * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
        auto turn = [&](Ring ring) {
            for (Vec2& p : ring)
                p = Vec2{c * p.x - s * p.y, s * p.x + c * p.y};
            return ring;
        };
        Plan plan = upright;
        plan.boundary = turn(plan.boundary);
        for (Ring& obstacle : plan.obstacles)
            obstacle = turn(obstacle);
        for (Room& room : plan.rooms)
            room.outline = turn(room.outline);
        return plan;
    };
    const double time = planCoverage(loopRequest(upright)).metrics.time;
    for (double degrees : {45.0, 90.0}) {
        const double turnedTime = planCoverage(loopRequest(turned(degrees))).metrics.time;
        std::printf("faculty turned by %.0f degrees: %.1f s, upright %.1f s\n", degrees, turnedTime,
                    time);
        EXPECT_NEAR(turnedTime, time, 0.04 * time) << degrees;
    }
}

// A rest piece whose dense lattice saves about the 25% at which Auto lays it out is planned
// in the other layout too: the estimate moves with the piece's outline, which moves with how
// the plan is turned. Far from the threshold, or where the dense lattice is not offered at
// all, only Auto's pick is planned.
TEST(WallLoopMaps, APieceNearTheDenseThresholdIsPlannedInBothLayouts) {
    Plan square;
    square.boundary = {{0, 0}, {6, 0}, {6, 6}, {0, 6}};
    const detail::PieceLayouts layouts(square, RobotProfile{}, true);
    Decomposition chosen;
    chosen.denseLatticeAvailable = true;
    chosen.layout = LatticeMode::Dense;
    chosen.denseSaving = 0.271; // the faculty's main piece upright
    EXPECT_EQ(layouts.alternative(chosen), layouts.own.get());
    chosen.layout = LatticeMode::Own;
    chosen.denseSaving = 0.248; // turned by 180 degrees
    EXPECT_EQ(layouts.alternative(chosen), layouts.dense.get());
    chosen.denseSaving = 0.10;
    EXPECT_EQ(layouts.alternative(chosen), nullptr);
    chosen.layout = LatticeMode::Dense;
    chosen.denseSaving = 0.40; // the faculty's whole floor
    EXPECT_EQ(layouts.alternative(chosen), nullptr);
    chosen.denseSaving = 0.26;
    chosen.denseLatticeAvailable = false;
    EXPECT_EQ(layouts.alternative(chosen), nullptr);
    EXPECT_EQ(layouts.automatic->stripeLattice(), LatticeMode::Auto);
    EXPECT_EQ(layouts.dense->stripeLattice(), LatticeMode::Dense);
    EXPECT_EQ(layouts.own->stripeLattice(), LatticeMode::Own);
}

// Drawn plans' walls run metres between corners: no loop is drafted and their paths stay
// what they were.
TEST(WallLoopMaps, DrawnPlansKeepTheirPaths) {
    for (const char* name : {"office", "room-obstacle"}) {
        const Plan plan = normalizedPlan(
            loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan);
        const Pair pair = planBoth(plan, name);
        EXPECT_NEAR(pair.with.metrics.length, pair.without.metrics.length, 1e-6) << name;
    }
}

} // namespace
} // namespace fc
