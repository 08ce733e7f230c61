#include "canvas/CanvasView.h"

#include "canvas/PlanScene.h"
#include "document/Document.h"
#include "tools/AbstractTool.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmapCache>
#include <QScrollBar>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace fc::ui {

namespace {

// The smallest "nice" length (1, 2, 5 x 10^k metres) of at least `minimum` metres.
double niceLength(double minimum) {
    const double decade = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (decade * factor >= minimum)
            return decade * factor;
    return decade * 10.0;
}

constexpr double kMinGridPixels = 16.0; // minor grid lines closer than this are hidden

} // namespace

CanvasView::CanvasView(QWidget* parent) : QGraphicsView(parent) {
    setTransformationAnchor(QGraphicsView::AnchorViewCenter); // the wheel anchors itself
    setResizeAnchor(QGraphicsView::AnchorViewCenter);
    setRenderHint(QPainter::Antialiasing);
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate); // the grid moves with panning
    // The grid is drawn once per zoom, not on every repaint (a path arriving, a tool's
    // rubber band): Qt scrolls the cached background and redraws it when the zoom changes.
    setCacheMode(QGraphicsView::CacheBackground);
    // Scene items keep their rendering (DeviceCoordinateCache) so that a new path repaints
    // only itself; a floor-sized item is a viewport-sized pixmap, and Qt's default 10 MB
    // of pixmap cache holds two of them, so every repaint would render everything again.
    QPixmapCache::setCacheLimit(std::max(QPixmapCache::cacheLimit(), 160 * 1024));
    setMouseTracking(true);
    setDragMode(QGraphicsView::NoDrag);
    setFocusPolicy(Qt::StrongFocus);
    // Plan coordinates have +y up; the scene keeps them as they are and the view flips.
    setTransform(QTransform::fromScale(40.0, -40.0));
}

void CanvasView::setTool(AbstractTool* tool) {
    tool_ = tool;
    restoreToolCursor();
}

void CanvasView::restoreToolCursor() {
    viewport()->setCursor(tool_ ? tool_->cursor() : QCursor(Qt::ArrowCursor));
}

double CanvasView::metresPerPixel() const {
    const double scale = std::abs(transform().m11());
    return scale > 0 ? 1.0 / scale : 1.0;
}

double CanvasView::gridStep() const {
    return niceLength(kMinGridPixels * metresPerPixel());
}

void CanvasView::setGridVisible(bool visible) {
    gridVisible_ = visible;
    resetCachedContent();
    viewport()->update();
}

void CanvasView::fitToPlan() {
    if (!scene())
        return;
    QRectF bounds;
    if (document_ && !document_->plan().boundary.empty()) {
        const BoundingBox box = document_->plan().bounds();
        bounds = QRectF(QPointF(box.minX, box.minY), QPointF(box.maxX, box.maxY));
    } else {
        bounds = QRectF(-1, -1, 22, 16); // an empty drawing: 20 x 14 m with a margin
    }
    const double margin = 0.05 * std::max(bounds.width(), bounds.height());
    fitInView(bounds.adjusted(-margin, -margin, margin, margin), Qt::KeepAspectRatio);
    layoutLabels();
}

void CanvasView::layoutLabels() {
    // Labels keep their screen size, so which of them fit changes with the zoom.
    if (auto* planScene = qobject_cast<PlanScene*>(scene()))
        planScene->layoutLabels(transform());
}

void CanvasView::zoomBy(double factor) {
    const double next = std::abs(transform().m11()) * factor;
    if (next < 0.05 || next > 5000.0)
        return; // metres per pixel between 20 and 0.0002
    scale(factor, factor);
    layoutLabels();
}

void CanvasView::scrollBy(QPoint pixels) {
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() + pixels.x());
    verticalScrollBar()->setValue(verticalScrollBar()->value() + pixels.y());
}

void CanvasView::wheelEvent(QWheelEvent* event) {
    const int delta = event->angleDelta().y();
    if (delta == 0)
        return;
    // Keep the plan point under the cursor where it is (QGraphicsView's AnchorUnderMouse
    // needs the view's own mouse tracking, which the tools replace).
    const QPoint cursor = event->position().toPoint();
    const QPointF anchor = mapToScene(cursor);
    setTransformationAnchor(QGraphicsView::NoAnchor);
    zoomBy(std::pow(1.0015, delta));
    setTransformationAnchor(QGraphicsView::AnchorViewCenter);
    scrollBy(mapFromScene(anchor) - cursor);
    event->accept();
}

bool CanvasView::startsPan(QMouseEvent* event) const {
    return event->button() == Qt::MiddleButton || (spaceHeld_ && event->button() == Qt::LeftButton);
}

ToolMouseEvent CanvasView::toolEvent(QMouseEvent* event) const {
    ToolMouseEvent e;
    e.position = mapToScene(event->position().toPoint());
    e.metresPerPixel = metresPerPixel();
    e.snapped = snapper_.snap(e.position, document_, gridStep(), e.metresPerPixel);
    e.button = event->button();
    e.buttons = event->buttons();
    e.modifiers = event->modifiers();
    return e;
}

void CanvasView::mousePressEvent(QMouseEvent* event) {
    if (startsPan(event)) {
        panning_ = true;
        lastPanPosition_ = event->position().toPoint();
        viewport()->setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    if (tool_)
        tool_->mousePressed(toolEvent(event));
    event->accept();
}

void CanvasView::mouseMoveEvent(QMouseEvent* event) {
    if (panning_) {
        scrollBy(lastPanPosition_ - event->position().toPoint()); // the plan follows the hand
        lastPanPosition_ = event->position().toPoint();
        event->accept();
        return;
    }
    const ToolMouseEvent e = toolEvent(event);
    emit cursorMoved(e.snapped);
    if (tool_)
        tool_->mouseMoved(e);
    event->accept();
}

void CanvasView::mouseReleaseEvent(QMouseEvent* event) {
    if (panning_) {
        panning_ = false;
        if (spaceHeld_)
            viewport()->setCursor(Qt::OpenHandCursor);
        else
            restoreToolCursor();
        event->accept();
        return;
    }
    if (tool_)
        tool_->mouseReleased(toolEvent(event));
    event->accept();
}

void CanvasView::mouseDoubleClickEvent(QMouseEvent* event) {
    if (tool_ && !startsPan(event))
        tool_->mouseDoubleClicked(toolEvent(event));
    event->accept();
}

void CanvasView::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
        spaceHeld_ = true;
        viewport()->setCursor(Qt::OpenHandCursor);
        event->accept();
        return;
    }
    if (tool_ && tool_->keyPressed(event)) {
        event->accept();
        return;
    }
    QGraphicsView::keyPressEvent(event);
}

void CanvasView::keyReleaseEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
        spaceHeld_ = false;
        if (!panning_)
            restoreToolCursor();
        event->accept();
        return;
    }
    QGraphicsView::keyReleaseEvent(event);
}

void CanvasView::drawBackground(QPainter* painter, const QRectF& rect) {
    painter->fillRect(rect, palette().color(QPalette::Base));
    if (!gridVisible_)
        return;
    const double step = gridStep();
    const double major = step * 5.0;
    const QColor text = palette().color(QPalette::Text);
    QColor minorColor = text;
    minorColor.setAlphaF(0.07);
    QColor majorColor = text;
    majorColor.setAlphaF(0.18);
    QPen minorPen(minorColor, 0); // width 0: one device pixel whatever the zoom
    QPen majorPen(majorColor, 0);
    const auto isMajor = [major](double v) {
        return std::abs(v / major - std::round(v / major)) < 1e-6;
    };
    for (double x = std::floor(rect.left() / step) * step; x <= rect.right(); x += step) {
        painter->setPen(isMajor(x) ? majorPen : minorPen);
        painter->drawLine(QPointF(x, rect.top()), QPointF(x, rect.bottom()));
    }
    for (double y = std::floor(rect.top() / step) * step; y <= rect.bottom(); y += step) {
        painter->setPen(isMajor(y) ? majorPen : minorPen);
        painter->drawLine(QPointF(rect.left(), y), QPointF(rect.right(), y));
    }
}

void CanvasView::drawForeground(QPainter* painter, const QRectF&) {
    // Scale bar in screen coordinates at the bottom left: a nice length of ~100 pixels.
    const double length = niceLength(100.0 * metresPerPixel());
    const double pixels = length / metresPerPixel();
    painter->save();
    painter->resetTransform();
    const QPointF origin(16, viewport()->height() - 16);
    painter->setPen(QPen(palette().color(QPalette::Text), 2));
    painter->drawLine(origin, origin + QPointF(pixels, 0));
    painter->drawLine(origin, origin + QPointF(0, -6));
    painter->drawLine(origin + QPointF(pixels, 0), origin + QPointF(pixels, -6));
    const QString label = length >= 1.0 ? tr("%1 m").arg(length) : tr("%1 cm").arg(length * 100);
    painter->drawText(origin + QPointF(4, -6), label);
    painter->restore();
}

} // namespace fc::ui
