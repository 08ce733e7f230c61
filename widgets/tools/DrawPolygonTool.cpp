#include "tools/DrawPolygonTool.h"

#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"
#include "canvas/Snapper.h"
#include "document/Conversions.h"
#include "document/Document.h"
#include "geometry/Geometry.h"

#include <QGraphicsPathItem>
#include <QKeyEvent>
#include <QLineF>
#include <algorithm>

namespace fc::ui {

namespace {

constexpr double kCloseTolerancePixels = 8.0;
constexpr double kDragThresholdPixels = 6.0;

// What distinguishes the three drawing tools.
struct DrawToolTraits {
    QString name;
    Qt::Key shortcut;
    const char* objectName; // stable, for tests and look-ups
};

DrawToolTraits traitsOf(PolygonRole role) {
    switch (role) {
    case PolygonRole::Boundary:
        return {DrawPolygonTool::tr("Draw Boundary"), Qt::Key_B, "drawBoundary"};
    case PolygonRole::Obstacle:
        return {DrawPolygonTool::tr("Draw Obstacle"), Qt::Key_O, "drawObstacle"};
    case PolygonRole::Room:
        break;
    }
    return {DrawPolygonTool::tr("Draw Room"), Qt::Key_R, "drawRoom"};
}

} // namespace

DrawPolygonTool::DrawPolygonTool(PolygonRole role, QObject* parent)
    : AbstractTool(traitsOf(role).name, QKeySequence(traitsOf(role).shortcut), parent),
      role_(role) {
    setObjectName(QLatin1String(traitsOf(role).objectName));
}

QString DrawPolygonTool::usageHint() const {
    return tr("%1: click vertices and click the first one to close, or drag a rectangle. "
              "Shift keeps right angles, Backspace removes a vertex, Esc cancels.")
        .arg(name());
}

void DrawPolygonTool::activate(Document* document, PlanScene* scene) {
    AbstractTool::activate(document, scene);
    clearSketch();
}

void DrawPolygonTool::deactivate() {
    clearSketch();
    delete preview_;
    preview_ = nullptr;
    AbstractTool::deactivate();
}

void DrawPolygonTool::clearSketch() {
    points_.clear();
    pressed_ = rectangle_ = rejected_ = false;
    updatePreview();
}

bool DrawPolygonTool::nearFirstPoint(const ToolMouseEvent& event) const {
    return points_.size() >= 3 && QLineF(points_.first(), event.position).length() <=
                                      kCloseTolerancePixels * event.metresPerPixel;
}

void DrawPolygonTool::mousePressed(const ToolMouseEvent& event) {
    metresPerPixel_ = event.metresPerPixel;
    if (event.button != Qt::LeftButton)
        return;
    if (rejected_)
        clearSketch(); // the next click starts afresh after a refused polygon
    if (points_.isEmpty()) {
        pressed_ = true;
        pressPosition_ = event.snapped;
        pressRaw_ = event.position;
        rectangle_ = false;
    }
}

QPointF DrawPolygonTool::target(const ToolMouseEvent& event) const {
    if (!(event.modifiers & Qt::ShiftModifier) || points_.isEmpty())
        return event.snapped;
    const std::optional<QPointF> previous =
        points_.size() >= 2 ? std::optional<QPointF>(points_[points_.size() - 2]) : std::nullopt;
    return snapToRightAngle(event.position, points_.last(), previous);
}

void DrawPolygonTool::mouseMoved(const ToolMouseEvent& event) {
    cursor_ = target(event);
    hasCursor_ = true;
    metresPerPixel_ = event.metresPerPixel;
    if (pressed_ && (event.buttons & Qt::LeftButton) &&
        QLineF(pressRaw_, event.position).length() > kDragThresholdPixels * event.metresPerPixel)
        rectangle_ = true;
    updatePreview();
}

void DrawPolygonTool::mouseReleased(const ToolMouseEvent& event) {
    if (event.button != Qt::LeftButton || !document())
        return;
    if (pressed_ && rectangle_) {
        pressed_ = rectangle_ = false;
        const QRectF box = QRectF(pressPosition_, event.snapped).normalized();
        QPolygonF rectangle;
        rectangle << box.bottomLeft() << box.bottomRight() << box.topRight() << box.topLeft();
        finish(rectangle);
        return;
    }
    pressed_ = false;
    if (nearFirstPoint(event)) {
        finish(points_);
        return;
    }
    const QPointF point = target(event);
    if (points_.isEmpty() || points_.last() != point)
        points_ << point;
    updatePreview();
}

bool DrawPolygonTool::keyPressed(QKeyEvent* event) {
    switch (event->key()) {
    case Qt::Key_Escape:
        clearSketch();
        return true;
    case Qt::Key_Backspace:
        if (!points_.isEmpty())
            points_.removeLast();
        rejected_ = false;
        updatePreview();
        return true;
    case Qt::Key_Return:
    case Qt::Key_Enter:
        if (points_.size() >= 3)
            finish(points_);
        return true;
    default:
        return false;
    }
}

void DrawPolygonTool::finish(const QPolygonF& polygon) {
    if (polygon.size() < 3) {
        emit statusMessage(tr("A polygon needs at least three vertices."));
        return;
    }
    points_ = polygon;
    if (role_ == PolygonRole::Boundary && !replacesBoundary(toRing(polygon))) {
        clearSketch();
        emit statusMessage(tr("Kept the existing boundary."));
        return;
    }
    QString problem;
    // The document reports a refused edit through editRejected; catch it for the sketch.
    auto connection = connect(document(), &Document::editRejected, this,
                              [&problem](const QString& message) { problem = message; });
    const bool accepted = document()->addPolygon(role_, toRing(polygon));
    disconnect(connection);
    if (accepted) {
        clearSketch();
        return;
    }
    rejected_ = true;
    updatePreview();
    emit statusMessage(tr("%1 refused: %2").arg(name(), problem));
}

bool DrawPolygonTool::replacesBoundary(const Ring& ring) const {
    const Ring& old = document()->plan().boundary;
    if (old.empty())
        return true;
    // Drawn around the old one: a larger outline, plainly meant to replace it.
    if (std::all_of(old.begin(), old.end(), [&ring](Vec2 p) { return pointInRing(ring, p); }))
        return true;
    return confirm(tr("The plan already has a boundary, and a plan has only one. Replace it "
                      "with the one you drew? (Undo brings the old boundary back.)"));
}

void DrawPolygonTool::updatePreview() {
    if (!scene())
        return;
    if (!preview_) {
        preview_ = new QGraphicsPathItem;
        preview_->setZValue(z::Tool);
        scene()->addItem(preview_);
    }
    QPainterPath path;
    if (pressed_ && rectangle_) {
        path.addRect(QRectF(pressPosition_, cursor_).normalized());
    } else if (!points_.isEmpty()) {
        path.addPolygon(points_);
        if (rejected_)
            path.closeSubpath();
        else if (hasCursor_)
            path.lineTo(cursor_);
        // Mark the first vertex: clicking it closes the polygon.
        const double r = 4.0 * metresPerPixel_;
        path.addEllipse(points_.first(), r, r);
    }
    preview_->setPath(path);
    const QColor colour =
        rejected_ ? QColor(220, 30, 30) : style::palette().color(QPalette::Highlight);
    preview_->setPen(style::cosmeticPen(colour, 2.0, rejected_ ? Qt::DashLine : Qt::SolidLine));
    preview_->setBrush(rejected_ ? QBrush(QColor(220, 30, 30, 50)) : QBrush(Qt::NoBrush));
}

} // namespace fc::ui
