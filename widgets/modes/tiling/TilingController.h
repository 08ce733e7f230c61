// The tiling-robot mode's planner (issue 7): tiles the document's floor and orders the tiles
// with the chosen method as a task (tasks/Task.h, kind "tiling"). A result is dropped when
// the geometry changes or a newer run starts (the older task is cancelled), so a slow
// ordering (aco, ga, ppo) never shows a stale floor; Cancel stops aco and ga within an
// iteration.
#pragma once

#include "tasks/Task.h"
#include "tiling/TilingPlanner.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <memory>

namespace fc::ui {

class Document;

class TilingController : public QObject {
    Q_OBJECT
public:
    TilingController(TaskManager* tasks, QObject* parent = nullptr);

    void setDocument(Document* document);
    void setRobot(const tiling::TilingRobotProfile& robot);
    const tiling::TilingRobotProfile& robot() const { return robot_; }

    std::shared_ptr<const tiling::TilingPlan> result() const { return result_; }
    QString errorMessage() const { return error_; }
    bool isBusy() const { return task_ != nullptr; }
    Task* task() const { return task_; } // the running one (null when none)
    // Starts run() and waits for it (tests, scripts). False on failure or timeout.
    bool runAndWait(const QString& solver, quint64 seed, int timeoutMs = 120000);

public slots:
    void run(const QString& solver, quint64 seed);
    void clear();

signals:
    void resultChanged();
    void errorChanged(const QString& message); // empty after a successful run
    void busyChanged(bool busy);

private:
    void setError(const QString& message);
    void cancel();

    TaskManager* tasks_;
    QPointer<Task> task_;
    QPointer<Document> document_;
    tiling::TilingRobotProfile robot_;
    std::shared_ptr<const tiling::TilingPlan> result_;
    QString error_;
};

} // namespace fc::ui
