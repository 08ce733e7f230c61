// Trains the tiling robot's PPO pointer network as a task (tasks/Task.h) for the Tiling Robot
// dock (issue 7: "trained in the background with the same live curve as the DQN"): the
// network learns on random rooms, not on the open plan, so one trained model serves every
// floor. Stop (or the task's Cancel) ends it after the current update (about a third of a
// second); the model is then saved and "ppo" plans with it.
#pragma once

#include "tasks/Task.h"

#include <QObject>
#include <QPointer>
#include <QString>

namespace fc::ui {

class PpoTrainer : public QObject {
    Q_OBJECT
public:
    explicit PpoTrainer(QObject* parent = nullptr);

    bool isRunning() const { return task_ != nullptr; }
    Task* task() const { return task_; }
    // The model "ppo" plans with after a training in this session (empty: none yet).
    QString modelPath() const { return modelPath_; }

public slots:
    void start(quint64 seed, double seconds);
    void stop();

signals:
    void progress(int update, double meanCostPerWaypoint, double secondsElapsed);
    void runningChanged(bool running);
    void trained(const QString& modelPath, int updates);
    void failed(const QString& message);
    void cancelled(); // stopped before the first update: no model

private:
    QPointer<Task> task_;
    QString modelPath_;
};

} // namespace fc::ui
