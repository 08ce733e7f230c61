#include "canvas/PlanScene.h"

#include "canvas/LabelPlacement.h"
#include "canvas/OverlayLayer.h"
#include "canvas/SceneStyle.h"
#include "document/Conversions.h"
#include "tasks/PlanningController.h"

#include <QBrush>
#include <QGraphicsEllipseItem>
#include <QGraphicsItemGroup>
#include <QGraphicsPathItem>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsView>
#include <QPainter>
#include <QPen>

namespace fc::ui {

PlanScene::PlanScene(QObject* parent) : QGraphicsScene(parent), overlays_(new OverlayLayer(this)) {
    setItemIndexMethod(QGraphicsScene::NoIndex); // items are rebuilt often, rarely queried
}

PlanScene::~PlanScene() = default;

void PlanScene::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    highlight_.reset();
    if (document_) {
        connect(document_, &Document::geometryChanged, this, &PlanScene::rebuildPolygons);
        connect(document_, &Document::roomsChanged, this, &PlanScene::rebuildPolygons);
        connect(document_, &Document::endpointsChanged, this, &PlanScene::rebuildMarkers);
    }
    rebuildPolygons();
    rebuildMarkers();
}

void PlanScene::setPlanningController(PlanningController* controller) {
    if (controller_)
        disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    overlays_->setPlanningController(controller);
    // The markers show the corner the planner snaps them to, which needs the graph.
    connect(controller, &PlanningController::preparedChanged, this, &PlanScene::rebuildMarkers);
    connect(controller, &PlanningController::resultChanged, this, &PlanScene::rebuildMarkers);
}

void PlanScene::setViewMode(ViewMode mode) {
    overlays_->setViewMode(mode);
    rebuildMarkers();
}

ViewMode PlanScene::viewMode() const {
    return overlays_->viewMode();
}

void PlanScene::layoutLabels() {
    const QList<QGraphicsView*> shown = views();
    if (!shown.isEmpty())
        layoutLabels(shown.first()->transform());
}

void PlanScene::layoutLabels(const QTransform& viewTransform) {
    QList<QGraphicsItem*> items;
    for (QGraphicsItemGroup* group : {markers_, roomLabels_})
        if (group)
            items += group->childItems();
    items += overlays_->labelItems();
    std::vector<LabelRequest> requests;
    std::vector<QGraphicsItem*> labels;
    for (QGraphicsItem* item : items) {
        const bool fixed = item->data(style::kFixedLabelKey).toBool();
        const QVariant priority = item->data(style::kLabelPriorityKey);
        if (!fixed && !priority.isValid())
            continue;
        const QPointF anchor = viewTransform.map(item->pos());
        LabelRequest request;
        request.fixed = fixed;
        request.priority = priority.toDouble();
        if (fixed) { // a marker: on its point, else beside it
            const QRectF here = item->boundingRect().translated(anchor);
            request.candidates = {here};
            for (QPointF step : {QPointF(1, 0), QPointF(0, -1), QPointF(-1, 0), QPointF(0, 1)})
                request.candidates.push_back(
                    here.translated(step.x() * here.width(), step.y() * here.height()));
        } else {
            request.candidates = labelCandidates(anchor, item->boundingRect().size());
        }
        requests.push_back(std::move(request));
        labels.push_back(item);
    }
    const std::vector<int> chosen = placeLabels(requests);
    for (size_t i = 0; i < labels.size(); ++i) {
        labels[i]->setVisible(chosen[i] >= 0);
        if (chosen[i] < 0)
            continue;
        // The label's own transform is in screen pixels (it ignores the view's scale).
        const QPointF offset = requests[i].candidates[chosen[i]].topLeft() -
                               viewTransform.map(labels[i]->pos()) -
                               labels[i]->boundingRect().topLeft();
        labels[i]->setTransform(QTransform::fromTranslate(offset.x(), offset.y()));
    }
}

QImage PlanScene::renderPathView(QSize size, double pixelRatio) {
    QImage image(size * pixelRatio, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(pixelRatio);
    image.fill(Qt::white);
    if (!document_ || document_->plan().boundary.empty())
        return image;
    const ViewMode mode = viewMode();
    if (mode != ViewMode::Path)
        setViewMode(ViewMode::Path);
    const BoundingBox box = document_->plan().bounds();
    const double margin = 0.03 * std::max(box.width(), box.height());
    const QRectF plan(QPointF(box.minX - margin, box.minY - margin),
                      QPointF(box.maxX + margin, box.maxY + margin));
    const double scale = std::min(size.width() / plan.width(), size.height() / plan.height());
    const double x0 = 0.5 * (size.width() - scale * plan.width());
    const double y0 = 0.5 * (size.height() - scale * plan.height());
    // Scene (y up) to image (y down), the plan centred.
    const QTransform toImage(scale, 0, 0, -scale, x0 - scale * plan.left(),
                             y0 + scale * plan.bottom());
    layoutLabels(toImage);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.setTransform(toImage);
    render(&painter, plan, plan);
    painter.end();
    if (mode != ViewMode::Path)
        setViewMode(mode);
    layoutLabels(); // back to the view's zoom
    return image;
}

void PlanScene::restyle() {
    rebuildPolygons();
    rebuildMarkers();
    overlays_->rebuild();
}

void PlanScene::updateSceneRect() {
    // Generous margins so that the view can pan well beyond the plan.
    QRectF bounds(-10, -10, 40, 30);
    if (document_ && !document_->plan().boundary.empty()) {
        const BoundingBox box = document_->plan().bounds();
        bounds = QRectF(QPointF(box.minX, box.minY), QPointF(box.maxX, box.maxY));
    }
    const double margin = std::max(50.0, 2.0 * std::max(bounds.width(), bounds.height()));
    setSceneRect(bounds.adjusted(-margin, -margin, margin, margin));
}

void PlanScene::rebuildPolygons() {
    delete polygons_;
    delete roomLabels_;
    // Room names above walls, obstacles and the path (on their plates), below the markers.
    roomLabels_ = new QGraphicsItemGroup;
    roomLabels_->setZValue(z::Markers - 0.5);
    addItem(roomLabels_);
    highlightItem_ = nullptr;
    polygons_ = new QGraphicsItemGroup;
    addItem(polygons_);
    updateSceneRect();
    if (!document_)
        return;
    const Plan& plan = document_->plan();
    const QPalette palette = style::palette();

    for (const Room& room : plan.rooms) {
        const QString name = fromStd(room.name);
        const bool selected = document_->isRoomSelected(name);
        QPainterPath path;
        addRing(path, room.outline);
        auto* item = new QGraphicsPathItem(path, polygons_);
        item->setCacheMode(QGraphicsItem::DeviceCoordinateCache); // redrawn only when edited
        item->setPen(style::cosmeticPen(style::roomOutline(palette), 1.0, Qt::DashLine));
        item->setBrush(selected ? QBrush(style::roomFill(palette, true))
                                : QBrush(style::roomFill(palette, false), Qt::BDiagPattern));
        item->setZValue(z::Rooms);
        item->setToolTip(selected ? tr("%1 (planned)").arg(name)
                                  : tr("%1 (not planned)").arg(name));
        // Room names before cell ids, bigger rooms first when names compete for space.
        style::addLabel(roomLabels_, name, toQt(interiorLabelPoint(room.outline, plan.obstacles)),
                        style::roomOutline(palette), true,
                        1e6 + std::abs(signedArea(room.outline)));
    }
    if (!plan.boundary.empty()) {
        QPainterPath walls;
        addRing(walls, plan.boundary);
        auto* boundary = new QGraphicsPathItem(walls, polygons_);
        boundary->setCacheMode(QGraphicsItem::DeviceCoordinateCache);
        boundary->setPen(style::cosmeticPen(palette.color(QPalette::Text), 2.0));
        boundary->setZValue(z::Walls);
    }
    for (const Ring& obstacle : plan.obstacles) {
        QPainterPath path;
        addRing(path, obstacle);
        auto* item = new QGraphicsPathItem(path, polygons_);
        item->setCacheMode(QGraphicsItem::DeviceCoordinateCache);
        item->setPen(style::cosmeticPen(palette.color(QPalette::Text), 1.5));
        item->setBrush(style::obstacleFill(palette));
        item->setZValue(z::Walls);
    }
    setHighlight(highlight_);
    rebuildProblems();
    layoutLabels();
}

void PlanScene::setProblemFocus(std::optional<QPointF> point) {
    problemFocus_ = point;
    rebuildProblems();
}

void PlanScene::rebuildProblems() {
    delete problems_;
    problems_ = new QGraphicsItemGroup;
    problems_->setZValue(z::Markers - 1);
    addItem(problems_);
    if (!document_ || !document_->needsRepair())
        return;
    for (const PlanProblem& problem : document_->problems()) {
        if (!problem.hasLocation)
            continue;
        const QPointF at = toQt(problem.location);
        const bool focused = problemFocus_ && QLineF(*problemFocus_, at).length() < 1e-9;
        const double radius = focused ? 16.0 : 10.0; // pixels
        auto* ring = new QGraphicsEllipseItem(-radius, -radius, 2 * radius, 2 * radius, problems_);
        ring->setPen(QPen(QColor(220, 20, 20), focused ? 4.0 : 2.5));
        ring->setBrush(QColor(220, 20, 20, 40));
        ring->setPos(at);
        ring->setFlag(QGraphicsItem::ItemIgnoresTransformations);
        ring->setToolTip(fromStd(problem.message));
    }
}

void PlanScene::rebuildMarkers() {
    delete markers_;
    markers_ = new QGraphicsItemGroup;
    markers_->setZValue(z::Markers);
    addItem(markers_);
    if (!document_)
        return;
    const Project& project = document_->project();
    const auto prepared = controller_ ? controller_->shownPlan() : nullptr;
    // The corner a marker snaps to is graph detail: the Graph view only.
    const auto showSnap = [&](Vec2 point) {
        if (!prepared || prepared->graph.nodes.empty() || viewMode() != ViewMode::Graph)
            return;
        const Frame& frame = prepared->decomposition.frame;
        const int node = nearestNode(prepared->graph, frame.toLocal(point));
        const QPointF corner = toQt(frame.toWorld(prepared->graph.nodes[node].position));
        QPainterPath link;
        link.moveTo(toQt(point));
        link.lineTo(corner);
        const double r = 0.12 * prepared->robot.coverageWidth;
        link.addEllipse(corner, r, r);
        auto* item = new QGraphicsPathItem(link, markers_);
        item->setPen(style::cosmeticPen(QColor(90, 90, 90), 1.5, Qt::DashLine));
        item->setToolTip(tr("The corner the planner starts or ends at"));
    };
    if (project.hasStart)
        showSnap(project.start);
    if (project.hasEnd)
        showSnap(project.end);
    if (project.hasStart)
        style::addMarker(markers_, toQt(project.start), tr("S"), QColor(0, 150, 60), tr("Start"));
    if (project.hasEnd)
        style::addMarker(markers_, toQt(project.end), tr("E"), QColor(200, 40, 40), tr("End"));
    // Without a start or end of the user's, the path's own ends are marked: where the
    // planner chose to start (where the robot reaches the most floor) and where it stops.
    auto result = controller_ ? controller_->result() : nullptr;
    if (!result && controller_)
        result = controller_->staleResult();
    if (result && !result->path.empty()) {
        if (!project.hasStart)
            style::addMarker(markers_, toQt(result->path.points.front()), tr("S"),
                             QColor(0, 150, 60), tr("Start, chosen by the planner"));
        if (!project.hasEnd)
            style::addMarker(markers_, toQt(result->path.points.back()), tr("E"),
                             QColor(200, 40, 40), tr("End of the path"));
    }
    layoutLabels();
}

void PlanScene::setHighlight(std::optional<PolygonRef> polygon) {
    delete highlightItem_;
    highlightItem_ = nullptr;
    highlight_ = polygon;
    if (!polygon || !document_ || polygon->index >= document_->polygonCount(polygon->role))
        return;
    QPainterPath path;
    addRing(path, document_->ring(*polygon));
    auto* item = new QGraphicsPathItem(path, polygons_);
    item->setPen(style::cosmeticPen(style::palette().color(QPalette::Highlight), 3.0));
    item->setZValue(z::Tool - 1);
    highlightItem_ = item;
}

std::optional<PolygonRef> PlanScene::polygonAt(QPointF point, double tolerance) const {
    if (!document_)
        return std::nullopt;
    const Vec2 p = toVec2(point);
    std::vector<PolygonRef> candidates;
    for (int i = document_->polygonCount(PolygonRole::Obstacle) - 1; i >= 0; --i)
        candidates.push_back({PolygonRole::Obstacle, i});
    for (int i = document_->polygonCount(PolygonRole::Room) - 1; i >= 0; --i)
        candidates.push_back({PolygonRole::Room, i});
    if (document_->polygonCount(PolygonRole::Boundary) > 0)
        candidates.push_back({PolygonRole::Boundary, 0});
    const auto nearOutline = [&](const Ring& ring) {
        for (size_t i = 0; i < ring.size(); ++i)
            if (pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]) <= tolerance)
                return true;
        return false;
    };
    for (const PolygonRef& ref : candidates)
        if (nearOutline(document_->ring(ref)))
            return ref;
    for (const PolygonRef& ref : candidates)
        if (pointInRing(document_->ring(ref), p))
            return ref;
    return std::nullopt;
}

} // namespace fc::ui
