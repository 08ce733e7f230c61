#include "modes/tiling/TilingController.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "tasks/Task.h"

#include <QEventLoop>
#include <QTimer>

namespace fc::ui {

TilingController::TilingController(TaskManager* tasks, QObject* parent)
    : QObject(parent), tasks_(tasks) {}

void TilingController::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    clear();
    if (document_)
        connect(document_, &Document::geometryChanged, this, &TilingController::clear);
}

void TilingController::setRobot(const tiling::TilingRobotProfile& robot) {
    robot_ = robot;
    clear(); // the tiles' size changed with the blocks
}

void TilingController::cancel() {
    tasks_->cancelKind(QStringLiteral("tiling"));
}

void TilingController::clear() {
    cancel(); // a running tiling is for the old floor or robot
    setError(QString());
    if (!result_)
        return;
    result_.reset();
    emit resultChanged();
}

void TilingController::setError(const QString& message) {
    if (error_ == message)
        return;
    error_ = message;
    emit errorChanged(error_);
}

void TilingController::run(const QString& solver, quint64 seed) {
    if (!document_)
        return;
    tiling::TilingRequest request;
    request.plan = document_->plan();
    request.robot = robot_;
    request.solver = solver.toStdString();
    request.seed = seed;
    const bool wasBusy = isBusy();
    Task* task = tasks_->run(tr("Tiling with %1").arg(solver),
                             [request](TaskFeedback& feedback) {
                                 tiling::TilingPlan plan = tiling::tilePlan(request);
                                 feedback.setProgress(0.25); // the ordering is the long part
                                 tiling::orderTiles(plan, request.solver, request.seed,
                                                    feedback.cancelledFunction());
                                 return plan;
                             },
                             {QStringLiteral("tiling")});
    task_ = task;
    connect(task, &Task::finished, this, [this, task] {
        result_ = task->result<tiling::TilingPlan>();
        setError(QString());
        emit resultChanged();
    });
    connect(task, &Task::failed, this, [this](const QString& message) {
        result_.reset();
        setError(message);
        emit resultChanged();
    });
    connect(task, &Task::ended, this, [this, task] {
        if (task != task_)
            return; // superseded: a newer run is the busy one
        task_ = nullptr;
        emit busyChanged(false);
    });
    if (!wasBusy)
        emit busyChanged(true);
}

bool TilingController::runAndWait(const QString& solver, quint64 seed, int timeoutMs) {
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
    const auto done = connect(this, &TilingController::busyChanged, &loop, [&loop](bool busy) {
        if (!busy)
            loop.quit();
    });
    run(solver, seed);
    if (isBusy()) {
        timeout.start(timeoutMs);
        loop.exec();
    }
    disconnect(done);
    return !isBusy() && result_ && error_.isEmpty();
}

} // namespace fc::ui
