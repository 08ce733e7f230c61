// Window-level behaviour: the sweep modes and per-room angles, recent files, preferences.
#include "EditorFixture.h"
#include "canvas/PlanScene.h"
#include "dialogs/PreferencesDialog.h"
#include "docks/PlanningDock.h"
#include "tasks/PlanningController.h"
#include "window/Translations.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QGraphicsPathItem>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>

using namespace fc::ui;
using namespace fc::ui::test;

class WindowTest : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;

private slots:
    void initTestCase();
    void autoAngleIsOneOfTheCandidates();
    void perRoomAnglesFollowWallsAndOverridesAreUndoable();
    void lossesShowInTheMetricsPanel();
    void savedFileAppearsInRecentFiles();
    void preferencesStoreTheLanguage();
    void newDocumentStartsWithTheBoundaryTool();
    void undoInterleavesGeometryAndSettings();
    void droppedFileOpens();
    void paletteChangeRestylesTheScene();
};

void WindowTest::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverTests"));
    QCoreApplication::setApplicationName(QStringLiteral("gui_window"));
    QVERIFY(dir_.isValid());
}

void WindowTest::autoAngleIsOneOfTheCandidates() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple-diamond.geojson")));
    window->planningDock()->sweepModeBox()->setCurrentIndex(1); // auto
    QVERIFY(window->document()->project().sweep.automatic);
    QVERIFY(window->planningController()->planAndWait());
    const double angle = window->planningController()->result()->stripeAngleDeg;
    const std::vector<double> candidates = fc::candidateAngles(window->document()->plan());
    QVERIFY(std::find(candidates.begin(), candidates.end(), angle) != candidates.end());
    QVERIFY(window->planningDock()
                ->metricText(QStringLiteral("angle"))
                .startsWith(QLocale().toString(angle, 'f', 1)));
    window->document()->undoStack()->undo();
    QCOMPARE(window->planningDock()->sweepModeBox()->currentIndex(), 0); // per room again
}

void WindowTest::perRoomAnglesFollowWallsAndOverridesAreUndoable() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/office.geojson")));
    PlanningDock* dock = window->planningDock();
    QCOMPARE(dock->sweepModeBox()->currentIndex(), 0); // per room is the default
    QTableWidget* table = dock->roomAngleTable();
    QCOMPARE(table->rowCount(), 13);
    int corridor = -1;
    for (int row = 0; row < table->rowCount(); ++row)
        if (table->item(row, 0)->text() == QStringLiteral("Corridor"))
            corridor = row;
    QVERIFY(corridor >= 0);
    // The corridor runs across the offices: its walls give it the other direction.
    QVERIFY(table->item(corridor, 1)->text() != table->item(0, 1)->text());
    QVERIFY(table->item(corridor, 2)->text().isEmpty());
    table->item(corridor, 2)->setText(QLocale().toString(45.0, 'f', 1));
    QCOMPARE(window->document()->project().sweep.roomAngles.at("Corridor"), 45.0);
    QVERIFY(window->planningController()->planAndWait());
    const auto result = window->planningController()->result();
    bool at45 = false;
    for (const fc::PlanPart& part : result->parts)
        at45 |= std::abs(part.stripeAngleDeg - 45.0) < 1e-9;
    QVERIFY(at45);
    // The angle each room was planned at: the corridor's is the one fixed.
    QCOMPARE(table->item(corridor, 3)->text(),
             QStringLiteral("%1°").arg(QLocale().toString(45.0, 'f', 1)));
    for (int row = 0; row < table->rowCount(); ++row)
        QVERIFY(table->item(row, 3)->text().endsWith(QStringLiteral("°")));
    window->document()->undoStack()->undo();
    QVERIFY(window->document()->project().sweep.roomAngles.empty());
    QVERIFY(table->item(corridor, 2)->text().isEmpty());
    // A word that is not an angle is refused and says so.
    table->item(corridor, 2)->setText(QStringLiteral("north"));
    QVERIFY(window->document()->project().sweep.roomAngles.empty());
}

void WindowTest::lossesShowInTheMetricsPanel() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_TEST_DATA_DIR "/door-0.5m.geojson")));
    window->document()->setStart(fc::Vec2{1, 1});
    QVERIFY(window->planningController()->planAndWait());
    // The east room lies behind a door narrower than the robot: half the floor uncovered.
    const QString uncovered = window->planningDock()->metricText(QStringLiteral("uncovered"));
    QVERIFY2(uncovered.contains(QStringLiteral("m²")), qPrintable(uncovered));
    const auto result = window->planningController()->result();
    QVERIFY(result->metrics.uncoveredArea > 25.0);
    QVERIFY(!result->warnings.empty());
}

void WindowTest::savedFileAppearsInRecentFiles() {
    auto window = makeWindow();
    window->openSample();
    const QString path = dir_.filePath(QStringLiteral("office.fcproj"));
    QVERIFY(window->saveFile(path));
    QMenu* recent = nullptr;
    for (QMenu* menu : window->menuBar()->findChildren<QMenu*>())
        if (menu->title() == QStringLiteral("Open &Recent"))
            recent = menu;
    QVERIFY(recent);
    QVERIFY(!recent->actions().isEmpty());
    QCOMPARE(recent->actions().first()->text(), QStringLiteral("office.fcproj"));
    // The entry opens the file.
    window->newDocument();
    recent->actions().first()->trigger();
    QCOMPARE(window->document()->fileName(), QFileInfo(path).absoluteFilePath());
}

void WindowTest::preferencesStoreTheLanguage() {
    const QString before = languageSetting();
    PreferencesDialog dialog;
    QComboBox* box = dialog.languageBox();
    box->setCurrentIndex(box->findData(QStringLiteral("de")));
    dialog.accept();
    QCOMPARE(languageSetting(), QStringLiteral("de"));
    setLanguageSetting(before);
}

void WindowTest::newDocumentStartsWithTheBoundaryTool() {
    auto window = makeWindow();
    window->openSample();
    window->newDocument();
    QVERIFY(window->document()->plan().boundary.empty());
    QCOMPARE(window->toolManager()->activeTool()->objectName(), QStringLiteral("drawBoundary"));
    QVERIFY(!window->document()->isModified());
}

void WindowTest::undoInterleavesGeometryAndSettings() {
    auto window = makeWindow();
    window->openSample();
    Document* document = window->document();
    const size_t obstacles = document->plan().obstacles.size();
    fc::RobotProfile robot = document->project().robot;
    robot.coverageWidth = 0.8;
    QVERIFY(document->setRobot(robot));
    QVERIFY(document->addPolygon(PolygonRole::Obstacle, {{2, 2}, {3, 2}, {3, 3}, {2, 3}}));
    QVERIFY(document->setSweep(fc::SweepOptions{0.0, false, false, {}}));
    QUndoStack* stack = document->undoStack();
    stack->undo(); // sweep
    QCOMPARE(document->plan().obstacles.size(), obstacles + 1);
    stack->undo(); // obstacle
    QCOMPARE(document->plan().obstacles.size(), obstacles);
    QCOMPARE(document->project().robot.coverageWidth, 0.8);
    stack->undo(); // robot: the plan stays as it is
    QCOMPARE(document->project().robot.coverageWidth, 1.0);
    QCOMPARE(document->plan().obstacles.size(), obstacles);
    stack->redo();
    stack->redo();
    stack->redo();
    QCOMPARE(document->plan().obstacles.size(), obstacles + 1);
    QCOMPARE(document->project().robot.coverageWidth, 0.8);
    QCOMPARE(document->project().sweep.angleDeg, 0.0);
}

void WindowTest::droppedFileOpens() {
    auto window = makeWindow();
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(QStringLiteral(FC_PLANS_DIR "/room-obstacle.geojson"))});
    QDragEnterEvent enter(QPoint(200, 200), Qt::CopyAction, &data, Qt::LeftButton, {});
    QCoreApplication::sendEvent(window.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(200, 200), Qt::CopyAction, &data, Qt::LeftButton, {});
    QCoreApplication::sendEvent(window.get(), &drop);
    QCOMPARE(window->document()->displayName(), QStringLiteral("room-obstacle"));
    QMimeData text;
    text.setText(QStringLiteral("not a file"));
    QDragEnterEvent refused(QPoint(200, 200), Qt::CopyAction, &text, Qt::LeftButton, {});
    QCoreApplication::sendEvent(window.get(), &refused);
    QVERIFY(!refused.isAccepted());
}

void WindowTest::paletteChangeRestylesTheScene() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson"))); // an obstacle
    const auto obstacleColour = [&window]() {
        for (QGraphicsItem* item : window->scene()->items())
            if (auto* path = dynamic_cast<QGraphicsPathItem*>(item);
                path && path->brush().style() == Qt::SolidPattern && path->zValue() == 1.0)
                return path->brush().color();
        return QColor();
    };
    const QPalette light = QApplication::palette();
    const QColor before = obstacleColour();
    QVERIFY(before.isValid());
    QPalette dark = light;
    dark.setColor(QPalette::Base, QColor(30, 30, 30));
    dark.setColor(QPalette::Text, QColor(230, 230, 230));
    QApplication::setPalette(dark);
    QTRY_VERIFY(obstacleColour() != before);
    QApplication::setPalette(light);
    QTRY_COMPARE(obstacleColour(), before);
}

QTEST_MAIN(WindowTest)
#include "test_window.moc"
