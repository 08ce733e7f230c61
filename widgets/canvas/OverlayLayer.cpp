#include "canvas/OverlayLayer.h"

#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"
#include "document/Conversions.h"
#include "tasks/PlanningController.h"

#include <QCoreApplication>
#include <QGraphicsItemGroup>
#include <QGraphicsPathItem>
#include <algorithm>

namespace fc::ui {

namespace {

QGraphicsPathItem* addPathItem(QGraphicsItem* parent, const QPainterPath& path, const QPen& pen,
                               const QBrush& brush = Qt::NoBrush) {
    auto* item = new QGraphicsPathItem(path, parent);
    item->setCacheMode(QGraphicsItem::DeviceCoordinateCache);
    item->setPen(pen);
    item->setBrush(brush);
    return item;
}

// A filled arrow head of size `size` metres at `tip` pointing along `direction`.
void addArrowHead(QPainterPath& path, Vec2 tip, Vec2 direction, double size) {
    const double length = norm(direction);
    if (length <= 0)
        return;
    const Vec2 d = direction * (1.0 / length), n(-d.y, d.x);
    const Vec2 back = tip - d * size;
    QPolygonF head;
    head << toQt(tip) << toQt(back + n * (size * 0.5)) << toQt(back - n * (size * 0.5))
         << toQt(tip);
    path.addPolygon(head);
}

} // namespace

QString overlayName(OverlayKind kind) {
    const char* names[kOverlayKindCount] = {
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Primary Cells"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Transition Cells"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Critical Slices"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Corner Nodes"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Coverage Edges"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Contour Edges"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Inter-cell Edges"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Path"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Overlap Segments"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Unreachable Areas"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Coverage Gaps"),
    };
    return QCoreApplication::translate("fc::ui::OverlayLayer", names[static_cast<int>(kind)]);
}

QString overlayDescription(OverlayKind kind) {
    const char* texts[kOverlayKindCount] = {
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "The cells the floor is split into, one colour per room, with their "
                          "numbers"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "Narrow strips between cells the robot passes through (hatched)"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "Where the floor's shape changes and one cell ends (dashed)"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "The cells' corners, where the path may enter or leave a cell"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "Which corners a cell's stripes join (entry and exit pairs)"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Moves along a cell's edge between its corners"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer", "Moves from one cell to the next"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "The robot's path: cleaning stripes in red, transit moves dashed, "
                          "arrows for the direction"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "Where the path passes over floor it has already cleaned (blue)"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "Floor the robot cannot reach: gaps narrower than the robot, corners "
                          "beyond its head"),
        QT_TRANSLATE_NOOP("fc::ui::OverlayLayer",
                          "Spots the robot could clean but the path misses"),
    };
    return QCoreApplication::translate("fc::ui::OverlayLayer", texts[static_cast<int>(kind)]);
}

OverlayStyle overlayStyle(OverlayKind kind) {
    switch (kind) {
    case OverlayKind::PrimaryCells: // each room has its own hue; this is the first one
        return {style::cosmeticPen(style::roomHue(0, 255), 1.0), style::roomHue(0, 90)};
    case OverlayKind::TransitionCells: // hatched grey, distinct from primary cells
        return {style::cosmeticPen(QColor(120, 120, 120), 1.0),
                QBrush(QColor(110, 110, 110, 140), Qt::FDiagPattern)};
    case OverlayKind::CriticalSlices:
        return {style::cosmeticPen(QColor(200, 60, 160), 1.5, Qt::DashLine), Qt::NoBrush};
    case OverlayKind::CornerNodes:
        return {style::cosmeticPen(QColor(20, 20, 20), 1.0), QColor(250, 220, 40)};
    case OverlayKind::CoverageEdges:
        return {style::cosmeticPen(QColor(30, 150, 70), 1.5, Qt::DashLine), Qt::NoBrush};
    case OverlayKind::ContourEdges:
        return {style::cosmeticPen(QColor(230, 140, 20), 1.5), Qt::NoBrush};
    case OverlayKind::InterEdges:
        return {style::cosmeticPen(QColor(140, 60, 200), 1.0, Qt::DotLine), Qt::NoBrush};
    case OverlayKind::Path:
        return {style::cosmeticPen(QColor(210, 50, 30), 1.8), QColor(150, 20, 10)};
    case OverlayKind::Overlaps: // blue like the paper's figures, see-through over the path
        return {style::cosmeticPen(QColor(30, 90, 255, 140), 3.0), Qt::NoBrush};
    case OverlayKind::CoverageGaps:
        return {Qt::NoPen, QColor(230, 0, 200, 200)};
    case OverlayKind::Unreachable:
        break;
    }
    return {style::cosmeticPen(QColor(220, 30, 30), 2.5), Qt::NoBrush};
}

OverlayStyle transitStyle() {
    return {style::cosmeticPen(QColor(235, 140, 0), 1.8, Qt::DashLine), Qt::NoBrush};
}

bool isGraphOverlay(OverlayKind kind) {
    switch (kind) {
    case OverlayKind::Path:
    case OverlayKind::Overlaps:
    case OverlayKind::Unreachable:
    case OverlayKind::CoverageGaps:
        return false;
    default:
        return true;
    }
}

bool overlayVisibleByDefault(OverlayKind kind) {
    return kind != OverlayKind::CoverageEdges && kind != OverlayKind::ContourEdges &&
           kind != OverlayKind::InterEdges;
}

OverlayLayer::OverlayLayer(PlanScene* scene) : QObject(scene), scene_(scene) {
    for (int i = 0; i < kOverlayKindCount; ++i)
        visible_[i] = overlayVisibleByDefault(static_cast<OverlayKind>(i));
}

void OverlayLayer::setPlanningController(PlanningController* controller) {
    if (controller_)
        disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    if (controller_) {
        connect(controller_, &PlanningController::preparedChanged, this, &OverlayLayer::refresh);
        connect(controller_, &PlanningController::resultChanged, this, &OverlayLayer::refresh);
    }
    rebuild();
}

void OverlayLayer::setVisible(OverlayKind kind, bool visible) {
    visible_[static_cast<int>(kind)] = visible;
    if (QGraphicsItemGroup* group = groups_[static_cast<int>(kind)])
        group->setVisible(isShown(kind));
}

bool OverlayLayer::isShown(OverlayKind kind) const {
    return isVisible(kind) && (mode_ == ViewMode::Graph || !isGraphOverlay(kind));
}

void OverlayLayer::setViewMode(ViewMode mode) {
    const bool graphNeeded = mode == ViewMode::Graph && mode_ != ViewMode::Graph;
    mode_ = mode;
    if (graphNeeded)
        refresh(); // the cells and graph of what is shown, built now
    for (int i = 0; i < kOverlayKindCount; ++i)
        if (QGraphicsItemGroup* group = groups_[i])
            group->setVisible(isShown(static_cast<OverlayKind>(i)));
}

QList<QGraphicsItem*> OverlayLayer::labelItems() const {
    QList<QGraphicsItem*> labels;
    const QGraphicsItemGroup* cells = groups_[static_cast<int>(OverlayKind::PrimaryCells)];
    if (!cells || !isShown(OverlayKind::PrimaryCells))
        return labels;
    for (QGraphicsItem* item : cells->childItems())
        if (item->data(style::kLabelPriorityKey).isValid())
            labels.push_back(item);
    return labels;
}

int OverlayLayer::itemCount(OverlayKind kind) const {
    const QGraphicsItemGroup* group = groups_[static_cast<int>(kind)];
    return group ? static_cast<int>(group->childItems().size()) : 0;
}

QGraphicsItemGroup* OverlayLayer::freshGroup(OverlayKind kind, double zValue) {
    auto*& group = groups_[static_cast<int>(kind)];
    delete group;
    group = new QGraphicsItemGroup;
    group->setZValue(zValue);
    group->setVisible(isShown(kind));
    scene_->addItem(group);
    return group;
}

void OverlayLayer::rebuild() {
    cellsKey_ = QStringLiteral("(none)"); // no key matches it: everything is built again
    pathShown_.reset();
    refresh();
}

double OverlayLayer::opacity(OverlayKind kind) const {
    const QGraphicsItemGroup* group = groups_[static_cast<int>(kind)];
    return group ? group->opacity() : 1.0;
}

void OverlayLayer::refresh() {
    // Cells and graph are built again only when they are not what is shown: a new path of
    // the same floor (a changed query, the full plan after the draft) rebuilds only the
    // path's layers, so the canvas renders only those again (its items keep their pixels).
    // The Path view shows none of them: they are built when the Graph view is chosen
    // (setViewMode), which keeps every edit's new path from waiting on thousands of items.
    const QString key = controller_ ? controller_->cellsKey() : QString();
    const QString wanted = mode_ == ViewMode::Graph ? key : QStringLiteral("(not built)");
    const bool cellsChanged = wanted != cellsKey_;
    cellsKey_ = wanted;
    const bool buildGraph = cellsChanged && mode_ == ViewMode::Graph;
    const auto result = controller_ ? controller_->result() : nullptr;
    const auto stale = controller_ ? controller_->staleResult() : nullptr;
    // The path on screen just went stale: it fades where it is (its items keep their
    // rendering, so this costs no drawing) rather than being drawn again in grey.
    const bool fadeOnly = !result && stale && stale == pathShown_;
    for (int i = 0; i < kOverlayKindCount; ++i) {
        const auto kind = static_cast<OverlayKind>(i);
        const bool fresh =
            isPathLayer(kind) ? !fadeOnly : cellsChanged || kind == OverlayKind::Unreachable;
        if (fresh)
            freshGroup(kind, z::Overlays + 0.1 * i);
    }
    pathShown_ = result ? result : stale;
    if (!controller_)
        return;
    const auto prepared = controller_->shownPlan();
    if (result && !result->parts.empty()) {
        // Per-room sweeps: each part's own cells and graph, at its own angle.
        if (buildGraph)
            for (const PlanPart& part : result->parts) {
                addCells(part.prepared, &part.rooms);
                addGraph(part.prepared, &part.rooms);
            }
        addUnreachable(result->prepared);
    } else if (prepared) {
        if (buildGraph) {
            addCells(*prepared);
            addCriticalSlices(*prepared);
            addGraph(*prepared);
        }
        addUnreachable(*prepared);
    }
    if (result) {
        addPath(*result);
    } else if (fadeOnly) {
        // Its overlaps and gaps are of a floor or query that changed: hidden.
        groups_[static_cast<int>(OverlayKind::Path)]->setOpacity(0.3);
        groups_[static_cast<int>(OverlayKind::Overlaps)]->setOpacity(0.0);
        groups_[static_cast<int>(OverlayKind::CoverageGaps)]->setOpacity(0.0);
    } else if (stale) {
        addPath(*stale, true);
    }
}

bool OverlayLayer::isPathLayer(OverlayKind kind) {
    return kind == OverlayKind::Path || kind == OverlayKind::Overlaps ||
           kind == OverlayKind::CoverageGaps;
}

namespace {

bool inRooms(const Decomposition& dec, int room, const std::vector<std::string>* rooms) {
    return !rooms || std::find(rooms->begin(), rooms->end(), dec.roomNames[room]) != rooms->end();
}

} // namespace

void OverlayLayer::addCells(const PreparedPlan& prepared, const std::vector<std::string>* rooms) {
    const Decomposition& dec = prepared.decomposition;
    auto* primary = groups_[static_cast<int>(OverlayKind::PrimaryCells)];
    auto* transition = groups_[static_cast<int>(OverlayKind::TransitionCells)];
    const QColor text = style::palette().color(QPalette::Text);
    for (const Cell& cell : dec.cells) {
        if (!inRooms(dec, cell.room, rooms))
            continue;
        QPainterPath path;
        addRing(path, dec.frame.toWorld(cell.outline()));
        if (cell.kind == CellKind::Primary) {
            addPathItem(primary, path, style::cosmeticPen(style::roomHue(cell.room, 255), 1.0),
                        style::roomHue(cell.room, 90));
            const double mid = 0.5 * (cell.x0 + cell.x1);
            const Vec2 centre(mid, 0.5 * (cell.floorAt(mid) + cell.ceilingAt(mid)));
            style::addLabel(primary, QString::number(cell.id), toQt(dec.frame.toWorld(centre)),
                            text);
        } else {
            // Transition strips: hatched and outlined in grey, distinct from primary cells.
            const OverlayStyle look = overlayStyle(OverlayKind::TransitionCells);
            addPathItem(transition, path, look.pen, look.brush);
        }
    }
}

void OverlayLayer::addCriticalSlices(const PreparedPlan& prepared) {
    const Decomposition& dec = prepared.decomposition;
    QPainterPath path;
    for (const CriticalSlice& slice : dec.criticalSlices)
        addPolyline(path, dec.frame.toWorld(Polyline{{slice.x, slice.y0}, {slice.x, slice.y1}}));
    addPathItem(groups_[static_cast<int>(OverlayKind::CriticalSlices)], path,
                overlayStyle(OverlayKind::CriticalSlices).pen);
}

void OverlayLayer::addGraph(const PreparedPlan& prepared, const std::vector<std::string>* rooms) {
    const Decomposition& dec = prepared.decomposition;
    const Frame& frame = dec.frame;
    const CornerGraph& graph = prepared.graph;
    auto nodeShown = [&](int node) {
        return inRooms(dec, graph.cells[graph.nodes[node].cell].room, rooms);
    };
    QPainterPath coverage, contour, inter, nodes;
    for (const GraphEdge& edge : graph.edges) {
        if (!nodeShown(edge.u) && !nodeShown(edge.v))
            continue;
        switch (edge.kind) {
        case EdgeKind::Coverage: // the pair's corners, not the whole stripe pattern
            addPolyline(coverage, frame.toWorld(Polyline{graph.nodes[edge.u].position,
                                                         graph.nodes[edge.v].position}));
            break;
        case EdgeKind::Contour:
            addPolyline(contour, frame.toWorld(edge.geometry));
            break;
        case EdgeKind::Inter:
            addPolyline(inter, frame.toWorld(edge.geometry));
            break;
        }
    }
    const double radius = 0.08 * prepared.robot.coverageWidth;
    for (const GraphNode& node : graph.nodes)
        if (nodeShown(node.id))
            nodes.addEllipse(toQt(frame.toWorld(node.position)), radius, radius);
    addPathItem(groups_[static_cast<int>(OverlayKind::CoverageEdges)], coverage,
                overlayStyle(OverlayKind::CoverageEdges).pen);
    addPathItem(groups_[static_cast<int>(OverlayKind::ContourEdges)], contour,
                overlayStyle(OverlayKind::ContourEdges).pen);
    addPathItem(groups_[static_cast<int>(OverlayKind::InterEdges)], inter,
                overlayStyle(OverlayKind::InterEdges).pen);
    addPathItem(groups_[static_cast<int>(OverlayKind::CornerNodes)], nodes,
                overlayStyle(OverlayKind::CornerNodes).pen,
                overlayStyle(OverlayKind::CornerNodes).brush);
}

void OverlayLayer::addUnreachable(const PreparedPlan& prepared) {
    auto* group = groups_[static_cast<int>(OverlayKind::Unreachable)];
    const double size = 0.3 * prepared.robot.coverageWidth;
    for (const UnreachableArea& area : prepared.decomposition.unreachable) {
        QPainterPath cross;
        const QPointF c = toQt(area.location);
        cross.moveTo(c + QPointF(-size, -size));
        cross.lineTo(c + QPointF(size, size));
        cross.moveTo(c + QPointF(-size, size));
        cross.lineTo(c + QPointF(size, -size));
        auto* item = addPathItem(group, cross, overlayStyle(OverlayKind::Unreachable).pen);
        item->setToolTip(
            tr("Unreachable: %1 (%2 m²)").arg(fromStd(area.reason)).arg(area.area, 0, 'f', 2));
    }
}

void OverlayLayer::addPath(const PlanResult& result, bool stale) {
    const CoveragePath& path = result.path;
    if (path.empty())
        return;
    auto* group = groups_[static_cast<int>(OverlayKind::Path)];
    QPainterPath sweeping, travelling, arrows;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) {
        QPainterPath& target = path.kinds[i] == SegmentKind::Transit ? travelling : sweeping;
        target.moveTo(toQt(path.points[i]));
        target.lineTo(toQt(path.points[i + 1]));
    }
    // Direction hints, sparse enough not to clutter the stripes: one arrow every ~16 W of
    // path, on a segment long enough to carry it.
    const double width = result.prepared.robot.coverageWidth;
    double sinceArrow = 8.0 * width;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) {
        const Vec2 a = path.points[i], b = path.points[i + 1];
        sinceArrow += distance(a, b);
        if (sinceArrow >= 16.0 * width && distance(a, b) >= 1.5 * width) {
            addArrowHead(arrows, (a + b) * 0.5 + (b - a) * (0.15 * width / distance(a, b)), b - a,
                         0.3 * width);
            sinceArrow = 0;
        }
    }
    // The path before the last edits: grey, under the new overlays, until a newer one comes.
    const QColor staleColour(150, 150, 150, 160);
    QPen pathPen = overlayStyle(OverlayKind::Path).pen;
    if (stale)
        pathPen.setColor(staleColour);
    addPathItem(group, sweeping, pathPen);
    QPen transitPen = transitStyle().pen; // travel between cells: dashed, its own colour
    if (stale)
        transitPen.setColor(staleColour);
    addPathItem(group, travelling, transitPen);
    addPathItem(group, arrows, Qt::NoPen,
                stale ? QBrush(staleColour) : overlayStyle(OverlayKind::Path).brush);
    if (stale)
        return; // its overlaps and gaps are of a floor or query that changed

    QPainterPath overlaps;
    for (const Segment& s : result.metrics.overlaps) {
        overlaps.moveTo(toQt(s.a));
        overlaps.lineTo(toQt(s.b));
    }
    addPathItem(groups_[static_cast<int>(OverlayKind::Overlaps)], overlaps,
                overlayStyle(OverlayKind::Overlaps).pen);

    // Missed spots as small squares: the metric's raster samples, at most ~20,000 of them
    // (as circles Qt traces a curve per dot: 15 ms more for the first paint on office).
    QPainterPath gaps;
    const double dot = 0.06 * width;
    for (Vec2 p : result.metrics.uncovered)
        gaps.addRect(QRectF(toQt(p) - QPointF(dot, dot), QSizeF(2 * dot, 2 * dot)));
    const OverlayStyle gapLook = overlayStyle(OverlayKind::CoverageGaps);
    addPathItem(groups_[static_cast<int>(OverlayKind::CoverageGaps)], gaps, gapLook.pen,
                gapLook.brush);
    // Floor no robot position can sweep (too narrow for the disc, corners beyond the head):
    // dots in the unreachable colour beside the decomposition's crosses.
    QPainterPath unreachable;
    for (Vec2 p : result.metrics.unreachable)
        unreachable.addRect(QRectF(toQt(p) - QPointF(dot, dot), QSizeF(2 * dot, 2 * dot)));
    addPathItem(groups_[static_cast<int>(OverlayKind::Unreachable)], unreachable, Qt::NoPen,
                overlayStyle(OverlayKind::Unreachable).pen.color());
}

} // namespace fc::ui
