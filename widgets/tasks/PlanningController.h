// Runs the planner for the current document as tasks (tasks/Task.h): the decomposition and
// corner graph (overlays, kind "prepare") whenever geometry, robot or sweep angle change,
// and the plan (kind "planning") when asked. A newer task of a kind supersedes the older
// one, whose result is dropped, so a slow run never overwrites a newer one.
//
// Live replanning (on by default): every edit of the plan or the query replans in the
// background, debounced. A quick draft (kind "draft": greedy, family angles, no search)
// comes first, then the full plan replaces it; until the draft arrives the previous path
// stays on screen greyed (staleResult). Cells and graphs are built once per plan and robot
// (PreparedPlans) and shared by the overlays, the draft and the plan: a changed query
// rebuilds nothing.
#pragma once

#include "pipeline/Planner.h"
#include "tasks/Task.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QString>
#include <memory>

class QTimer;

namespace fc {
class FloorCache;
class PreparedPlans;
} // namespace fc

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
    // The latest plan of the document as it is now (null after any relevant edit), the
    // draft while the full plan is being computed.
    std::shared_ptr<const PlanResult> result() const { return result_; }
    // Whether result() is the quick draft of live replanning (the full plan follows).
    bool isDraft() const { return result_ && draft_; }
    // The path of the document before its last edits, shown greyed while nothing newer is
    // there (null once result() is set, or when there was none).
    std::shared_ptr<const PlanResult> staleResult() const { return stale_; }
    // Live replanning (see above); when off, an edit clears the path until plan().
    bool liveReplanning() const { return live_; }
    void setLiveReplanning(bool live);
    // Milliseconds a floor, robot or sweep edit that follows another this soon waits for a
    // pause before live replanning starts (single edits replan in the next turn of the
    // event loop).
    static constexpr int kLiveDelayMs = 30;
    // What the canvas shows: the plan's own decomposition when there is a path (with "auto"
    // its angle may differ from the preview's, and cells and path must agree), else the
    // preview's.
    std::shared_ptr<const PreparedPlan> shownPlan() const {
        return result_ ? std::shared_ptr<const PreparedPlan>(result_, &result_->prepared)
                       : prepared_;
    }
    // Names the cells and graph the canvas shows (the plan's parts, or the preview of the
    // floor as it was when built): equal keys, equal cells, so a new path of the same floor
    // leaves them as they are drawn.
    QString cellsKey() const;
    QString errorMessage() const { return error_; }
    bool isBusy() const {
        return prepareTask_ || planTask_ || draftTask_ || pendingPrepare_ ||
               (live_ && pendingReplan_);
    }
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
    // An edit of the query (rooms, start, end, solver): the path is stale; with live
    // replanning a new one is scheduled.
    void queryChanged();

signals:
    void preparedChanged();
    void resultChanged();
    void errorChanged(const QString& message); // empty when the last run succeeded
    void busyChanged(bool busy);

private:
    static QString repairFirstMessage();
    void startPrepare();
    void startDraft();
    void scheduleReplan(bool queryOnly);
    // The plans of the document's plan and robot, shared by every task until they change.
    std::shared_ptr<const PreparedPlans> preparedPlans();
    void invalidateResult();
    void setError(const QString& message);
    void taskEnded(Task* task);
    void updateBusy();

    TaskManager* tasks_;
    QPointer<Document> document_;
    QTimer* prepareTimer_;
    QTimer* replanTimer_;
    std::shared_ptr<const PreparedPlan> prepared_;
    std::shared_ptr<const PlanResult> result_;
    std::shared_ptr<const PlanResult> stale_;
    std::shared_ptr<const PreparedPlans> preparedPlans_;
    // What the plans of earlier edits built from the floor's free space (clearance field,
    // metrics raster): an edit of the rooms or of the robot's speed reuses it.
    std::shared_ptr<FloorCache> floorCache_;
    bool draft_ = false;
    bool live_ = true;
    QString error_;
    bool errorFromPrepare_ = false; // error_ came from the preparation, not from planning
    std::string modelPath_;
    // The current tasks (null when none); an edit cancels them.
    QPointer<Task> prepareTask_;
    QPointer<Task> planTask_;
    QPointer<Task> draftTask_;
    bool pendingPrepare_ = false;
    bool prepareAfterDraft_ = false; // startPrepare deferred until the draft ends
    QElapsedTimer lastFloorEdit_;    // a floor edit soon after another waits for a pause
    bool pendingReplan_ = false;
    quint64 edits_ = 0;                           // edits seen (query or plan)
    quint64 floorEdits_ = 0;                      // edits of the plan, robot or sweep
    quint64 preparedFloor_ = 0, resultFloor_ = 0; // floorEdits_ when prepared_/result_ began
    quint64 plannedEdit_ = 0;                     // edits_ when the running plan() started
    bool busy_ = false;                           // as last announced by busyChanged
};

} // namespace fc::ui
