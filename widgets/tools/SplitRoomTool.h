// Cuts a room in two: press on one side of the room, drag across it and release on the other
// side; the room under the middle of the line is split along it (Document::splitRoom).
#pragma once

#include "tools/AbstractTool.h"

class QGraphicsLineItem;

namespace fc::ui {

class SplitRoomTool : public AbstractTool {
    Q_OBJECT
public:
    explicit SplitRoomTool(QObject* parent = nullptr);

    QString usageHint() const override;
    QCursor cursor() const override { return QCursor(Qt::CrossCursor); }
    void deactivate() override;
    void mousePressed(const ToolMouseEvent& event) override;
    void mouseMoved(const ToolMouseEvent& event) override;
    void mouseReleased(const ToolMouseEvent& event) override;
    bool keyPressed(QKeyEvent* event) override;

private:
    void showLine(QPointF to);
    void clearLine();

    bool pressed_ = false;
    QPointF from_;
    QGraphicsLineItem* line_ = nullptr;
};

} // namespace fc::ui
