// The 3D building-model importer: FZK-Haus (IFC), generated OBJ/STL/glTF rooms, bad files.
#include "BuildingModels.h"
#include "importers/BuildingModelImport.h"
#include "model/Validation.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace fc {
namespace {

namespace fs = std::filesystem;
const std::string kModels = "/usr/share/assimp/models";
const std::string kFzkHaus = kModels + "/IFC/AC14-FZK-Haus.ifc";

double freeArea(const Plan& plan) {
    double area = ringArea(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        area -= ringArea(obstacle);
    return area;
}

const Room* findRoom(const Plan& plan, const std::string& name) {
    for (const Room& room : plan.rooms)
        if (room.name == name)
            return &room;
    return nullptr;
}

std::string tempPath(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "fc-building-tests";
    fs::create_directories(dir);
    return (dir / name).string();
}

std::vector<test::Cuboid> withoutRoomVolume() {
    auto cuboids = test::pillarRoom();
    cuboids.pop_back(); // the "kitchen" volume
    return cuboids;
}

// The message of the InputError `call` throws ("" when it throws none).
template <class Call> std::string errorOf(Call call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(BuildingImport, ObjPillarRoomHasTheExactFreeArea) {
    const std::string path = tempPath("pillar-room.obj");
    test::writeText(path, test::objText(test::pillarRoom()));
    ImportOptions options;
    options.layers.rooms = {"kitchen"};
    const ImportResult result = importBuildingModel(path, options);
    const Plan& plan = result.project.plan;
    EXPECT_NEAR(freeArea(plan), 59.75, 1e-9);
    ASSERT_EQ(plan.obstacles.size(), 1u);
    EXPECT_NEAR(ringArea(plan.obstacles[0]), 0.25, 1e-9);
    EXPECT_EQ(plan.boundary.size(), 4u); // collinear section vertices merged
    const Room* kitchen = findRoom(plan, "kitchen");
    ASSERT_NE(kitchen, nullptr);
    EXPECT_NEAR(ringArea(kitchen->outline), 60.0, 1e-9);
    EXPECT_EQ(plan.name, "pillar-room");
    EXPECT_NO_THROW(validatePlan(plan, RobotProfile{}));
}

TEST(BuildingImport, StlIsZUpAndScaledByMetresPerUnit) {
    auto cuboids = withoutRoomVolume();
    for (auto& c : cuboids) // the same room in millimetres
        for (double* v : {&c.x0, &c.y0, &c.h0, &c.x1, &c.y1, &c.h1})
            *v *= 1000;
    const std::string path = tempPath("pillar-room-mm.stl");
    test::writeText(path, test::stlText(cuboids));
    ImportOptions options;
    options.metresPerUnit = 0.001;
    const Plan plan = importBuildingModel(path, options).project.plan;
    EXPECT_NEAR(freeArea(plan), 59.75, 1e-6);
    EXPECT_EQ(plan.obstacles.size(), 1u);
    const BoundingBox box = plan.bounds();
    EXPECT_NEAR(box.minX, 0.0, 1e-9);
    EXPECT_NEAR(box.maxY, 6.0, 1e-9);
    // Read as Y-up the same file is cut across its walls' height: no enclosed floor.
    EXPECT_NE(errorOf([&] {
                  importBuildingModel(path, options, {UpAxis::Y});
              }).find("pillar-room-mm.stl: "),
              std::string::npos);
}

// No building-like glTF ships with assimp-testmodels (boxes, a truck, an engine), so the room
// is written as GLB here; assimp's BoxTextured.glb, a closed cube, encloses no floor.
TEST(BuildingImport, GlbRoomAndTheTestModelsCube) {
    const std::string path = tempPath("pillar-room.glb");
    test::writeText(path, test::glbBytes(test::pillarRoom()));
    ImportOptions options;
    options.layers.rooms = {"kitchen"};
    const Plan plan = importBuildingModel(path, options).project.plan;
    EXPECT_NEAR(freeArea(plan), 59.75, 1e-9); // float coordinates, snapped to 0.1 mm
    ASSERT_EQ(plan.rooms.size(), 1u);
    EXPECT_EQ(plan.rooms[0].name, "kitchen");
    const std::string cube = kModels + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(cube))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    ImportOptions low;
    low.sliceHeight = 0.5;
    EXPECT_NE(errorOf([&] { importBuildingModel(cube, low); }).find("encloses no free space"),
              std::string::npos);
}

TEST(BuildingImport, OneStoreyForNonIfcModelsWithTheFloorAtTheLowestPoint) {
    auto cuboids = withoutRoomVolume();
    cuboids.push_back({"slab", -0.2, -0.2, -0.3, 10.2, 6.2, 0});
    const std::string path = tempPath("preview.obj");
    test::writeText(path, test::objText(cuboids));
    const ImportPreview preview = previewBuildingModel(path);
    EXPECT_EQ(preview.format, "obj");
    EXPECT_EQ(preview.storeys, std::vector<std::string>{"whole model"});
    EXPECT_FALSE(preview.metresPerUnit.has_value());
    EXPECT_NE(std::find(preview.layers.begin(), preview.layers.end(), "pillar"),
              preview.layers.end());
    // The slab's underside (-0.3 m) is the floor: 0.3 m above it cuts nothing but the slab top.
    ImportOptions options;
    options.sliceHeight = 0.6; // 0.3 m above the room's floor
    EXPECT_NEAR(freeArea(importBuildingModel(path, options).project.plan), 59.75, 1e-9);
}

TEST(BuildingImport, IgnoredLayersAndAnAbovePlaneAreReported) {
    const std::string path = tempPath("ignored.obj");
    test::writeText(path, test::objText(withoutRoomVolume()));
    ImportOptions options;
    options.sliceHeight = 0.6;
    options.layers.ignored = {"pillar"};
    const Plan plan = importBuildingModel(path, options).project.plan;
    EXPECT_TRUE(plan.obstacles.empty());
    EXPECT_NEAR(freeArea(plan), 60.0, 1e-9);
    options.sliceHeight = 5.0;
    const std::string message = errorOf([&] { importBuildingModel(path, options); });
    EXPECT_NE(message.find("no section at height 5 m"), std::string::npos) << message;
}

TEST(BuildingImport, BadFilesGiveAClearError) {
    const std::string empty = tempPath("empty.obj");
    test::writeText(empty, "");
    EXPECT_NE(errorOf([&] { importBuildingModel(empty, {}); }).find("empty.obj: the file is empty"),
              std::string::npos);
    const std::string text = test::stlText(withoutRoomVolume());
    const std::string truncated = tempPath("truncated.stl");
    test::writeText(truncated, text.substr(0, text.size() / 2));
    EXPECT_NE(errorOf([&] { importBuildingModel(truncated, {}); }), "");
    const std::string binary = tempPath("short-binary.stl");
    std::string header(80, 'x');
    header += std::string("\xE8\x03\0\0", 4); // 1000 triangles announced, none present
    test::writeText(binary, header);
    EXPECT_NE(errorOf([&] { importBuildingModel(binary, {}); }).find("short-binary.stl: "),
              std::string::npos);
    const std::string garbage = tempPath("garbage.glb");
    test::writeText(garbage, "glTF this is not a binary glTF container at all");
    EXPECT_NE(errorOf([&] { importBuildingModel(garbage, {}); }), "");
    EXPECT_NE(errorOf([&] {
                  importBuildingModel(tempPath("missing.obj"), {});
              }).find("cannot read the file"),
              std::string::npos);
    const std::string unknown = tempPath("plan.xyz");
    test::writeText(unknown, "1 2 3\n");
    EXPECT_NE(errorOf([&] { importBuildingModel(unknown, {}); }).find("unsupported"),
              std::string::npos);
    const std::string hostile = tempPath("hostile.obj");
    test::writeText(hostile, "o huge\nv 0 0 0\nv 1e300 0 0\nv 0 1 1\nf 1 2 3\n");
    EXPECT_NE(errorOf([&] { importBuildingModel(hostile, {}); }).find("huge coordinate"),
              std::string::npos);
    ImportOptions badHeight;
    badHeight.sliceHeight = -1;
    const std::string obj = tempPath("height.obj");
    test::writeText(obj, test::objText(withoutRoomVolume()));
    EXPECT_NE(errorOf([&] { importBuildingModel(obj, badHeight); }).find("slice height"),
              std::string::npos);
}

TEST(BuildingImport, TruncatedIfcNeverCrashes) {
    if (!fs::exists(kFzkHaus))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    std::ifstream in(kFzkHaus, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string path = tempPath("truncated.ifc");
    for (size_t parts : {2, 3, 7, 50}) { // cut at several places: a valid plan or an error
        test::writeText(path, text.substr(0, text.size() / parts));
        try {
            validatePlan(importBuildingModel(path, {}).project.plan, RobotProfile{});
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        }
    }
}

// FZK-Haus (KIT, in Debian's assimp-testmodels): two storeys, six IfcSpaces on the ground
// floor. The file states no areas (no IfcQuantityArea), so the free floor is compared with the
// sum of the IfcSpace sections: with furniture and stairs ignored it is larger by the floor
// inside the doorways (door leaves ignored), 0.83 %.
TEST(BuildingImport, FzkHausGroundFloor) {
    if (!fs::exists(kFzkHaus))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    const ImportPreview preview = previewBuildingModel(kFzkHaus);
    EXPECT_EQ(preview.format, "ifc");
    EXPECT_EQ(preview.storeys, (std::vector<std::string>{"0. Erdgeschoss", "1. Dachgeschoss"}));
    ASSERT_TRUE(preview.metresPerUnit.has_value());
    EXPECT_EQ(*preview.metresPerUnit, 1.0);

    const Plan plan = importBuildingModel(kFzkHaus, {}).project.plan;
    std::vector<std::string> names;
    double spaces = 0;
    for (const Room& room : plan.rooms) {
        names.push_back(room.name);
        spaces += ringArea(room.outline);
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"Bad", "Buero", "Flur", "K\u00fcche", "Schlafzimmer",
                                               "Wohnen"}));
    EXPECT_NEAR(ringArea(findRoom(plan, "Wohnen")->outline), 29.309, 0.001);
    EXPECT_GT(plan.obstacles.size(), 10u); // furniture, stairs, the chimney
    EXPECT_NO_THROW(validatePlan(plan, RobotProfile{}));

    ImportOptions bare;
    bare.layers.ignored = {"IfcFurnishingElement*", "IfcStair*"};
    const Plan empty = importBuildingModel(kFzkHaus, bare).project.plan;
    EXPECT_TRUE(empty.obstacles.empty());
    EXPECT_GT(freeArea(empty), spaces);
    EXPECT_LT(std::abs(freeArea(empty) - spaces) / spaces, 0.01)
        << freeArea(empty) << " vs " << spaces;
    EXPECT_LT(freeArea(plan), freeArea(empty) - 5.0); // the furniture is cut out

    // Closed door leaves split the floor: the largest enclosed part is kept.
    ImportOptions doors;
    doors.ignoreDoorLeaves = false;
    const ImportResult closed = importBuildingModel(kFzkHaus, doors);
    EXPECT_LT(freeArea(closed.project.plan), freeArea(plan) - 10.0);
    EXPECT_FALSE(closed.warnings.empty());
    std::printf("FZK-Haus ground floor at 0.3 m: boundary %.2f m2, free %.2f m2, %zu obstacles, "
                "%zu rooms (IfcSpaces %.2f m2); furniture ignored: free %.2f m2 (%+.2f %%); door "
                "leaves closed: boundary %.2f m2, free %.2f m2\n",
                ringArea(plan.boundary), freeArea(plan), plan.obstacles.size(), plan.rooms.size(),
                spaces, freeArea(empty), 100 * (freeArea(empty) / spaces - 1),
                ringArea(closed.project.plan.boundary), freeArea(closed.project.plan));
}

TEST(BuildingImport, FzkHausStoreysAndHeights) {
    if (!fs::exists(kFzkHaus))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    ImportOptions options;
    options.storey = "1. Dachgeschoss";
    const Plan upper = importBuildingModel(kFzkHaus, options).project.plan;
    EXPECT_NE(findRoom(upper, "Galerie"), nullptr);
    options.storey = "Keller";
    EXPECT_NE(errorOf([&] { importBuildingModel(kFzkHaus, options); })
                  .find("no storey \"Keller\" (the model has \"0. Erdgeschoss\", "
                        "\"1. Dachgeschoss\")"),
              std::string::npos);
    options.storey = "0.Erdgeschoss"; // spaces do not matter
    options.sliceHeight = 12.0;       // far above the roof
    EXPECT_NE(errorOf([&] {
                  importBuildingModel(kFzkHaus, options);
              }).find("AC14-FZK-Haus.ifc: no section at height 12 m"),
              std::string::npos);
}

} // namespace
} // namespace fc
