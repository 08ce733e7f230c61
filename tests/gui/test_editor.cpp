// The editor driven through its real widgets: drawing by mouse, undo/redo, files, room
// selection, start/end, planning, exports and refused input.
#include "EditorFixture.h"
#include "canvas/OverlayLayer.h"
#include "canvas/PlanScene.h"
#include "docks/PlanningDock.h"
#include "document/Autosaver.h"
#include "formats/Export.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "tasks/PlanningController.h"
#include "tools/DrawPolygonTool.h"

#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QListWidget>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <nlohmann/json.hpp>

using namespace fc::ui;
using namespace fc::ui::test;

class EditorTest : public QObject {
    Q_OBJECT

private:
    // A 20 x 14 m floor with one room (left half) and a 3 x 3 m obstacle, all by mouse.
    void drawFloor(MainWindow& window);
    QTemporaryDir dir_;

private slots:
    void initTestCase();
    void drawRoomAndObstacleByMouse();
    void invalidGeometryIsRefusedWithMessage();
    void undoRedo();
    void editVertexByDrag();
    void saveAndReopen();
    void toggleRoomOnCanvas();
    void placeStartAndEnd();
    void planShowsPathAndMetrics();
    void robotProfileUpdatesOverlays();
    void invalidRobotProfileIsRefused();
    void exportGeoJsonParses();
    void screenshotWritesPng();
    void brokenFileKeepsDocument();
    void longitudeLatitudePlanOpensInMetres();
    void autosaveRecoversAfterCrash();
};

void EditorTest::initTestCase() {
    QStandardPaths::setTestModeEnabled(true); // recent files go to a test settings file
    QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverTests"));
    QCoreApplication::setApplicationName(QStringLiteral("gui_tests"));
    QVERIFY(dir_.isValid());
}

void EditorTest::drawFloor(MainWindow& window) {
    window.newDocument();
    useDrawingScale(window);
    useTool(window, "drawBoundary");
    clickPolygon(window, {{0, 0}, {20, 0}, {20, 14}, {0, 14}});
    useTool(window, "drawRoom");
    clickPolygon(window, {{0, 0}, {10, 0}, {10, 14}, {0, 14}});
    useTool(window, "drawObstacle");
    drag(window, {13, 5}, {16, 8}); // rectangle by drag
}

void EditorTest::drawRoomAndObstacleByMouse() {
    auto window = makeWindow();
    drawFloor(*window);
    const fc::Plan& plan = window->document()->plan();
    QCOMPARE(plan.boundary.size(), size_t(4));
    QCOMPARE(plan.rooms.size(), size_t(1));
    QCOMPARE(plan.rooms[0].outline.size(), size_t(4));
    QCOMPARE(QString::fromStdString(plan.rooms[0].name), QStringLiteral("Room 1"));
    QCOMPARE(plan.obstacles.size(), size_t(1));
    // Snapped to the grid: the rectangle's corners are exactly where the mouse went.
    QCOMPARE(fc::boundsOf(plan.obstacles[0]).minX, 13.0);
    QCOMPARE(fc::boundsOf(plan.obstacles[0]).maxY, 8.0);
    QCOMPARE(window->document()->undoStack()->count(), 3);
    QVERIFY(window->document()->isModified());
}

void EditorTest::invalidGeometryIsRefusedWithMessage() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "drawObstacle");
    // Crosses the boundary: the planner's validation refuses it.
    drag(*window, {18, 10}, {23, 12});
    QCOMPARE(window->document()->plan().obstacles.size(), size_t(1));
    QVERIFY2(window->lastError().contains(QLatin1String("Obstacle")),
             qPrintable(window->lastError()));
    auto* tool = qobject_cast<DrawPolygonTool*>(window->toolManager()->activeTool());
    QVERIFY(tool);
    QCOMPARE(tool->sketch().size(), 4); // the refused polygon stays marked on the canvas
}

void EditorTest::undoRedo() {
    auto window = makeWindow();
    drawFloor(*window);
    QUndoStack* stack = window->document()->undoStack();
    stack->undo();
    QCOMPARE(window->document()->plan().obstacles.size(), size_t(0));
    stack->undo();
    QCOMPARE(window->document()->plan().rooms.size(), size_t(0));
    QCOMPARE(window->planningDock()->roomList()->count(), 1); // "Floor"
    stack->redo();
    stack->redo();
    QCOMPARE(window->document()->plan().rooms.size(), size_t(1));
    QCOMPARE(window->document()->plan().obstacles.size(), size_t(1));
    QCOMPARE(window->planningDock()->roomList()->item(0)->text(), QStringLiteral("Room 1"));
}

void EditorTest::editVertexByDrag() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "editVertices");
    drag(*window, {16, 8}, {17, 9}); // the obstacle's top-right corner
    const fc::Ring& obstacle = window->document()->plan().obstacles.at(0);
    QVERIFY(std::find(obstacle.begin(), obstacle.end(), fc::Vec2(17, 9)) != obstacle.end());
    QCOMPARE(window->document()->undoStack()->undoText(), QStringLiteral("Move vertex"));
    window->document()->undoStack()->undo();
    const fc::Ring& restored = window->document()->plan().obstacles.at(0);
    QVERIFY(std::find(restored.begin(), restored.end(), fc::Vec2(16, 8)) != restored.end());
}

void EditorTest::saveAndReopen() {
    auto window = makeWindow();
    drawFloor(*window);
    const QString path = dir_.filePath(QStringLiteral("floor.fcproj"));
    QVERIFY(window->saveFile(path));
    QVERIFY(!window->document()->isModified());
    QVERIFY(window->windowTitle().startsWith(QStringLiteral("floor.fcproj")));

    auto reopened = makeWindow();
    QVERIFY2(reopened->openFile(path), qPrintable(reopened->lastError()));
    const fc::Plan& plan = reopened->document()->plan();
    QCOMPARE(plan.boundary.size(), size_t(4));
    QCOMPARE(plan.obstacles.size(), size_t(1));
    QCOMPARE(reopened->document()->roomNames(), QStringList{QStringLiteral("Room 1")});
    QCOMPARE(reopened->document()->fileName(), QFileInfo(path).absoluteFilePath());
}

void EditorTest::toggleRoomOnCanvas() {
    auto window = makeWindow();
    window->openSample();
    Document* document = window->document();
    QVERIFY(document->isRoomSelected(QStringLiteral("Corridor")));
    useTool(*window, "pickRooms");
    window->view()->fitToPlan();
    // The office corridor runs along y = 9..11 (see resources/plans/office.geojson).
    const std::optional<QString> room = document->roomAt({15.0, 10.0});
    QVERIFY(room.has_value());
    click(*window, {15.0, 10.0});
    QVERIFY(!document->isRoomSelected(*room));
    const QList<QListWidgetItem*> items =
        window->planningDock()->roomList()->findItems(*room, Qt::MatchExactly);
    QCOMPARE(items.size(), 1);
    QCOMPARE(items[0]->checkState(), Qt::Unchecked);
    // The check box toggles it back.
    items[0]->setCheckState(Qt::Checked);
    QVERIFY(document->isRoomSelected(*room));
}

void EditorTest::placeStartAndEnd() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "placeStart");
    click(*window, {1, 1});
    useTool(*window, "placeEnd");
    click(*window, {19, 13});
    const fc::Project& project = window->document()->project();
    QVERIFY(project.hasStart && project.hasEnd);
    QCOMPARE(project.start, fc::Vec2(1, 1));
    QCOMPARE(project.end, fc::Vec2(19, 13));
    click(*window, {19, 13}, Qt::RightButton); // removes the end
    QVERIFY(!window->document()->project().hasEnd);
}

void EditorTest::planShowsPathAndMetrics() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "placeStart");
    click(*window, {1, 1});
    PlanningController* planner = window->planningController();
    QTRY_VERIFY_WITH_TIMEOUT(planner->prepared() != nullptr, 20000);
    OverlayLayer* overlays = window->scene()->overlays();
    window->setViewMode(ViewMode::Graph); // cells and graph are built for the Graph view
    QVERIFY(overlays->itemCount(OverlayKind::PrimaryCells) > 0);
    QVERIFY(overlays->itemCount(OverlayKind::TransitionCells) > 0);
    QVERIFY(overlays->itemCount(OverlayKind::CornerNodes) > 0);

    QTest::mouseClick(window->planningDock()->planButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(planner->result() != nullptr, 30000);
    QVERIFY(overlays->itemCount(OverlayKind::Path) > 0);
    QCOMPARE(overlays->itemCount(OverlayKind::CoverageGaps), 1); // one path of dots
    const fc::Metrics& metrics = planner->result()->metrics;
    QVERIFY(metrics.coverage >= 0.99);
    QVERIFY(metrics.length > 0);
    QVERIFY(window->planningDock()->metricText(QStringLiteral("length")).endsWith(" m"));
    QVERIFY(window->planningDock()->metricText(QStringLiteral("coverage")).endsWith(" %"));

    // Any edit makes the path stale: it stays on screen greyed, without its gaps, until
    // live replanning brings the new one.
    const auto before = planner->result();
    useTool(*window, "placeEnd");
    click(*window, {19, 13});
    QVERIFY(planner->result() == nullptr);
    QCOMPARE(planner->staleResult(), before);
    QVERIFY(overlays->itemCount(OverlayKind::Path) > 0);
    QVERIFY(overlays->opacity(OverlayKind::Path) < 0.5);
    QCOMPARE(overlays->opacity(OverlayKind::CoverageGaps), 0.0);
    QTRY_VERIFY_WITH_TIMEOUT(planner->result() && !planner->isDraft(), 30000);
    QVERIFY(planner->staleResult() == nullptr);
    QCOMPARE(overlays->itemCount(OverlayKind::CoverageGaps), 1);
    QCOMPARE(overlays->opacity(OverlayKind::Path), 1.0);
    QCOMPARE(overlays->opacity(OverlayKind::CoverageGaps), 1.0);
}

void EditorTest::robotProfileUpdatesOverlays() {
    auto window = makeWindow();
    drawFloor(*window);
    PlanningController* planner = window->planningController();
    QTRY_VERIFY_WITH_TIMEOUT(planner->prepared() != nullptr && !planner->isBusy(), 20000);
    const auto stripeCount = [planner]() {
        size_t stripes = 0;
        for (const fc::Cell& cell : planner->prepared()->decomposition.cells)
            stripes += cell.stripes.size();
        return stripes;
    };
    const size_t stripesBefore = stripeCount();
    window->planningDock()->widthBox()->setValue(0.6); // W = 0.6 m: more stripes
    QCOMPARE(window->document()->project().robot.coverageWidth, 0.6);
    QTRY_VERIFY_WITH_TIMEOUT(!planner->isBusy() && planner->prepared() &&
                                 planner->prepared()->robot.coverageWidth == 0.6,
                             20000);
    QVERIFY(stripeCount() > stripesBefore);
    window->document()->undoStack()->undo();
    QCOMPARE(window->planningDock()->widthBox()->value(), 1.0);
}

void EditorTest::invalidRobotProfileIsRefused() {
    auto window = makeWindow();
    drawFloor(*window);
    const int commands = window->document()->undoStack()->count();
    window->planningDock()->widthBox()->setValue(0.4); // W < L = 0.6 m
    QCOMPARE(window->document()->project().robot.coverageWidth, 1.0);
    QCOMPARE(window->planningDock()->widthBox()->value(), 1.0); // put back
    QCOMPARE(window->document()->undoStack()->count(), commands);
    QVERIFY(!window->lastError().isEmpty());
}

void EditorTest::exportGeoJsonParses() {
    auto window = makeWindow();
    window->openSample();
    const QString path = dir_.filePath(QStringLiteral("path.geojson"));
    QVERIFY(!window->exportPath(path)); // nothing planned yet
    QVERIFY(window->planningController()->planAndWait());
    QVERIFY2(window->exportPath(path), qPrintable(window->lastError()));
    const auto root = nlohmann::json::parse(fc::readFile(path.toStdString()));
    QCOMPARE(root.at("type").get<std::string>(), std::string("FeatureCollection"));
    const auto& geometry = root.at("features").at(0).at("geometry");
    QCOMPARE(geometry.at("type").get<std::string>(), std::string("LineString"));
    QVERIFY(geometry.at("coordinates").size() > 10);
    QVERIFY(window->exportPath(dir_.filePath(QStringLiteral("path.csv"))));
    QVERIFY(window->exportView(dir_.filePath(QStringLiteral("view.svg"))));
    QVERIFY(QFileInfo(dir_.filePath(QStringLiteral("view.svg"))).size() > 1000);
    const QString report = dir_.filePath(QStringLiteral("report.pdf"));
    QVERIFY(window->exportReport(report));
    QFile pdf(report);
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5) == "%PDF-");
    QVERIFY(pdf.size() > 5000);
}

void EditorTest::screenshotWritesPng() {
    MainWindow window;
    const QString path = dir_.filePath(QStringLiteral("shot.png"));
    QString error;
    QVERIFY2(window.renderScreenshot(path, QStringLiteral(FC_PLANS_DIR "/simple.geojson"), &error),
             qPrintable(error));
    QImage image(path);
    QVERIFY(!image.isNull());
    QVERIFY(image.width() >= 800 && image.height() >= 500);
    QVERIFY(window.scene()->overlays()->itemCount(OverlayKind::Path) > 0);
}

void EditorTest::brokenFileKeepsDocument() {
    auto window = makeWindow();
    window->openSample();
    Document* before = window->document();
    const size_t rooms = before->plan().rooms.size();
    // (A plan that parses but is invalid opens for repair: gui_repair.)
    for (const char* name : {"truncated.geojson", "nan.geojson", "bad-robot.fcproj"}) {
        const QString path = QStringLiteral(FC_TEST_DATA_DIR "/") + QLatin1String(name);
        QVERIFY2(!window->openFile(path), name);
        QCOMPARE(window->document(), before);
        QCOMPARE(window->document()->plan().rooms.size(), rooms);
        QVERIFY2(window->lastError().contains(QLatin1String(name)),
                 qPrintable(window->lastError()));
    }
    QVERIFY(!window->openFile(dir_.filePath(QStringLiteral("missing.fcproj"))));
    QCOMPARE(window->document(), before);
}

// A plan in longitude/latitude (what GIS tools write) opens in metres, in its UTM zone, and
// the status bar says so.
void EditorTest::longitudeLatitudePlanOpensInMetres() {
    const fc::Plan utm = fc::loadProjectFile(FC_TEST_DATA_DIR "/utm-offset.geojson").plan;
    const QString path = dir_.filePath(QStringLiteral("lonlat.geojson"));
    fc::writeFileAtomically(
        path.toStdString(),
        fc::exportToFormat(fc::ExportFormat::Wgs84GeoJson, fc::ExportSubject::Plan, utm, {}, {}));
    auto window = makeWindow();
    QVERIFY2(window->openFile(path), qPrintable(window->lastError()));
    QCOMPARE(window->document()->plan().epsg, std::optional<int>(32632));
    QVERIFY(std::abs(window->document()->plan().boundary[0].x - utm.boundary[0].x) < 1e-3);
    const QString message = window->statusBar()->currentMessage();
    QVERIFY2(message.contains(QLatin1String("UTM zone 32N (EPSG:32632)")), qPrintable(message));
}

void EditorTest::autosaveRecoversAfterCrash() {
    QFile::remove(Autosaver::recoveryPath()); // test mode: a folder of the tests' own
    {
        auto crashed = makeWindow();
        drawFloor(*crashed);
        crashed->autosaver()->saveNow();
        QVERIFY(Autosaver::hasRecovery());
    } // destroyed without closing: the recovery file stays, as after a crash
    auto window = makeWindow();
    QVERIFY(window->recoverAutosave());
    QCOMPARE(window->document()->plan().obstacles.size(), size_t(1));
    QCOMPARE(window->document()->roomNames(), QStringList{QStringLiteral("Room 1")});
    QVERIFY(window->document()->isModified());
    QVERIFY(window->saveFile(dir_.filePath(QStringLiteral("recovered.fcproj"))));
    QVERIFY(!Autosaver::hasRecovery()); // saved: nothing left to recover
    QVERIFY(!window->recoverAutosave());
}

QTEST_MAIN(EditorTest)
#include "test_editor.moc"
