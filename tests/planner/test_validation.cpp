// Plan validation: every geometric defect is an InputError naming the ring and the place,
// at small and at UTM-sized coordinates, fast on large plans.
#include "TestPlans.h"
#include "formats/PlanIO.h"
#include "model/OverlapArea.h"
#include "model/Validation.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

using namespace fc;
using fc::test::rectangle;
using fc::test::shifted;
namespace fs = std::filesystem;

namespace {

const std::string kPlansDir = FC_PLANS_DIR;
const std::string kDataDir = FC_TEST_DATA_DIR;
const Vec2 kUtmOffset{500000.0, 5000000.0};

std::string validationError(const Plan& plan, const RobotProfile& robot = {}) {
    try {
        validatePlan(normalizedPlan(plan), robot);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expectOneLineMessage(const std::string& message) {
    ASSERT_FALSE(message.empty());
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.back(), '.') << message;
    EXPECT_FALSE(std::isupper(static_cast<unsigned char>(message.front()))) << message;
}

void expectKeywords(const std::string& message, const std::vector<std::string>& keywords) {
    for (const std::string& keyword : keywords)
        EXPECT_NE(message.find(keyword), std::string::npos)
            << "missing \"" << keyword << "\" in: " << message;
}

struct FixtureCase {
    const char* file;
    std::vector<std::string> keywords;
};

const std::vector<FixtureCase> kGeometryFixtures = {
    {"selfintersecting.geojson", {"boundary", "intersects itself", "(5.0, 4.0)"}},
    {"hole-outside.geojson", {"obstacle 1", "outside the boundary"}},
    {"hole-crossing.geojson", {"obstacle 1", "crosses the boundary"}},
    {"overlapping-holes.geojson", {"obstacles 1 and 2", "overlap"}},
    {"duplicate-holes.geojson", {"obstacles 1 and 2", "identical"}},
    {"room-outside.geojson", {"room \"Garage\"", "outside the boundary"}},
    {"room-in-obstacle.geojson", {"room \"Shaft\"", "inside obstacle 1"}},
    {"overlapping-rooms.geojson", {"rooms \"West\" and \"East\"", "overlap", "16.00 m^2"}},
    {"tiny.geojson", {"free area", "0.25 m^2", "smaller"}},
    {"zero-area.geojson", {"boundary", "zero area"}},
    {"spike.geojson", {"boundary", "spike", "(5.0, 12.0)"}},
};

} // namespace

TEST(Validation, SamplePlansAreValid) {
    for (const auto& entry : fs::directory_iterator(kPlansDir)) {
        if (entry.path().extension() != ".geojson")
            continue;
        SCOPED_TRACE(entry.path().string());
        const Plan plan = loadProjectFile(entry.path().string()).plan;
        EXPECT_NO_THROW(validatePlan(normalizedPlan(plan), RobotProfile{}));
        EXPECT_NO_THROW(validatePlan(plan, RobotProfile{})) << "valid without clean-up too";
        EXPECT_NO_THROW(validatePlan(normalizedPlan(shifted(plan, kUtmOffset)), RobotProfile{}));
    }
    for (const char* valid : {"utm-offset.geojson", "rooms-with-hole.geojson"}) {
        SCOPED_TRACE(valid);
        const Plan plan = loadProjectFile(kDataDir + "/" + valid).plan;
        EXPECT_EQ(validationError(plan), "");
    }
}

TEST(Validation, FixturesGiveOneLineErrorsNamingRingAndPlace) {
    for (const FixtureCase& c : kGeometryFixtures) {
        SCOPED_TRACE(c.file);
        const Plan plan = loadProjectFile(kDataDir + "/" + c.file).plan;
        const std::string message = validationError(plan);
        expectOneLineMessage(message);
        expectKeywords(message, c.keywords);
    }
}

TEST(Validation, SameVerdictAtUtmCoordinates) {
    for (const FixtureCase& c : kGeometryFixtures) {
        SCOPED_TRACE(c.file);
        const Plan plan = loadProjectFile(kDataDir + "/" + c.file).plan;
        const std::string message = validationError(shifted(plan, kUtmOffset));
        expectOneLineMessage(message);
        for (const std::string& keyword : c.keywords) {
            if (keyword.front() != '(') { // locations move with the offset
                EXPECT_NE(message.find(keyword), std::string::npos) << message;
            }
        }
    }
}

TEST(Validation, RobotProfileIsChecked) {
    Plan plan;
    plan.boundary = rectangle(0, 0, 10, 10);
    RobotProfile robot;
    robot.robotDiameter = 1.5; // L > W
    expectKeywords(validationError(plan, robot), {"robot diameter"});
    const Project project = loadProjectFile(kDataDir + "/bad-robot.fcproj");
    expectKeywords(validationError(project.plan, project.robot), {"exceeds"});
}

// A drawing in millimetres read as metres (an office 30 km across) would plan for hours in
// tens of GB: refused at once, naming the likely cause. A 1 km^2 site still plans.
TEST(Validation, APlanInMillimetresIsRefusedNamingTheUnits) {
    Plan huge;
    huge.boundary = rectangle(0, 0, 30000, 20000);
    try {
        validatePlan(huge, RobotProfile{});
        ADD_FAILURE() << "a 600 km^2 floor was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("in metres?"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("600000 km of stripes"), std::string::npos)
            << e.what();
    }
    Plan site;
    site.boundary = rectangle(0, 0, 1000, 1000);
    EXPECT_NO_THROW(validatePlan(site, RobotProfile{}));
}

// A coverage width in millimetres: a 573 m^2 office at W = 5 mm is 23 million squares W^2
// (6 GB); refused at once, naming W. One centimetre still plans.
TEST(Validation, AWidthOfMillimetresIsRefusedNamingW) {
    Plan office;
    office.boundary = rectangle(0, 0, 30, 20);
    RobotProfile robot;
    robot.coverageWidth = robot.robotDiameter = robot.cleaningDiameter = 0.005;
    const std::string message = validationError(office, robot);
    expectOneLineMessage(message);
    expectKeywords(message, {"24.0 million coverage squares", "W = 0.005", "in metres?"});
    robot.coverageWidth = robot.robotDiameter = robot.cleaningDiameter = 0.01;
    EXPECT_NO_THROW(validatePlan(office, robot));
}

TEST(Validation, NonFiniteCoordinatesNameTheRing) {
    Plan plan;
    plan.boundary = rectangle(0, 0, 10, 10);
    plan.obstacles = {rectangle(1, 1, 2, 2), rectangle(4, 4, 5, 5)};
    plan.obstacles[1][2].y = NAN;
    const std::string message = validationError(plan);
    expectOneLineMessage(message);
    expectKeywords(message, {"obstacle 2", "non-finite", "vertex 3"});
}

TEST(Validation, ObstaclePlacement) {
    Plan plan;
    plan.boundary = rectangle(0, 0, 10, 10);
    plan.obstacles = {rectangle(2, 2, 8, 8), rectangle(4, 4, 5, 5)};
    expectKeywords(validationError(plan), {"obstacle 2 lies inside obstacle 1"});

    plan.obstacles = {rectangle(0, 2, 3, 4)};
    expectKeywords(validationError(plan), {"obstacle 1 touches the boundary"});

    plan.obstacles = {rectangle(2, 2, 4, 4), rectangle(4, 2, 6, 4)};
    expectKeywords(validationError(plan), {"obstacles 1 and 2 touch"});

    plan.obstacles = {rectangle(2, 2, 4, 4), rectangle(4.5, 2, 6, 4)};
    EXPECT_EQ(validationError(plan), "");
}

TEST(Validation, SelfIntersectionInRoomsAndObstacles) {
    Plan plan;
    plan.boundary = rectangle(0, 0, 10, 10);
    plan.obstacles = {{{2, 2}, {4, 4}, {4, 2}, {2, 4}}};
    expectKeywords(validationError(plan), {"obstacle 1 intersects itself near (3.0, 3.0)"});
    plan.obstacles.clear();
    plan.rooms = {{"Kitchen", {{0, 0}, {10, 10}, {10, 0}, {0, 10}}}};
    expectKeywords(validationError(plan), {"room \"Kitchen\" intersects itself"});
}

TEST(Validation, RoomsSharingWallsOrReachingIntoWallsAreFine) {
    Plan plan;
    plan.boundary = rectangle(0, 0, 10, 10);
    plan.obstacles = {rectangle(4, 4, 6, 6)};
    // Drawn over the wall thickness, sharing a border, one around the pillar.
    plan.rooms = {{"A", rectangle(-0.2, -0.2, 5, 10.2)}, {"B", rectangle(5, -0.2, 10.2, 10.2)}};
    EXPECT_EQ(validationError(plan), "");
    EXPECT_EQ(validationError(shifted(plan, kUtmOffset)), "");
    // A sliver of overlap from sloppy drawing is tolerated; a real one is not.
    plan.rooms[1].outline = rectangle(4.99, -0.2, 10.2, 10.2);
    EXPECT_EQ(validationError(plan), "");
    plan.rooms[1].outline = rectangle(4, -0.2, 10.2, 10.2);
    expectKeywords(validationError(plan), {"rooms \"A\" and \"B\" overlap"});
    // A room that is only the pillar covers no free space.
    plan.rooms = {{"Pillar", rectangle(4, 4, 6, 6)}};
    expectKeywords(validationError(plan), {"room \"Pillar\" lies inside obstacle 1"});
    plan.rooms = {{"Rooms", {}}, {"Rooms", rectangle(0, 0, 2, 2)}};
    plan.rooms[0].outline = rectangle(2, 2, 3, 3);
    expectKeywords(validationError(plan), {"duplicate room name \"Rooms\""});
}

TEST(Validation, RotatedRoomsAtUtmCoordinatesShareWallsWithinRounding) {
    // Room corners on the boundary's edges are computed separately, so they are off the
    // walls by rounding noise only; shared walls must still count as shared.
    const double angle = 30.0 * M_PI / 180.0;
    auto place = [&](double x, double y) {
        return kUtmOffset + Vec2{x * std::cos(angle) - y * std::sin(angle),
                                 x * std::sin(angle) + y * std::cos(angle)};
    };
    Plan plan;
    plan.boundary = {place(0, 0), place(12, 0), place(12, 8), place(0, 8)};
    plan.obstacles = {{place(2, 2), place(3, 2), place(3, 3), place(2, 3)}};
    const Vec2 bottom = place(5.3, 0), top = place(5.3, 8);
    plan.rooms = {{"West", {place(0, 0), bottom, top, place(0, 8)}},
                  {"East", {bottom, place(12, 0), place(12, 8), top}}};
    EXPECT_EQ(validationError(plan), "");
    plan.rooms[1].outline[0] = place(3.3, 0); // a triangle of 2 m x 8 m / 2 overlaps
    expectKeywords(validationError(plan), {"rooms \"West\" and \"East\" overlap by 8.00 m^2"});
    plan.rooms[1].outline[3] = place(3.3, 8); // and now a 2 m x 8 m strip
    expectKeywords(validationError(plan), {"rooms \"West\" and \"East\" overlap by 16.00 m^2"});
}

TEST(Validation, NormalizedPlanDropsRepeatsAndStraightVertices) {
    Plan plan;
    plan.boundary = {{0, 0},   {5, 0},     {5, 0},  {10, 0}, {10, 5},
                     {10, 10}, {5, 5 + 5}, {0, 10}, {0, 0}};
    plan.obstacles = {{{2, 2}, {3, 3}, {4, 4}, {2, 4}}};
    const Plan clean = normalizedPlan(plan);
    EXPECT_EQ(clean.boundary, rectangle(0, 0, 10, 10));
    EXPECT_EQ(clean.obstacles[0], (Ring{{2, 2}, {4, 4}, {2, 4}}));
    // The seam (last to first vertex) is cleaned too.
    plan.boundary = {{5, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
    EXPECT_EQ(normalizedPlan(plan).boundary, (Ring{{10, 0}, {10, 10}, {0, 10}, {0, 0}}));
    // Collinear vertices are found at UTM-sized values too.
    const Plan utm = normalizedPlan(shifted(plan, kUtmOffset));
    EXPECT_EQ(utm.obstacles[0].size(), 3u);
    // A degenerate ring is kept as it was so that validation can name the problem.
    plan.boundary = {{0, 0}, {5, 5}, {10, 10}};
    EXPECT_EQ(normalizedPlan(plan).boundary.size(), 3u);
}

TEST(Validation, ThousandRoomsValidateQuickly) {
    // 40 x 25 rooms of 2 x 2 m with a vertex at each edge midpoint (8 vertices each), a
    // pillar in every fourth room and a boundary with 1,000 vertices: ~10,000 vertices.
    const int columns = 40, rows = 25;
    Plan plan;
    const double width = 2.0 * columns, height = 2.0 * rows;
    const int perSide = 250;
    for (int k = 0; k < perSide; ++k)
        plan.boundary.push_back({width * k / perSide, 0});
    for (int k = 0; k < perSide; ++k)
        plan.boundary.push_back({width, height * k / perSide});
    for (int k = 0; k < perSide; ++k)
        plan.boundary.push_back({width - width * k / perSide, height});
    for (int k = 0; k < perSide; ++k)
        plan.boundary.push_back({0, height - height * k / perSide});
    for (int i = 0; i < columns; ++i) {
        for (int j = 0; j < rows; ++j) {
            const double x = 2.0 * i, y = 2.0 * j;
            plan.rooms.push_back({"R" + std::to_string(i) + "-" + std::to_string(j),
                                  {{x, y},
                                   {x + 1, y},
                                   {x + 2, y},
                                   {x + 2, y + 1},
                                   {x + 2, y + 2},
                                   {x + 1, y + 2},
                                   {x, y + 2},
                                   {x, y + 1}}});
            if ((i + j) % 4 == 0)
                plan.obstacles.push_back(rectangle(x + 0.8, y + 0.8, x + 1.2, y + 1.2));
        }
    }
    size_t vertices = plan.boundary.size();
    for (const Ring& obstacle : plan.obstacles)
        vertices += obstacle.size();
    for (const Room& room : plan.rooms)
        vertices += room.outline.size();
    EXPECT_GE(vertices, 10000u);

    for (const Vec2 offset : {Vec2{0, 0}, kUtmOffset}) {
        const Plan input = shifted(plan, offset);
        const auto start = std::chrono::steady_clock::now();
        EXPECT_NO_THROW(validatePlan(input, RobotProfile{}));
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
#ifdef NDEBUG
        EXPECT_LT(seconds, 0.5);
#else
        EXPECT_LT(seconds, 5.0);
#endif
    }
    // One defect among them is still found and named.
    plan.rooms[777].outline[2] = {plan.rooms[777].outline[2].x + 1.5, plan.rooms[777].outline[2].y};
    expectKeywords(validationError(plan), {"rooms", "overlap", plan.rooms[777].name});
}

// A room over a floor full of speckle (a traced map's thousands of small obstacles): the
// shared area of room and free space is the room less the specks' parts inside it, also for
// specks cut by the room's edges.
TEST(Validation, RoomOverThousandsOfSpecksSharesTheRightArea) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> jitter(0.0, 0.1);
    const Ring boundary{{0, 0}, {40, 0}, {40, 30}, {0, 30}};
    std::vector<overlap::DirectedEdge> freeEdges = overlap::edgesOf(boundary, true);
    std::vector<Ring> specks;
    const double roomX0 = 5.05, roomY0 = 4.02, roomX1 = 31.93, roomY1 = 22.07;
    double inside = 0.0;
    for (int i = 0; i < 80; ++i)
        for (int j = 0; j < 60; ++j) {
            const double x = 0.5 * i + 0.1 + jitter(rng), y = 0.5 * j + 0.1 + jitter(rng);
            const double s = 0.05 + jitter(rng);
            specks.push_back({{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}});
            const double w = std::max(0.0, std::min(x + s, roomX1) - std::max(x, roomX0));
            const double h = std::max(0.0, std::min(y + s, roomY1) - std::max(y, roomY0));
            inside += w * h;
        }
    for (const Ring& speck : specks) {
        const auto edges = overlap::edgesOf(speck, false);
        freeEdges.insert(freeEdges.end(), edges.begin(), edges.end());
    }
    const overlap::EvenOddIndex freeIndex(freeEdges);
    const Ring room{{roomX0, roomY0}, {roomX1, roomY0}, {roomX1, roomY1}, {roomX0, roomY1}};
    const auto roomEdges = overlap::edgesOf(room, true);
    const overlap::EvenOddIndex roomIndex(roomEdges);
    const auto shared = overlap::overlapArea(
        roomEdges, [&](Vec2 p) { return roomIndex.contains(p); }, freeEdges,
        [&](Vec2 p) { return freeIndex.contains(p); }, boundary.front(), 1e-9);
    EXPECT_GT(inside, 10.0); // the specks matter
    EXPECT_NEAR(shared.area, ringArea(room) - inside, 1e-6);
    // The plan itself validates with one room over the specks.
    Plan plan;
    plan.boundary = boundary;
    plan.obstacles = specks;
    plan.rooms.push_back({"Hall", room});
    EXPECT_NO_THROW(validatePlan(plan, RobotProfile{}));
}
