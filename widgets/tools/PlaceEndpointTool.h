// Places the start or the end point of the path: press and release where it should be
// (drag to adjust before releasing); right-click removes it, so the planner's default
// applies (start: a corner of the first cell; end: back at the start).
#pragma once

#include "tools/AbstractTool.h"

class QGraphicsItem;

namespace fc::ui {

enum class Endpoint { Start, End };

class PlaceEndpointTool : public AbstractTool {
    Q_OBJECT
public:
    PlaceEndpointTool(Endpoint endpoint, QObject* parent = nullptr);

    QString usageHint() const override;
    QCursor cursor() const override { return QCursor(Qt::CrossCursor); }
    void deactivate() override;
    void mousePressed(const ToolMouseEvent& event) override;
    void mouseMoved(const ToolMouseEvent& event) override;
    void mouseReleased(const ToolMouseEvent& event) override;

private:
    void showGhost(QPointF position);

    Endpoint endpoint_;
    bool pressed_ = false;
    QGraphicsItem* ghost_ = nullptr; // the marker following the cursor while pressed
};

} // namespace fc::ui
