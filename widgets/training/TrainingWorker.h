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

class TrainingWorker : public QObject {
    Q_OBJECT
public:
    explicit TrainingWorker(QObject* parent = nullptr);
    ~TrainingWorker() override;

    // Thread-safe: the running train() returns after the current episode.
    void requestStop() { stopRequested_ = true; }

public slots:
    // A new model for the plan's corner graph (replaces any previous one).
    void start(std::shared_ptr<const fc::PreparedPlan> prepared, fc::TrainingOptions options,
               double seconds);
    // Continues the current model, or the one in `modelPath` when given.
    void resume(double seconds, QString modelPath = {});
    void save(QString path);
    void setPlan(std::shared_ptr<const fc::PreparedPlan> prepared);

signals:
    void progress(QVector<fc::ui::TrainingPoint> points);
    void finished(fc::ui::TrainingEnd end, double trainedSeconds, long episodes);
    void failed(QString message);
    void saved(QString path, QString error); // error empty on success
    void modelLoaded(QString path, long episodes);

private:
    void run(double seconds);

    std::shared_ptr<const fc::PreparedPlan> prepared_;
    std::unique_ptr<fc::DqnTrainer> trainer_;
    std::atomic<bool> stopRequested_{false};
};

} // namespace fc::ui

Q_DECLARE_METATYPE(fc::ui::TrainingPoint)
Q_DECLARE_METATYPE(fc::ui::TrainingEnd)
