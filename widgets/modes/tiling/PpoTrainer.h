// Trains the tiling robot's PPO pointer network on a worker thread for the Tiling Robot dock
// (issue 7: "trained in the background with the same live curve as the DQN"): the network
// learns on random rooms, not on the open plan, so one trained model serves every floor.
// When training ends (time up or stopped) the model is saved and "ppo" plans with it.
#pragma once

#include <QObject>
#include <QString>
#include <QThread>
#include <atomic>
#include <memory>

namespace fc::ui {

class PpoTrainingJob : public QObject {
    Q_OBJECT
public:
    PpoTrainingJob(quint64 seed, double seconds, QString modelPath,
                   std::shared_ptr<std::atomic<bool>> cancelled);

public slots:
    void run();

signals:
    void progress(int update, double meanCostPerWaypoint, double secondsElapsed);
    void finished(const QString& modelPath, int updates, const QString& error);

private:
    quint64 seed_;
    double seconds_;
    QString modelPath_;
    std::shared_ptr<std::atomic<bool>> cancelled_;
};

class PpoTrainer : public QObject {
    Q_OBJECT
public:
    explicit PpoTrainer(QObject* parent = nullptr);
    ~PpoTrainer() override;

    bool isRunning() const { return thread_ != nullptr; }
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

private:
    void finish(const QString& modelPath, int updates, const QString& error);

    QThread* thread_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancelled_;
    QString modelPath_;
};

} // namespace fc::ui
