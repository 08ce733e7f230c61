// Trains the Double-DQN planner on a worker thread (Tiled/QGIS style: a QObject moved to a
// QThread, driven by queued calls). The GUI thread never touches the trainer; it gets
// progress in batches (at most every 100 ms, so plotting never floods the event loop) and
// stops a run through an atomic flag that the trainer checks between episodes.
#pragma once

#include "learning/dqn/DqnTrainer.h"
#include "pipeline/Planner.h"

#include <QMetaType>
#include <QObject>
#include <QString>
#include <QVector>
#include <atomic>
#include <memory>

namespace fc::ui {

struct TrainingPoint {
    long episode = 0;
    long steps = 0;
    double seconds = 0.0; // training time so far
    double reward = 0.0;
    double average = 0.0;
    double loss = 0.0; // NaN while not learning yet
    double epsilon = 0.0;
    double stepsPerSecond = 0.0;
};

enum class TrainingEnd { BudgetReached, Interrupted, Failed };

// The model on the trainer's fixed test queries (DqnTrainer::evaluate), in percent.
struct TrainingEvaluation {
    int queries = 0;
    int failures = 0;
    double policyGap = 0.0;  // the learnt rollout alone, above the reference solver
    double plannedGap = 0.0; // what solver dqn returns (after the model's refinement)
    double milliseconds = 0.0;
    QString reference; // "exact", "heuristic" or "exact/heuristic"
};

class TrainingWorker : public QObject {
    Q_OBJECT
public:
    explicit TrainingWorker(QObject* parent = nullptr);
    ~TrainingWorker() override;

    // Thread-safe: the running train() returns after the current episode.
    void requestStop() { stopRequested_ = true; }
    // Thread-safe, from the GUI thread: arm before queuing evaluate(), then cancel it. A
    // separate flag, so that a cancel sent while a run is still ending is not lost.
    void armEvaluation() { evaluationCancelled_ = false; }
    void cancelEvaluation() { evaluationCancelled_ = true; }

public slots:
    // A new model for the plan's corner graph (replaces any previous one).
    void start(std::shared_ptr<const fc::PreparedPlan> prepared, fc::TrainingOptions options,
               double seconds);
    // Continues the current model, or the one in `modelPath` when given.
    void resume(double seconds, QString modelPath = {});
    void save(QString path);
    // Measures the current model; cancelEvaluation() cancels it.
    void evaluate();
    void setPlan(std::shared_ptr<const fc::PreparedPlan> prepared);

signals:
    void progress(QVector<fc::ui::TrainingPoint> points);
    void finished(fc::ui::TrainingEnd end, double trainedSeconds, long episodes);
    void failed(QString message);
    void saved(QString path, QString error); // error empty on success
    void modelLoaded(QString path, long episodes);
    void evaluated(fc::ui::TrainingEvaluation result);
    void evaluationFailed(QString message); // empty when cancelled

private:
    void run(double seconds);

    std::shared_ptr<const fc::PreparedPlan> prepared_;
    std::unique_ptr<fc::DqnTrainer> trainer_;
    std::atomic<bool> stopRequested_{false};
    std::atomic<bool> evaluationCancelled_{false};
};

} // namespace fc::ui

Q_DECLARE_METATYPE(fc::ui::TrainingPoint)
Q_DECLARE_METATYPE(fc::ui::TrainingEnd)
Q_DECLARE_METATYPE(fc::ui::TrainingEvaluation)
