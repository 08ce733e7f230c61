// Edits existing polygons: drag a vertex to move it, double-click an edge to insert a
// vertex, right-click a vertex (or select it and press Delete) to delete it; click inside
// a polygon to select it and press Delete to delete the whole polygon.
#pragma once

#include "tools/AbstractTool.h"
#include "document/Document.h"

#include <optional>

class QGraphicsItem;
class QGraphicsItemGroup;
class QGraphicsPathItem;

namespace fc::ui {

struct VertexRef {
    PolygonRef polygon;
    int index = -1;
};

class EditVerticesTool : public AbstractTool {
    Q_OBJECT
public:
    explicit EditVerticesTool(QObject* parent = nullptr);

    QString usageHint() const override;
    void activate(Document* document, PlanScene* scene) override;
    void deactivate() override;
    void mousePressed(const ToolMouseEvent& event) override;
    void mouseMoved(const ToolMouseEvent& event) override;
    void mouseReleased(const ToolMouseEvent& event) override;
    void mouseDoubleClicked(const ToolMouseEvent& event) override;
    bool keyPressed(QKeyEvent* event) override;

    std::optional<PolygonRef> selectedPolygon() const { return selected_; }

private:
    std::optional<VertexRef> vertexAt(QPointF point, double tolerance) const;
    void select(std::optional<PolygonRef> polygon, int vertex = -1);
    void rebuildHandles();
    static QGraphicsItem* addHandle(QGraphicsItem* parent, QPointF position, bool current);
    void showHover(std::optional<VertexRef> vertex);
    void showDragPreview(QPointF position);
    void endDrag();

    std::optional<PolygonRef> selected_;
    int selectedVertex_ = -1;
    bool dragging_ = false;
    QPointF dragOrigin_;
    QGraphicsItemGroup* handles_ = nullptr;
    QGraphicsPathItem* dragPreview_ = nullptr;
    QGraphicsItem* hover_ = nullptr; // the vertex under the cursor
};

} // namespace fc::ui
