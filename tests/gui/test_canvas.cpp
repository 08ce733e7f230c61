// Canvas and editing details through the real view: zoom, pan, cursor coordinates,
// vertex insertion and deletion, polygon deletion, right angles, renaming, merging.
#include "EditorFixture.h"
#include "docks/LegendDock.h"
#include "canvas/PathPreview.h"
#include "docks/PathPreviewBar.h"
#include "canvas/PlanScene.h"
#include "tasks/PlanningController.h"
#include "docks/PlanningDock.h"
#include "window/Translations.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollBar>
#include <QSlider>
#include <QStatusBar>
#include <QTranslator>
#include <QUndoStack>

using namespace fc::ui;
using namespace fc::ui::test;

class CanvasTest : public QObject {
    Q_OBJECT

private:
    // A 20 x 14 m floor with one 3 x 3 m obstacle at (13, 5).
    static std::unique_ptr<MainWindow> floorWithObstacle();

private slots:
    void wheelZoomsAroundCursor();
    void middleDragPans();
    void statusBarShowsCursorCoordinates();
    void refusedVertexMoveKeepsThePlan();
    void doubleClickInsertsVertex();
    void rightClickDeletesVertex();
    void deleteKeyDeletesSelectedPolygon();
    void shiftKeepsRightAngles();
    void renameRoomInList();
    void spinBoxStepsMergeIntoOneCommand();
    void legendAndViewMenuToggleOverlays();
    void previewDrivesRobotAlongPath();
    void translationsAreCompleteAndLoad();
};

std::unique_ptr<MainWindow> CanvasTest::floorWithObstacle() {
    auto window = makeWindow();
    window->newDocument();
    useDrawingScale(*window);
    useTool(*window, "drawBoundary");
    clickPolygon(*window, {{0, 0}, {20, 0}, {20, 14}, {0, 14}});
    useTool(*window, "drawObstacle");
    clickPolygon(*window, {{13, 5}, {16, 5}, {16, 8}, {13, 8}});
    return window;
}

void CanvasTest::wheelZoomsAroundCursor() {
    auto window = floorWithObstacle();
    CanvasView* view = window->view();
    const double before = view->metresPerPixel();
    const QPoint at = viewPoint(*window, {5, 5});
    QWheelEvent wheel(at, view->viewport()->mapToGlobal(at), QPoint(), QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view->viewport(), &wheel);
    QVERIFY(view->metresPerPixel() < before);
    // The point under the cursor stays put (anchor under mouse), within a pixel.
    const QPointF under = view->mapToScene(at);
    QVERIFY(std::abs(under.x() - 5) < 2 * view->metresPerPixel());
    QVERIFY(std::abs(under.y() - 5) < 2 * view->metresPerPixel());
    // y points up: a larger plan y is higher on screen.
    QVERIFY(viewPoint(*window, {5, 10}).y() < viewPoint(*window, {5, 5}).y());
}

void CanvasTest::middleDragPans() {
    auto window = floorWithObstacle();
    CanvasView* view = window->view();
    view->zoomIn();
    view->zoomIn();
    const QPointF centreBefore = view->mapToScene(view->viewport()->rect().center());
    QWidget* viewport = view->viewport();
    QTest::mousePress(viewport, Qt::MiddleButton, {}, QPoint(300, 300));
    QTest::mouseMove(viewport, QPoint(350, 320));
    QTest::mouseMove(viewport, QPoint(400, 340));
    QTest::mouseRelease(viewport, Qt::MiddleButton, {}, QPoint(400, 340));
    const QPointF centreAfter = view->mapToScene(view->viewport()->rect().center());
    QVERIFY(centreAfter.x() < centreBefore.x());           // content moved right: view looks left
    QVERIFY(centreAfter.y() > centreBefore.y());           // content moved down: view looks up
    QCOMPARE(window->document()->undoStack()->count(), 2); // panning edits nothing
}

void CanvasTest::statusBarShowsCursorCoordinates() {
    auto window = floorWithObstacle();
    QTest::mouseMove(window->view()->viewport(), viewPoint(*window, {7, 3}));
    bool found = false;
    for (const QLabel* label : window->statusBar()->findChildren<QLabel*>())
        found = found || label->text().contains(QLatin1String("7.00 m"));
    QVERIFY(found);
}

void CanvasTest::refusedVertexMoveKeepsThePlan() {
    auto window = floorWithObstacle();
    useTool(*window, "editVertices");
    const fc::Ring before = window->document()->plan().obstacles.at(0);
    drag(*window, {16, 8}, {21, 9}); // the obstacle's corner outside the boundary
    QVERIFY(window->document()->plan().obstacles.at(0) == before);
    QVERIFY2(window->lastError().contains(QLatin1String("obstacle"), Qt::CaseInsensitive),
             qPrintable(window->lastError()));
    QCOMPARE(window->document()->undoStack()->count(), 2);
}

void CanvasTest::doubleClickInsertsVertex() {
    auto window = floorWithObstacle();
    useTool(*window, "editVertices");
    QTest::mouseDClick(window->view()->viewport(), Qt::LeftButton, {},
                       viewPoint(*window, {14.5, 5}));
    const fc::Ring& obstacle = window->document()->plan().obstacles.at(0);
    QCOMPARE(obstacle.size(), size_t(5));
    QVERIFY(std::find(obstacle.begin(), obstacle.end(), fc::Vec2(14.5, 5)) != obstacle.end());
    QCOMPARE(window->document()->undoStack()->undoText(), QStringLiteral("Insert vertex"));
}

void CanvasTest::rightClickDeletesVertex() {
    auto window = floorWithObstacle();
    useTool(*window, "editVertices");
    QTest::mouseDClick(window->view()->viewport(), Qt::LeftButton, {},
                       viewPoint(*window, {14.5, 5}));
    click(*window, {14.5, 5}, Qt::RightButton);
    QCOMPARE(window->document()->plan().obstacles.at(0).size(), size_t(4));
    // A triangle is the least: deleting from a quadrilateral's triangle is refused.
    click(*window, {13, 5}, Qt::RightButton);
    click(*window, {16, 5}, Qt::RightButton);
    QCOMPARE(window->document()->plan().obstacles.at(0).size(), size_t(3));
    QVERIFY(window->lastError().contains(QLatin1String("three")));
}

void CanvasTest::deleteKeyDeletesSelectedPolygon() {
    auto window = floorWithObstacle();
    useTool(*window, "editVertices");
    click(*window, {14.5, 6.5}); // inside the obstacle: selects it
    QTest::keyClick(window->view(), Qt::Key_Delete);
    QCOMPARE(window->document()->plan().obstacles.size(), size_t(0));
    QCOMPARE(window->document()->undoStack()->undoText(), QStringLiteral("Delete obstacle"));
}

void CanvasTest::shiftKeepsRightAngles() {
    auto window = makeWindow();
    window->newDocument();
    useDrawingScale(*window);
    window->view()->snapper().snapToGrid = false; // only the right-angle constraint
    useTool(*window, "drawBoundary");
    QWidget* viewport = window->view()->viewport();
    click(*window, {0, 0});
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, viewPoint(*window, {10, 0.4}));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, viewPoint(*window, {10.3, 8}));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, viewPoint(*window, {0.2, 8}));
    click(*window, {0, 0});
    const fc::Ring& boundary = window->document()->plan().boundary;
    QCOMPARE(boundary.size(), size_t(4));
    QCOMPARE(boundary[1].y, boundary[0].y); // horizontal
    QCOMPARE(boundary[2].x, boundary[1].x); // perpendicular to it
    QCOMPARE(boundary[3].y, boundary[2].y);
}

void CanvasTest::renameRoomInList() {
    auto window = makeWindow();
    window->openSample();
    QListWidget* list = window->planningDock()->roomList();
    QListWidgetItem* item = list->item(0);
    const QString old = item->text();
    item->setText(QStringLiteral("Kitchen"));
    QVERIFY(window->document()->roomNames().contains(QStringLiteral("Kitchen")));
    QVERIFY(!window->document()->roomNames().contains(old));
    // A duplicate name is refused and the list shows the document's name again.
    list->item(1)->setText(QStringLiteral("Kitchen"));
    QCOMPARE(window->document()->roomNames().count(QStringLiteral("Kitchen")), 1);
    QVERIFY(list->item(1)->text() != QStringLiteral("Kitchen"));
    window->document()->undoStack()->undo();
    QVERIFY(window->document()->roomNames().contains(old));
}

void CanvasTest::spinBoxStepsMergeIntoOneCommand() {
    auto window = floorWithObstacle();
    QDoubleSpinBox* width = window->planningDock()->widthBox();
    const int before = window->document()->undoStack()->count();
    width->stepDown();
    width->stepDown();
    QCOMPARE(window->document()->undoStack()->count(), before + 1);
    QCOMPARE(window->document()->project().robot.coverageWidth, 0.9);
    window->document()->undoStack()->undo();
    QCOMPARE(window->document()->project().robot.coverageWidth, 1.0);
}

void CanvasTest::legendAndViewMenuToggleOverlays() {
    auto window = floorWithObstacle();
    OverlayLayer* overlays = window->scene()->overlays();
    QCheckBox* box = window->legendDock()->checkBox(OverlayKind::PrimaryCells);
    QVERIFY(box->isChecked() && overlays->isVisible(OverlayKind::PrimaryCells));
    box->setChecked(false);
    QVERIFY(!overlays->isVisible(OverlayKind::PrimaryCells));
    QVERIFY(!window->overlayAction(OverlayKind::PrimaryCells)->isChecked());
    window->overlayAction(OverlayKind::InterEdges)->setChecked(true);
    QVERIFY(overlays->isVisible(OverlayKind::InterEdges));
    QVERIFY(window->legendDock()->checkBox(OverlayKind::InterEdges)->isChecked());
}

void CanvasTest::previewDrivesRobotAlongPath() {
    auto window = floorWithObstacle();
    PathPreview* preview = window->pathPreview();
    auto* bar = window->planningDock()->findChild<PathPreviewBar*>();
    QVERIFY(bar);
    QVERIFY(!bar->isEnabled()); // nothing planned yet
    QVERIFY(window->planningController()->planAndWait());
    QVERIFY(bar->isEnabled());
    bar->speedSlider()->setValue(100);
    QTest::mouseClick(bar->playButton(), Qt::LeftButton);
    QVERIFY(preview->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(preview->progress() > 0.0, 5000);
    QTest::mouseClick(bar->playButton(), Qt::LeftButton);
    QVERIFY(!preview->isPlaying());
    preview->setProgress(1.0);
    QCOMPARE(preview->progress(), 1.0);
    // An edit makes the path stale: the preview stops and its controls are disabled.
    window->document()->setSweep(fc::SweepOptions{0.0, false, false, {}});
    QVERIFY(!preview->hasPath());
    QVERIFY(!bar->isEnabled());
}

void CanvasTest::translationsAreCompleteAndLoad() {
    for (const char* language : {"de", "fr"}) {
        QFile ts(QStringLiteral(FC_TRANSLATIONS_DIR "/floorcover_%1.ts").arg(language));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        const QByteArray text = ts.readAll();
        QVERIFY2(!text.contains("type=\"unfinished\""), language);
        QVERIFY(text.count("<message>") > 150);
    }
    QTranslator german;
    QVERIFY(loadEditorTranslation(german, QLocale(QLocale::German)));
    QCoreApplication::installTranslator(&german);
    PlanningDock dock;
    QCOMPARE(dock.planButton()->text(), QStringLiteral("Planen"));
    QCoreApplication::removeTranslator(&german);
    QTranslator english;
    QVERIFY(!loadEditorTranslation(english, QLocale(QLocale::English))); // the source
}

QTEST_MAIN(CanvasTest)
#include "test_canvas.moc"
