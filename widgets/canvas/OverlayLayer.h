// The planner's results drawn over the plan: cells, critical slices, the corner graph and
// the planned path with its overlaps. Rebuilt whenever the planning controller publishes a
// new decomposition or plan; each kind is a group that the View menu shows or hides.
#pragma once

#include <QBrush>
#include <QList>
#include <QObject>
#include <QPen>
#include <QPointer>
#include <QString>
#include <array>
#include <memory>

class QGraphicsItem;
class QGraphicsItemGroup;

namespace fc {
struct PreparedPlan;
struct PlanResult;
} // namespace fc

namespace fc::ui {

class PlanScene;
class PlanningController;

enum class OverlayKind {
    PrimaryCells,
    TransitionCells,
    CriticalSlices,
    CornerNodes,
    CoverageEdges,
    ContourEdges,
    InterEdges,
    Path,
    Overlaps,
    Unreachable,
    CoverageGaps, // sample points of sweepable area the path missed
};
constexpr int kOverlayKindCount = 11;

// Menu text of an overlay kind (translated).
QString overlayName(OverlayKind kind);
// What an overlay kind shows, in a sentence (translated; the legend's tooltips).
QString overlayDescription(OverlayKind kind);
// How an overlay kind is drawn (also the legend's swatches).
struct OverlayStyle {
    QPen pen;
    QBrush brush;
};
OverlayStyle overlayStyle(OverlayKind kind);

// What the canvas is for: Path shows a supervisor the floor, the rooms and the path (its
// coverage, transit and overlaps, start and end); Graph adds the planner's internals
// (cells, slices, corners and the graph's edges) for whoever studies the method.
enum class ViewMode { Path, Graph };
// Overlays of the planner's internals, shown only in the Graph view.
bool isGraphOverlay(OverlayKind kind);
// How transit moves between cells are drawn (the path's other segments: the Path kind).
OverlayStyle transitStyle();
// Shown unless the user hides them; the graph's edges would hide the cells by default.
bool overlayVisibleByDefault(OverlayKind kind);

class OverlayLayer : public QObject {
    Q_OBJECT
public:
    explicit OverlayLayer(PlanScene* scene);

    void setPlanningController(PlanningController* controller);
    void setVisible(OverlayKind kind, bool visible);
    // The user's choice (View > Overlays, legend), whatever the view mode.
    bool isVisible(OverlayKind kind) const { return visible_[static_cast<int>(kind)]; }
    // Drawn now: chosen by the user and part of the view mode.
    bool isShown(OverlayKind kind) const;
    void setViewMode(ViewMode mode);
    ViewMode viewMode() const { return mode_; }
    // The labels of shown overlays (cell ids), for PlanScene's label placement.
    QList<QGraphicsItem*> labelItems() const;
    // Number of items drawn for a kind (tests check that overlays appear).
    int itemCount(OverlayKind kind) const;
    // 1 normally; below 1 for the path's layers while the path is stale (faded).
    double opacity(OverlayKind kind) const;

public slots:
    // Builds every layer again (a new palette, a new controller).
    void rebuild();
    // Builds again what the controller's change touched: the path's layers, and cells and
    // graph only when others are shown (PlanningController::cellsKey).
    void refresh();

private:
    QGraphicsItemGroup* freshGroup(OverlayKind kind, double zValue);
    static bool isPathLayer(OverlayKind kind);
    // rooms: only the cells of these rooms (one part of a per-room plan); null: all.
    void addCells(const PreparedPlan& prepared, const std::vector<std::string>* rooms = nullptr);
    void addCriticalSlices(const PreparedPlan& prepared);
    void addGraph(const PreparedPlan& prepared, const std::vector<std::string>* rooms = nullptr);
    void addUnreachable(const PreparedPlan& prepared);
    void addPath(const PlanResult& result, bool stale = false);

    PlanScene* scene_;
    QPointer<PlanningController> controller_;
    std::array<QGraphicsItemGroup*, kOverlayKindCount> groups_{};
    std::array<bool, kOverlayKindCount> visible_{};
    ViewMode mode_ = ViewMode::Path;
    QString cellsKey_;                            // of the cells and graph built
    std::shared_ptr<const PlanResult> pathShown_; // whose path the path's layers draw
};

} // namespace fc::ui
