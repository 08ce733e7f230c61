#include "tasks/Task.h"

#include "document/PlannerMessages.h"

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include <QThread>
#include <QTimer>
#include <algorithm>

namespace fc::ui {

void TaskFeedback::throwIfCancelled() const {
    if (isCancelled())
        throw TaskCancelled();
}

void TaskFeedback::setProgress(double fraction) {
    progress_ = std::clamp(fraction, 0.0, 1.0);
}

void TaskFeedback::setStatus(const QString& text) {
    const std::lock_guard<std::mutex> guard(mutex_);
    status_ = text;
}

QString TaskFeedback::status() const {
    const std::lock_guard<std::mutex> guard(mutex_);
    return status_;
}

void TaskFeedback::post(const QVariant& value) {
    const std::lock_guard<std::mutex> guard(mutex_);
    posted_.push_back(value);
}

QVariantList TaskFeedback::takePosted() {
    const std::lock_guard<std::mutex> guard(mutex_);
    QVariantList values;
    values.swap(posted_);
    return values;
}

SolveControl TaskFeedback::solveControl() {
    SolveControl control;
    control.cancelled = cancelledFunction();
    control.progress = [this](double fraction) { setProgress(fraction); };
    return control;
}

std::function<bool()> TaskFeedback::cancelledFunction() {
    return [this] { return isCancelled(); };
}

Task::Task(QString description, TaskOptions options, QObject* parent)
    : QObject(parent), description_(std::move(description)), options_(std::move(options)) {}

void Task::cancel() {
    if (state_ == State::Running)
        feedback_->cancel();
}

void Task::drop() {
    dropped_ = true;
    cancel();
}

void Task::poll() {
    const double progress = feedback_->progress();
    if (progress != progress_) {
        progress_ = progress;
        emit progressChanged(progress_);
    }
    const QString status = feedback_->status();
    if (status != status_) {
        status_ = status;
        emit statusChanged(status_);
    }
    const QVariantList values = feedback_->takePosted();
    if (!values.isEmpty() && !dropped_)
        emit posted(values);
}

void Task::complete(std::any result, QString error, bool threw) {
    poll(); // the last progress and posted values come before the end
    const bool cancelRequested = feedback_->isCancelled();
    if (dropped_ || (cancelRequested && (threw || !options_.keepResultWhenCancelled))) {
        state_ = State::Cancelled;
        emit cancelled();
    } else if (threw) {
        state_ = State::Failed;
        // The planner's own words (fc::InputError, fc::SolverError) in the editor's, here on
        // the GUI thread; a message the editor wrote itself passes through unchanged.
        emit failed(plainMessage(error));
    } else {
        state_ = State::Finished;
        result_ = std::move(result);
        emit finished();
    }
    emit ended();
}

TaskManager::TaskManager(QObject* parent) : QObject(parent), poll_(new QTimer(this)) {
    setObjectName(QStringLiteral("TaskManager"));
    // Tasks are few (one per kind, the trainings) and some run for minutes: each gets a
    // thread, so a training never holds the overlays or a plan in the queue.
    pool_.setMaxThreadCount(std::max(8, 2 * QThread::idealThreadCount()));
    poll_->setInterval(100);
    connect(poll_, &QTimer::timeout, this, [this] {
        for (Task* task : tasks_)
            task->poll();
    });
}

TaskManager::~TaskManager() {
    cancelAll();
    pool_.waitForDone(); // the work functions see the cancellation and return
}

TaskManager* TaskManager::of(const QObject* object) {
    for (; object; object = object->parent()) {
        if (auto* manager = qobject_cast<TaskManager*>(const_cast<QObject*>(object)))
            return manager;
        if (auto* manager = object->findChild<TaskManager*>(QString(), Qt::FindDirectChildrenOnly))
            return manager;
    }
    return nullptr;
}

TaskManager* TaskManager::forObject(QObject* object) {
    TaskManager* manager = of(object);
    return manager ? manager : new TaskManager(object);
}

namespace {

// Workers yield to the GUI thread: on a two-core machine a plan's threads would otherwise
// take the cores from it while a new path is drawn. Threads the work starts (the per-room
// search's) inherit the niceness. Linux only: elsewhere thread niceness does not exist.
void lowerThisThreadsPriority() {
#ifdef __linux__
    static thread_local bool lowered = false;
    if (!lowered) {
        lowered = true;
        setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 8);
    }
#endif
}

} // namespace

Task* TaskManager::start(const QString& description, const TaskOptions& options,
                         std::function<std::any(TaskFeedback&)> work) {
    if (!options.kind.isEmpty())
        cancelKind(options.kind);
    auto* task = new Task(description, options, this);
    tasks_.push_back(task);
    connect(task, &Task::ended, this, [this, task] { finish(task); });
    std::shared_ptr<TaskFeedback> feedback = task->feedback_;
    pool_.start([task, feedback, work = std::move(work)] {
        lowerThisThreadsPriority();
        std::any result;
        QString error;
        bool threw = false;
        try {
            result = work(*feedback);
        } catch (const std::exception& e) {
            threw = true;
            error = QString::fromStdString(e.what());
        } catch (...) {
            threw = true;
            error = QStringLiteral("unknown error");
        }
        // The manager outlives the work (its destructor waits), so the task is still there.
        QMetaObject::invokeMethod(
            task,
            [task, result = std::move(result), error, threw]() mutable {
                task->complete(std::move(result), error, threw);
            },
            Qt::QueuedConnection);
    });
    if (tasks_.size() == 1) {
        poll_->start();
        emit busyChanged(true);
    }
    emit taskAdded(task);
    return task;
}

void TaskManager::finish(Task* task) {
    tasks_.removeOne(task);
    emit taskRemoved(task);
    task->deleteLater();
    if (tasks_.isEmpty()) {
        poll_->stop();
        emit busyChanged(false);
    }
}

QList<Task*> TaskManager::tasks() const {
    return tasks_;
}

void TaskManager::cancelAll() {
    for (Task* task : tasks_)
        task->drop();
}

void TaskManager::cancelKind(const QString& kind) {
    for (Task* task : tasks_)
        if (task->kind() == kind)
            task->drop();
}

} // namespace fc::ui
