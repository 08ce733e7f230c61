// Straightening traced map walls (importers/MapWalls): ragged walls become lines within the
// band, shallow notches are filled, teeth deeper than the band and round walls are kept.
#include "NoisyMap.h"
#include "formats/PlanIO.h"
#include "importers/Import.h"
#include "importers/MapWalls.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <numeric>
#include <random>

namespace fc {
namespace {

using importing::StraightenOptions;
using importing::StraightenStats;

// A w x h rectangle (counter-clockwise) traced every pixel with up to `jitter` of noise
// across each wall, a notch (depth `notch`, 12 px wide) into the bottom wall and a tooth
// (depth `tooth`, 6 px wide) into the room from the top wall, turned by `deg`.
Ring raggedRoom(double w, double h, double jitter, double notch, double tooth, double deg,
                unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> noise(-jitter, jitter);
    Ring r;
    for (double x = 0; x < w; x += 1) {
        const bool inNotch = x >= 40 && x < 52;
        r.push_back({x, (inNotch ? -notch : 0.0) + noise(rng)});
    }
    for (double y = 0; y < h; y += 1)
        r.push_back({w + noise(rng), y});
    for (double x = w; x > 0; x -= 1) {
        const bool inTooth = x > 100 && x <= 106;
        r.push_back({x, h - (inTooth ? tooth : 0.0) + noise(rng)});
    }
    for (double y = h; y > 0; y -= 1)
        r.push_back({noise(rng), y});
    const double a = deg * M_PI / 180.0;
    for (Vec2& p : r)
        p = {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a)};
    return r;
}

double areaOf(const Ring& r) {
    return std::abs(ringArea(r));
}

StraightenOptions optionsAt(double deg) {
    StraightenOptions o;
    o.angleDeg = deg;
    o.band = 1.0;
    o.notchDepth = 2.5;
    o.minRun = 4.0;
    return o;
}

TEST(WallStraightening, ARaggedRoomAtAnyAngleBecomesItsFourWalls) {
    for (double deg : {0.0, 17.0, 45.0, 73.5}) {
        StraightenStats stats;
        const Ring room = raggedRoom(200, 100, 0.5, 2.0, 0.0, deg, 3);
        const Ring straight = importing::straightenRing(room, true, optionsAt(deg), stats);
        // The notch (2 px, under the 2.5 px limit) is filled: four corners remain.
        EXPECT_EQ(straight.size(), 4u) << deg;
        EXPECT_NEAR(areaOf(straight), 200.0 * 100.0, 0.01 * 200 * 100) << deg;
        EXPECT_EQ(stats.notchesFilled, 1) << deg;
        const double a = deg * M_PI / 180.0;
        for (Vec2 corner : {Vec2{0, 0}, Vec2{200, 0}, Vec2{200, 100}, Vec2{0, 100}}) {
            const Vec2 c{corner.x * std::cos(a) - corner.y * std::sin(a),
                         corner.x * std::sin(a) + corner.y * std::cos(a)};
            double nearest = INFINITY;
            for (const Vec2& p : straight)
                nearest = std::min(nearest, distance(p, c));
            EXPECT_LT(nearest, 2.0) << deg;
        }
    }
}

// A pillar traced with its corners cut (a 45-degree chamfer 5 px along each wall, as the
// tracing and the opening leave them) and a rounded corner (an arc of radius 5 px): the walls
// meet at their intersections again when the corner may move that far (the map importer
// allows the opening's radius between walls of a metre or more). Cut corners had cost the
// room-obstacle noisy map of seed 7 1.2 m of path and 3 turns.
TEST(WallStraightening, CutAndRoundedCornersAreSquared) {
    for (double deg : {0.0, 23.0}) {
        Ring pillar;
        for (double x = 5; x < 95; x += 1)
            pillar.push_back({x, 0});
        for (double y = 5; y < 45; y += 1) // the chamfer (95, 0)-(100, 5) between the walls
            pillar.push_back({100, y});
        for (double x = 95; x > 5; x -= 1)
            pillar.push_back({x, 50});
        for (int k = 0; k <= 6; ++k) { // a round corner at (0, 50)
            const double t = M_PI / 2 + k * M_PI / 12;
            pillar.push_back({5 + 5 * std::cos(t), 45 + 5 * std::sin(t)});
        }
        for (double y = 44; y > 5; y -= 1)
            pillar.push_back({0, y});
        const double a = deg * M_PI / 180.0;
        for (Vec2& p : pillar)
            p = {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a)};
        StraightenOptions options = optionsAt(deg);
        options.chamferShift = 6.0;
        options.chamferMinWall = 20.0;
        StraightenStats stats;
        const Ring square = importing::straightenRing(pillar, false, options, stats);
        EXPECT_EQ(square.size(), 4u) << deg;
        EXPECT_NEAR(areaOf(square), 100.0 * 50.0, 1.0) << deg;
        // Within 3 px (the bound before), the cut corners stay; so do those of walls shorter
        // than chamferMinWall (clutter: the real maps planned longer with it squared).
        options.chamferShift = 3.0;
        EXPECT_GT(importing::straightenRing(pillar, false, options, stats).size(), 4u) << deg;
        options.chamferShift = 6.0;
        options.chamferMinWall = 60.0;
        EXPECT_GT(importing::straightenRing(pillar, false, options, stats).size(), 4u) << deg;
    }
}

TEST(WallStraighteningSafety, DeepNotchesAndTeethStay) {
    StraightenStats stats;
    // A notch deeper than the limit is floor the robot can use: it stays. A tooth deeper
    // than the band is a wall the robot must avoid: it stays too.
    const Ring room = raggedRoom(200, 100, 0.5, 6.0, 4.0, 0.0, 5);
    const Ring straight = importing::straightenRing(room, true, optionsAt(0), stats);
    EXPECT_EQ(straight.size(), 12u);
    EXPECT_EQ(stats.notchesFilled, 0);
    EXPECT_NEAR(areaOf(straight), 200.0 * 100 + 12 * 6 - 6 * 4, 0.01 * 200 * 100);
}

TEST(WallStraighteningSafety, AnObstacleIsStraightenedFromTheFloorSide) {
    // The same outline as an obstacle: its notch (towards the obstacle's inside) is floor
    // beside it, but now the bottom "notch" points away from the obstacle, into the floor:
    // it is a tooth of the obstacle and must stay.
    StraightenStats stats;
    const Ring pillar = raggedRoom(200, 100, 0.5, 2.0, 0.0, 0.0, 9);
    const Ring straight = importing::straightenRing(pillar, false, optionsAt(0), stats);
    EXPECT_EQ(stats.notchesFilled, 0);
    EXPECT_EQ(straight.size(), 8u);
}

TEST(WallStraightening, ARoundWallKeepsItsPoints) {
    Ring circle;
    for (int i = 0; i < 360; i += 3)
        circle.push_back({100 * std::cos(i * M_PI / 180), 100 * std::sin(i * M_PI / 180)});
    StraightenStats stats;
    const Ring straight = importing::straightenRing(circle, true, optionsAt(0), stats);
    EXPECT_GT(straight.size(), 80u);
    EXPECT_NEAR(areaOf(straight), areaOf(circle), 0.005 * areaOf(circle));
}

Plan samplePlan(const std::string& name) {
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

std::string noisyMapOf(const std::string& name, std::uint64_t seed) {
    const auto dir = std::filesystem::temp_directory_path() / ("fc-walls-" + name);
    std::filesystem::create_directories(dir);
    test::NoisyMapOptions options;
    options.seed = seed;
    return test::renderNoisyMap(samplePlan(name), options).write(dir.string(), name);
}

TEST(WallStraightening, ANoisyMapTracesIntoTheDrawingsFewWalls) {
    const std::string yaml = noisyMapOf("simple", 4);
    ImportOptions options;
    options.roomSegmentation.method = RoomSegmentationMethod::None;
    const ImportResult straight = importPlanFile(yaml, options);
    options.cleaning.straightenWalls = false;
    const ImportResult ragged = importPlanFile(yaml, options);
    ASSERT_TRUE(straight.cleaning && straight.cleaning->wallAngle);
    const double angle = *straight.cleaning->wallAngle;
    EXPECT_LT(std::min(angle, 90.0 - angle), 0.5);
    EXPECT_GT(straight.cleaning->wallsStraightened, 8);
    // The drawing: a 4-corner room and a 4-corner pillar; the ragged trace has hundreds.
    EXPECT_LT(straight.project.plan.boundary.size(), 40u);
    EXPECT_GT(ragged.project.plan.boundary.size(), 2 * straight.project.plan.boundary.size());
    // What straightening moved is reported and stays small.
    const double free = freeAreaOf(straight.project.plan);
    EXPECT_LT(straight.cleaning->straightenedAdded, 0.01 * free);
    EXPECT_LT(straight.cleaning->straightenedRemoved, 0.01 * free);
    EXPECT_NEAR(free, freeAreaOf(samplePlan("simple")), 0.02 * free);
}

TEST(WallStraightening, RoomsEndOnTheFloorsWalls) {
    const ImportResult imported = importPlanFile(noisyMapOf("office", 4));
    const Plan& plan = imported.project.plan;
    ASSERT_GT(plan.rooms.size(), 5u);
    // The rooms tile the floor: what lies outside every room is not a sliver along each
    // wall (before, a quarter of a square metre per room).
    double rooms = 0;
    for (const Room& r : plan.rooms)
        rooms += areaOf(r.outline);
    double obstaclesInRooms = 0;
    for (const Ring& o : plan.obstacles)
        obstaclesInRooms += areaOf(o);
    EXPECT_GT(rooms - obstaclesInRooms, 0.985 * freeAreaOf(plan));
}

// Where a room ends at one of the floor's corners (a doorway's jamb), it ends exactly there:
// a corner cut by a hair, as a bevelled opening of the room did, leaves a sliver between
// the two that starts cells of its own at every jamb (ward seed 6: 8 stripes an office for 6).
TEST(WallStraightening, RoomsMeetTheFloorsCornersExactly) {
    const Plan plan = importPlanFile(noisyMapOf("ward", 6)).project.plan;
    ASSERT_GT(plan.rooms.size(), 10u);
    int exact = 0, nearMisses = 0;
    for (const Room& room : plan.rooms)
        for (const Vec2& p : room.outline) {
            double nearest = INFINITY;
            for (const Vec2& q : plan.boundary)
                nearest = std::min(nearest, distance(p, q));
            exact += nearest < 1e-9;
            nearMisses += nearest >= 1e-9 && nearest < 0.01;
        }
    EXPECT_GT(exact, 4 * static_cast<int>(plan.rooms.size()));
    EXPECT_EQ(nearMisses, 0);
}

} // namespace
} // namespace fc

namespace fc {
namespace {

Plan turned(Plan plan, double deg) {
    const double a = deg * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
    auto turn = [&](Ring& ring) {
        for (Vec2& p : ring)
            p = {c * p.x - s * p.y, s * p.x + c * p.y};
    };
    turn(plan.boundary);
    for (Ring& o : plan.obstacles)
        turn(o);
    for (Room& r : plan.rooms)
        turn(r.outline);
    return plan;
}

// A map of a building drawn at an odd angle: the walls are found along it and straightened,
// and the floor keeps its area.
TEST(WallStraightening, AMapOfATurnedBuildingFindsItsAngle) {
    for (const char* name : {"simple", "room-obstacle"}) {
        const Plan plan = turned(samplePlan(name), 23.0);
        test::NoisyMapOptions options;
        options.seed = 5;
        const auto dir = std::filesystem::temp_directory_path() / "fc-walls-turned";
        std::filesystem::create_directories(dir);
        const std::string yaml = test::renderNoisyMap(plan, options).write(dir.string(), name);
        const ImportResult r = importPlanFile(yaml);
        ASSERT_TRUE(r.cleaning && r.cleaning->wallAngle) << name;
        const double off = std::fmod(*r.cleaning->wallAngle - 23.0 + 90.0, 90.0);
        EXPECT_LT(std::min(off, 90.0 - off), 0.3) << name;
        EXPECT_GE(r.cleaning->wallsStraightened, 8) << name; // 4 walls + a pillar's 4
        EXPECT_NEAR(freeAreaOf(r.project.plan), freeAreaOf(plan), 0.02 * freeAreaOf(plan)) << name;
        PlanRequest drawn, mapped;
        drawn.plan = plan;
        mapped.plan = r.project.plan;
        const double drawnLength = planCoverage(drawn).metrics.length;
        const PlanResult result = planCoverage(mapped);
        EXPECT_GT(result.metrics.coverage, 0.99) << name;
        // Measured: paths +25% (simple), +29% (room-obstacle) at 23 degrees, against 0-8%
        // for the same maps drawn along the pixel axes (docs/formats.md): the turned
        // outline's pixel staircase still leaves short folds.
        EXPECT_LT(result.metrics.length, 1.4 * drawnLength) << name;
    }
}

// A map of a building turned by 30 degrees: the rooms' territories met across each doorway
// along the pixel rows, diagonally through the wall, and gave each ward a jog 0.13 m into the
// corridor and the corridor a triangle of the passage (each a cell with its own stripe). Now
// each ward ends on its own wall and the corridor, with more doorways, owns the passages.
TEST(RoomSegmentation, DoorwayBordersOfATurnedMapFollowTheWalls) {
    const Plan drawing = turned(samplePlan("ward"), 30.0);
    test::NoisyMapOptions options;
    options.seed = 3;
    const auto dir = std::filesystem::temp_directory_path() / "fc-doorway-borders";
    std::filesystem::create_directories(dir);
    const ImportResult imported =
        importPlanFile(test::renderNoisyMap(drawing, options).write(dir.string(), "ward-30"));
    const Plan& map = imported.project.plan;
    ASSERT_EQ(map.rooms.size(), drawing.rooms.size());
    // The report counts each of the 16 doors once (16 now).
    ASSERT_TRUE(imported.cleaning);
    EXPECT_GE(imported.cleaning->doorwaysAligned, 14);
    EXPECT_LE(imported.cleaning->doorwaysAligned, 16);
    auto byArea = [](const Room& a, const Room& b) {
        return areaOf(a.outline) < areaOf(b.outline);
    };
    const Room& corridor = *std::max_element(drawing.rooms.begin(), drawing.rooms.end(), byArea);
    const Room& found = *std::max_element(map.rooms.begin(), map.rooms.end(), byArea);
    double furthest = 0; // of a ward's corners from the drawn wards' outlines
    for (const Room& room : map.rooms) {
        if (&room == &found)
            continue;
        for (const Vec2& p : room.outline) {
            double nearest = INFINITY;
            for (const Room& drawn : drawing.rooms) {
                if (&drawn == &corridor)
                    continue;
                const Ring& r = drawn.outline;
                for (size_t i = 0; i < r.size(); ++i)
                    nearest =
                        std::min(nearest, pointSegmentDistance(p, r[i], r[(i + 1) % r.size()]));
            }
            furthest = std::max(furthest, nearest);
        }
    }
    // 0.34 m with the diagonal borders; 0.17 m now, at a notch the tracing left in a wall.
    EXPECT_LT(furthest, 0.2);
    // The corridor holds its passages (0.2 m walls, 16 doors of 0.9 m): 3 m^2 more.
    EXPECT_NEAR(areaOf(found.outline), areaOf(corridor.outline) + 16 * 0.9 * 0.2, 1.5);
}

// Generated office floors (offices of several sizes off wing corridors joined by a spine,
// 1.2 m doors, furniture), upright and turned: each office is found, and the corridors,
// which meet without doors, are one room.
TEST(RoomSegmentation, GeneratedOfficeFloorsSplitIntoTheirRooms) {
    const auto dir = std::filesystem::temp_directory_path() / "fc-rooms-generated";
    std::filesystem::create_directories(dir);
    for (const auto& [rooms, seed] : {std::pair{6, 1u}, std::pair{10, 2u}, std::pair{16, 3u}}) {
        for (const double deg : {0.0, 31.0}) {
            const Plan plan = turned(generateOfficeFloor(rooms, seed), deg);
            Plan offices = plan;
            offices.rooms.clear();
            for (const Room& room : plan.rooms)
                if (room.name.find("Corridor") == std::string::npos && room.name != "Spine")
                    offices.rooms.push_back(room);
            test::NoisyMapOptions options;
            options.seed = seed;
            const std::string name =
                "office" + std::to_string(rooms) + "-" + std::to_string(static_cast<int>(deg));
            const ImportResult r =
                importPlanFile(test::renderNoisyMap(plan, options).write(dir.string(), name));
            EXPECT_EQ(r.project.plan.rooms.size(), offices.rooms.size() + 1) << name;
            const std::vector<double> ious = test::roomIoUs(offices, r.project.plan.rooms);
            // Measured: 0.986-0.993 (a few cells of each doorway go to either side).
            EXPECT_GE(*std::min_element(ious.begin(), ious.end()), 0.9) << name;
        }
    }
}

} // namespace
} // namespace fc
