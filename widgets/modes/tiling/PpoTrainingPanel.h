// The Tiling Robot dock's training panel for "ppo": a time budget, Train / Stop, and a live
// QCustomPlot of the sampled tours' energy per waypoint against the PPO update, like the
// DQN's Training dock. The plot is fed by the training task's posted points.
#pragma once

#include <QWidget>

class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace fc::ui {

class PpoTrainer;

class PpoTrainingPanel : public QWidget {
    Q_OBJECT
public:
    explicit PpoTrainingPanel(QWidget* parent = nullptr);

    PpoTrainer* trainer() const { return trainer_; }
    QCustomPlot* plot() const { return plot_; }
    int plottedPoints() const;
    QString statusText() const;
    void setSeconds(double seconds);
    void setSeed(quint64 seed) { seed_ = seed; }

public slots:
    void start();

private:
    void addPoint(int update, double cost, double seconds);
    void setRunning(bool running);

    PpoTrainer* trainer_;
    QDoubleSpinBox* seconds_;
    QPushButton* train_;
    QPushButton* stop_;
    QLabel* status_;
    QCustomPlot* plot_;
    quint64 seed_ = 1;
};

} // namespace fc::ui
