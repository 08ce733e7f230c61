// Snapping of cursor positions: to the vertices of the plan within a few screen pixels,
// otherwise to the grid shown on the canvas.
#pragma once

#include <QPointF>
#include <optional>

namespace fc::ui {

class Document;

class Snapper {
public:
    bool snapToGrid = true;
    bool snapToVertices = true;
    double vertexTolerancePixels = 10.0;

    // gridStep: the grid spacing in metres; metresPerPixel: the view's scale.
    QPointF snap(QPointF position, const Document* document, double gridStep,
                 double metresPerPixel) const;
};

// The point nearest `position` on a line through `last` that is parallel or perpendicular
// to the segment previous -> last (axis-parallel when there is no previous segment):
// drawing with right angles.
QPointF snapToRightAngle(QPointF position, QPointF last, std::optional<QPointF> previous);

} // namespace fc::ui
