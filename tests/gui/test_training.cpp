// The training dock driven as a user would: start, see points on the reward plot, pause,
// resume, stop, save and reload the model, and the model offered to solver "dqn". The
// trainer runs as a task on the window's pool while this (GUI) thread keeps processing
// events; Cancel in the status bar's task list pauses it and cancels an evaluation.
#include "EditorFixture.h"
#include "SmallTraining.h"
#include "docks/TrainingDock.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnSolver.h"
#include "tasks/DqnTraining.h"
#include "tasks/PlanningController.h"
#include "tasks/Task.h"
#include "tasks/TaskListWidget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>
#include <qcustomplot.h>

using namespace fc;
using namespace fc::ui;

namespace {

std::shared_ptr<const PreparedPlan> preparedSample(const char* name, double angle = 90.0) {
    const Project project = loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson");
    return std::make_shared<const PreparedPlan>(preparePlan(project.plan, project.robot, angle));
}

TrainingOptions smallOptions() {
    return fc::ui::test::smallTrainingOptions();
}

} // namespace

class TrainingDockTest : public QObject {
    Q_OBJECT
private slots:
    void trainsPausesResumesAndSaves();
    void refusesAModelOfAnotherPlanAndKeepsItsOwn();
    void planChangeInvalidatesTheModel();
    void mainWindowTrainsAndPlansWithDqn();
    void trainsWithTheGraphStateSetting();
    void evaluatesTheModelAndStopCancels();
    void taskListCancelsTrainingAndEvaluationPromptly();
    void progressSaysDoneWhenTheBudgetIsSpent();
    void pausedRunKeepsTheBestEvaluatedWeights();
};

void TrainingDockTest::trainsPausesResumesAndSaves() {
    registerDqnSolver();
    TrainingDock dock;
    dock.setTrainingOptions(smallOptions());
    QSignalSpy ready(&dock, &TrainingDock::modelReady);
    dock.setPreparedPlan(preparedSample("simple"));
    QCOMPARE(dock.state(), TrainingDock::State::Idle);

    dock.start();
    QCOMPARE(dock.state(), TrainingDock::State::Running);
    // The GUI thread stays free: events are processed while points arrive.
    QElapsedTimer longestGap;
    qint64 worst = 0;
    QElapsedTimer total;
    total.start();
    longestGap.start();
    while (dock.plottedPoints() < 20 && total.elapsed() < 30000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        worst = std::max(worst, longestGap.restart());
    }
    QVERIFY2(dock.plottedPoints() >= 20, "no reward points on the plot");
    QVERIFY(dock.plot()->graph(1)->dataCount() >= 20); // moving average too
    // The policy alone was measured where training started: what training buys shows.
    QTRY_VERIFY_WITH_TIMEOUT(dock.plottedEvaluations() >= 1, 10000);
    QVERIFY2(worst < 1000, qPrintable(QString("event loop blocked for %1 ms").arg(worst)));

    dock.pause();
    QCOMPARE(dock.state(), TrainingDock::State::Paused);
    QTRY_VERIFY_WITH_TIMEOUT(!ready.isEmpty(), 10000); // saved to the cache on pause
    const QString cached = ready.last().at(0).toString();
    QVERIFY(QFile::exists(cached));
    const long pausedEpisodes = dock.episodes();
    QVERIFY(pausedEpisodes > 0);

    dock.resumeTraining();
    QCOMPARE(dock.state(), TrainingDock::State::Running);
    QTRY_VERIFY_WITH_TIMEOUT(dock.episodes() > pausedEpisodes + 5, 30000);
    dock.stop();
    QCOMPARE(dock.state(), TrainingDock::State::Finished);
    QTRY_VERIFY_WITH_TIMEOUT(ready.size() >= 2, 10000);

    QTemporaryDir dir;
    const QString path = dir.filePath("simple.fcdqn");
    QVERIFY2(dock.saveModel(path), qPrintable(dock.lastError()));
    const DqnModelInfo info = loadDqnModelInfo(path.toStdString());
    QCOMPARE(info.episodes, dock.episodes());
    QCOMPARE(dock.modelPath(), path);

    // The saved model plans through solver dqn.
    PlanRequest request;
    request.plan = loadProjectFile(std::string(FC_PLANS_DIR) + "/simple.geojson").plan;
    request.solver = "dqn";
    request.modelPath = path.toStdString();
    QVERIFY(planCoverage(request).metrics.coverage >= 0.99);
}

// The setting combo's "Graph state" entry trains a graph-state model end to end.
void TrainingDockTest::trainsWithTheGraphStateSetting() {
    registerDqnSolver();
    TrainingDock dock;
    dock.setPreparedPlan(preparedSample("simple"));
    auto* setting = dock.findChild<QComboBox*>();
    QVERIFY(setting != nullptr);
    const int graph = setting->findData(QStringLiteral("graph"));
    QVERIFY(graph >= 0);
    setting->setCurrentIndex(graph);
    dock.start();
    QTRY_VERIFY_WITH_TIMEOUT(dock.episodes() >= 5, 30000);
    dock.stop();
    QTRY_COMPARE_WITH_TIMEOUT(dock.state(), TrainingDock::State::Finished, 10000);
    QTemporaryDir dir;
    const QString path = dir.filePath("graph.fcdqn");
    QVERIFY2(dock.saveModel(path), qPrintable(dock.lastError()));
    const DqnModelInfo info = loadDqnModelInfo(path.toStdString());
    QCOMPARE(info.setting, std::string("graph"));
    QVERIFY(info.environment.graphState);
    // "From the generalist" is on by default: the model was fine-tuned from it.
    QVERIFY2(info.provenance.find("generalist") != std::string::npos, info.provenance.c_str());
    QVERIFY(!info.generalist);
    PlanRequest request;
    request.plan = loadProjectFile(std::string(FC_PLANS_DIR) + "/simple.geojson").plan;
    request.solver = "dqn";
    request.modelPath = path.toStdString();
    QVERIFY(planCoverage(request).metrics.coverage >= 0.99);

    // Off: from random weights. The box only applies to the graph state.
    auto* fromGeneralist = dock.findChild<QCheckBox*>();
    QVERIFY(fromGeneralist != nullptr);
    QVERIFY(fromGeneralist->isEnabled());
    fromGeneralist->setChecked(false);
    dock.start();
    QTRY_VERIFY_WITH_TIMEOUT(dock.episodes() >= 5, 30000);
    dock.stop();
    QTRY_COMPARE_WITH_TIMEOUT(dock.state(), TrainingDock::State::Finished, 10000);
    QVERIFY2(dock.saveModel(path), qPrintable(dock.lastError()));
    QVERIFY(loadDqnModelInfo(path.toStdString()).provenance.empty());
    setting->setCurrentIndex(setting->findData(QStringLiteral("improved")));
    QVERIFY(!fromGeneralist->isEnabled());
}

void TrainingDockTest::refusesAModelOfAnotherPlanAndKeepsItsOwn() {
    QTemporaryDir dir;
    const QString other = dir.filePath("room-obstacle.fcdqn");
    {
        DqnTrainer trainer(preparedSample("room-obstacle")->graph, smallOptions());
        trainer.train(3, 0.0);
        trainer.save(other.toStdString());
    }
    TrainingDock dock;
    dock.setTrainingOptions(smallOptions());
    dock.setPreparedPlan(preparedSample("simple"));
    QVERIFY(!dock.loadModel(other));
    QVERIFY2(dock.lastError().contains("another floor plan"), qPrintable(dock.lastError()));
    QCOMPARE(dock.state(), TrainingDock::State::Idle);
    const QString broken = dir.filePath("broken.fcdqn");
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("FLOORCOVER-DQN 1\n{");
    file.close();
    QVERIFY(!dock.loadModel(broken));
    QVERIFY(dock.lastError().contains("broken.fcdqn"));
}

void TrainingDockTest::planChangeInvalidatesTheModel() {
    TrainingDock dock;
    dock.setTrainingOptions(smallOptions());
    QSignalSpy ready(&dock, &TrainingDock::modelReady);
    dock.setPreparedPlan(preparedSample("simple"));
    dock.start();
    QTRY_VERIFY_WITH_TIMEOUT(dock.plottedPoints() > 0, 30000);
    dock.stop();
    QTRY_VERIFY_WITH_TIMEOUT(!ready.isEmpty() && !ready.last().at(0).toString().isEmpty(), 10000);
    dock.setPreparedPlan(preparedSample("simple")); // same graph: the model stays
    QVERIFY(!dock.modelPath().isEmpty());
    dock.setPreparedPlan(preparedSample("simple", 0.0)); // another graph
    QCOMPARE(dock.state(), TrainingDock::State::Idle);
    QVERIFY(dock.modelPath().isEmpty());
    QVERIFY(ready.last().at(0).toString().isEmpty());
}

void TrainingDockTest::mainWindowTrainsAndPlansWithDqn() {
    registerDqnSolver();
    auto window = fc::ui::test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/room-obstacle.geojson")));
    TrainingDock* dock = window->trainingDock();
    QVERIFY(dock);
    dock->setTrainingOptions(smallOptions());
    QPushButton* startButton = nullptr;
    QPushButton* stopButton = nullptr;
    for (QPushButton* b : dock->findChildren<QPushButton*>()) {
        if (b->text() == QLatin1String("Start"))
            startButton = b;
        if (b->text() == QLatin1String("Stop"))
            stopButton = b;
    }
    QVERIFY(startButton && stopButton);
    QTRY_VERIFY_WITH_TIMEOUT(startButton->isEnabled(), 10000); // follows the planner's graph
    QTest::mouseClick(startButton, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(dock->plottedPoints() >= 10, 30000);
    QTest::mouseClick(stopButton, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!dock->modelPath().isEmpty(), 10000);

    window->document()->setSolver(QStringLiteral("dqn"));
    QVERIFY2(window->planningController()->planAndWait(),
             qPrintable(window->planningController()->errorMessage()));
    const auto result = window->planningController()->result();
    QVERIFY(result);
    QCOMPARE(QString::fromStdString(result->solution.solver), QStringLiteral("dqn"));
    QVERIFY(result->metrics.coverage >= 0.99);
}

// Evaluate plans the trainer's test queries with the model on the worker thread and reports
// the gaps; Stop cancels an evaluation in progress and leaves the model usable.
void TrainingDockTest::evaluatesTheModelAndStopCancels() {
    registerDqnSolver();
    TrainingDock dock;
    TrainingOptions options = TrainingOptions::graph(3);
    options.agent.learningStarts = 50;
    dock.setTrainingOptions(options);
    dock.setPreparedPlan(preparedSample("room-obstacle"));
    QPushButton* evaluateButton = nullptr;
    for (QPushButton* b : dock.findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Evaluate"))
            evaluateButton = b;
    QVERIFY(evaluateButton != nullptr);
    QVERIFY(!evaluateButton->isEnabled()); // no model yet
    dock.start();
    QTRY_VERIFY_WITH_TIMEOUT(dock.episodes() >= 20, 30000);
    dock.stop();
    QTRY_COMPARE_WITH_TIMEOUT(dock.state(), TrainingDock::State::Finished, 10000);
    QVERIFY(evaluateButton->isEnabled());

    evaluateButton->click();
    QVERIFY(dock.evaluating());
    QVERIFY(!evaluateButton->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(!dock.evaluating(), 60000);
    QVERIFY2(dock.lastEvaluation().has_value(), qPrintable(dock.lastError()));
    const TrainingEvaluation& e = *dock.lastEvaluation();
    QCOMPARE(e.failures, 0);
    QVERIFY(e.queries > 0);
    QCOMPARE(e.reference, QStringLiteral("exact"));
    QVERIFY(e.plannedGap >= -1e-6);
    QVERIFY(e.plannedGap <= e.policyGap + 1e-6); // the refinement never makes it worse

    QTemporaryDir dir;
    QVERIFY2(dock.saveModel(dir.filePath("after.fcdqn")), qPrintable(dock.lastError()));

    // Stop right after Evaluate: the worker sees the cancel before its first query (the
    // flag is armed before the request is queued), the dock says so, the model stays usable
    // and the previous figures stay.
    dock.evaluate();
    QVERIFY(dock.evaluating());
    dock.stop();
    QTRY_VERIFY_WITH_TIMEOUT(!dock.evaluating(), 30000);
    QVERIFY2(dock.lastError().contains(QStringLiteral("cancelled")), qPrintable(dock.lastError()));
    QVERIFY(dock.lastEvaluation().has_value());
    QCOMPARE(dock.state(), TrainingDock::State::Finished);
    QVERIFY(evaluateButton->isEnabled());
    QVERIFY2(dock.saveModel(dir.filePath("again.fcdqn")), qPrintable(dock.lastError()));
}

// Milliseconds from clicking `task`'s Cancel in the window's task list until it ended.
static qint64 cancelFromTaskList(MainWindow& window, Task* task) {
    if (!task || !task->isActive())
        return -1;
    QWidget* row = window.taskList()->rowOf(task);
    auto* button = row ? row->findChild<QToolButton*>(QStringLiteral("CancelTask")) : nullptr;
    if (!button)
        return -1;
    QSignalSpy ended(task, &Task::ended);
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(button, Qt::LeftButton);
    if (ended.isEmpty() && !ended.wait(10000))
        return 10000;
    return clock.elapsed();
}

// Training and evaluation are tasks of the window: both report progress, and Cancel in the
// status bar stops them within a fraction of a second (the training keeps its model).
void TrainingDockTest::taskListCancelsTrainingAndEvaluationPromptly() {
    registerDqnSolver();
    auto window = fc::ui::test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/room-obstacle.geojson")));
    TrainingDock* dock = window->trainingDock();
    TrainingOptions options = smallOptions();
    options.evaluationQueries = 5000; // an evaluation of minutes
    dock->setTrainingOptions(options);
    QTRY_VERIFY_WITH_TIMEOUT(window->planningController()->prepared() != nullptr, 30000);
    dock->start();
    Task* training = dock->trainingTask();
    QVERIFY(training);
    QTRY_VERIFY_WITH_TIMEOUT(training->progress() > 0.0 && dock->plottedPoints() > 0, 30000);
    qint64 ms = cancelFromTaskList(*window, training);
    QVERIFY2(ms >= 0 && ms < 2000, qPrintable(QStringLiteral("cancel took %1 ms").arg(ms)));
    QCOMPARE(dock->state(), TrainingDock::State::Paused); // the model so far stays
    QTRY_VERIFY_WITH_TIMEOUT(!dock->modelPath().isEmpty(), 10000);

    dock->evaluate();
    Task* evaluation = dock->evaluationTask();
    QVERIFY(evaluation);
    QTRY_VERIFY_WITH_TIMEOUT(evaluation->progress() > 0.0, 30000);
    ms = cancelFromTaskList(*window, evaluation);
    QVERIFY2(ms >= 0 && ms < 2000, qPrintable(QStringLiteral("cancel took %1 ms").arg(ms)));
    QVERIFY(!dock->evaluating());
    QVERIFY2(dock->lastError().contains(QStringLiteral("cancelled")),
             qPrintable(dock->lastError()));

    // Still usable: training resumes.
    const long episodes = dock->episodes();
    dock->resumeTraining();
    QTRY_VERIFY_WITH_TIMEOUT(dock->episodes() > episodes, 30000);
    dock->stop();
    QTRY_COMPARE_WITH_TIMEOUT(dock->state(), TrainingDock::State::Finished, 10000);
}

// Issue 16 trap: the bar stayed at "96% · 0:01 left" after training had ended.
void TrainingDockTest::progressSaysDoneWhenTheBudgetIsSpent() {
    registerDqnSolver();
    TrainingDock dock;
    dock.setTrainingOptions(smallOptions());
    dock.setPreparedPlan(preparedSample("simple"));
    auto* budget = dock.findChild<QDoubleSpinBox*>();
    QVERIFY(budget != nullptr);
    budget->setValue(budget->minimum()); // 5 s
    dock.start();
    QTRY_COMPARE_WITH_TIMEOUT(dock.state(), TrainingDock::State::Finished, 60000);
    auto* bar = dock.findChild<QProgressBar*>();
    QVERIFY(bar != nullptr);
    QTRY_COMPARE_WITH_TIMEOUT(bar->value(), bar->maximum(), 10000);
    QVERIFY2(!bar->text().contains(QStringLiteral("left")), qPrintable(bar->text()));
    QVERIFY2(bar->text().startsWith(QStringLiteral("Done")), qPrintable(bar->text()));
    // The policy gap where training started and where the budget left it, on its own axis.
    QTRY_VERIFY_WITH_TIMEOUT(dock.plottedEvaluations() >= 2, 10000);
}

// However a run ends, Pause included, the session keeps the best evaluated weights: weights
// trained further without an evaluation give way to them when the next run is paused.
void TrainingDockTest::pausedRunKeepsTheBestEvaluatedWeights() {
    const std::shared_ptr<const PreparedPlan> plan = preparedSample("simple");
    DqnSession session;
    TaskFeedback first;
    startDqn(session, *plan, smallOptions(), 1.0, first); // evaluated at its start and end
    QVERIFY(session.trainer->bestEvaluation().has_value());
    CoverageEnvironment env(plan->graph, session.trainer->options().environment);
    std::mt19937_64 rng(3);
    const std::vector<float> observation = env.reset(rng);
    const std::vector<float> best = session.trainer->agent().qValues(observation, 1);
    session.trainer->train(40, 0.0); // on, without any evaluation
    QVERIFY(session.trainer->agent().qValues(observation, 1) != best);
    TaskFeedback paused;
    paused.cancel(); // Pause before its first episode
    const TrainingRun run = trainDqn(session, 60.0, paused);
    QCOMPARE(run.end, TrainingEnd::Interrupted);
    QVERIFY(session.trainer->agent().qValues(observation, 1) == best);
}

QTEST_MAIN(TrainingDockTest)
#include "test_training.moc"
