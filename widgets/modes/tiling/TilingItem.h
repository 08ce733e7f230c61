// The tiling robot's result on the canvas: every tile filled in its shape's colour, the
// cells left untiled or unreachable in red, and the ordered tour through the waypoints.
// One item paints everything: a floor holds thousands of tiles, too many for an item each.
#pragma once

#include "tiling/TilingPlanner.h"

#include <QColor>
#include <QGraphicsItem>
#include <QPainterPath>
#include <array>
#include <memory>

namespace fc::ui {

// The fill colour of a shape (also the dock's legend).
QColor tileShapeColor(tiling::Shape shape);

class TilingItem : public QGraphicsItem {
public:
    TilingItem();

    void setPlan(std::shared_ptr<const tiling::TilingPlan> plan);
    bool hasPlan() const { return plan_ != nullptr; }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    std::shared_ptr<const tiling::TilingPlan> plan_;
    std::array<QPainterPath, tiling::kShapeCount> tiles_; // per shape
    QPainterPath leftOver_;                               // untiled and unreachable cells
    QPolygonF tour_;
    QRectF bounds_;
};

} // namespace fc::ui
