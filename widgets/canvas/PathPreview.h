// The animated preview of the robot along the planned path: a disc of the robot's
// diameter L with its cleaning head (width W) across the direction of travel, moved by a
// timer at the robot's speed times a speed-up factor.
#pragma once

#include "model/CoveragePath.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <vector>

class QGraphicsItemGroup;
class QTimer;

namespace fc::ui {

class PlanScene;
class PlanningController;

class PathPreview : public QObject {
    Q_OBJECT
public:
    PathPreview(PlanScene* scene, PlanningController* controller, QObject* parent = nullptr);
    ~PathPreview() override;

    bool isPlaying() const;
    bool hasPath() const { return !path_.empty(); }
    double progress() const; // 0..1 of the path length
    double speedFactor() const { return speedFactor_; }

public slots:
    void setPlaying(bool playing);
    void setProgress(double progress);
    void setSpeedFactor(double factor); // times the robot's real speed

signals:
    void playingChanged(bool playing);
    void progressChanged(double progress);
    void availabilityChanged(bool hasPath);

private:
    void resetPath();
    void advance();
    void placeRobot();

    PlanScene* scene_;
    QPointer<PlanningController> controller_;
    QTimer* timer_;
    QElapsedTimer clock_;
    CoveragePath path_;
    std::vector<double> cumulative_; // path length up to each point
    double distance_ = 0.0;          // metres along the path
    double speed_ = 0.5;             // m/s, the robot's
    double speedFactor_ = 10.0;
    double robotDiameter_ = 0.6, headWidth_ = 1.0;
    QGraphicsItemGroup* robot_ = nullptr;
};

} // namespace fc::ui
