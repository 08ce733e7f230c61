#include "tasks/PlanningController.h"

#include "decomposition/FloorCache.h"
#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"
#include "pipeline/PerRoomSweep.h"
#include "pipeline/PreparedPlans.h"
#include "tasks/Task.h"

#include <QEventLoop>
#include <QThreadPool>
#include <QTimer>
#include <algorithm>
#include <map>

namespace fc::ui {

namespace {

// Drops `slot`'s reference on a pool thread. Results, cells and graphs are built on worker
// threads, in their malloc arenas; freeing their many small blocks from the GUI thread while
// a planner thread allocates in the same arena made the GUI thread wait on the arena's lock,
// now and then for 60-140 ms (perf sched: voluntary waits, not CPU).
template <class T> void releaseOffThread(std::shared_ptr<T>& slot) {
    if (!slot)
        return;
    QThreadPool::globalInstance()->start([doomed = std::move(slot)]() mutable { doomed.reset(); });
    slot.reset();
}

template <class T> void replaceReleasingOld(std::shared_ptr<T>& slot, std::shared_ptr<T> value) {
    std::shared_ptr<T> old = std::move(slot);
    slot = std::move(value);
    releaseOffThread(old);
}

} // namespace

PlanningController::PlanningController(TaskManager* tasks, QObject* parent)
    : QObject(parent), tasks_(tasks), prepareTimer_(new QTimer(this)),
      replanTimer_(new QTimer(this)), floorCache_(std::make_shared<FloorCache>()) {
    prepareTimer_->setSingleShot(true);
    prepareTimer_->setInterval(kLiveDelayMs);
    connect(prepareTimer_, &QTimer::timeout, this, &PlanningController::startPrepare);
    replanTimer_->setSingleShot(true);
    replanTimer_->setInterval(kLiveDelayMs);
    connect(replanTimer_, &QTimer::timeout, this, &PlanningController::startDraft);
}

void PlanningController::setLiveReplanning(bool live) {
    if (live_ == live)
        return;
    live_ = live;
    if (!live_) {
        replanTimer_->stop();
        pendingReplan_ = false;
        tasks_->cancelKind(QStringLiteral("draft"));
    } else if (document_ && !result_) {
        scheduleReplan(false);
    }
    updateBusy();
}

void PlanningController::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    releaseOffThread(prepared_);
    releaseOffThread(preparedPlans_);
    invalidateResult();
    releaseOffThread(stale_); // another document's path
    emit preparedChanged();
    if (!document_)
        return;
    // Geometry, robot and sweep change the cells and graph; the rest only the path.
    for (auto signal :
         {&Document::geometryChanged, &Document::robotChanged, &Document::sweepChanged})
        connect(document_, signal, this, &PlanningController::schedulePrepare);
    for (auto signal :
         {&Document::roomsChanged, &Document::endpointsChanged, &Document::solverChanged})
        connect(document_, signal, this, &PlanningController::queryChanged);
    schedulePrepare();
}

QString PlanningController::cellsKey() const {
    if (result_) {
        QString key = QStringLiteral("plan of floor %1").arg(resultFloor_);
        if (result_->parts.empty())
            key += QStringLiteral(" at %1").arg(result_->stripeAngleDeg, 0, 'g', 17);
        for (const PlanPart& part : result_->parts) {
            key += QStringLiteral(" | %1:").arg(part.stripeAngleDeg, 0, 'g', 17);
            for (const std::string& room : part.rooms)
                key += QLatin1Char(' ') + fromStd(room);
        }
        return key;
    }
    return prepared_ ? QStringLiteral("preview of floor %1").arg(preparedFloor_) : QString();
}

void PlanningController::schedulePrepare() {
    ++floorEdits_;
    // Cells and graphs are of the old plan, robot or sweep (a sweep change keeps them valid,
    // but every typed angle would otherwise stay cached).
    releaseOffThread(preparedPlans_);
    invalidateResult();
    tasks_->cancelKind(QStringLiteral("prepare")); // its overlays are for the old geometry
    pendingPrepare_ = true;
    scheduleReplan(false);
    prepareTimer_->start(replanTimer_->interval());
    updateBusy();
}

void PlanningController::queryChanged() {
    invalidateResult();
    scheduleReplan(true);
    updateBusy();
}

void PlanningController::scheduleReplan(bool queryOnly) {
    ++edits_;
    if (!live_)
        return;
    // An edit is planned in the next turn of the event loop, which still joins edits made
    // together. Floor edits also come in bursts (a vertex dragged, a value typed): one that
    // follows another within kLiveDelayMs waits for a pause, and a floor edit pending keeps
    // its delay.
    const bool floorPending = pendingReplan_ && replanTimer_->interval() > 0;
    const bool burst =
        !queryOnly && lastFloorEdit_.isValid() && lastFloorEdit_.elapsed() < kLiveDelayMs;
    if (!queryOnly)
        lastFloorEdit_.restart();
    pendingReplan_ = true;
    replanTimer_->start(floorPending || burst ? kLiveDelayMs : 0);
}

std::shared_ptr<const PreparedPlans> PlanningController::preparedPlans() {
    if (!preparedPlans_ && document_)
        preparedPlans_ = std::make_shared<const PreparedPlans>(
            document_->plan(), document_->project().robot, true, floorCache_);
    return preparedPlans_;
}

void PlanningController::cancelPlanning() {
    tasks_->cancelKind(QStringLiteral("draft"));
    tasks_->cancelKind(QStringLiteral("planning"));
}

void PlanningController::invalidateResult() {
    cancelPlanning(); // the solvers stop when the document changes under them
    if (!result_)
        return;
    replaceReleasingOld(stale_, result_); // shown greyed until a newer path arrives
    releaseOffThread(result_);
    draft_ = false;
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
    if (task == draftTask_)
        draftTask_ = nullptr;
    updateBusy();
}

void PlanningController::startPrepare() {
    // A sketch of the same floor is on its way: the overlays wait for it, so that on a
    // two-core machine it has a core of its own, and then mostly find their cells and graph
    // already built by it (PreparedPlans).
    if (live_ && (pendingReplan_ || draftTask_)) {
        prepareAfterDraft_ = true;
        return;
    }
    prepareAfterDraft_ = false;
    pendingPrepare_ = false;
    if (!document_) {
        updateBusy();
        return;
    }
    const Project project = document_->project();
    if (project.plan.boundary.empty() || document_->needsRepair()) {
        releaseOffThread(prepared_);
        emit preparedChanged();
        // A new drawing is not a mistake (the dock shows a hint); a broken plan waits for
        // its repair.
        setError(document_->needsRepair() ? repairFirstMessage() : QString());
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
    Task* task = tasks_->run(tr("Preparing the overlays"),
                             [plans = preparedPlans(), angle](TaskFeedback& feedback) {
                                 // edited again while this waited for a thread
                                 feedback.throwIfCancelled();
                                 plans->robot().validate();
                                 return plans->at(angle, false);
                             },
                             {QStringLiteral("prepare")});
    prepareTask_ = task;
    connect(task, &Task::finished, this, [this, task, floor = floorEdits_] {
        replaceReleasingOld(prepared_, task->result<PreparedPlan>());
        preparedFloor_ = floor;
        // Only a preparation's own error is cleared: a plan that failed (solver dqn without
        // a model) keeps saying why while the overlays are brought up to date.
        if (errorFromPrepare_)
            setError(QString());
        errorFromPrepare_ = false;
        emit preparedChanged();
    });
    connect(task, &Task::failed, this, [this](const QString& message) {
        releaseOffThread(prepared_);
        setError(plainMessage(message));
        errorFromPrepare_ = true;
        emit preparedChanged();
    });
    connect(task, &Task::ended, this, [this, task] { taskEnded(task); });
    updateBusy();
}

void PlanningController::startDraft() {
    pendingReplan_ = false;
    // Nothing to draw yet, or the full plan of this very state is already on its way.
    if (!document_ || document_->plan().boundary.empty() || document_->needsRepair() ||
        (planTask_ && plannedEdit_ == edits_)) {
        if (prepareAfterDraft_ && pendingPrepare_)
            startPrepare(); // no sketch to wait for
        updateBusy();
        return;
    }
    PlanRequest request = planRequestFor(document_->project());
    // The sketch follows the path shown before the edit where that is cheaper than greedy
    // (Query::orderHint): the path changes where the edit changed it, not everywhere.
    if (const auto before = result_ ? result_ : stale_) {
        request.previousPath = before->path;
        if (resultFloor_ == floorEdits_) // the same floor: the same cells at those angles
            request.previousAngles = roomAnglesOf(*before, request.plan);
    }
    const quint64 edit = edits_;
    Task* task = tasks_->run(tr("Sketching the path"),
                             [request, plans = preparedPlans()](TaskFeedback& feedback) {
                                 feedback.throwIfCancelled();
                                 return draftCoverage(request, *plans, feedback.solveControl());
                             },
                             {QStringLiteral("draft")});
    draftTask_ = task;
    connect(task, &Task::finished, this, [this, task, edit, floor = floorEdits_] {
        replaceReleasingOld(result_, task->result<PlanResult>());
        resultFloor_ = floor;
        draft_ = true;
        releaseOffThread(stale_);
        // The message of an earlier query that failed no longer applies; a plan still
        // failing (e.g. dqn with a model of another plan) says so again when it ends.
        setError(QString());
        errorFromPrepare_ = false;
        emit resultChanged();
        if (!(planTask_ && plannedEdit_ == edit))
            plan(); // the full plan replaces the draft
    });
    connect(task, &Task::failed, this, [this](const QString& message) {
        // The query itself is wrong (a start the robot cannot leave, rooms it cannot reach):
        // the full plan would say the same.
        releaseOffThread(stale_);
        setError(plainMessage(message));
        errorFromPrepare_ = false;
        emit resultChanged();
    });
    connect(task, &Task::ended, this, [this, task] {
        taskEnded(task);
        if (prepareAfterDraft_ && pendingPrepare_ && !draftTask_ && !pendingReplan_)
            startPrepare();
    });
    updateBusy();
}

QString PlanningController::repairFirstMessage() {
    return tr("This plan has problems: repair it first (Plan > Repair Plan, or the button in "
              "the Problems panel).");
}

void PlanningController::plan() {
    if (!document_)
        return;
    if (document_->needsRepair()) {
        setError(repairFirstMessage());
        return;
    }
    PlanRequest request = planRequestFor(document_->project());
    request.modelPath = modelPath_;
    plannedEdit_ = edits_;
    Task* task = tasks_->run(tr("Planning the path"),
                             [request, plans = preparedPlans()](TaskFeedback& feedback) {
                                 return planCoverage(request, feedback.solveControl(), plans.get());
                             },
                             {QStringLiteral("planning")});
    planTask_ = task;
    connect(task, &Task::finished, this, [this, task, floor = floorEdits_] {
        replaceReleasingOld(result_, task->result<PlanResult>());
        resultFloor_ = floor;
        draft_ = false;
        releaseOffThread(stale_);
        setError(QString());
        errorFromPrepare_ = false;
        emit resultChanged();
    });
    connect(task, &Task::failed, this, [this](const QString& message) {
        releaseOffThread(result_);
        releaseOffThread(stale_);
        draft_ = false;
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
