// Conversions between the planner's plain values and Qt's geometry types. Scene
// coordinates are plan metres (world frame); the view flips y so that +y points up.
#pragma once

#include "geometry/Geometry.h"

#include <QPainterPath>
#include <QPointF>
#include <QPolygonF>
#include <QString>

namespace fc::ui {

inline QPointF toQt(Vec2 p) {
    return {p.x, p.y};
}

inline Vec2 toVec2(QPointF p) {
    return {p.x(), p.y()};
}

inline QPolygonF toPolygon(const std::vector<Vec2>& points) {
    QPolygonF polygon;
    polygon.reserve(static_cast<int>(points.size()));
    for (Vec2 p : points)
        polygon << toQt(p);
    return polygon;
}

inline Ring toRing(const QPolygonF& polygon) {
    Ring ring;
    ring.reserve(polygon.size());
    for (QPointF p : polygon)
        ring.push_back(toVec2(p));
    return ring;
}

// A closed ring as a painter path subpath.
inline void addRing(QPainterPath& path, const Ring& ring) {
    if (ring.empty())
        return;
    path.addPolygon(toPolygon(ring));
    path.closeSubpath();
}

inline void addPolyline(QPainterPath& path, const Polyline& line) {
    if (line.empty())
        return;
    path.moveTo(toQt(line.front()));
    for (size_t i = 1; i < line.size(); ++i)
        path.lineTo(toQt(line[i]));
}

inline QString fromStd(const std::string& text) {
    return QString::fromStdString(text);
}

} // namespace fc::ui
