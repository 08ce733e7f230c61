// Issue 16, item 5: the traps a supervisor fell into on the first day, each reproduced.
// (Training progress reaching "Done" is in gui_training; 1-, 8- and 16-bit maps in
// map_tests.)
#include "EditorFixture.h"
#include "docks/PlanningDock.h"
#include "docks/TrainingDock.h"
#include "document/Autosaver.h"
#include "document/DocumentFiles.h"
#include "document/PlannerMessages.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnSolver.h"
#include "learning/dqn/DqnTrainer.h"
#include "model/RobotPlacement.h"
#include "modes/tiling/TilingDock.h"
#include "modes/tiling/TilingMode.h"
#include "tasks/PlanningController.h"

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QWheelEvent>

using namespace fc::ui;
using namespace fc::ui::test;

class TrapsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void redoShortcutRedoes();
    void recoveryPromptNamesTheFile();
    void secondBoundaryAsksBeforeReplacing();
    void wheelOverAnUnfocusedFieldLeavesItAlone();
    void exportRemembersFormatAndFolder();
    void tilingModeKeepsTheWindowOnTheScreen();
    void plannerMessagesSpeakOfTheEditor();
    void startInAnObstacleIsRefusedOnTheSpot();
    void trainedModelComesBackWithTheProject();
};

void TrapsTest::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverTests"));
    QCoreApplication::setApplicationName(QStringLiteral("gui_traps"));
}

QAction* redoAction(MainWindow& window) {
    for (QAction* menu : window.menuBar()->actions())
        if (menu->menu())
            for (QAction* action : menu->menu()->actions())
                if (action->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)))
                    return action;
    return nullptr;
}

// Ctrl+Shift+Z was bound twice to Redo ("Ambiguous shortcut overload") and did nothing.
void TrapsTest::redoShortcutRedoes() {
    auto window = makeWindow();
    window->openSample();
    QApplication::setActiveWindow(window.get());
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    QAction* redo = redoAction(*window);
    QVERIFY(redo != nullptr);
    const QList<QKeySequence> keys = redo->shortcuts();
    for (const QKeySequence& key : keys)
        QCOMPARE(keys.count(key), 1);

    Document* document = window->document();
    const size_t obstacles = document->plan().obstacles.size();
    QVERIFY(document->addPolygon(PolygonRole::Obstacle, {{2, 2}, {3, 2}, {3, 3}, {2, 3}}));
    for (const QKeySequence& key : keys) {
        document->undoStack()->undo();
        QCOMPARE(document->plan().obstacles.size(), obstacles);
        QTest::keySequence(window.get(), key);
        QCOMPARE(document->plan().obstacles.size(), obstacles + 1);
    }
}

// The prompt at start-up said "Recover the unsaved changes?" without saying of which file.
void TrapsTest::recoveryPromptNamesTheFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("east-wing.fcproj"));
    Document document;
    document.setFileName(path);
    QVERIFY(document.addPolygon(PolygonRole::Boundary, {{0, 0}, {10, 0}, {10, 8}, {0, 8}}));
    Autosaver saver;
    saver.setDocument(&document);
    saver.saveNow();
    QVERIFY(Autosaver::hasRecovery());
    const QString question = MainWindow::recoveryQuestion();
    QVERIFY2(question.contains(QStringLiteral("east-wing.fcproj")), qPrintable(question));
    QVERIFY2(question.contains(QDir::toNativeSeparators(dir.path())), qPrintable(question));
    saver.discard();
    Document untitled;
    QVERIFY(untitled.addPolygon(PolygonRole::Boundary, {{0, 0}, {10, 0}, {10, 8}, {0, 8}}));
    saver.setDocument(&untitled);
    saver.saveNow();
    QVERIFY(MainWindow::recoveryQuestion().contains(QStringLiteral("untitled")));
    saver.discard();
}

// A second boundary drawn beside the first silently replaced it (and the rooms inside).
void TrapsTest::secondBoundaryAsksBeforeReplacing() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    useDrawingScale(*window);
    int asked = 0;
    bool answer = false;
    window->toolManager()->setConfirmation([&](const QString&) {
        ++asked;
        return answer;
    });
    useTool(*window, "drawBoundary");
    const fc::Ring before = window->document()->plan().boundary;
    const int steps = window->document()->undoStack()->count();
    // Overlapping the old one (and holding the obstacle), not around it.
    const std::vector<QPointF> beside{{2, 1}, {10, 1}, {10, 7}, {2, 7}};
    clickPolygon(*window, beside);
    QCOMPARE(asked, 1);
    QCOMPARE(window->document()->plan().boundary, before); // "no": kept
    QCOMPARE(window->document()->undoStack()->count(), steps);
    answer = true;
    clickPolygon(*window, beside);
    QCOMPARE(asked, 2);
    QCOMPARE(window->document()->plan().boundary.size(), size_t(4));
    QVERIFY(window->document()->plan().boundary != before); // "yes": replaced, one step
    QCOMPARE(window->document()->undoStack()->count(), steps + 1);
    window->document()->undoStack()->undo();
    QCOMPARE(window->document()->plan().boundary, before);
}

// Scrolling the Planning panel over a spin box changed its value (turn time set to 0.0).
void TrapsTest::wheelOverAnUnfocusedFieldLeavesItAlone() {
    auto window = makeWindow();
    window->openSample();
    QApplication::setActiveWindow(window.get());
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    QDoubleSpinBox* width = window->planningDock()->widthBox();
    QVERIFY(width->isVisible());
    const double before = width->value();
    auto wheelDown = [&] {
        const QPointF local = width->rect().center();
        QWheelEvent wheel(local, width->mapToGlobal(local), QPoint(), QPoint(0, -120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(width, &wheel);
    };
    window->view()->setFocus();
    wheelDown();
    QCOMPARE(width->value(), before);
    width->setFocus();
    QTRY_VERIFY(width->hasFocus());
    wheelDown();
    QVERIFY(width->value() < before); // focused: the wheel steps it
}

// After an export nothing confirmed it, and the next export started again at GeoJSON in
// the working folder.
void TrapsTest::exportRemembersFormatAndFolder() {
    QTemporaryDir dir;
    auto window = makeWindow();
    window->openSample();
    QVERIFY(window->planningController()->planAndWait());
    const QString csv = dir.filePath(QStringLiteral("tour.csv"));
    QVERIFY(window->exportFile(csv, fc::ExportFormat::Csv, fc::ExportSubject::Path));
    const MainWindow::ExportDefaults next = window->exportDefaults(fc::ExportSubject::Path);
    QVERIFY2(next.filter.startsWith(QStringLiteral("CSV")), qPrintable(next.filter));
    QCOMPARE(QFileInfo(next.path).absolutePath(), QFileInfo(csv).absolutePath());
    QVERIFY(next.path.endsWith(QStringLiteral(".csv")));
    // The status bar says where it went.
    QVERIFY(window->statusBar()->currentMessage().contains(csv));
    // Another subject keeps its own format.
    QVERIFY(
        !window->exportDefaults(fc::ExportSubject::Zones).filter.startsWith(QStringLiteral("CSV")));
}

// Tiling Robot Mode un-maximised the window and grew it past the screen: its dock was
// stacked under four others, and their minimum heights added up.
void TrapsTest::tilingModeKeepsTheWindowOnTheScreen() {
    auto window = makeWindow();
    window->openSample();
    window->showMaximized();
    QTest::qWait(300);
    const QRect screen = window->screen()->availableGeometry();
    window->tilingMode()->action()->setChecked(true);
    QTest::qWait(300);
    QVERIFY2(window->minimumSizeHint().height() <= screen.height(),
             qPrintable(QStringLiteral("minimum height %1 on a screen %2 high")
                            .arg(window->minimumSizeHint().height())
                            .arg(screen.height())));
    QVERIFY2(screen.contains(window->frameGeometry()) || window->isMaximized(),
             qPrintable(QStringLiteral("window %1,%2 %3x%4 on a screen %5x%6")
                            .arg(window->frameGeometry().x())
                            .arg(window->frameGeometry().y())
                            .arg(window->frameGeometry().width())
                            .arg(window->frameGeometry().height())
                            .arg(screen.width())
                            .arg(screen.height())));
    if (QGuiApplication::platformName() == QLatin1String("xcb"))
        QVERIFY(window->isMaximized());
    // As a tab it is in front and the mode is on; closing it still leaves the mode.
    QVERIFY(window->tilingMode()->isActive());
    QTRY_VERIFY(window->tilingMode()->dock()->isVisible());
    window->tilingMode()->dock()->close();
    QVERIFY(!window->tilingMode()->isActive());
}

// "use `--solver heuristic`" told a supervisor which command-line flag to pass.
void TrapsTest::plannerMessagesSpeakOfTheEditor() {
    for (const char* cli :
         {"exact solver: 174 required cells exceed its limit of 40; use `--solver heuristic` for "
          "this query",
          "exact solver: 30 required cells: no proof of optimality within its budget (2,000,000 "
          "states or 60 s; the best walk known is within 1.2% of optimal); use `--solver "
          "heuristic` for this query"}) {
        const QString plain = plainMessage(QString::fromLatin1(cli));
        QVERIFY2(!plain.contains(QStringLiteral("--")) && !plain.contains(QStringLiteral("cli")),
                 qPrintable(plain));
        QVERIFY2(plain.contains(QStringLiteral("panel")), qPrintable(plain));
    }
    QCOMPARE(plainMessage(QStringLiteral("the start point lies in an obstacle")),
             QStringLiteral("the start point lies in an obstacle"));
    // A save that fails names the file once, then says why in the editor's words.
    {
        Document document;
        const QString path = QStringLiteral("/nonexistent-folder/plan.fcproj");
        QString error;
        QVERIFY(!saveDocument(document, path, &error));
        QCOMPARE(error.count(path), 1);
        QVERIFY2(error.startsWith(QStringLiteral("Cannot save ") + path), qPrintable(error));
        QVERIFY2(!error.contains(QStringLiteral("cannot write (")), qPrintable(error));
    }
    // Through the window: dqn with a model of another plan; the message stays when the
    // background preparation of the overlays ends after the plan failed (it cleared it).
    fc::registerDqnSolver();
    QTemporaryDir dir;
    const QString model = dir.filePath(QStringLiteral("simple.fcdqn"));
    {
        const fc::Project simple = fc::loadProjectFile(FC_PLANS_DIR "/simple.geojson");
        fc::DqnTrainer trainer(fc::preparePlan(simple.plan, simple.robot, 90.0).graph,
                               fc::TrainingOptions::graph(1));
        trainer.train(2, 0.0);
        trainer.save(model.toStdString());
    }
    auto window = makeWindow();
    window->openSample();
    window->planningController()->setModelPath(model);
    QVERIFY(window->document()->setSolver(QStringLiteral("dqn")));
    QVERIFY(!window->planningController()->planAndWait());
    QTRY_VERIFY2_WITH_TIMEOUT(
        window->planningController()->errorMessage().contains(QStringLiteral("Training panel")),
        qPrintable(window->planningController()->errorMessage()), 10000);
}

// A start clicked inside an obstacle was accepted; planning then failed with "the start
// point cannot be joined to the corner graph without collision".
void TrapsTest::startInAnObstacleIsRefusedOnTheSpot() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson"))); // pillar 5-7 x 3-5
    useDrawingScale(*window);
    QString said;
    connect(window->toolManager(), &ToolManager::statusMessage, this,
            [&said](const QString& message) { said = message; });
    useTool(*window, "placeStart");
    click(*window, {6, 4});
    QVERIFY(!window->document()->project().hasStart);
    QVERIFY2(said.contains(QStringLiteral("obstacle")), qPrintable(said));
    // At the wall: moved to where the disc fits, and planning works from there.
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text().contains(QStringLiteral("Snap to Grid")))
            action->setChecked(false);
    click(*window, {0.15, 4.2});
    QVERIFY(window->document()->project().hasStart);
    const fc::Vec2 start = window->document()->project().start;
    QVERIFY(fc::distanceToWalls(window->document()->plan(), start) >= 0.3);
    QVERIFY2(said.contains(QStringLiteral("moved")), qPrintable(said));
    QVERIFY(window->planningController()->planAndWait());
}

// A trained model sat in the cache and was gone after a restart: it is saved beside the
// project and loaded back with it; a model of another plan is refused with a message.
void TrapsTest::trainedModelComesBackWithTheProject() {
    fc::registerDqnSolver();
    QTemporaryDir dir;
    const QString project = dir.filePath(QStringLiteral("site.fcproj"));
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
        PlanningController* planner = window->planningController();
        QTRY_VERIFY_WITH_TIMEOUT(planner->prepared() != nullptr, 20000);
        TrainingDock* dock = window->trainingDock();
        fc::TrainingOptions small = fc::TrainingOptions::improved(1);
        small.agent.conv1Channels = small.agent.conv2Channels = small.agent.conv3Channels = 8;
        small.agent.hiddenUnits = 32;
        small.agent.learningStarts = 50;
        small.agent.batchSize = 16;
        dock->setTrainingOptions(small);
        dock->start();
        QTRY_VERIFY_WITH_TIMEOUT(dock->episodes() >= 3, 30000);
        dock->stop();
        QTRY_COMPARE_WITH_TIMEOUT(dock->state(), TrainingDock::State::Finished, 20000);
        QVERIFY(dock->hasModel());
        QVERIFY(window->saveFile(project));
        QVERIFY(QFile::exists(modelFileFor(project)));
        QCOMPARE(modelFileFor(project), dir.filePath(QStringLiteral("site.fcdqn")));
    }
    // A new session: the project brings its model, and solver dqn plans with it.
    {
        auto window = makeWindow();
        QVERIFY(window->openFile(project));
        TrainingDock* dock = window->trainingDock();
        QTRY_VERIFY_WITH_TIMEOUT(dock->hasModel(), 20000);
        QCOMPARE(dock->modelPath(), modelFileFor(project));
        PlanningController* planner = window->planningController();
        QCOMPARE(QString::fromStdString(planner->modelPath()), modelFileFor(project));
        QVERIFY(window->document()->setSolver(QStringLiteral("dqn")));
        QVERIFY2(planner->planAndWait(), qPrintable(planner->errorMessage()));
        QCOMPARE(QString::fromStdString(planner->result()->solution.solver), QStringLiteral("dqn"));
    }
    // The same model beside a project of another plan: refused, named, nothing lost.
    {
        const QString other = dir.filePath(QStringLiteral("other.fcproj"));
        {
            auto window = makeWindow();
            QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/room-notches.geojson")));
            QVERIFY(window->saveFile(other));
        }
        QVERIFY(QFile::copy(modelFileFor(project), modelFileFor(other)));
        auto window = makeWindow();
        QVERIFY(window->openFile(other));
        QTRY_VERIFY_WITH_TIMEOUT(window->lastError().contains(QStringLiteral("other.fcdqn")),
                                 20000);
        QVERIFY(!window->trainingDock()->hasModel());
        QVERIFY(!window->document()->plan().boundary.empty());
    }
}

QTEST_MAIN(TrapsTest)
#include "test_traps.moc"
