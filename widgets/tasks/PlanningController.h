// Runs the planner for the current document as tasks (tasks/Task.h): the decomposition and
// corner graph (overlays, kind "prepare") whenever geometry, robot or sweep angle change,
// and the full plan (kind "planning") when asked. A newer task of a kind supersedes the
// older one, whose result is dropped, so a slow run never overwrites a newer one.
#pragma once

#include "pipeline/Planner.h"
#include "tasks/Task.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <memory>

class QTimer;

namespace fc::ui {

class Document;

class PlanningController : public QObject {
    Q_OBJECT
public:
    // The tasks run on `tasks` (the window's manager).
    explicit PlanningController(TaskManager* tasks, QObject* parent = nullptr);

    void setDocument(Document* document);

    // The latest decomposition and graph of the document (null while none is valid).
    std::shared_ptr<const PreparedPlan> prepared() const { return prepared_; }
    // The latest plan of the document as it is now (null after any relevant edit).
    std::shared_ptr<const PlanResult> result() const { return result_; }
    // What the canvas shows: the plan's own decomposition when there is a path (with "auto"
    // its angle may differ from the preview's, and cells and path must agree), else the
    // preview's.
    std::shared_ptr<const PreparedPlan> shownPlan() const {
        return result_ ? std::shared_ptr<const PreparedPlan>(result_, &result_->prepared)
                       : prepared_;
    }
    QString errorMessage() const { return error_; }
    bool isBusy() const { return prepareTask_ || planTask_ || pendingPrepare_; }
    // The running planning task (null when none): its progress, Cancel.
    Task* planningTask() const { return planTask_; }
    void cancelPlanning();

    // Plans synchronously in the event loop's sense: starts plan() and waits for it.
    // Returns false (message in errorMessage()) on failure or after timeoutMs.
    bool planAndWait(int timeoutMs = 60000);
    // The trained model solver "dqn" plans with (empty: none).
    const std::string& modelPath() const { return modelPath_; }

public slots:
    void plan();
    void setModelPath(const QString& path) { modelPath_ = path.toStdString(); }
    void schedulePrepare(); // debounced: several edits in a row run the planner once

signals:
    void preparedChanged();
    void resultChanged();
    void errorChanged(const QString& message); // empty when the last run succeeded
    void busyChanged(bool busy);

private:
    void startPrepare();
    void invalidateResult();
    void setError(const QString& message);
    void taskEnded(Task* task);
    void updateBusy();

    TaskManager* tasks_;
    QPointer<Document> document_;
    QTimer* prepareTimer_;
    std::shared_ptr<const PreparedPlan> prepared_;
    std::shared_ptr<const PlanResult> result_;
    QString error_;
    bool errorFromPrepare_ = false; // error_ came from the preparation, not from planning
    std::string modelPath_;
    // The current tasks (null when none); an edit cancels them.
    QPointer<Task> prepareTask_;
    QPointer<Task> planTask_;
    bool pendingPrepare_ = false;
    bool busy_ = false; // as last announced by busyChanged
};

} // namespace fc::ui
