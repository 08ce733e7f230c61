#include "canvas/PathPreview.h"

#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"
#include "document/Conversions.h"
#include "tasks/PlanningController.h"

#include <QGraphicsEllipseItem>
#include <QGraphicsItemGroup>
#include <QGraphicsLineItem>
#include <QTimer>
#include <algorithm>
#include <cmath>

namespace fc::ui {

PathPreview::PathPreview(PlanScene* scene, PlanningController* controller, QObject* parent)
    : QObject(parent), scene_(scene), controller_(controller), timer_(new QTimer(this)) {
    timer_->setInterval(33); // ~30 frames per second
    connect(timer_, &QTimer::timeout, this, &PathPreview::advance);
    connect(controller, &PlanningController::resultChanged, this, &PathPreview::resetPath);
    resetPath();
}

PathPreview::~PathPreview() {
    delete robot_;
}

bool PathPreview::isPlaying() const {
    return timer_->isActive();
}

double PathPreview::progress() const {
    const double total = cumulative_.empty() ? 0.0 : cumulative_.back();
    return total > 0 ? distance_ / total : 0.0;
}

void PathPreview::resetPath() {
    setPlaying(false);
    const auto result = controller_ ? controller_->result() : nullptr;
    path_ = result ? result->path : CoveragePath{};
    if (result) {
        speed_ = result->prepared.robot.speed;
        robotDiameter_ = result->prepared.robot.robotDiameter;
        headWidth_ = result->prepared.robot.coverageWidth;
    }
    cumulative_.assign(1, 0.0);
    for (size_t i = 1; i < path_.points.size(); ++i)
        cumulative_.push_back(cumulative_.back() + distance(path_.points[i - 1], path_.points[i]));
    distance_ = 0.0;
    delete robot_;
    robot_ = nullptr;
    emit availabilityChanged(hasPath());
    emit progressChanged(0.0);
}

void PathPreview::setPlaying(bool playing) {
    if (playing == isPlaying() || (playing && !hasPath()))
        return;
    if (playing) {
        if (progress() >= 1.0)
            distance_ = 0.0; // play again from the start
        clock_.start();
        timer_->start();
        placeRobot();
    } else {
        timer_->stop();
    }
    emit playingChanged(playing);
}

void PathPreview::setProgress(double progress) {
    if (!hasPath())
        return;
    distance_ = std::clamp(progress, 0.0, 1.0) * cumulative_.back();
    placeRobot();
    emit progressChanged(this->progress());
}

void PathPreview::setSpeedFactor(double factor) {
    speedFactor_ = std::max(0.1, factor);
}

void PathPreview::advance() {
    const double seconds = clock_.restart() / 1000.0;
    distance_ = std::min(cumulative_.back(), distance_ + seconds * speed_ * speedFactor_);
    placeRobot();
    emit progressChanged(progress());
    if (distance_ >= cumulative_.back())
        setPlaying(false);
}

void PathPreview::placeRobot() {
    if (!hasPath())
        return;
    if (!robot_) {
        robot_ = new QGraphicsItemGroup;
        robot_->setZValue(z::Markers - 1);
        const double r = robotDiameter_ / 2;
        auto* body = new QGraphicsEllipseItem(-r, -r, 2 * r, 2 * r, robot_);
        body->setPen(style::cosmeticPen(QColor(20, 20, 20), 1.5));
        body->setBrush(QColor(255, 200, 0, 200));
        // The cleaning head across the direction of travel (local +x is the heading).
        auto* head = new QGraphicsLineItem(0, -headWidth_ / 2, 0, headWidth_ / 2, robot_);
        head->setPen(style::cosmeticPen(QColor(0, 140, 60), 3.0));
        auto* nose = new QGraphicsLineItem(0, 0, r, 0, robot_);
        nose->setPen(style::cosmeticPen(QColor(20, 20, 20), 2.0));
        scene_->addItem(robot_);
    }
    // The segment holding distance_, and the point and heading on it.
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), distance_);
    const size_t i = std::min<size_t>(std::max<std::ptrdiff_t>(it - cumulative_.begin(), 1),
                                      path_.points.size() - 1);
    const Vec2 a = path_.points[i - 1], b = path_.points[i];
    const double length = cumulative_[i] - cumulative_[i - 1];
    const double t = length > 0 ? (distance_ - cumulative_[i - 1]) / length : 0.0;
    robot_->setPos(toQt(a + (b - a) * t));
    robot_->setRotation(std::atan2(b.y - a.y, b.x - a.x) * 180.0 / M_PI);
}

} // namespace fc::ui
