// The planner's results drawn over the plan: cells, critical slices, the corner graph and
// the planned path with its overlaps. Rebuilt whenever the planning controller publishes a
// new decomposition or plan; each kind is a group that the View menu shows or hides.
#pragma once

#include <QBrush>
#include <QObject>
#include <QPen>
#include <QPointer>
#include <QString>
#include <array>
#include <memory>

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
// How an overlay kind is drawn (also the legend's swatches).
struct OverlayStyle {
    QPen pen;
    QBrush brush;
};
OverlayStyle overlayStyle(OverlayKind kind);
// Shown unless the user hides them; the graph's edges would hide the cells by default.
bool overlayVisibleByDefault(OverlayKind kind);

class OverlayLayer : public QObject {
    Q_OBJECT
public:
    explicit OverlayLayer(PlanScene* scene);

    void setPlanningController(PlanningController* controller);
    void setVisible(OverlayKind kind, bool visible);
    bool isVisible(OverlayKind kind) const { return visible_[static_cast<int>(kind)]; }
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
    QString cellsKey_;                            // of the cells and graph built
    std::shared_ptr<const PlanResult> pathShown_; // whose path the path's layers draw
};

} // namespace fc::ui
