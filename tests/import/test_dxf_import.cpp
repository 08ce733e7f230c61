// DXF import: files written by ezdxf (tests/data/import/make_dxf_fixtures.py, run by CTest
// before these tests) and OpenSCAD's DXF edge cases (Debian's openscad-testing-data).
#include "ImportTestSupport.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace fc {
namespace {

using test::expectedArea;
using test::fixture;
using test::freeArea;

bool hasWarning(const ImportResult& r, const std::string& part) {
    return std::any_of(r.warnings.begin(), r.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

TEST(DxfImport, OfficeFromEzdxfHasTheKnownFreeArea) {
    const ImportResult r = importPlanFile(fixture("office.dxf"));
    const double expected = expectedArea("office.dxf");
    ASSERT_GT(expected, 0);
    EXPECT_NEAR(freeArea(r.project.plan), expected, 0.01 * expected);
    // Millimetres ($INSUNITS 4): the boundary spans 25 m (20 m + the 5 m bulge).
    const BoundingBox box = r.project.plan.bounds();
    EXPECT_NEAR(box.width(), 25.0, 0.01);
    EXPECT_NEAR(box.height(), 10.0, 0.01);
    // 2 columns, 2 desks (one rotated, one scaled), the hatch, the gap-closed cabinet.
    EXPECT_EQ(r.project.plan.obstacles.size(), 6u);
    ASSERT_EQ(r.project.plan.rooms.size(), 2u);
    EXPECT_EQ(r.project.plan.rooms[0].name, "Office A");
    EXPECT_EQ(r.project.plan.rooms[1].name, "Office B");
    EXPECT_TRUE(hasWarning(r, "layer \"NOTES\": 2 open segments")) << r.warnings.size();
}

TEST(DxfImport, TheGapToleranceDecidesWhetherTheCabinetCloses) {
    ImportOptions options;
    options.gapTolerance = 0.005; // the cabinet's gap is 20 mm
    const ImportResult r = importPlanFile(fixture("office.dxf"), options);
    EXPECT_EQ(r.project.plan.obstacles.size(), 5u);
    EXPECT_TRUE(hasWarning(r, "layer \"OBSTACLES\": 4 open segments"));
    EXPECT_NEAR(freeArea(r.project.plan), expectedArea("office.dxf") + 2.0, 0.01 * 236);
}

TEST(DxfImport, UnitsCanBeOverridden) {
    ImportOptions options;
    options.metresPerUnit = 0.01; // read the millimetre drawing as centimetres
    const ImportResult r = importPlanFile(fixture("office.dxf"), options);
    EXPECT_NEAR(r.project.plan.bounds().width(), 250.0, 0.1);
    EXPECT_NEAR(freeArea(r.project.plan), 100 * expectedArea("office.dxf"), 0.01 * 23500);
}

TEST(DxfImport, AnExplicitLayerMappingReplacesTheGuess) {
    ImportOptions options;
    options.layers.boundary = {"WALLS"};
    options.layers.obstacles = {"COLUMNS"}; // furniture, hatch and cabinet left out
    const ImportResult r = importPlanFile(fixture("office.dxf"), options);
    EXPECT_EQ(r.project.plan.obstacles.size(), 2u);
    EXPECT_TRUE(r.project.plan.rooms.empty());
    const double columns = 2 * M_PI * 0.09;
    EXPECT_NEAR(freeArea(r.project.plan), 200 + 12.5 * M_PI - columns, 2.4);
}

TEST(DxfImport, PreviewListsLayersAndUnits) {
    const ImportPreview p = previewImport(fixture("office.dxf"));
    EXPECT_EQ(p.format, "dxf");
    ASSERT_TRUE(p.metresPerUnit);
    EXPECT_DOUBLE_EQ(*p.metresPerUnit, 0.001);
    for (const char* layer : {"WALLS", "COLUMNS", "FURNITURE", "OBSTACLES", "ROOMS", "NOTES"})
        EXPECT_NE(std::find(p.layers.begin(), p.layers.end(), layer), p.layers.end()) << layer;
}

TEST(DxfImport, LineAndArcPiecesChainIntoTheBoundary) {
    const ImportResult r = importPlanFile(fixture("rounded.dxf"));
    const double expected = expectedArea("rounded.dxf");
    EXPECT_NEAR(freeArea(r.project.plan), expected, 0.01 * expected);
    EXPECT_EQ(r.project.plan.obstacles.size(), 1u); // the closed POLYLINE inside
    EXPECT_TRUE(hasWarning(r, "no $INSUNITS in the header: drawing units taken as metres"));
}

TEST(DxfImport, LayerNamesAreGuessed) {
    EXPECT_EQ(guessLayerRole("A-WALL"), "boundary");
    EXPECT_EQ(guessLayerRole("Columns"), "obstacles");
    EXPECT_EQ(guessLayerRole("ROOMS"), "rooms");
    EXPECT_EQ(guessLayerRole("ROOM_TEXT"), "ignored");
    EXPECT_EQ(guessLayerRole("0"), "");
}

const std::string kOpenScad = FC_OPENSCAD_DXF_DIR;

// OpenSCAD's drawings are a few hundred millimetres wide: smaller than the robot. Read as
// metres (the unit override) they are floor-sized.
ImportResult importMetres(const std::string& path) {
    ImportOptions options;
    options.metresPerUnit = 1.0;
    return importPlanFile(path, options);
}

TEST(OpenScadDxf, EveryFileImportsOrGivesAnInputError) {
    int imported = 0, refused = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kOpenScad)) {
        if (entry.path().extension() != ".dxf")
            continue;
        try {
            const ImportResult r = importMetres(entry.path().string());
            EXPECT_GT(freeArea(r.project.plan), 0) << entry.path();
            ++imported;
        } catch (const InputError& e) {
            // One line that names the file.
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(entry.path().string() + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            ++refused;
        }
    }
    EXPECT_EQ(imported + refused, 31);
    EXPECT_GE(imported, 20);
}

TEST(OpenScadDxf, KnownShapes) {
    // A circle of radius 100 (segmented every 4 degrees: 0.2 % short of pi r^2).
    EXPECT_NEAR(freeArea(importMetres(kOpenScad + "/circle.dxf").project.plan), M_PI * 100 * 100,
                0.01 * M_PI * 1e4);
    // The closed LWPOLYLINE triangle (50,50) (0,0) (0,50).
    EXPECT_NEAR(freeArea(importMetres(kOpenScad + "/lwpolyline-closed.dxf").project.plan), 1250,
                1e-6);
    // An open POLYLINE: three sides of a 100 x 100 square (and a zero-length line). Refused
    // with the open segments named, and closed when the gap tolerance spans the fourth side.
    try {
        importMetres(kOpenScad + "/open-polyline.dxf");
        ADD_FAILURE() << "an open outline imported";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("layer \"0\": 3 open segments (300 m)"),
                  std::string::npos)
            << e.what();
    }
    ImportOptions wide;
    wide.metresPerUnit = 1.0;
    wide.gapTolerance = 100.5;
    EXPECT_NEAR(freeArea(importPlanFile(kOpenScad + "/open-polyline.dxf", wide).project.plan), 1e4,
                1e-6);
}

TEST(DxfImport, CorruptAndTruncatedFilesGiveAnInputError) {
    const auto dir = test::scratchDir("dxf-corrupt");
    const std::string office = test::readBytes(fixture("office.dxf"));
    const std::vector<std::pair<std::string, std::string>> cases{
        {"empty.dxf", ""},
        {"garbage.dxf", "this is not a drawing\n\x01\x02\x03"},
        {"truncated.dxf", office.substr(0, office.size() / 3)},
        {"header-only.dxf", "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nEOF\n"},
        {"bad-number.dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\nx\n20\n1e999\n0\nENDSEC\n"
                           "0\nEOF\n"},
    };
    for (const auto& [name, contents] : cases) {
        const std::string path = test::writeText(dir / name, contents);
        EXPECT_THROW(importPlanFile(path), InputError) << name;
    }
    EXPECT_THROW(importPlanFile((dir / "missing.dxf").string()), InputError);
}

TEST(DxfImport, HugeDrawingsStopAtALimitWithAClearError) {
    const auto dir = test::scratchDir("dxf-huge");
    std::string dxf = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n"
                      "0\nSECTION\n2\nENTITIES\n";
    for (int i = 0; i <= 50000; ++i) { // disjoint lines: nothing chains
        const std::string x = std::to_string(i * 10);
        dxf += "0\nLINE\n8\nNOTES\n10\n" + x + "\n20\n0\n11\n" + x + "\n21\n1\n";
    }
    dxf += "0\nENDSEC\n0\nEOF\n";
    const std::string path = test::writeText(dir / "huge.dxf", dxf);
    try {
        importPlanFile(path);
        FAIL() << "imported";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": more than 50000 open lines");
    }
}

TEST(Import, BuildingModelsGoToTheThreeDImporterWhichNamesTheFileOnce) {
    const auto dir = test::scratchDir("model");
    const std::string path = test::writeText(dir / "house.ifc", "ISO-10303-21;");
    for (int preview = 0; preview < 2; ++preview) {
        try {
            if (preview)
                previewImport(path);
            else
                importPlanFile(path);
            FAIL() << "no error";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find(path, 1), std::string::npos) << "named twice: " << message;
        }
    }
    const std::vector<std::string> extensions = importableExtensions();
    for (const char* model : {"ifc", "obj", "gltf", "glb", "stl"})
        EXPECT_NE(std::find(extensions.begin(), extensions.end(), model), extensions.end());
}

} // namespace
} // namespace fc
