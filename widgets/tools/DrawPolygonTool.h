// Draws a boundary, obstacle or room: click vertices and close by clicking the first one
// (or Enter), or drag for a rectangle; Shift keeps the new edge at a right angle to the last.
// Backspace removes the last vertex, Escape cancels. A polygon the planner's validation refuses
// stays on the canvas in red with the message.
#pragma once

#include "document/Document.h"
#include "tools/AbstractTool.h"

#include <QPolygonF>

class QGraphicsPathItem;

namespace fc::ui {

class DrawPolygonTool : public AbstractTool {
    Q_OBJECT
public:
    DrawPolygonTool(PolygonRole role, QObject* parent = nullptr);

    QString usageHint() const override;
    QCursor cursor() const override { return QCursor(Qt::CrossCursor); }
    void activate(Document* document, PlanScene* scene) override;
    void deactivate() override;
    void mousePressed(const ToolMouseEvent& event) override;
    void mouseMoved(const ToolMouseEvent& event) override;
    void mouseReleased(const ToolMouseEvent& event) override;
    bool keyPressed(QKeyEvent* event) override;

    // The vertices placed so far (tests).
    QPolygonF sketch() const { return points_; }

private:
    // Where a click puts the next vertex: snapped, and with Shift at a right angle.
    QPointF target(const ToolMouseEvent& event) const;
    void finish(const QPolygonF& polygon);
    // Whether a drawn boundary may replace the plan's (asks unless it encloses the old one).
    bool replacesBoundary(const Ring& ring) const;
    void updatePreview();
    void clearSketch();
    bool nearFirstPoint(const ToolMouseEvent& event) const;

    PolygonRole role_;
    QPolygonF points_;
    QPointF cursor_;
    bool hasCursor_ = false;
    double metresPerPixel_ = 0.02;
    // Left button pressed with no sketch: a drag draws a rectangle, a click starts a polygon.
    bool pressed_ = false;
    QPointF pressPosition_;
    QPointF pressRaw_;
    bool rectangle_ = false;
    bool rejected_ = false; // the shown sketch was refused by validation
    QGraphicsPathItem* preview_ = nullptr;
};

} // namespace fc::ui
