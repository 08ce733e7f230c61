// ROS map_server occupancy maps: PGM (P5, P2) and PNG images with known free areas.
#include "ImportTestSupport.h"

#include <cmath>
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <sstream>

namespace fc {
namespace {

constexpr unsigned char kFree = 254, kOccupied = 0, kUnknown = 205;

// A 10 x 6 m room (0.05 m pixels) inside a 3-pixel wall, a 1 x 0.5 m pillar, an unknown
// 0.5 x 0.5 m patch, and a lone free pixel outside (a separate part, dropped).
struct Map {
    int width = 206, height = 126;
    std::vector<unsigned char> pixels;
    double freeArea = 0;
    Map() : pixels(static_cast<size_t>(width * height), kOccupied) {
        auto fill = [&](int x0, int y0, int x1, int y1, unsigned char v) {
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x)
                    pixels[static_cast<size_t>(y * width + x)] = v;
        };
        fill(3, 3, 203, 123, kFree);                        // 200 x 120 px = 10 x 6 m
        fill(50, 40, 70, 50, kOccupied);                    // pillar 1 x 0.5 m
        fill(150, 75, 170, 95, kUnknown);                   // unknown 1 x 1 m
        pixels[static_cast<size_t>(1 * width + 1)] = kFree; // noise in the wall
        freeArea = 10 * 6 - 0.5 - 1.0;
    }
    std::string pgm(bool binary) const {
        std::ostringstream out;
        out << (binary ? "P5" : "P2") << "\n# written by the test\n"
            << width << " " << height << "\n255\n";
        if (binary)
            out.write(reinterpret_cast<const char*>(pixels.data()),
                      static_cast<std::streamsize>(pixels.size()));
        else
            for (unsigned char p : pixels)
                out << int(p) << (&p == &pixels.back() ? "\n" : " ");
        return out.str();
    }
};

std::string yaml(const std::string& image, const std::string& extra = "") {
    return "image: " + image +
           "\nresolution: 0.05\norigin: [-2.0, 1.5, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
           "free_thresh: 0.196  # map_saver's defaults\n" +
           extra;
}

TEST(RosMap, BinaryPgmGivesTheFreeAreaInMapCoordinates) {
    const auto dir = test::scratchDir("ros-p5");
    const Map map;
    test::writeText(dir / "room.pgm", map.pgm(true));
    const std::string path =
        test::writeText(dir / "room.yaml", yaml("room.pgm", "start_pose: [1.0, 2.5, 0.3]\n"));
    const ImportResult r = importPlanFile(path);
    EXPECT_NEAR(test::freeArea(r.project.plan), map.freeArea, 0.01 * map.freeArea);
    EXPECT_EQ(r.project.plan.obstacles.size(), 2u); // pillar and unknown patch (over 0.6 m^2)
    // Origin (-2, 1.5) is the lower-left pixel corner; the room starts 3 pixels in.
    const BoundingBox box = r.project.plan.bounds();
    EXPECT_NEAR(box.minX, -2.0 + 0.15, 0.03);
    EXPECT_NEAR(box.minY, 1.5 + 0.15, 0.03);
    EXPECT_NEAR(box.width(), 10.0, 0.03);
    // Image row 0 is the top: the pillar (rows 40..50 of 126) is in the upper half.
    double pillarY = 0;
    for (const Ring& o : r.project.plan.obstacles)
        if (std::abs(ringArea(o) - 0.5) < 0.05)
            pillarY = (boundsOf(o).minY + boundsOf(o).maxY) / 2;
    EXPECT_NEAR(pillarY, 1.5 + (126 - 45) * 0.05, 0.03);
    ASSERT_TRUE(r.robotStartPose);
    EXPECT_TRUE(r.project.hasStart);
    EXPECT_DOUBLE_EQ(r.project.start.x, 1.0);
    EXPECT_DOUBLE_EQ(r.project.start.y, 2.5);
    // The lone free pixel in the wall: cleaned away (the report counts it), without cleaning
    // a separate part named in a warning.
    EXPECT_TRUE(r.warnings.empty());
    ASSERT_TRUE(r.cleaning);
    ImportOptions raw;
    raw.cleaning.enabled = false;
    EXPECT_EQ(importPlanFile(path, raw).warnings.size(), 1u);
}

TEST(RosMap, AsciiPgmAndAmclPoseAndNegate) {
    const auto dir = test::scratchDir("ros-p2");
    Map map;
    for (unsigned char& p : map.pixels) // negate: dark is free
        p = static_cast<unsigned char>(255 - p);
    test::writeText(dir / "room.pgm", map.pgm(false));
    const std::string path = test::writeText(
        dir / "room.yml", "image: \"room.pgm\"\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 1\n"
                          "initial_pose_x: 3.0\ninitial_pose_y: 4.0\n");
    const ImportResult r = importPlanFile(path);
    EXPECT_NEAR(test::freeArea(r.project.plan), map.freeArea, 0.01 * map.freeArea);
    ASSERT_TRUE(r.robotStartPose);
    EXPECT_DOUBLE_EQ(r.robotStartPose->x, 3.0);
}

TEST(RosMap, AStartPoseOutsideTheFreeSpaceIsReportedNotUsed) {
    const auto dir = test::scratchDir("ros-start");
    const Map map;
    test::writeText(dir / "room.pgm", map.pgm(true));
    // (1.0, 5.5) is in the pillar: x -2 + (50..70) * 0.05, y 1.5 + (126 - 50..126 - 40) * 0.05
    const std::string path =
        test::writeText(dir / "room.yaml", yaml("room.pgm", "start_pose: [1.0, 5.5, 0]\n"));
    const ImportResult r = importPlanFile(path);
    EXPECT_FALSE(r.project.hasStart);
    EXPECT_NE(r.warnings.back().find("is not in the free space; not used"), std::string::npos);
}

TEST(RosMap, PngThroughGdal) {
    const auto dir = test::scratchDir("ros-png");
    Map map;
    GDALAllRegister();
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
    ASSERT_TRUE(mem && png);
    GDALDataset* raster = mem->Create("", map.width, map.height, 1, GDT_Byte, nullptr);
    ASSERT_EQ(raster->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, map.width, map.height,
                                                 map.pixels.data(), map.width, map.height, GDT_Byte,
                                                 0, 0, nullptr),
              CE_None);
    GDALClose(
        png->CreateCopy((dir / "room.png").c_str(), raster, FALSE, nullptr, nullptr, nullptr));
    GDALClose(raster);
    const std::string path = test::writeText(dir / "room.yaml", yaml("room.png"));
    const ImportResult r = importPlanFile(path);
    EXPECT_NEAR(test::freeArea(r.project.plan), map.freeArea, 0.01 * map.freeArea);
    EXPECT_FALSE(r.robotStartPose);
}

TEST(RosMap, RotatedOriginTurnsTheMap) {
    const auto dir = test::scratchDir("ros-yaw");
    const Map map;
    test::writeText(dir / "room.pgm", map.pgm(true));
    const std::string path =
        test::writeText(dir / "room.yaml",
                        "image: room.pgm\nresolution: 0.05\norigin: [0, 0, 1.5707963267948966]\n");
    const ImportResult r = importPlanFile(path);
    const BoundingBox box = r.project.plan.bounds();
    EXPECT_NEAR(box.width(), 6.0, 0.03); // 10 x 6 m turned a quarter
    EXPECT_NEAR(box.height(), 10.0, 0.03);
    EXPECT_NEAR(test::freeArea(r.project.plan), map.freeArea, 0.01 * map.freeArea);
}

// A desk edge or a glass wall the laser saw as a diagonal line of single cells: one obstacle,
// not a dotted line of diamonds (the cells' outlines through their edge midpoints) with
// passages the robot cannot pass, each cutting the floor into sliver cells; a line that ends
// closer to a wall than the robot's width joins the wall. Blocks further apart stay apart.
TEST(RosMap, ObstaclesTheRobotCannotPassBetweenAreJoined) {
    const auto dir = test::scratchDir("ros-passages");
    Map map;
    auto set = [&](int x, int y) {
        map.pixels[static_cast<size_t>(y * map.width + x)] = kOccupied;
    };
    map.pixels.assign(map.pixels.size(), kOccupied);
    for (int y = 3; y < 123; ++y)
        for (int x = 3; x < 203; ++x)
            map.pixels[static_cast<size_t>(y * map.width + x)] = kFree;
    // Lines of 2 x 2 cell blocks touching at their corners (a one-cell line is smoothed away).
    auto block = [&](int x, int y) { set(x, y), set(x + 1, y), set(x, y + 1), set(x + 1, y + 1); };
    for (int k = 0; k < 40; ++k) {
        block(30 + 2 * k, 20 + 2 * k);  // free-standing, 5.6 m long
        block(120 + 2 * k, 40 + 2 * k); // ends three cells (0.15 m) from two walls
    }
    for (int y = 20; y < 30; ++y)
        for (int x = 0; x < 10; ++x)
            set(130 + x, y), set(164 + x, y); // 0.5 m blocks 1.2 m apart
    test::writeText(dir / "lines.pgm", map.pgm(true));
    const std::string path = test::writeText(dir / "lines.yaml", yaml("lines.pgm"));
    const ImportResult r = importPlanFile(path);
    ASSERT_TRUE(r.cleaning);
    EXPECT_EQ(r.project.plan.obstacles.size(), 3u); // the free-standing line, two blocks
    EXPECT_GE(r.cleaning->obstaclesJoined, 50);
    EXPECT_GT(r.cleaning->passageArea, 0.0);
    EXPECT_LT(r.cleaning->passageArea, 0.5); // the gaps between the cells, not the floor
    const double lines = 2 * 160 * 0.05 * 0.05, blocks = 2 * 0.25;
    EXPECT_NEAR(test::freeArea(r.project.plan), 60.0 - lines - blocks, 1.0);
    // The joined line's outline is simplified like the rest, not left a staircase of blocks.
    for (const Ring& obstacle : r.project.plan.obstacles)
        EXPECT_LT(obstacle.size(), 20u);
}

// The same on a map large enough that each passage is judged on the floor round it (nested
// clips of the floor, importers/MapTracing.cpp): nine copies of a dotted line and of two
// blocks 1.2 m apart, wherever they fall against the clips' edges.
TEST(RosMap, PassagesAreJudgedAlikeAllOverABigMap) {
    const auto dir = test::scratchDir("ros-passages-big");
    const int width = 620, height = 380;
    std::vector<unsigned char> pixels(static_cast<size_t>(width * height), kOccupied);
    auto set = [&](int x, int y, unsigned char v) {
        pixels[static_cast<size_t>(y * width + x)] = v;
    };
    for (int y = 3; y < height - 3; ++y)
        for (int x = 3; x < width - 3; ++x)
            set(x, y, kFree);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int ox = 206 * i, oy = 126 * j;
            for (int k = 0; k < 40; ++k)
                for (int b = 0; b < 4; ++b)
                    set(ox + 30 + 2 * k + b % 2, oy + 20 + 2 * k + b / 2, kOccupied);
            for (int y = 20; y < 30; ++y)
                for (int x = 0; x < 10; ++x)
                    set(ox + 130 + x, oy + y, kOccupied), set(ox + 164 + x, oy + y, kOccupied);
        }
    std::ostringstream pgm;
    pgm << "P5\n" << width << " " << height << "\n255\n";
    pgm.write(reinterpret_cast<const char*>(pixels.data()),
              static_cast<std::streamsize>(pixels.size()));
    test::writeText(dir / "lines.pgm", pgm.str());
    const ImportResult r = importPlanFile(test::writeText(dir / "lines.yaml", yaml("lines.pgm")));
    ASSERT_TRUE(r.cleaning);
    EXPECT_EQ(r.project.plan.obstacles.size(), 27u); // nine lines, eighteen blocks
    // 77 per line: the count that judging each piece on the whole floor gave before the clips.
    EXPECT_EQ(r.cleaning->obstaclesJoined, 9 * 77);
}

TEST(RosMap, BadMapsGiveOneLineErrors) {
    const auto dir = test::scratchDir("ros-bad");
    const Map map;
    const std::string good = map.pgm(true);
    test::writeText(dir / "room.pgm", good);
    test::writeText(dir / "truncated.pgm", good.substr(0, good.size() / 2));
    test::writeText(dir / "huge.pgm", "P5\n100000 100000\n255\n");
    test::writeText(dir / "blank.pgm", "P2\n3 3\n255\n0 0 0 0 0 0 0 0 0\n");
    test::writeText(dir / "nonsense.png", "\x89PNG\r\n\x1a\n garbage");
    const std::vector<std::pair<std::string, std::string>> cases{
        {"no-image.yaml", "resolution: 0.05\norigin: [0, 0, 0]\n"},
        {"no-resolution.yaml", "image: room.pgm\norigin: [0, 0, 0]\n"},
        {"bad-origin.yaml", "image: room.pgm\nresolution: 0.05\norigin: [0, 0]\n"},
        {"bad-mode.yaml", yaml("room.pgm", "mode: fancy\n")},
        {"bad-thresholds.yaml", "image: room.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                                "free_thresh: 0.9\noccupied_thresh: 0.1\n"},
        {"missing-image.yaml", yaml("nowhere.pgm")},
        {"truncated.yaml", yaml("truncated.pgm")},
        {"huge.yaml", yaml("huge.pgm")},
        {"blank.yaml", yaml("blank.pgm")},
        {"nonsense.yaml", yaml("nonsense.png")},
        {"binary.yaml", std::string("\x00\xff\x12:", 4)},
    };
    for (const auto& [name, contents] : cases) {
        const std::string path = test::writeText(dir / name, contents);
        try {
            importPlanFile(path);
            ADD_FAILURE() << name << " imported";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        }
    }
}

} // namespace
} // namespace fc
