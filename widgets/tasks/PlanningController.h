// Runs the planner for the current document off the GUI thread: the decomposition and
// corner graph (overlays) whenever geometry, robot or sweep angle change, and the full plan
// when asked. Results of superseded runs are dropped, so a slow run never overwrites a
// newer one.
#pragma once

#include "pipeline/Planner.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <atomic>
#include <memory>

class QTimer;

namespace fc::ui {

class Document;

class PlanningController : public QObject {
    Q_OBJECT
public:
    explicit PlanningController(QObject* parent = nullptr);

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
    bool isBusy() const { return running_ > 0 || pendingPrepare_; }

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
    template <typename T, typename Job, typename Done> void runInBackground(Job job, Done done);

    QPointer<Document> document_;
    QTimer* prepareTimer_;
    std::shared_ptr<const PreparedPlan> prepared_;
    std::shared_ptr<const PlanResult> result_;
    QString error_;
    std::string modelPath_;
    // Bumped by every edit; a finished run whose stamp is older is ignored, and a queued or
    // running one stops early (the workers read the atomic copies).
    quint64 prepareGeneration_ = 0;
    quint64 planGeneration_ = 0;
    std::shared_ptr<std::atomic<quint64>> latestPrepare_;
    std::shared_ptr<std::atomic<quint64>> latestPlan_;
    int running_ = 0;
    bool pendingPrepare_ = false;
};

} // namespace fc::ui
