// Plain language and help (issue 16, item 3): every control explains itself in a tooltip,
// the planner's messages reach the window in the editor's words and translated, Qt's own
// dialogs speak the user's language, a welcome page offers the samples and a Getting
// Started page is in the Help menu.
#include "EditorFixture.h"
#include "dialogs/CompareDialog.h"
#include "dialogs/ImportDialog.h"
#include "dialogs/PreferencesDialog.h"
#include "docks/ProblemsDock.h"
#include "document/PlannerMessages.h"
#include "formats/Export.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "importers/Import.h"
#include "importers/ImportSupport.h"
#include "learning/dqn/DqnModelFile.h"
#include "model/RoomEdits.h"
#include "model/Validation.h"
#include "tiling/TilingRobot.h"
#include "window/HelpDialog.h"
#include "window/SamplePlans.h"
#include "window/Translations.h"
#include "window/WelcomeDialog.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QLibraryInfo>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTranslator>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

using namespace fc::ui;
using namespace fc::ui::test;

namespace {

// Controls a person clicks or types into that say nothing when hovered.
QStringList controlsWithoutTooltip(QWidget* root) {
    QStringList missing;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        const bool control = qobject_cast<QAbstractButton*>(w) ||
                             qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w) ||
                             qobject_cast<QLineEdit*>(w) || qobject_cast<QSlider*>(w) ||
                             qobject_cast<QListWidget*>(w) || qobject_cast<QTableWidget*>(w);
        if (!control || qobject_cast<QLineEdit*>(w->parentWidget()) ||
            qobject_cast<QAbstractSpinBox*>(w->parentWidget()) ||
            qobject_cast<QComboBox*>(w->parentWidget()))
            continue; // the editor inside a spin box or combo box
        // Dock title buttons, scroll bar parts and tab bar scrollers are Qt's own.
        if (w->inherits("QDockWidgetTitleButton") || w->inherits("QToolBarExtension") ||
            w->objectName().startsWith(QLatin1String("qt_")) || w->inherits("QTabBar") ||
            w->parentWidget()->inherits("QTabBar") || w->inherits("QTableCornerButton"))
            continue;
        // OK and Cancel of a dialog's button box say what they do.
        if (auto* button = qobject_cast<QAbstractButton*>(w);
            button && qobject_cast<QDialogButtonBox*>(w->parentWidget())) {
            const auto role =
                static_cast<QDialogButtonBox*>(w->parentWidget())->standardButton(button);
            if (role == QDialogButtonBox::Ok || role == QDialogButtonBox::Cancel)
                continue;
        }
        if (w->toolTip().isEmpty()) {
            QString name = QString::fromLatin1(w->metaObject()->className());
            if (auto* b = qobject_cast<QAbstractButton*>(w))
                name += QStringLiteral(" \"") + b->text() + QLatin1Char('"');
            if (!w->objectName().isEmpty())
                name += QStringLiteral(" #") + w->objectName();
            for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
                if (auto* dock = qobject_cast<QDockWidget*>(p)) {
                    name += QStringLiteral(" in ") + dock->windowTitle();
                    break;
                }
            missing << name;
        }
    }
    return missing;
}

// What a planner call throws, as the planner words it.
template <typename Call> QString thrown(Call&& call) {
    try {
        call();
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return QStringLiteral("(the call threw nothing)");
}

// Each message reworded (no command-line flags, no placeholder left) and translated into
// German and French.
void saidInTheEditorsWordsAndTranslated(const QStringList& messages) {
    static const QRegularExpression placeholder(QStringLiteral("%\\d"));
    QTranslator german, french;
    QVERIFY(loadEditorTranslation(german, QLocale(QLocale::German)));
    QVERIFY(loadEditorTranslation(french, QLocale(QLocale::French)));
    for (const QString& message : messages) {
        const QString plain = plainMessage(message);
        QVERIFY2(plain != message, qPrintable(QStringLiteral("not reworded: ") + message));
        QVERIFY2(!plain.contains(QStringLiteral("--")), qPrintable(plain));
        QVERIFY2(!plain.contains(placeholder), qPrintable(plain));
        for (QTranslator* translator : {&german, &french}) {
            QCoreApplication::installTranslator(translator);
            const QString translated = plainMessage(message);
            QCoreApplication::removeTranslator(translator);
            QVERIFY2(translated != plain,
                     qPrintable(translator->language() + QStringLiteral(" lacks: ") + plain));
            QVERIFY2(!translated.contains(placeholder), qPrintable(translated));
        }
    }
}

std::string featureCollection(const std::string& features) {
    return R"({"type":"FeatureCollection","features":[)" + features + "]}";
}

std::string feature(const std::string& properties, const std::string& geometry) {
    return R"({"type":"Feature","properties":)" + properties + R"(,"geometry":)" + geometry + "}";
}

std::string polygon(const std::string& rings) {
    return R"({"type":"Polygon","coordinates":)" + rings + "}";
}

std::string multiPolygon(const std::string& polygons) {
    return R"({"type":"MultiPolygon","coordinates":)" + polygons + "}";
}

const std::string kSquare = "[[0,0],[10,0],[10,10],[0,10],[0,0]]";
const std::string kInner = "[[2,2],[4,2],[4,4],[2,4],[2,2]]";
const std::string kBoundary = feature(R"({"role":"boundary"})", polygon("[" + kSquare + "]"));

QString geoJsonError(const std::string& features) {
    return thrown([&] { fc::readGeoJsonPlan(featureCollection(features)); });
}

QString projectError(const std::string& members) {
    return thrown([&] {
        fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{"boundary":)"
                        R"([[0,0],[10,0],[10,10],[0,10]]})" +
                        members + "}");
    });
}

QString yamlError(const std::string& text) {
    return thrown([&] { fc::importing::parseRosMapYaml(text); });
}

QString pgmError(const std::string& bytes) {
    return thrown([&] { fc::importing::readPgm(bytes); });
}

void writeFile(const QString& path, const std::string& text) {
    std::ofstream(path.toStdString(), std::ios::binary) << text;
}

QStringList plannerMessagesAsWorded() {
    QStringList messages;
    auto add = [&](const QString& message) { messages << message; };
    auto literal = [&](const char* message) { messages << QString::fromUtf8(message); };

    // The plan's checks.
    {
        const double w = fc::RobotProfile{}.coverageWidth;
        fc::Plan small;
        small.boundary = {{0, 0}, {0.95 * w, 0}, {0.95 * w, 0.95 * w}, {0, 0.95 * w}};
        add(thrown([&] { fc::validatePlan(small, fc::RobotProfile{}); }));
        fc::Plan shapes;
        shapes.boundary = {{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}};
        shapes.obstacles = {{{1, 1}, {2, 1}, {1, 1}},
                            {{3, 3}, {4, 4}, {5, 5}},
                            {{6, 6}, {7, std::nan("")}, {7, 7}}};
        for (const fc::PlanProblem& problem : fc::planProblems(shapes, fc::RobotProfile{}))
            add(QString::fromStdString(problem.message));
    }
    // The robot.
    for (auto change : std::vector<std::function<void(fc::RobotProfile&)>>{
             [](fc::RobotProfile& r) { r.robotDiameter = 0; },
             [](fc::RobotProfile& r) { r.coverageWidth = -1; },
             [](fc::RobotProfile& r) { r.cleaningDiameter = std::nan(""); },
             [](fc::RobotProfile& r) { r.speed = 0; }, [](fc::RobotProfile& r) { r.turnTime = -1; },
             [](fc::RobotProfile& r) { r.coverageWidth = 2000, r.cleaningDiameter = 3000; }}) {
        fc::RobotProfile robot;
        change(robot);
        add(thrown([&] { robot.validate(); }));
    }
    // Merging and splitting rooms.
    {
        const fc::Ring square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
        const fc::Ring far = {{10, 0}, {14, 0}, {14, 4}, {10, 4}};
        const fc::Ring u = {{0, 0}, {6, 0}, {6, 6}, {4, 6}, {4, 2}, {2, 2}, {2, 6}, {0, 6}};
        add(thrown([&] { fc::mergedRoomOutline({{0, 0}, {1, 0}}, square); }));
        add(thrown([&] { fc::mergedRoomOutline(square, far); }));
        add(thrown([&] { fc::splitRoomOutline({{0, 0}, {1, 0}}, {0, 0}, {1, 1}); }));
        add(thrown([&] { fc::splitRoomOutline(square, {1, 1}, {1, 1}); }));
        add(thrown([&] { fc::splitRoomOutline(square, {5, 0}, {5, 4}); }));
        add(thrown([&] { fc::splitRoomOutline(u, {-1, 4}, {7, 4}); }));
        add(thrown([&] { fc::splitRoomOutline(square, {-1, 0.001}, {5, 0.001}); }));
        literal("the merged room would be in several pieces");
        literal("the merged room would enclose a hole; merge the room inside it too");
    }
    // Planning and the solvers.
    literal("the sweep angle must be a finite number of degrees");
    literal("unknown room \"Attic\" (rooms: Hall Kitchen)");
    literal("unknown solver \"magic\" (available: dqn exact greedy heuristic)");
    literal("the rooms cannot be joined: no collision-free way from Kitchen's neighbour into it");
    literal("cancelled");
    literal("heuristic solver: cancelled");
    literal("dqn: cancelled");
    literal("greedy solver: 3 required cell(s) cannot be reached from the start node 7 "
            "(separate part of the graph)");
    literal("exact solver: the end node 9 cannot be reached from the start node 2");
    literal("greedy solver: internal error: the walk it built is not connected");
    literal("heuristic solver: required cell 4 has no coverage edge");
    // Solver dqn and its model files.
    literal("dqn: the model's network does not fit its state kind (image/graph)");
    literal("dqn: the model was trained on a graph of another size");
    literal("dqn: CoverageEnvironment: start or end node out of range");
    literal("dqn: no corner of an uncovered cell can be reached");
    literal("dqn: the policy ran out of steps");
    literal("dqn: the policy's walk does not cover the query (internal error)");
    literal("randomQueries: the graph has no reachable cell");
    literal("/models/office.fcdqn: the model was trained for another floor plan or robot profile "
            "(it knows 40 corners in 10 cells at sweep angle 0 deg and coverage width 0.6 m; this "
            "plan has 52 corners in 13 cells); train a model for this plan");
    literal("/models/office.fcdqn: corrupt model weights: unexpected end of data");
    for (const char* file : {"hello\n", "FLOORCOVER-DQN 99\n", "FLOORCOVER-DQN 1\n",
                             "FLOORCOVER-DQN 1\n{\n", "FLOORCOVER-DQN x\n"}) {
        std::istringstream in(file);
        add(thrown([&] { fc::readDqnModelInfo(in, "model.fcdqn"); }));
    }
    add(thrown([] { fc::loadDqnModelInfo("/no/such/folder/model.fcdqn"); }));
    // JSON and GeoJSON.
    add(thrown([] { fc::readGeoJsonPlan(""); }));
    add(thrown([] { fc::readGeoJsonPlan(R"({"type":)"); }));
    add(thrown([] { fc::readGeoJsonPlan("{]"); }));
    add(thrown([] { fc::readGeoJsonPlan(R"({"features":[], "x": 1e400})"); }));
    literal("number 1e400 is out of range (not a finite coordinate)");
    literal("a number is out of range: number overflow");
    add(thrown([] { fc::readGeoJsonPlan("[]"); }));
    add(thrown([] { fc::readGeoJsonPlan(R"({"type":"FeatureCollection"})"); }));
    add(geoJsonError("1"));
    add(geoJsonError(R"({"properties":3})"));
    add(geoJsonError(R"({"properties":{}})"));
    add(geoJsonError(R"({"properties":{"role":5}})"));
    add(geoJsonError(R"({"properties":{"role":"wall"}})"));
    add(geoJsonError(R"({"properties":{"role":"boundary"}})"));
    add(geoJsonError(feature(R"({"role":"boundary"})", "{}")));
    add(geoJsonError(feature(R"({"role":"boundary"})", R"({"type":"Point","coordinates":[0,0]})")));
    add(geoJsonError(feature(R"({"role":"boundary"})", R"({"type":"Polygon"})")));
    add(geoJsonError(feature(R"({"role":"boundary"})", R"({"type":"Polygon","coordinates":[]})")));
    add(geoJsonError(feature(R"({"role":"boundary"})", polygon("[5]"))));
    add(geoJsonError(feature(R"({"role":"boundary"})", polygon("[[[0,0],[1],[1,1]]]"))));
    add(geoJsonError(feature(R"({"role":"boundary"})", polygon(R"([[[0,0],["a",1],[1,1]]])"))));
    add(geoJsonError(feature(R"({"role":"boundary"})", polygon("[[[0,0],[1,1],[0,0]]]"))));
    add(geoJsonError(feature(R"({"role":"boundary"})", polygon("[" + kSquare + ",5]"))));
    const std::string inner = polygon("[" + kInner + "]");
    add(geoJsonError(kBoundary + "," + feature(R"({"role":"room","name":true})", inner)));
    add(geoJsonError(kBoundary + "," + feature(R"({"role":"room"})", inner)));
    add(geoJsonError(kBoundary + "," + kBoundary));
    const std::string twoParts = multiPolygon("[[" + kSquare + "],[" + kInner + "]]");
    add(geoJsonError(feature(R"({"role":"boundary"})", twoParts)));
    // A site's second building with a broken hole: named by its part.
    add(geoJsonError(feature(R"({"role":"boundary"})",
                             multiPolygon("[[" + kSquare + "],[" + kInner + ",5]]"))));
    add(geoJsonError(
        kBoundary + "," +
        feature(R"({"role":"obstacle"})", polygon("[" + kSquare + "," + kInner + "]"))));
    add(geoJsonError(kBoundary + "," + feature(R"({"role":"room","name":"A"})", inner) + "," +
                     feature(R"({"role":"room","name":"A"})", inner)));
    add(geoJsonError(kBoundary + "," + feature(R"({"role":"room","name":"A"})", twoParts)));
    add(geoJsonError(
        kBoundary + "," +
        feature(R"({"role":"room","name":"A"})", polygon("[" + kSquare + "," + kInner + "]"))));
    add(geoJsonError(feature(R"({"role":"obstacle"})", polygon("[" + kInner + "]"))));
    literal("obstacle 2 (feature 3): vertex 4 has a non-finite coordinate");
    // Projects.
    add(thrown([] { fc::readProject("{}"); }));
    add(thrown([] { fc::readProject(R"({"format":"other"})"); }));
    add(thrown([] { fc::readProject(R"({"format":"floorcover-project"})"); }));
    add(thrown([] { fc::readProject(R"({"format":"floorcover-project","version":99})"); }));
    add(thrown([] { fc::readProject(R"({"format":"floorcover-project","version":0})"); }));
    add(thrown([] { fc::readProject(R"({"format":"floorcover-project","version":1})"); }));
    add(thrown(
        [] { fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{}})"); }));
    add(thrown([] {
        fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{"boundary":)"
                        R"([[0,0],[10,0],[10,10]],"obstacles":5}})");
    }));
    add(thrown([] {
        fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{"boundary":)"
                        R"([[0,0],[10,0],[10,10]],"obstacles":[[[0,0],[1,1]]]}})");
    }));
    add(thrown([] {
        fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{"boundary":)"
                        R"([[0,0],[10,0],[10,10]],"rooms":5}})");
    }));
    add(thrown([] {
        fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{"boundary":)"
                        R"([[0,0],[10,0],[10,10]],"rooms":[{"name":"A"}]}})");
    }));
    add(thrown([] {
        fc::readProject(R"({"format":"floorcover-project","version":1,"plan":{"boundary":)"
                        R"([[0,0],[10,0],[10,10]],"epsg":-1}})");
    }));
    add(projectError(R"(,"robot":{"speed":"fast"})"));
    add(projectError(R"(,"robot":5)"));
    add(projectError(R"(,"sweep":{"automatic":1})"));
    add(projectError(R"(,"sweep":{"per_room":"yes"})"));
    add(projectError(R"(,"sweep":{"room_angles":5})"));
    add(projectError(R"(,"sweep":{"room_angles":{"Hall":"x"}})"));
    add(projectError(R"(,"solver":5)"));
    add(projectError(R"(,"selectedRooms":5)"));
    add(projectError(R"(,"selectedRooms":[5])"));
    add(projectError(R"(,"start":[1])"));
    literal("end has a non-finite coordinate");
    // Files.
    QTemporaryDir dir;
    const QString base = dir.path() + QLatin1Char('/');
    QDir(dir.path()).mkdir(QStringLiteral("folder.geojson"));
    writeFile(base + QStringLiteral("broken.geojson"), "{]");
    for (const char* name :
         {"missing.geojson", "folder.geojson", "plan.txt", "plan", "broken.geojson"})
        add(thrown([&] { fc::loadProjectFile((base + QLatin1String(name)).toStdString()); }));
    add(thrown(
        [&] { fc::writeFileAtomically((base + "no/such/folder/a.fcproj").toStdString(), ""); }));
    literal("/plans/office.fcproj: cannot read (Input/output error)");
    literal("/plans/office.fcproj: cannot write (rename failed: Permission denied)");
    literal("/plans/huge.dxf: file larger than 256 MiB");
    // Exports.
    add(thrown([] { fc::exportFormatNamed("xyz"); }));
    add(thrown([] { fc::exportSubjectNamed("rooms"); }));
    literal("format csv cannot hold the plan");
    literal("format geojson cannot hold the path");
    literal("format svg cannot hold the zones");
    literal("unknown export format");
    // Imports: the dispatcher, WKT, ROS maps.
    writeFile(base + QStringLiteral("plan.abc"), "x");
    add(thrown([&] { fc::importPlanFile((base + "missing.dxf").toStdString()); }));
    add(thrown([&] { fc::importPlanFile((base + "plan.abc").toStdString()); }));
    add(thrown([&] { fc::previewImport((base + "plan.abc").toStdString()); }));
    const std::vector<std::pair<const char*, const char*>> wkt = {
        {"point.wkt", "POINT (1 2)"},
        {"srid.wkt", "SRID=4326"},
        {"sridname.wkt", "SRID=abc;POLYGON ((0 0,10 0,10 10,0 0))"},
        {"nonsense.wkt", "nonsense"},
        {"after.wkt", "POLYGON ((0 0,10 0,10 10,0 0)) more"},
        {"empty.wkt", "POLYGON EMPTY"}};
    for (const auto& [name, text] : wkt) {
        writeFile(base + QLatin1String(name), text);
        add(thrown([&] { fc::importPlanFile((base + QLatin1String(name)).toStdString()); }));
    }
    {
        fc::ImportOptions unit;
        unit.metresPerUnit = -1;
        add(thrown([&] { fc::importPlanFile((base + "point.wkt").toStdString(), unit); }));
        fc::ImportOptions gap;
        gap.gapTolerance = -1;
        add(thrown([&] { fc::importPlanFile((base + "point.wkt").toStdString(), gap); }));
        writeFile(base + QStringLiteral("bowtie.wkt"), "POLYGON ((0 0,10 8,10 0,0 8,0 0))");
        fc::ImportOptions keep;
        keep.keepInvalid = true;
        for (const std::string& warning :
             fc::importPlanFile((base + "bowtie.wkt").toStdString(), keep).warnings)
            add(QString::fromStdString(warning));
    }
    literal("holes of polygon 2 (a room) ignored");
    literal("the start pose (3.000000, 4.000000) is not in the free space; not used");
    const std::string map = "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
    add(yamlError("resolution: 0.05\n"));
    add(yamlError("image: map.pgm\nresolution: abc\n"));
    add(yamlError(map + "negate: maybe\n"));
    add(yamlError("image: map.pgm\norigin: 1\n"));
    add(yamlError("image: map.pgm\norigin: [1, 2]\n"));
    add(yamlError("garbage\n"));
    add(yamlError("image: map.pgm\nresolution: -1\n"));
    add(yamlError("image: map.pgm\nresolution: 5\n"));
    add(yamlError("image: map.pgm\nresolution: 0.05\n"));
    add(yamlError("image: map.pgm\nresolution: 0.05\norigin: [1e9, 0, 0]\n"));
    add(yamlError(map + "occupied_thresh: 0.1\nfree_thresh: 0.5\n"));
    add(yamlError(map + "mode: foo\n"));
    add(yamlError(std::string((1 << 20) + 1, '#')));
    add(pgmError("XX"));
    add(pgmError("P2\nx\n"));
    add(pgmError("P2 0 0 255\n"));
    add(pgmError("P5 2 2 255\n\x01"));
    add(pgmError("P4 8 1\n"));
    add(pgmError("P1 2 1\n2 2"));
    writeFile(base + QStringLiteral("lost.yaml"), map);
    add(thrown([&] { fc::importPlanFile((base + "lost.yaml").toStdString()); }));
    writeFile(base + QStringLiteral("unknown.yaml"),
              "image: unknown.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
    writeFile(base + QStringLiteral("unknown.pgm"),
              "P2 4 4 255\n128 128 128 128 128 128 128 128 128 128 128 128 128 128 128 128\n");
    add(thrown([&] { fc::importPlanFile((base + "unknown.yaml").toStdString()); }));
    writeFile(base + QStringLiteral("walls.yaml"),
              "image: walls.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
    writeFile(base + QStringLiteral("walls.pgm"), "P2 4 4 255\n0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
    add(thrown([&] { fc::importPlanFile((base + "walls.yaml").toStdString()); }));
    literal("map image pixels are Float32 (expected 1- to 16-bit unsigned grey or colour)");
    literal("map image map.png is not a readable PNG/PGM/BMP/TIFF");
    literal("map image is empty");
    literal("map image larger than 67108864 pixels");
    literal("map image unreadable: read error");
    literal("map image uses a colour missing from its palette");
    literal("cleaning left no free space (the map's free cells are specks)");
    literal("the free space is thinner than a pixel everywhere");
    literal("GDAL lacks its in-memory drivers");
    literal("cannot hold the map image in memory");
    literal("the free space is split into more than 200000 pieces");
    literal("tracing the free space failed: out of memory");
    literal("simplifying the free space failed");
    // Assembling and repairing plans, DXF drawings.
    literal("no free area left to import");
    literal("2 separate free space parts (3.5 m2) not connected to the largest; dropped");
    literal("the obstacles could not be merged (invalid geometry)");
    literal("the obstacles could not be cut out of the boundary");
    literal("no closed outline for the boundary; layer \"WALLS\": 2 open segments (4.2 m) (a "
            "larger gap tolerance may close them)");
    literal("no closed outline for the boundary");
    literal("3 closed outlines outside the boundary ignored");
    literal("2 room outlines outside the boundary ignored");
    add(thrown([] {
        std::vector<std::string> notes;
        fc::repairPlan(fc::Plan{}, notes);
    }));
    literal("the boundary encloses no area");
    {
        fc::Plan broken;
        broken.boundary = {{0, 0}, {10, 8}, {10, 0}, {0, 8}};
        broken.obstacles = {{{1, 1}, {2, 1}}, {{4, 3}, {6, 5}, {6, 3}, {4, 5}}};
        broken.rooms = {{"", {{20, 20}, {21, 20}, {21, 21}}},
                        {"A", {{-1, 3}, {5, 3}, {5, 5}, {-1, 5}}}};
        std::vector<std::string> notes;
        fc::repairPlan(broken, notes);
        for (const std::string& note : notes)
            add(QString::fromStdString(note));
    }
    literal("obstacles merged, clipped to the boundary or joined to the wall: 3 before, 2 after");
    literal("room \"Store\" lies outside the floor or under other rooms: removed");
    literal("room \"Hall\" reshaped to fit the floor (12 m2 before, 10.5 m2 after)");
    literal("an unnamed room renamed \"Room 2\"");
    literal("not a readable DXF file (unexpected end of file)");
    literal("not a readable DXF file");
    literal("more than 4000000 vertices");
    literal("more than 50000 open lines");
    literal("more than 200000 entities");
    literal("a coordinate on layer \"WALLS\" is not finite");
    literal("no $INSUNITS in the header: drawing units taken as metres");
    literal("$INSUNITS 0 (unitless or unknown): drawing units taken as metres");
    literal("the drawing has no entities");
    literal("layer \"DIMENSIONS\": 12 entities ignored");
    literal("3 entities without usable 2D geometry skipped");
    literal("layer \"NOTES\": 1 open segment (2.5 m) not closed into an outline; ignored");
    // 3D building models and separating a map's rooms.
    literal("cannot read the file (No such file or directory)");
    literal("the file is empty");
    literal("the file is larger than 512 MiB");
    literal("the model is too large");
    literal("out of memory while reading the model");
    literal("unsupported 3D model format \".3ds\"");
    literal("cannot read the model: OBJ: unexpected end of file");
    literal("the model holds no meshes");
    literal("the model holds no triangles");
    literal("more than 20000000 triangles");
    literal("the node tree is deeper than 256");
    literal("node \"Wall_01\" indexes a missing vertex");
    literal("node \"Wall_01\" refers to a missing mesh");
    literal("node \"Wall_01\" has a non-finite or huge coordinate");
    literal("metres per unit must be a positive number");
    literal("the slice height must be a positive number of metres");
    literal("no storey \"Attic\" (the model has \"Ground floor\", \"First floor\")");
    literal(
        "no section at height 3 m (storey \"whole model\" floor + 3 m): the plane cuts no wall");
    literal("the section at height 1.3 m (storey \"Ground floor\" floor + 0.3 m) has more than "
            "400000 segments");
    literal("the section encloses no free space (the outer walls are open at that height, or the "
            "model is not closed) at height 0.3 m (storey \"whole model\" floor + 0.3 m)");
    literal("the section at height 0.3 m (storey \"whole model\" floor + 0.3 m) is not a valid "
            "plan: the boundary encloses no area");
    literal("2 smaller enclosed region(s) left out (3.5 m^2 in all)");
    literal("space \"Kitchen\" has no closed section");
    literal("room \"Kitchen\" left out: room \"Kitchen\" lies outside the boundary");
    literal("/plans/house.ifc: the model holds no meshes");
    literal("separating the rooms failed");
    // The tiling robot.
    {
        fc::tiling::TilingRobotProfile robot;
        robot.blockLeg = -1;
        add(thrown([&] { robot.validate(); }));
        robot = {};
        robot.blockMass[1] = 0;
        add(thrown([&] { robot.validate(); }));
    }
    literal("unsupported waypoint file \"/plans/tour.txt\" (use .csv or .json)");
    literal("exact ordering is limited to 12 waypoints (this floor has 40)");
    literal("unknown tiling solver \"magic\" (zigzag, spiral, greedy, exact, aco, ga, ppo)");
    return messages;
}
} // namespace

class HelpTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyControlHasATooltip() {
        auto window = makeWindow();
        window->openSample();
        QVERIFY(window->planningController() != nullptr);
        QStringList missing = controlsWithoutTooltip(window.get());
        // The dialogs too.
        CompareDialog compare(fc::planRequestFor(window->document()->project()));
        missing += controlsWithoutTooltip(&compare);
        PreferencesDialog preferences;
        missing += controlsWithoutTooltip(&preferences);
        ImportDialog import(QStringLiteral(FC_PLANS_DIR "/office.geojson"));
        missing += controlsWithoutTooltip(&import);
        for (const QString& control : missing)
            qWarning("no tooltip: %s", qPrintable(control));
        QVERIFY2(missing.isEmpty(), "controls without a tooltip (listed above)");
    }

    void welcomePageOffersTheSamplesAndOpensThem() {
        auto window = makeWindow();
        window->showWelcome();
        auto* welcome = window->findChild<WelcomeDialog*>();
        QVERIFY(welcome);
        QVERIFY(welcome->isVisible());
        QCOMPARE(welcome->samples()->count(), int(samplePlans().size()));
        QVERIFY(samplePlans().size() >= 6);
        for (const SamplePlan& sample : samplePlans())
            QVERIFY2(QFile::exists(sample.path), qPrintable(sample.path));
        welcome->samples()->setCurrentRow(1); // the ward
        QPushButton* open = nullptr;
        for (QPushButton* b : welcome->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Open Sample"))
                open = b;
        QVERIFY(open);
        open->click();
        QCOMPARE(window->document()->displayName(), QStringLiteral("ward"));
        QTRY_VERIFY(!window->findChild<WelcomeDialog*>() ||
                    !window->findChild<WelcomeDialog*>()->isVisible());
        // Shown at start until turned off.
        QSettings().remove(QStringLiteral("welcome/show"));
        QVERIFY(WelcomeDialog::showAtStart());
        WelcomeDialog again;
        again.findChild<QCheckBox*>()->setChecked(false);
        QVERIFY(!WelcomeDialog::showAtStart());
        QSettings().remove(QStringLiteral("welcome/show"));
    }

    void gettingStartedIsInTheHelpMenuAndTranslated() {
        auto window = makeWindow();
        QAction* guide = window->findChild<QAction*>(QStringLiteral("gettingStarted"));
        QVERIFY(guide);
        QCOMPARE(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
        guide->trigger();
        auto* help = window->findChild<HelpDialog*>();
        QVERIFY(help);
        const QString text = help->browser()->toPlainText();
        QVERIFY2(text.contains(QStringLiteral("Getting started")), qPrintable(text.left(200)));
        QVERIFY(text.contains(QStringLiteral("Repair Plan")));
        QVERIFY(
            HelpDialog::pagePath(QLocale(QLocale::German)).endsWith(QStringLiteral("_de.html")));
        QVERIFY(
            HelpDialog::pagePath(QLocale(QLocale::French)).endsWith(QStringLiteral("_fr.html")));
        QCOMPARE(HelpDialog::pagePath(QLocale(QLocale::Spanish)),
                 QStringLiteral(":/help/getting-started.html"));
        QFile german(HelpDialog::pagePath(QLocale(QLocale::German)));
        QVERIFY(german.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(german.readAll()).contains(QStringLiteral("Erste Schritte")));
    }

    void qtsOwnDialogsAreTranslated() {
        for (QLocale::Language language : {QLocale::German, QLocale::French}) {
            QTranslator qt;
            QVERIFY2(loadQtTranslation(qt, QLocale(language)),
                     "Qt's translations are missing (qt6-translations-l10n)");
            QCoreApplication::installTranslator(&qt);
            const QString open = QCoreApplication::translate("QFileDialog", "&Open");
            const QString cancel = QCoreApplication::translate("QPlatformTheme", "Cancel");
            QCoreApplication::removeTranslator(&qt);
            QVERIFY2(open != QStringLiteral("&Open"), qPrintable(open));
            QVERIFY2(cancel != QStringLiteral("Cancel"), qPrintable(cancel));
        }
    }

    // What the planner says reaches the window in the editor's words, and translated.
    void plannerMessagesAreSaidInTheEditorsWords() {
        fc::Plan plan;
        plan.boundary = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
        plan.obstacles = {{{-1, 4}, {2, 4}, {2, 6}, {-1, 6}},
                          {{8, 2}, {12, 2}, {12, 5}, {8, 5}},
                          {{10, 3}, {14, 3}, {14, 7}, {10, 7}}};
        plan.rooms = {{"A", {{0, 0}, {12, 0}, {12, 10}, {0, 10}}},
                      {"B", {{8, 0}, {20, 0}, {20, 10}, {8, 10}}}};
        QStringList messages;
        for (const fc::PlanProblem& problem : fc::planProblems(plan, fc::RobotProfile{}))
            messages << QString::fromStdString(problem.message);
        fc::Plan bowTie;
        bowTie.boundary = {{0, 0}, {10, 8}, {10, 0}, {0, 8}};
        for (const fc::PlanProblem& problem : fc::planProblems(bowTie, fc::RobotProfile{}))
            messages << QString::fromStdString(problem.message);
        fc::Plan rooms;
        rooms.boundary = plan.boundary;
        rooms.rooms = plan.rooms;
        for (const fc::PlanProblem& problem : fc::planProblems(rooms, fc::RobotProfile{}))
            messages << QString::fromStdString(problem.message);
        fc::RobotProfile robot;
        robot.robotDiameter = 2.0;
        try {
            robot.validate();
        } catch (const fc::InputError& e) {
            messages << QString::fromStdString(e.what());
        }
        // Forms the plans above do not reach, as the validator words them.
        messages << QStringLiteral("obstacles 2 and 5 are identical (duplicate obstacle)")
                 << QStringLiteral("room 3 has no name")
                 << QStringLiteral("room \"Store\" does not overlap the free space (it covers "
                                   "only obstacles)")
                 << QStringLiteral("free area 0.12 m^2 (boundary minus obstacles) is smaller "
                                   "than the robot footprint 0.28 m^2 (L = 0.6 m)");
        QVERIFY(messages.size() >= 9);
        saidInTheEditorsWordsAndTranslated(messages);
    }

    // The planner's other messages as it words them today: the plan's checks, the robot,
    // room edits, planning, the solvers, dqn models, files, imports, exports and the tiling
    // robot. Most come from calling the planner, so that a change of its wording shows here.
    void everyPlannerMessageHasAForm() {
        QStringList messages = plannerMessagesAsWorded();
        QVERIFY(messages.size() >= 150);
        saidInTheEditorsWordsAndTranslated(messages);
    }

    // A message about a file keeps the file's path in front; values are put in once (a room
    // named "%2" stays "%2"); a message without a form passes through.
    void plannerMessagesKeepPathsAndValues() {
        const QString path = QStringLiteral("/plans/My Plan.geojson");
        QCOMPARE(plainMessage(path + QStringLiteral(": feature 3 (obstacle) has no geometry")),
                 path + QStringLiteral(": Feature 3 (obstacle) has no geometry."));
        QCOMPARE(plainMessage(QStringLiteral(":/plans/office.geojson: file is empty")),
                 QStringLiteral(":/plans/office.geojson: The file is empty."));
        QCOMPARE(plainMessage(QStringLiteral("model.fcdqn: cannot open the model file")),
                 QStringLiteral("model.fcdqn: The model file cannot be opened: check that it "
                                "exists and can be read."));
        QCOMPARE(plainMessage(QStringLiteral("duplicate room name \"%2 %1\"")),
                 QStringLiteral("Two rooms are named “%2 %1”: rename one."));
        QCOMPARE(plainMessage(QStringLiteral("room \"A (room)\" (feature 2) has a hole; model "
                                             "the hole as an obstacle instead")),
                 QStringLiteral("Room “A (room)” (feature 2) has a hole: draw the hole as an "
                                "obstacle instead."));
        QCOMPARE(
            plainMessage(path + QStringLiteral(": boundary intersects itself near (1.0, 2.0)")),
            path + QStringLiteral(": The outer wall crosses itself near (1.0, 2.0)."));
        QCOMPARE(plainMessage(QStringLiteral("the plan needs repair: obstacle 2 lies inside "
                                             "obstacle 1")),
                 QStringLiteral("The plan needs repair (Plan > Repair Plan, after the import): "
                                "Obstacle 2 lies inside obstacle 1."));
        QCOMPARE(plainMessage(QStringLiteral("room \"Kitchen\" left out: room \"Kitchen\" lies "
                                             "outside the boundary")),
                 QStringLiteral("Room “Kitchen” is left out: Room “Kitchen” lies outside the "
                                "walls."));
        QCOMPARE(
            plainMessage(QStringLiteral("/plans/house.ifc: the section at height 0.3 m (storey "
                                        "\"whole model\" floor + 0.3 m) is not a valid plan: "
                                        "the boundary encloses no area")),
            QStringLiteral("/plans/house.ifc: The cut at height 0.3 m (0.3 m above the floor "
                           "of storey “whole model”) makes no valid plan: The outer wall "
                           "encloses no area."));
        for (const char* unknown : {"/plans/a.geojson: something new", "a: b", "Training failed"})
            QCOMPARE(plainMessage(QLatin1String(unknown)), QLatin1String(unknown));
    }
};

QTEST_MAIN(HelpTest)
#include "test_help.moc"
