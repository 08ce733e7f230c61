#include "tools/EditVerticesTool.h"

#include "document/Conversions.h"
#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"

#include <QGraphicsItemGroup>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QKeyEvent>

namespace fc::ui {

namespace {

constexpr double kHitPixels = 8.0;

std::vector<PolygonRef> polygonsByPriority(const Document& document,
                                           std::optional<PolygonRef> first) {
    std::vector<PolygonRef> refs;
    if (first)
        refs.push_back(*first);
    for (int i = 0; i < document.polygonCount(PolygonRole::Obstacle); ++i)
        refs.push_back({PolygonRole::Obstacle, i});
    for (int i = 0; i < document.polygonCount(PolygonRole::Room); ++i)
        refs.push_back({PolygonRole::Room, i});
    if (document.polygonCount(PolygonRole::Boundary) > 0)
        refs.push_back({PolygonRole::Boundary, 0});
    return refs;
}

} // namespace

EditVerticesTool::EditVerticesTool(QObject* parent)
    : AbstractTool(tr("Edit Vertices"), QKeySequence(Qt::Key_E), parent) {
    setObjectName(QStringLiteral("editVertices"));
}

QString EditVerticesTool::usageHint() const {
    return tr("Edit Vertices: drag a vertex to move it, double-click an edge to add one, "
              "right-click a vertex to delete it; select a polygon and press Delete to "
              "delete it.");
}

void EditVerticesTool::activate(Document* document, PlanScene* scene) {
    AbstractTool::activate(document, scene);
    connect(document, &Document::geometryChanged, this, &EditVerticesTool::rebuildHandles);
    select(std::nullopt);
}

void EditVerticesTool::deactivate() {
    if (document())
        disconnect(document(), nullptr, this, nullptr);
    if (scene())
        scene()->setHighlight(std::nullopt);
    delete handles_;
    handles_ = nullptr;
    delete dragPreview_;
    dragPreview_ = nullptr;
    delete hover_;
    hover_ = nullptr;
    dragging_ = false;
    selected_.reset();
    AbstractTool::deactivate();
}

std::optional<VertexRef> EditVerticesTool::vertexAt(QPointF point, double tolerance) const {
    const Vec2 p = toVec2(point);
    for (const PolygonRef& ref : polygonsByPriority(*document(), selected_)) {
        const Ring& ring = document()->ring(ref);
        for (size_t i = 0; i < ring.size(); ++i)
            if (distance(ring[i], p) <= tolerance)
                return VertexRef{ref, static_cast<int>(i)};
    }
    return std::nullopt;
}

void EditVerticesTool::select(std::optional<PolygonRef> polygon, int vertex) {
    selected_ = polygon;
    selectedVertex_ = vertex;
    scene()->setHighlight(polygon);
    rebuildHandles();
}

void EditVerticesTool::rebuildHandles() {
    if (!scene() || !document())
        return;
    if (selected_ && selected_->index >= document()->polygonCount(selected_->role))
        selected_.reset(); // undo removed it
    if (selected_ && selectedVertex_ >= static_cast<int>(document()->ring(*selected_).size()))
        selectedVertex_ = -1;
    scene()->setHighlight(selected_);
    delete handles_;
    handles_ = new QGraphicsItemGroup;
    handles_->setZValue(z::Tool);
    scene()->addItem(handles_);
    if (!selected_)
        return;
    // Handles on the selected polygon only, as in Tiled: a whole plan of handles hides it.
    const Ring& ring = document()->ring(*selected_);
    for (size_t i = 0; i < ring.size(); ++i)
        addHandle(handles_, toQt(ring[i]), static_cast<int>(i) == selectedVertex_);
}

QGraphicsItem* EditVerticesTool::addHandle(QGraphicsItem* parent, QPointF position, bool current) {
    const QColor colour = style::palette().color(QPalette::Highlight);
    const double half = current ? 5.0 : 3.5; // pixels
    auto* handle = new QGraphicsRectItem(-half, -half, 2 * half, 2 * half, parent);
    handle->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    handle->setPos(position);
    handle->setPen(QPen(colour, 1));
    handle->setBrush(current ? colour : style::palette().color(QPalette::Base));
    handle->setZValue(z::Tool);
    return handle;
}

void EditVerticesTool::showHover(std::optional<VertexRef> vertex) {
    delete hover_;
    hover_ = nullptr;
    if (!vertex || !scene())
        return;
    hover_ = addHandle(nullptr, toQt(document()->ring(vertex->polygon)[vertex->index]), true);
    scene()->addItem(hover_);
}

void EditVerticesTool::mousePressed(const ToolMouseEvent& event) {
    if (!document())
        return;
    endDrag(); // also clears a refused move's red outline
    const double tolerance = kHitPixels * event.metresPerPixel;
    const std::optional<VertexRef> vertex = vertexAt(event.position, tolerance);
    if (event.button == Qt::RightButton) {
        if (vertex && document()->deleteVertex(vertex->polygon, vertex->index))
            select(vertex->polygon);
        return;
    }
    if (event.button != Qt::LeftButton)
        return;
    if (vertex) {
        showHover(std::nullopt);
        select(vertex->polygon, vertex->index);
        dragging_ = true;
        dragOrigin_ = event.position;
        return;
    }
    select(scene()->polygonAt(event.position, tolerance));
}

void EditVerticesTool::showDragPreview(QPointF position) {
    if (!dragPreview_) {
        dragPreview_ = new QGraphicsPathItem;
        dragPreview_->setZValue(z::Tool);
        dragPreview_->setPen(
            style::cosmeticPen(style::palette().color(QPalette::Highlight), 1.5, Qt::DashLine));
        scene()->addItem(dragPreview_);
    }
    Ring moved = document()->ring(*selected_);
    moved[selectedVertex_] = toVec2(position);
    QPainterPath path;
    addRing(path, moved);
    dragPreview_->setPath(path);
}

void EditVerticesTool::mouseMoved(const ToolMouseEvent& event) {
    if (dragging_ && selected_ && selectedVertex_ >= 0) {
        showDragPreview(event.snapped);
        return;
    }
    if (document())
        showHover(vertexAt(event.position, kHitPixels * event.metresPerPixel));
}

void EditVerticesTool::endDrag() {
    dragging_ = false;
    delete dragPreview_;
    dragPreview_ = nullptr;
}

void EditVerticesTool::mouseReleased(const ToolMouseEvent& event) {
    if (event.button != Qt::LeftButton || !dragging_)
        return;
    const bool moved = QLineF(dragOrigin_, event.position).length() >
                       2.0 * event.metresPerPixel; // a click selects without moving
    const PolygonRef polygon = *selected_;
    const int vertex = selectedVertex_;
    dragging_ = false;
    if (moved && !document()->moveVertex(polygon, vertex, toVec2(event.snapped)) && dragPreview_) {
        // Refused by validation: the outline stays in red until the next click, with the
        // message in the status bar, so that the user sees what was wrong.
        dragPreview_->setPen(style::cosmeticPen(QColor(220, 30, 30), 2.0, Qt::DashLine));
        return;
    }
    endDrag();
}

void EditVerticesTool::mouseDoubleClicked(const ToolMouseEvent& event) {
    if (!document() || event.button != Qt::LeftButton)
        return;
    const double tolerance = kHitPixels * event.metresPerPixel;
    if (vertexAt(event.position, tolerance))
        return;
    const Vec2 p = toVec2(event.position);
    for (const PolygonRef& ref : polygonsByPriority(*document(), selected_)) {
        const Ring& ring = document()->ring(ref);
        for (size_t i = 0; i < ring.size(); ++i) {
            if (pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]) <= tolerance) {
                if (document()->insertVertex(ref, static_cast<int>(i) + 1, toVec2(event.snapped)))
                    select(ref, static_cast<int>(i) + 1);
                return;
            }
        }
    }
}

bool EditVerticesTool::keyPressed(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && selected_) {
        select(std::nullopt);
        return true;
    }
    if (event->key() != Qt::Key_Delete && event->key() != Qt::Key_Backspace)
        return false;
    if (!selected_)
        return false;
    const PolygonRef polygon = *selected_;
    if (selectedVertex_ >= 0) {
        if (document()->deleteVertex(polygon, selectedVertex_))
            select(polygon);
    } else if (document()->deletePolygon(polygon)) {
        select(std::nullopt);
    }
    return true;
}

} // namespace fc::ui
