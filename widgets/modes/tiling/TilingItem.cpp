#include "modes/tiling/TilingItem.h"

#include "document/Conversions.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

namespace fc::ui {

QColor tileShapeColor(tiling::Shape shape) {
    switch (shape) {
    case tiling::Shape::Rectangle:
        return QColor(0x4e, 0x79, 0xa7);
    case tiling::Shape::Triangle:
        return QColor(0xf2, 0x8e, 0x2b);
    case tiling::Shape::Parallelogram:
        return QColor(0x59, 0xa1, 0x4f);
    case tiling::Shape::Curve:
        return QColor(0xb0, 0x7a, 0xa1);
    case tiling::Shape::Square:
        return QColor(0xed, 0xc9, 0x48);
    }
    return Qt::gray;
}

TilingItem::TilingItem() {
    setZValue(40); // above the plan's fills and the cell overlays, below markers
}

void TilingItem::setPlan(std::shared_ptr<const tiling::TilingPlan> plan) {
    prepareGeometryChange();
    plan_ = std::move(plan);
    tiles_ = {};
    leftOver_ = QPainterPath();
    tour_.clear();
    bounds_ = QRectF();
    if (!plan_)
        return;
    const tiling::TriangleGrid& grid = plan_->grid;
    auto addCell = [&grid](QPainterPath& path, int cell) {
        const auto v = grid.vertices(cell);
        path.addPolygon(QPolygonF({toQt(v[0]), toQt(v[1]), toQt(v[2]), toQt(v[0])}));
    };
    for (const tiling::Tile& tile : plan_->tiling.tiles) {
        QPainterPath blocks; // the tile's outline, not its four triangles'
        for (int cell : tile.cells)
            addCell(blocks, cell);
        tiles_[static_cast<int>(tile.shape)].addPath(blocks.simplified());
    }
    for (int cell : plan_->tiling.untiled)
        addCell(leftOver_, cell);
    for (int cell : plan_->tiling.unreachable)
        addCell(leftOver_, cell);
    for (int index : plan_->tour)
        tour_ << toQt(plan_->problem.poses[index].waypoint());
    if (!tour_.isEmpty())
        tour_ << tour_.front(); // the tour is closed (the paper's Eq. 5)
    for (const QPainterPath& path : tiles_)
        bounds_ |= path.boundingRect();
    bounds_ |= leftOver_.boundingRect() | tour_.boundingRect();
}

QRectF TilingItem::boundingRect() const {
    return bounds_.adjusted(-0.1, -0.1, 0.1, 0.1);
}

void TilingItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*) {
    if (!plan_)
        return;
    painter->setClipRect(option->exposedRect);
    QPen outline(QColor(255, 255, 255, 160), 0); // cosmetic: one pixel at any zoom
    painter->setPen(outline);
    for (int s = 0; s < tiling::kShapeCount; ++s) {
        QColor fill = tileShapeColor(static_cast<tiling::Shape>(s));
        fill.setAlpha(210); // hides the cell overlays underneath
        painter->setBrush(fill);
        painter->drawPath(tiles_[s]);
    }
    painter->setBrush(QColor(220, 30, 30, 200));
    painter->drawPath(leftOver_);
    QPen tour(QColor(30, 30, 30, 200), 0);
    painter->setPen(tour);
    painter->setBrush(Qt::NoBrush);
    painter->drawPolyline(tour_);
    if (!tour_.isEmpty()) {
        painter->setPen(QPen(Qt::darkGreen, 0));
        painter->setBrush(Qt::green);
        const double r = plan_->grid.leg() * 0.6;
        painter->drawEllipse(tour_.front(), r, r);
    }
}

} // namespace fc::ui
