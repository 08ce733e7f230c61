// The scene of one document: the plan's polygons (boundary, obstacles, rooms with their
// names and planning selection), start and end markers, and the planner's overlays. Items
// are rebuilt from the document whenever it signals a change, so they always follow it.
#pragma once

#include "document/Document.h"

#include <QGraphicsScene>
#include <QPointer>
#include <optional>

class QGraphicsItem;
class QGraphicsItemGroup;

namespace fc::ui {

class OverlayLayer;
class PlanningController;

// Stacking order of the scene's layers (higher is drawn on top).
namespace z {
constexpr double Rooms = 0, Walls = 1, Overlays = 2, Path = 6, Markers = 10, Tool = 20;
}

class PlanScene : public QGraphicsScene {
    Q_OBJECT
public:
    explicit PlanScene(QObject* parent = nullptr);
    ~PlanScene() override;

    void setDocument(Document* document);
    void setPlanningController(PlanningController* controller);
    Document* document() const { return document_; }
    OverlayLayer* overlays() const { return overlays_; }

    // Redraws everything in the colours of the current application palette (dark or light
    // theme switched while running).
    void restyle();

    // Outlines the polygon the edit tool works on.
    void setHighlight(std::optional<PolygonRef> polygon);
    // The polygon whose outline passes within `tolerance` of a point, else the innermost
    // one containing it (obstacles before rooms before the boundary).
    std::optional<PolygonRef> polygonAt(QPointF point, double tolerance) const;

private:
    void rebuildPolygons();
    void rebuildMarkers();
    void updateSceneRect();

    QPointer<Document> document_;
    QPointer<PlanningController> controller_;
    OverlayLayer* overlays_;
    QGraphicsItemGroup* polygons_ = nullptr;
    QGraphicsItemGroup* markers_ = nullptr;
    QGraphicsItem* highlightItem_ = nullptr;
    std::optional<PolygonRef> highlight_;
};

} // namespace fc::ui
