#include "modes/tiling/TilingController.h"

#include "document/Conversions.h"
#include "document/Document.h"

#include <QEventLoop>
#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent>

namespace fc::ui {

namespace {

struct TilingOutcome {
    std::shared_ptr<const tiling::TilingPlan> plan;
    QString error;
};

} // namespace

TilingController::TilingController(QObject* parent) : QObject(parent) {}

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

void TilingController::clear() {
    ++generation_;
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
    const quint64 generation = ++generation_;
    if (running_++ == 0)
        emit busyChanged(true);
    auto* watcher = new QFutureWatcher<TilingOutcome>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation]() {
        const TilingOutcome outcome = watcher->result();
        watcher->deleteLater();
        if (generation == generation_) {
            result_ = outcome.plan;
            setError(outcome.error);
            emit resultChanged();
        }
        if (--running_ == 0)
            emit busyChanged(false);
    });
    watcher->setFuture(QtConcurrent::run([request]() {
        TilingOutcome outcome;
        try {
            outcome.plan = std::make_shared<const tiling::TilingPlan>(tiling::planTiling(request));
        } catch (const std::exception& e) {
            outcome.error = fromStd(e.what());
        }
        return outcome;
    }));
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
