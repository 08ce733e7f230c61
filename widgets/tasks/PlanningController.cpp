#include "tasks/PlanningController.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "pipeline/PerRoomSweep.h"

#include <QEventLoop>
#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent>
#include <algorithm>
#include <map>

namespace fc::ui {

namespace {

// Either a value or the planner's message: exceptions must not cross threads silently.
template <typename T> struct Outcome {
    std::shared_ptr<const T> value;
    QString error;
};

template <typename T, typename Job> Outcome<T> capture(const Job& job) {
    Outcome<T> outcome;
    try {
        outcome.value = std::make_shared<const T>(job());
    } catch (const std::exception& e) {
        outcome.error = fromStd(e.what());
    }
    return outcome;
}

} // namespace

PlanningController::PlanningController(QObject* parent)
    : QObject(parent), prepareTimer_(new QTimer(this)),
      latestPrepare_(std::make_shared<std::atomic<quint64>>(0)),
      latestPlan_(std::make_shared<std::atomic<quint64>>(0)) {
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
    *latestPrepare_ = ++prepareGeneration_;
    if (!pendingPrepare_)
        emit busyChanged(true);
    pendingPrepare_ = true;
    prepareTimer_->start();
}

void PlanningController::invalidateResult() {
    *latestPlan_ = ++planGeneration_;
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

template <typename T, typename Job, typename Done>
void PlanningController::runInBackground(Job job, Done done) {
    auto* watcher = new QFutureWatcher<Outcome<T>>(this);
    ++running_;
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, done]() {
        --running_;
        done(watcher->result());
        watcher->deleteLater();
        if (!isBusy())
            emit busyChanged(false);
    });
    watcher->setFuture(QtConcurrent::run([job]() { return capture<T>(job); }));
}

void PlanningController::startPrepare() {
    pendingPrepare_ = false;
    if (!document_)
        return;
    const Project project = document_->project();
    const quint64 generation = prepareGeneration_;
    if (project.plan.boundary.empty()) {
        prepared_.reset();
        emit preparedChanged();
        setError(QString()); // a new drawing, not a mistake: the dock shows a hint
        if (!isBusy())
            emit busyChanged(false);
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
    runInBackground<PreparedPlan>(
        [project, angle, latest = latestPrepare_, generation]() {
            if (*latest != generation) // edited again while this waited for a thread
                throw InputError("superseded");
            project.robot.validate();
            return preparePlan(project.plan, project.robot, angle);
        },
        [this, generation](const Outcome<PreparedPlan>& outcome) {
            if (generation != prepareGeneration_)
                return; // superseded by a later edit
            prepared_ = outcome.value;
            setError(outcome.error);
            emit preparedChanged();
        });
}

void PlanningController::plan() {
    if (!document_)
        return;
    PlanRequest request = planRequestFor(document_->project());
    request.modelPath = modelPath_;
    const quint64 generation = ++planGeneration_;
    *latestPlan_ = generation;
    if (!isBusy())
        emit busyChanged(true);
    SolveControl control; // the solvers stop when the document changes under them
    control.cancelled = [latest = latestPlan_, generation]() { return *latest != generation; };
    runInBackground<PlanResult>([request, control]() { return planCoverage(request, control); },
                                [this, generation](const Outcome<PlanResult>& outcome) {
                                    if (generation != planGeneration_)
                                        return;
                                    result_ = outcome.value;
                                    setError(outcome.error);
                                    emit resultChanged();
                                });
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
