#include "tools/SplitRoomTool.h"

#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"
#include "document/Conversions.h"
#include "document/Document.h"

#include <QGraphicsLineItem>
#include <QKeyEvent>

namespace fc::ui {

SplitRoomTool::SplitRoomTool(QObject* parent)
    : AbstractTool(tr("Split Room"), QKeySequence(Qt::Key_K), parent) {
    setObjectName(QStringLiteral("splitRoom"));
}

QString SplitRoomTool::usageHint() const {
    return tr("Split Room: drag a line across a room to cut it in two (Esc cancels); the "
              "larger part keeps the name.");
}

void SplitRoomTool::deactivate() {
    clearLine();
    AbstractTool::deactivate();
}

void SplitRoomTool::clearLine() {
    delete line_;
    line_ = nullptr;
    pressed_ = false;
}

void SplitRoomTool::showLine(QPointF to) {
    if (!scene())
        return;
    if (!line_) {
        line_ = new QGraphicsLineItem;
        line_->setZValue(z::Tool);
        line_->setPen(
            style::cosmeticPen(style::palette().color(QPalette::Highlight), 2.0, Qt::DashLine));
        scene()->addItem(line_);
    }
    line_->setLine(QLineF(from_, to));
}

void SplitRoomTool::mousePressed(const ToolMouseEvent& event) {
    if (event.button != Qt::LeftButton || !document())
        return;
    pressed_ = true;
    from_ = event.snapped;
    showLine(from_);
}

void SplitRoomTool::mouseMoved(const ToolMouseEvent& event) {
    if (pressed_)
        showLine(event.snapped);
}

void SplitRoomTool::mouseReleased(const ToolMouseEvent& event) {
    if (event.button != Qt::LeftButton || !pressed_ || !document())
        return;
    const Vec2 from = toVec2(from_), to = toVec2(event.snapped);
    clearLine();
    if (distance(from, to) < 4.0 * event.metresPerPixel) {
        emit statusMessage(tr("Split Room: drag the cut across the room."));
        return;
    }
    // The room under the middle of the cut (the ends usually lie on or beyond its walls).
    const std::vector<Room>& rooms = document()->plan().rooms;
    int index = -1;
    for (const Vec2 at : {(from + to) * 0.5, from, to}) {
        for (int i = static_cast<int>(rooms.size()) - 1; i >= 0 && index < 0; --i)
            if (pointInRing(rooms[i].outline, at))
                index = i;
        if (index >= 0)
            break;
    }
    if (index < 0) {
        emit statusMessage(tr("Split Room: the cut must cross a room."));
        return;
    }
    QString problem;
    auto connection = connect(document(), &Document::editRejected, this,
                              [&problem](const QString& message) { problem = message; });
    const bool accepted = document()->splitRoom(index, from, to);
    disconnect(connection);
    emit statusMessage(accepted ? tr("Split %1 in two.").arg(fromStd(rooms.at(index).name))
                                : problem);
}

bool SplitRoomTool::keyPressed(QKeyEvent* event) {
    if (event->key() != Qt::Key_Escape || !pressed_)
        return false;
    clearLine();
    return true;
}

} // namespace fc::ui
