// Clicking a room toggles whether it is planned (the room selection of the project).
#pragma once

#include "tools/AbstractTool.h"

namespace fc::ui {

class PickRoomTool : public AbstractTool {
    Q_OBJECT
public:
    explicit PickRoomTool(QObject* parent = nullptr);

    QString usageHint() const override;
    QCursor cursor() const override { return QCursor(Qt::PointingHandCursor); }
    void mouseReleased(const ToolMouseEvent& event) override;
};

} // namespace fc::ui
