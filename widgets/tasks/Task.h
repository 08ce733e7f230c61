// The editor's one mechanism for long work (issue 14, in the style of QGIS's QgsTask and
// QgsFeedback): a work function R(TaskFeedback&) runs on the TaskManager's thread pool; the
// Task, living in the GUI thread, reports its progress and ends with a result, an error or
// a cancellation. The work checks feedback.isCancelled() often (or hands the planner
// feedback.solveControl()), so that Cancel ends it within a fraction of a second.
//
// A task of a "kind" (e.g. "planning") supersedes the running tasks of the same kind: they
// are cancelled and their results dropped, so a slow run never overwrites a newer one.
// Results and errors are delivered on the GUI thread; progress, status text and posted
// values (e.g. the training's episodes) are polled from the feedback about ten times a
// second, so a busy worker never floods the event loop.
#pragma once

#include "solvers/Solver.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QThreadPool>
#include <QVariant>
#include <any>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <type_traits>

class QTimer;

namespace fc::ui {

// What the work function sees: thread-safe; shared by the worker and its Task.
class TaskFeedback {
public:
    bool isCancelled() const { return cancelled_.load(); }
    void cancel() { cancelled_ = true; }
    // Throws TaskCancelled when cancelled (work functions that cannot return early).
    void throwIfCancelled() const;

    void setProgress(double fraction); // clamped to 0..1
    double progress() const { return progress_.load(); }
    void setStatus(const QString& text);
    QString status() const;
    // Values for the GUI thread, in order (Task::posted delivers them in batches).
    void post(const QVariant& value);

    // The planner's view: cancelled() and progress() forward here.
    SolveControl solveControl();
    std::function<bool()> cancelledFunction();

private:
    friend class Task;
    QVariantList takePosted();

    std::atomic<bool> cancelled_{false};
    std::atomic<double> progress_{0.0};
    mutable std::mutex mutex_;
    QString status_;
    QVariantList posted_;
};

// Thrown by TaskFeedback::throwIfCancelled.
class TaskCancelled : public std::runtime_error {
public:
    TaskCancelled() : std::runtime_error("cancelled") {}
};

struct TaskOptions {
    QString kind; // non-empty: a new task of this kind cancels the running ones
    // When cancel() is called by the user, a result the work returns anyway is delivered
    // (trainings return the model so far); superseded tasks and cancelAll() drop it.
    bool keepResultWhenCancelled = false;
};

class Task : public QObject {
    Q_OBJECT
public:
    enum class State { Running, Finished, Failed, Cancelled };

    QString description() const { return description_; }
    QString kind() const { return options_.kind; }
    State state() const { return state_; }
    bool isActive() const { return state_ == State::Running; }
    double progress() const { return progress_; }
    QString status() const { return status_; }

    // The value the work returned (valid in and after finished()).
    template <typename R> std::shared_ptr<const R> result() const {
        return std::any_cast<std::shared_ptr<const R>>(result_);
    }

public slots:
    // Asks the work to end; the task ends (finished, failed or cancelled) when it returns.
    void cancel();

signals:
    void progressChanged(double fraction);
    void statusChanged(const QString& text);
    void posted(const QVariantList& values);
    void finished();
    void failed(const QString& message);
    void cancelled();
    void ended(); // after any of the three above

private:
    friend class TaskManager;
    Task(QString description, TaskOptions options, QObject* parent);
    void poll(); // GUI thread: progress, status and posted values
    void drop(); // superseded or closing: nothing is delivered
    void complete(std::any result, QString error, bool threw);

    QString description_;
    TaskOptions options_;
    std::shared_ptr<TaskFeedback> feedback_ = std::make_shared<TaskFeedback>();
    State state_ = State::Running;
    double progress_ = 0.0;
    QString status_;
    bool dropped_ = false;
    std::any result_;
};

// One per main window (standalone docks and dialogs make their own).
class TaskManager : public QObject {
    Q_OBJECT
public:
    explicit TaskManager(QObject* parent = nullptr);
    // Cancels every task and waits for the work functions (they stop promptly).
    ~TaskManager() override;

    // The manager of `object`'s window: the nearest ancestor (or itself) that owns one.
    static TaskManager* of(const QObject* object);
    // of(object), or a new manager owned by `object` when it has none (standalone docks
    // and dialogs in tests).
    static TaskManager* forObject(QObject* object);

    // Runs work(feedback) -> R on the pool. An exception fails the task with its message
    // (or cancels it when cancel was requested).
    template <typename Work>
    Task* run(const QString& description, Work work, const TaskOptions& options = {}) {
        using R = std::decay_t<std::invoke_result_t<Work&, TaskFeedback&>>;
        return start(description, options, [work = std::move(work)](TaskFeedback& feedback) {
            return std::any(std::make_shared<const R>(work(feedback)));
        });
    }

    QList<Task*> tasks() const; // the running ones, oldest first
    bool isBusy() const { return !tasks_.isEmpty(); }
    // Cancels every running task and drops their results; returns at once.
    void cancelAll();
    // Cancels the running tasks of `kind` and drops their results.
    void cancelKind(const QString& kind);

signals:
    void taskAdded(fc::ui::Task* task);
    void taskRemoved(fc::ui::Task* task);
    void busyChanged(bool busy);

private:
    Task* start(const QString& description, const TaskOptions& options,
                std::function<std::any(TaskFeedback&)> work);
    void finish(Task* task);

    QThreadPool pool_;
    QList<Task*> tasks_;
    QTimer* poll_;
};

} // namespace fc::ui
