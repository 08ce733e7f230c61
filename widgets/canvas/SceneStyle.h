// Colours, pens and small item factories shared by the scene layers, derived from the
// application palette so that dark and light themes both stay readable.
#pragma once

#include "geometry/Geometry.h"

#include <QColor>
#include <QPalette>
#include <QPen>
#include <QString>

class QGraphicsItem;

namespace fc::ui::style {

QPalette palette();
bool isDark(const QPalette& palette);
// A pen whose width is in screen pixels whatever the zoom.
QPen cosmeticPen(const QColor& color, double width, Qt::PenStyle penStyle = Qt::SolidLine);
QColor roomOutline(const QPalette& palette);
QColor roomFill(const QPalette& palette, bool selected);
QColor obstacleFill(const QPalette& palette);
// A distinct, stable colour per room index for the cell overlay.
QColor roomHue(int room, int alpha);

// Item data keys of the labels and markers that PlanScene::layoutLabels places.
constexpr int kLabelPriorityKey = 1; // double: higher is placed first
constexpr int kFixedLabelKey = 2;    // bool: markers, never moved or hidden

// A text label of constant screen size centred on `position`, on a see-through plate of
// the base colour so that it stays readable over the path; `priority` orders the label
// placement (room names before cell ids).
QGraphicsItem* addLabel(QGraphicsItem* parent, const QString& text, QPointF position,
                        const QColor& color, bool bold = false, double priority = 0);
// A round marker of constant screen size with a letter (start and end points).
QGraphicsItem* addMarker(QGraphicsItem* parent, QPointF position, const QString& letter,
                         const QColor& color, const QString& toolTip);

} // namespace fc::ui::style
