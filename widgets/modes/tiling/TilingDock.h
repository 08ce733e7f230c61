// The tiling-robot mode's dock (issue 7): the robot's blocks, the ordering method, "Tile and
// Order", the energy figures of the result with a legend of the shapes, and the export of
// the waypoint list (position, shape and heading per waypoint).
#pragma once

#include <QDockWidget>
#include <QString>

class QComboBox;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace fc::ui {

class PpoTrainingPanel;
class TilingController;

class TilingDock : public QDockWidget {
    Q_OBJECT
public:
    explicit TilingDock(TilingController* controller, QWidget* parent = nullptr);

    QString solver() const;
    void setSolver(const QString& name);
    QString metricsText() const;
    // Writes the current result's waypoints (.csv or .json) atomically; false with the
    // reason in lastError() when there is no result or the file cannot be written.
    bool exportWaypoints(const QString& path);
    QString lastError() const { return lastError_; }
    PpoTrainingPanel* trainingPanel() const { return training_; }

public slots:
    void tileAndOrder();

signals:
    void showTilesChanged(bool show);

private:
    void commitRobot();
    void refresh();
    void chooseExportFile();

    TilingController* controller_;
    QComboBox* solver_;
    QSpinBox* seed_;
    QDoubleSpinBox* blockLeg_;
    QDoubleSpinBox* masses_[4];
    QPushButton* run_;
    QPushButton* export_;
    QCheckBox* showTiles_;
    QLabel* metrics_;
    PpoTrainingPanel* training_;
    QString lastError_;
};

} // namespace fc::ui
