// Long work as tasks (issue 14, item 4): the task manager's contract (progress, result,
// error, cancel, supersession), and for planning, Compare and tiling in the main window:
// progress is reported, Cancel (the status bar's task list) stops the work promptly and the
// editor stays usable, a superseded plan is dropped, and closing the window returns at once.
#include "EditorFixture.h"
#include "dialogs/CompareDialog.h"
#include "modes/tiling/TilingController.h"
#include "modes/tiling/TilingDock.h"
#include "modes/tiling/TilingMode.h"
#include "tasks/PlanningController.h"
#include "tasks/Task.h"
#include "tasks/TaskListWidget.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QThread>
#include <QToolButton>
#include <QtTest>

using namespace fc;
using namespace fc::ui;

namespace {

// Milliseconds from `cancel` (a click, a call) until `task` ended.
// -1: the task had already ended (it did not wait for the cancel).
template <typename Cancel> qint64 timeToEnd(QPointer<Task> task, Cancel cancel) {
    if (!task || !task->isActive())
        return -1;
    QSignalSpy ended(task.data(), &Task::ended);
    QElapsedTimer clock;
    clock.start();
    cancel();
    if (ended.isEmpty() && !ended.wait(10000))
        return 10000;
    return clock.elapsed();
}

// Clicks the Cancel button of `task`'s row in the window's task list.
void clickCancel(MainWindow& window, Task* task) {
    QWidget* row = window.taskList()->rowOf(task);
    QVERIFY(row);
    auto* button = row->findChild<QToolButton*>(QStringLiteral("CancelTask"));
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
}

// The work of a test task: counts to `steps` in 10 ms steps.
int countTo(TaskFeedback& feedback, int steps) {
    for (int i = 0; i < steps; ++i) {
        feedback.throwIfCancelled();
        feedback.setProgress(double(i + 1) / steps);
        QThread::msleep(10);
    }
    return steps;
}

std::unique_ptr<MainWindow> officeWindow() {
    auto window = test::makeWindow();
    if (!window->openFile(QStringLiteral(FC_PLANS_DIR "/office.geojson")))
        qWarning("office.geojson did not open");
    return window;
}

} // namespace

class TasksTest : public QObject {
    Q_OBJECT
private slots:
    void taskReportsProgressAndResult();
    void taskFailsWithTheMessage();
    void cancelStopsATaskAndDropsItsResult();
    void newerTaskOfAKindSupersedesTheOlder();
    void planningReportsProgressAndCancels();
    void supersededPlanningResultIsDropped();
    void compareCancelsWhenTheDialogCloses();
    void tilingReportsProgressAndCancels();
    void closingTheWindowWhileTasksRunReturnsPromptly();
};

void TasksTest::taskReportsProgressAndResult() {
    TaskManager manager;
    QSignalSpy busy(&manager, &TaskManager::busyChanged);
    Task* task = manager.run(QStringLiteral("count"), [](TaskFeedback& f) {
        f.post(QStringLiteral("first"));
        return countTo(f, 40);
    });
    QVERIFY(manager.isBusy());
    QSignalSpy progress(task, &Task::progressChanged);
    QSignalSpy posted(task, &Task::posted);
    QSignalSpy finished(task, &Task::finished);
    int result = 0;
    connect(task, &Task::finished, this, [&] { result = *task->result<int>(); });
    QVERIFY(finished.wait(10000));
    QCOMPARE(result, 40);
    QVERIFY(progress.size() >= 1);
    QCOMPARE(progress.last().at(0).toDouble(), 1.0);
    QCOMPARE(posted.size(), 1);
    QCOMPARE(posted.first().at(0).toList().value(0).toString(), QStringLiteral("first"));
    QTRY_VERIFY(!manager.isBusy());
    QCOMPARE(busy.size(), 2);
}

void TasksTest::taskFailsWithTheMessage() {
    TaskManager manager;
    Task* task = manager.run(QStringLiteral("fail"),
                             [](TaskFeedback&) -> int { throw std::runtime_error("no floor"); });
    QSignalSpy failed(task, &Task::failed);
    QVERIFY(failed.wait(10000));
    QCOMPARE(failed.first().at(0).toString(), QStringLiteral("no floor"));
}

void TasksTest::cancelStopsATaskAndDropsItsResult() {
    TaskManager manager;
    Task* task =
        manager.run(QStringLiteral("long"), [](TaskFeedback& f) { return countTo(f, 100000); });
    QSignalSpy cancelled(task, &Task::cancelled);
    QSignalSpy finished(task, &Task::finished);
    QTRY_VERIFY(task->progress() > 0.0);
    QVERIFY(timeToEnd(task, [task] { task->cancel(); }) < 2000);
    QCOMPARE(cancelled.size(), 1);
    QCOMPARE(finished.size(), 0);

    // A task that keeps its result when cancelled (trainings) delivers what it has.
    TaskOptions keep;
    keep.keepResultWhenCancelled = true;
    Task* training = manager.run(
        QStringLiteral("train"),
        [](TaskFeedback& f) {
            int i = 0;
            for (; !f.isCancelled(); ++i)
                QThread::msleep(5);
            return i;
        },
        keep);
    QSignalSpy kept(training, &Task::finished);
    QTest::qWait(50);
    int episodes = 0;
    connect(training, &Task::finished, this, [&] { episodes = *training->result<int>(); });
    training->cancel();
    QVERIFY(kept.wait(2000));
    QVERIFY(episodes > 0);

    // cancelAll (closing) drops even such results.
    Task* again = manager.run(
        QStringLiteral("train"),
        [](TaskFeedback& f) {
            while (!f.isCancelled())
                QThread::msleep(5);
            return 1;
        },
        keep);
    QSignalSpy dropped(again, &Task::cancelled);
    manager.cancelAll();
    QVERIFY(dropped.wait(2000));
}

void TasksTest::newerTaskOfAKindSupersedesTheOlder() {
    TaskManager manager;
    TaskOptions kind;
    kind.kind = QStringLiteral("planning");
    Task* older = manager.run(
        QStringLiteral("older"), [](TaskFeedback& f) { return countTo(f, 100000); }, kind);
    QSignalSpy olderCancelled(older, &Task::cancelled);
    QSignalSpy olderFinished(older, &Task::finished);
    Task* newer = manager.run(
        QStringLiteral("newer"), [](TaskFeedback& f) { return countTo(f, 5); }, kind);
    QSignalSpy newerFinished(newer, &Task::finished);
    QVERIFY(newerFinished.wait(10000));
    QTRY_COMPARE(olderCancelled.size(), 1);
    QCOMPARE(olderFinished.size(), 0);
}

void TasksTest::planningReportsProgressAndCancels() {
    auto window = officeWindow();
    PlanningController* planner = window->planningController();
    planner->setLiveReplanning(false); // the plan is started by hand here
    QTRY_VERIFY_WITH_TIMEOUT(planner->prepared() != nullptr && !planner->isBusy(), 60000);
    window->document()->setSolver(QStringLiteral("exact")); // minutes on the office
    QVERIFY(window->taskList()->isHidden());
    planner->plan();
    QPointer<Task> task = planner->planningTask();
    QVERIFY(task);
    QVERIFY(window->taskList()->isVisible());
    QVERIFY(window->taskList()->rowOf(task));
    // Per room, the screening is the first half; then exact plans the finalists.
    QTRY_VERIFY_WITH_TIMEOUT(!task || task->progress() >= 0.5, 60000);
    QVERIFY2(task, "planning ended before it could be cancelled");
    const qint64 ms = timeToEnd(task, [&] { clickCancel(*window, task); });
    QVERIFY2(ms >= 0 && ms < 2000, qPrintable(QStringLiteral("cancel took %1 ms").arg(ms)));
    QVERIFY(!planner->result());
    QTRY_VERIFY(window->taskList()->isHidden());
    // The editor is still usable: another solver plans.
    window->document()->setSolver(QStringLiteral("greedy"));
    QVERIFY2(planner->planAndWait(), qPrintable(planner->errorMessage()));
}

void TasksTest::supersededPlanningResultIsDropped() {
    auto window = test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    PlanningController* planner = window->planningController();
    QSignalSpy results(planner, &PlanningController::resultChanged);
    planner->plan();
    Task* first = planner->planningTask();
    QSignalSpy firstCancelled(first, &Task::cancelled);
    QSignalSpy firstFinished(first, &Task::finished);
    QVERIFY(planner->planAndWait()); // a second plan supersedes the first
    QTRY_COMPARE(firstCancelled.size(), 1);
    QCOMPARE(firstFinished.size(), 0);
    QCOMPARE(results.size(), 1); // only the newer result arrived
}

void TasksTest::compareCancelsWhenTheDialogCloses() {
    auto window = officeWindow();
    QAction* compare = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text().contains(QStringLiteral("Compare")))
            compare = action;
    QVERIFY(compare);
    compare->trigger();
    QPointer<CompareDialog> dialog = window->findChild<CompareDialog*>();
    QVERIFY(dialog);
    QPointer<Task> task = dialog->task();
    QVERIFY(task);
    QCOMPARE(task->kind(), QString());
    QVERIFY(window->taskList()->rowOf(task));
    // exact (the first solver) past its screening, planning the finalists
    QTRY_VERIFY_WITH_TIMEOUT(!task || task->progress() >= 0.1, 60000);
    QVERIFY2(task, "the comparison ended before it could be cancelled");
    QCOMPARE(task->status(), QStringLiteral("exact"));
    QSignalSpy ended(task.data(), &Task::ended);
    QElapsedTimer clock;
    clock.start();
    dialog->close(); // deletes it: no waiting for the solvers
    QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
    QVERIFY(ended.wait(2000) || !ended.isEmpty());
    QTRY_VERIFY(!dialog); // deleted on close
    // The row goes when the worker has stopped; on two busy cores that took 6.3 s once.
    QTRY_VERIFY_WITH_TIMEOUT(window->taskList()->isHidden(), 30000);
    window->document()->setSolver(QStringLiteral("greedy"));
    QVERIFY(window->planningController()->planAndWait());
}

void TasksTest::tilingReportsProgressAndCancels() {
    auto window = officeWindow();
    TilingController* controller = window->tilingMode()->controller();
    controller->run(QStringLiteral("ga"), 1); // seconds on the office
    QPointer<Task> task = controller->task();
    QVERIFY(task);
    QVERIFY(window->taskList()->rowOf(task));
    QTRY_VERIFY_WITH_TIMEOUT(!task || task->progress() > 0.0, 60000); // tiled, now ordering
    QVERIFY2(task, "tiling ended before it could be cancelled");
    const qint64 ms = timeToEnd(task, [&] { clickCancel(*window, task); });
    QVERIFY2(ms >= 0 && ms < 2000, qPrintable(QStringLiteral("cancel took %1 ms").arg(ms)));
    QVERIFY(!controller->isBusy());
    QVERIFY(!controller->result());
    QVERIFY(controller->runAndWait(QStringLiteral("greedy"), 1)); // still usable
}

void TasksTest::closingTheWindowWhileTasksRunReturnsPromptly() {
    auto window = officeWindow();
    QTRY_VERIFY_WITH_TIMEOUT(window->planningController()->prepared() != nullptr, 60000);
    window->document()->setSolver(QStringLiteral("exact"));
    window->planningController()->plan();
    window->tilingMode()->controller()->run(QStringLiteral("aco"), 1);
    QPointer<Task> planning = window->planningController()->planningTask();
    QPointer<Task> tiling = window->tilingMode()->controller()->task();
    QVERIFY(planning && tiling);
    // Both inside their cancellable parts (exact's search, the ant colony).
    QTRY_VERIFY_WITH_TIMEOUT(
        planning && planning->progress() >= 0.5 && tiling && tiling->progress() > 0.0, 60000);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(window->close());
    QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
    clock.restart();
    window.reset(); // the pool waits for the cancelled work
    QVERIFY2(clock.elapsed() < 3000, qPrintable(QString::number(clock.elapsed())));
}

QTEST_MAIN(TasksTest)
#include "test_tasks.moc"
