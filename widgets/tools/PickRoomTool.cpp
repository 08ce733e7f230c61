#include "tools/PickRoomTool.h"

#include "document/Conversions.h"
#include "document/Document.h"

namespace fc::ui {

PickRoomTool::PickRoomTool(QObject* parent)
    : AbstractTool(tr("Pick Rooms"), QKeySequence(Qt::Key_P), parent) {
    setObjectName(QStringLiteral("pickRooms"));
}

QString PickRoomTool::usageHint() const {
    return tr("Pick Rooms: click a room to include it in or exclude it from planning.");
}

void PickRoomTool::mouseReleased(const ToolMouseEvent& event) {
    if (event.button != Qt::LeftButton || !document())
        return;
    if (const std::optional<QString> room = document()->roomAt(toVec2(event.position)))
        document()->toggleRoomSelection(*room);
    else
        emit statusMessage(tr("No room here."));
}

} // namespace fc::ui
