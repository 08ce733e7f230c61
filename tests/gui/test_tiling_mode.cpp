// Plan > Tiling Robot Mode (issue 7): the dock tiles the open floor off the GUI thread, the
// canvas shows the tiles and the tour, the figures appear in the dock, the waypoints export,
// and an edit of the floor drops the stale tiling.
#include "EditorFixture.h"
#include "modes/tiling/PpoTrainer.h"
#include "modes/tiling/PpoTrainingPanel.h"
#include "modes/tiling/TilingController.h"
#include "modes/tiling/TilingDock.h"
#include "modes/tiling/TilingItem.h"
#include "modes/tiling/TilingMode.h"
#include "tasks/Task.h"
#include "tasks/TaskListWidget.h"
#include "tiling/WaypointOrder.h"
#include "tiling/ppo/PpoOrdering.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace fc;
using namespace fc::ui;

class TilingModeTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerPpoOrdering(); } // as the app's main does
    void tilesOrdersShowsAndExports();
    void badRobotIsReportedNotCrashing();
    void trainsPpoWithALiveCurveAndPlansWithIt();
    void taskListCancelsPpoTrainingPromptly();
};

void TilingModeTest::tilesOrdersShowsAndExports() {
    auto window = test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    TilingMode* mode = window->tilingMode();
    QVERIFY(!mode->isActive());
    QVERIFY(!mode->dock()->isVisible());
    mode->action()->trigger();
    QVERIFY(mode->isActive());
    QVERIFY(mode->dock()->isVisible());

    mode->dock()->setSolver(QStringLiteral("greedy"));
    QCOMPARE(mode->dock()->solver(), QStringLiteral("greedy"));
    mode->dock()->tileAndOrder();
    QTRY_VERIFY_WITH_TIMEOUT(!mode->controller()->isBusy(), 60000);
    const auto plan = mode->controller()->result();
    QVERIFY2(plan, qPrintable(mode->controller()->errorMessage()));
    QCOMPARE(QString::fromStdString(plan->solver), QStringLiteral("greedy"));
    QVERIFY(plan->problem.size() > 100);
    QVERIFY(tiling::isTour(plan->tour, plan->problem.size()));
    QCOMPARE(static_cast<int>(plan->tiling.tiles.size()) * 4 +
                 static_cast<int>(plan->tiling.untiled.size() + plan->tiling.unreachable.size()),
             plan->tiling.freeCells);
    QVERIFY(mode->item()->hasPlan());
    QVERIFY(mode->item()->isVisible());
    QVERIFY(!mode->item()->boundingRect().isEmpty());
    QVERIFY2(mode->dock()->metricsText().contains(QStringLiteral("energy")),
             qPrintable(mode->dock()->metricsText()));
    QVERIFY(mode->dock()->metricsText().contains(QStringLiteral("rectangle")));

    // The canvas draws the tiles: the rendered view holds the rectangle's colour.
    const QImage image = window->view()->grab().toImage();
    const QColor tile = tileShapeColor(tiling::Shape::Rectangle);
    bool found = false;
    for (int y = 0; y < image.height() && !found; y += 3)
        for (int x = 0; x < image.width() && !found; x += 3) {
            const QColor c = image.pixelColor(x, y);
            found = c.saturation() > 40 && std::abs(c.hue() - tile.hue()) < 15;
        }
    QVERIFY2(found, "no tile colour on the canvas");

    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("waypoints.csv"));
    QVERIFY2(mode->dock()->exportWaypoints(csv), qPrintable(mode->dock()->lastError()));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    QCOMPARE(lines.front(), QByteArray("x,y,shape,heading"));
    QCOMPARE(lines.size(), plan->problem.size() + 1);
    QVERIFY(!mode->dock()->exportWaypoints(dir.filePath(QStringLiteral("waypoints.txt"))));
    QVERIFY(!mode->dock()->lastError().isEmpty());

    // Leaving the mode hides the tiles; an edit of the floor drops the stale result.
    mode->action()->trigger();
    QVERIFY(!mode->item()->isVisible());
    Ring boundary = window->document()->plan().boundary;
    for (Vec2& p : boundary)
        p.x *= 1.5;
    QVERIFY(window->document()->replaceRing({PolygonRole::Boundary, 0}, boundary,
                                            QStringLiteral("Stretch")));
    QVERIFY(!mode->controller()->result());
    QVERIFY(!mode->item()->hasPlan());
}

void TilingModeTest::badRobotIsReportedNotCrashing() {
    auto window = test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    TilingController* controller = window->tilingMode()->controller();
    tiling::TilingRobotProfile robot;
    robot.blockLeg = 50.0; // larger than the room: no tile fits anywhere
    controller->setRobot(robot);
    controller->runAndWait(QStringLiteral("greedy"), 1);
    QVERIFY(!controller->isBusy());
    if (controller->result()) // a tiling with no tiles is still a valid, empty answer
        QCOMPARE(controller->result()->tiling.tiles.size(), std::size_t(0));
    else
        QVERIFY(!controller->errorMessage().isEmpty());
    robot.blockLeg = -1.0;
    controller->setRobot(robot);
    QVERIFY(!controller->runAndWait(QStringLiteral("greedy"), 1));
    QVERIFY2(controller->errorMessage().contains(QStringLiteral("leg")) ||
                 controller->errorMessage().contains(QStringLiteral("block")),
             qPrintable(controller->errorMessage()));
}

void TilingModeTest::trainsPpoWithALiveCurveAndPlansWithIt() {
    auto window = test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    TilingMode* mode = window->tilingMode();
    mode->action()->trigger();
    PpoTrainingPanel* panel = mode->dock()->trainingPanel();
    panel->setSeconds(5);
    QSignalSpy trained(panel->trainer(), &PpoTrainer::trained);
    panel->start();
    QVERIFY(panel->trainer()->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!panel->trainer()->isRunning(), 120000);
    QCOMPARE(trained.count(), 1);
    QVERIFY(panel->plottedPoints() > 0); // the curve grew while it trained
    QVERIFY2(panel->statusText().contains(QStringLiteral("Trained")),
             qPrintable(panel->statusText()));
    QVERIFY(QFile::exists(panel->trainer()->modelPath()));

    // "ppo" now plans with the trained network instead of training on first use.
    mode->dock()->setSolver(QStringLiteral("ppo"));
    QCOMPARE(mode->dock()->solver(), QStringLiteral("ppo"));
    mode->dock()->tileAndOrder();
    QTRY_VERIFY_WITH_TIMEOUT(!mode->controller()->isBusy(), 120000);
    const auto plan = mode->controller()->result();
    QVERIFY2(plan, qPrintable(mode->controller()->errorMessage()));
    QVERIFY(tiling::isTour(plan->tour, plan->problem.size()));
}

// PPO training is a task of the window: it reports progress, and Cancel in the status bar
// ends it after the current update (the model so far is kept).
void TilingModeTest::taskListCancelsPpoTrainingPromptly() {
    auto window = test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    TilingMode* mode = window->tilingMode();
    mode->action()->trigger();
    PpoTrainingPanel* panel = mode->dock()->trainingPanel();
    panel->setSeconds(600);
    panel->start();
    Task* task = panel->trainer()->task();
    QVERIFY(task);
    QTRY_VERIFY_WITH_TIMEOUT(task->progress() > 0.0, 60000);
    QWidget* row = window->taskList()->rowOf(task);
    QVERIFY(row);
    auto* cancel = row->findChild<QToolButton*>(QStringLiteral("CancelTask"));
    QVERIFY(cancel);
    QSignalSpy ended(task, &Task::ended);
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(ended.wait(10000) || !ended.isEmpty());
    QVERIFY2(clock.elapsed() < 2000, qPrintable(QString::number(clock.elapsed())));
    QVERIFY(!panel->trainer()->isRunning());
    QVERIFY2(panel->statusText().contains(QStringLiteral("Trained")),
             qPrintable(panel->statusText()));
    QVERIFY(window->taskList()->isHidden());
}

QTEST_MAIN(TilingModeTest)
#include "test_tiling_mode.moc"
