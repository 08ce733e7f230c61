// The scene of one document: the plan's polygons (boundary, obstacles, rooms with their
// names and planning selection), start and end markers, and the planner's overlays. Items
// are rebuilt from the document whenever it signals a change, so they always follow it.
#pragma once

#include "canvas/OverlayLayer.h"
#include "document/Document.h"

#include <QGraphicsScene>
#include <QImage>
#include <QPointer>
#include <optional>

class QGraphicsItem;
class QGraphicsItemGroup;

namespace fc::ui {

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

    // Path (default) or Graph: see ViewMode. Markers and overlays follow.
    void setViewMode(ViewMode mode);
    ViewMode viewMode() const;

    // Places the room names, cell ids and markers so that none overlaps another at the
    // zoom of `viewTransform` (labels keep their screen size); those that do not fit are
    // hidden (their room's tooltip still names it). The no-argument form uses the first
    // view's transform and is called after every rebuild; views call it when they zoom.
    void layoutLabels(const QTransform& viewTransform);
    void layoutLabels();

    // The plan in the Path view, fitted into an image of `size` logical pixels (labels and
    // markers keep their screen size, so a larger page shows more of them) at
    // `pixelRatio` device pixels each; the view mode and labels are restored afterwards.
    QImage renderPathView(QSize size, double pixelRatio);

    // A plan that needs repair: its problems are circled in red; the focused one (clicked
    // in the Problems panel) is drawn larger.
    void setProblemFocus(std::optional<QPointF> point);

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
    void rebuildProblems();
    void updateSceneRect();

    QPointer<Document> document_;
    QPointer<PlanningController> controller_;
    OverlayLayer* overlays_;
    QGraphicsItemGroup* polygons_ = nullptr;
    QGraphicsItemGroup* roomLabels_ = nullptr;
    QGraphicsItemGroup* markers_ = nullptr;
    QGraphicsItemGroup* problems_ = nullptr;
    std::optional<QPointF> problemFocus_;
    QGraphicsItem* highlightItem_ = nullptr;
    std::optional<PolygonRef> highlight_;
};

} // namespace fc::ui
