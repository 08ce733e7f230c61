#include "tasks/PlanningController.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"
#include "pipeline/PerRoomSweep.h"
#include "tasks/Task.h"

#include <QEventLoop>
#include <QTimer>
#include <algorithm>
#include <map>

namespace fc::ui {

PlanningController::PlanningController(TaskManager* tasks, QObject* parent)
    : QObject(parent), tasks_(tasks), prepareTimer_(new QTimer(this)) {
    prepareTimer_->setSingleShot(true);
    prepareTimer_->setInterval(120);
    connect(prepareTimer_, &QTimer::timeout, this, &PlanningController::startPrepare);
}

void PlanningController::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    prepared_.reset();
    invalidateResult();
    emit preparedChanged();
    if (!document_)
        return;
    // Geometry, robot and sweep change the cells and graph; the rest only the path.
    for (auto signal :
         {&Document::geometryChanged, &Document::robotChanged, &Document::sweepChanged})
        connect(document_, signal, this, &PlanningController::schedulePrepare);
    for (auto signal :
         {&Document::roomsChanged, &Document::endpointsChanged, &Document::solverChanged})
        connect(document_, signal, this, &PlanningController::invalidateResult);
    schedulePrepare();
}

void PlanningController::schedulePrepare() {
    invalidateResult();
    tasks_->cancelKind(QStringLiteral("prepare")); // its overlays are for the old geometry
    pendingPrepare_ = true;
    updateBusy();
    prepareTimer_->start();
}

void PlanningController::cancelPlanning() {
    tasks_->cancelKind(QStringLiteral("planning"));
}

void PlanningController::invalidateResult() {
    cancelPlanning(); // the solvers stop when the document changes under them
    if (!result_)
        return;
    result_.reset();
    emit resultChanged();
}

void PlanningController::setError(const QString& message) {
    if (error_ == message)
        return;
    error_ = message;
    emit errorChanged(error_);
}

void PlanningController::updateBusy() {
    if (isBusy() == busy_)
        return;
    busy_ = isBusy();
    emit busyChanged(busy_);
}

void PlanningController::taskEnded(Task* task) {
    if (task == prepareTask_)
        prepareTask_ = nullptr;
    if (task == planTask_)
        planTask_ = nullptr;
    updateBusy();
}

void PlanningController::startPrepare() {
    pendingPrepare_ = false;
    if (!document_) {
        updateBusy();
        return;
    }
    const Project project = document_->project();
    if (project.plan.boundary.empty()) {
        prepared_.reset();
        emit preparedChanged();
        setError(QString()); // a new drawing, not a mistake: the dock shows a hint
        updateBusy();
        return;
    }
    // "auto" picks its angle while planning; until then the overlays use its first
    // candidate (stripes across the dominant walls).
    double angle =
        project.sweep.automatic ? candidateAngles(project.plan).front() : project.sweep.angleDeg;
    if (project.sweep.perRoom && !project.sweep.automatic) {
        // Per room: the preview shows the angle most rooms sweep at; the plan shows each
        // room's own cells.
        std::map<double, int> votes;
        for (const auto& [room, a] : roomSweepAngles(project.plan, project.sweep))
            ++votes[a];
        angle = std::max_element(votes.begin(), votes.end(), [](const auto& x, const auto& y) {
                    return x.second < y.second;
                })->first;
    }
    Task* task =
        tasks_->run(tr("Preparing the overlays"),
                    [project, angle](TaskFeedback& feedback) {
                        feedback.throwIfCancelled(); // edited again while this waited for a thread
                        project.robot.validate();
                        return preparePlan(project.plan, project.robot, angle);
                    },
                    {QStringLiteral("prepare")});
    prepareTask_ = task;
    connect(task, &Task::finished, this, [this, task] {
        prepared_ = task->result<PreparedPlan>();
        // Only a preparation's own error is cleared: a plan that failed (solver dqn without
        // a model) keeps saying why while the overlays are brought up to date.
        if (errorFromPrepare_)
            setError(QString());
        errorFromPrepare_ = false;
        emit preparedChanged();
    });
    connect(task, &Task::failed, this, [this](const QString& message) {
        prepared_.reset();
        setError(plainMessage(message));
        errorFromPrepare_ = true;
        emit preparedChanged();
    });
    connect(task, &Task::ended, this, [this, task] { taskEnded(task); });
    updateBusy();
}

void PlanningController::plan() {
    if (!document_)
        return;
    PlanRequest request = planRequestFor(document_->project());
    request.modelPath = modelPath_;
    Task* task = tasks_->run(tr("Planning the path"),
                             [request](TaskFeedback& feedback) {
                                 return planCoverage(request, feedback.solveControl());
                             },
                             {QStringLiteral("planning")});
    planTask_ = task;
    connect(task, &Task::finished, this, [this, task] {
        result_ = task->result<PlanResult>();
        setError(QString());
        errorFromPrepare_ = false;
        emit resultChanged();
    });
    connect(task, &Task::failed, this, [this](const QString& message) {
        result_.reset();
        setError(plainMessage(message));
        errorFromPrepare_ = false;
        emit resultChanged();
    });
    connect(task, &Task::ended, this, [this, task] { taskEnded(task); });
    updateBusy();
}

bool PlanningController::planAndWait(int timeoutMs) {
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
    connect(this, &PlanningController::busyChanged, &loop, [&loop](bool busy) {
        if (!busy)
            loop.quit();
    });
    plan();
    timeout.start(timeoutMs);
    if (isBusy())
        loop.exec();
    return result_ != nullptr;
}

} // namespace fc::ui
