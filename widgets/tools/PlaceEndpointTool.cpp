#include "tools/PlaceEndpointTool.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"

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
               ? tr("Place Start: click where the robot starts (snapped to the nearest corner "
                    "when planning); right-click removes it.")
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
    const Vec2 position = toVec2(event.snapped);
    if (!document()->roomAt(position) && !pointInRing(document()->plan().boundary, position)) {
        emit statusMessage(tr("%1: the point must lie inside the floor.").arg(name()));
        return;
    }
    if (endpoint_ == Endpoint::Start)
        document()->setStart(position);
    else
        document()->setEnd(position);
}

} // namespace fc::ui
