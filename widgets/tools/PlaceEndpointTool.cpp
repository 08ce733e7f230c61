#include "tools/PlaceEndpointTool.h"

#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"
#include "document/Conversions.h"
#include "document/Document.h"
#include "model/RobotPlacement.h"

#include <QGraphicsItem>

namespace fc::ui {

PlaceEndpointTool::PlaceEndpointTool(Endpoint endpoint, QObject* parent)
    : AbstractTool(endpoint == Endpoint::Start ? tr("Place Start") : tr("Place End"),
                   QKeySequence(endpoint == Endpoint::Start ? Qt::Key_S : Qt::Key_N), parent),
      endpoint_(endpoint) {
    setObjectName(endpoint == Endpoint::Start ? QStringLiteral("placeStart")
                                              : QStringLiteral("placeEnd"));
}

QString PlaceEndpointTool::usageHint() const {
    return endpoint_ == Endpoint::Start
               ? tr("Place Start: click where the robot starts (moved off a wall to where the "
                    "robot fits); right-click removes it.")
               : tr("Place End: click where the robot should finish; right-click removes it "
                    "(the path then returns to the start).");
}

void PlaceEndpointTool::deactivate() {
    delete ghost_;
    ghost_ = nullptr;
    pressed_ = false;
    AbstractTool::deactivate();
}

void PlaceEndpointTool::showGhost(QPointF position) {
    delete ghost_;
    ghost_ = style::addMarker(nullptr, position, endpoint_ == Endpoint::Start ? tr("S") : tr("E"),
                              QColor(128, 128, 128, 180), name());
    ghost_->setZValue(z::Tool);
    scene()->addItem(ghost_);
}

void PlaceEndpointTool::mousePressed(const ToolMouseEvent& event) {
    if (!document())
        return;
    if (event.button == Qt::RightButton) {
        if (endpoint_ == Endpoint::Start)
            document()->setStart(std::nullopt);
        else
            document()->setEnd(std::nullopt);
        return;
    }
    if (event.button == Qt::LeftButton) {
        pressed_ = true;
        showGhost(event.snapped);
    }
}

void PlaceEndpointTool::mouseMoved(const ToolMouseEvent& event) {
    if (pressed_)
        showGhost(event.snapped);
}

void PlaceEndpointTool::mouseReleased(const ToolMouseEvent& event) {
    if (event.button != Qt::LeftButton || !pressed_ || !document())
        return;
    pressed_ = false;
    delete ghost_;
    ghost_ = nullptr;
    // Refused or moved on the spot: a start in an obstacle used to be accepted and planning
    // then failed with "cannot be joined to the corner graph without collision".
    const RobotProfile& robot = document()->project().robot;
    // L = 0 reads as L = W, as in the planner.
    const double diameter = robot.robotDiameter > 0.0 ? robot.robotDiameter : robot.coverageWidth;
    const RobotPlacement placed = placeRobot(document()->plan(), toVec2(event.snapped), diameter);
    switch (placed.problem) {
    case PlacementProblem::OutsideFloor:
        emit statusMessage(tr("%1: the point must lie inside the floor.").arg(name()));
        return;
    case PlacementProblem::InsideObstacle:
        emit statusMessage(
            tr("%1: that point is inside an obstacle; click on the floor.").arg(name()));
        return;
    case PlacementProblem::NoRoom:
        emit statusMessage(tr("%1: the robot (%2 m across) does not fit there or nearby.")
                               .arg(name())
                               .arg(diameter, 0, 'f', 2));
        return;
    case PlacementProblem::None:
        break;
    }
    const bool accepted = endpoint_ == Endpoint::Start ? document()->setStart(placed.position)
                                                       : document()->setEnd(placed.position);
    if (accepted && placed.moved > 0.0)
        emit statusMessage(tr("%1: moved %2 m off the wall, where the robot fits.")
                               .arg(name())
                               .arg(placed.moved, 0, 'f', 2));
}

} // namespace fc::ui
