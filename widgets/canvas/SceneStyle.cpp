#include "canvas/SceneStyle.h"

#include <QBrush>
#include <QFont>
#include <QGraphicsEllipseItem>
#include <QGraphicsSimpleTextItem>
#include <QGuiApplication>
#include <QPainter>

namespace fc::ui::style {

QPalette palette() {
    return QGuiApplication::palette();
}

bool isDark(const QPalette& palette) {
    return palette.color(QPalette::Base).lightnessF() < 0.5;
}

QPen cosmeticPen(const QColor& color, double width, Qt::PenStyle penStyle) {
    QPen pen(color, width, penStyle);
    pen.setCosmetic(true);
    // Wider than a pixel, Qt strokes the outline of the line; round joins and caps make it
    // trace a curve at every vertex (a path's first paint took 21 ms on the office, 1.5 ms
    // with mitred joins and square caps). One-pixel lines take Qt's fast path either way.
    const bool wide = width > 1.0;
    pen.setJoinStyle(wide ? Qt::MiterJoin : Qt::RoundJoin);
    pen.setCapStyle(wide ? Qt::SquareCap : Qt::RoundCap);
    return pen;
}

QColor roomOutline(const QPalette& palette) {
    return isDark(palette) ? QColor(150, 190, 255) : QColor(40, 80, 160);
}

QColor roomFill(const QPalette& palette, bool selected) {
    if (!selected)
        return isDark(palette) ? QColor(120, 120, 120, 90) : QColor(120, 120, 120, 70);
    return isDark(palette) ? QColor(70, 110, 170, 60) : QColor(120, 160, 230, 45);
}

QColor obstacleFill(const QPalette& palette) {
    return isDark(palette) ? QColor(90, 90, 90) : QColor(170, 170, 170);
}

QColor roomHue(int room, int alpha) {
    // Golden-angle steps give neighbouring indices clearly different hues.
    const int hue = (room * 137) % 360;
    return QColor::fromHsv(hue, 110, 235, alpha);
}

namespace {

// Text on a rounded plate: names stay legible where they cross the path or a hatch.
class PlateTextItem : public QGraphicsSimpleTextItem {
public:
    PlateTextItem(const QString& text, QGraphicsItem* parent)
        : QGraphicsSimpleTextItem(text, parent) {}
    QRectF boundingRect() const override {
        return QGraphicsSimpleTextItem::boundingRect().adjusted(-2, 0, 2, 0);
    }
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option,
               QWidget* widget) override {
        QColor plate = style::palette().color(QPalette::Base);
        plate.setAlpha(190);
        painter->setPen(Qt::NoPen);
        painter->setBrush(plate);
        painter->drawRoundedRect(boundingRect(), 3, 3);
        QGraphicsSimpleTextItem::paint(painter, option, widget);
    }
};

} // namespace

QGraphicsItem* addLabel(QGraphicsItem* parent, const QString& text, QPointF position,
                        const QColor& color, bool bold, double priority) {
    auto* label = new PlateTextItem(text, parent);
    label->setData(kLabelPriorityKey, priority);
    QFont font = label->font();
    font.setPointSizeF(bold ? 9.0 : 7.5);
    font.setBold(bold);
    label->setFont(font);
    label->setBrush(color);
    // Constant screen size and upright although the view flips y.
    label->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    const QRectF box = label->boundingRect();
    label->setPos(position);
    label->setTransform(QTransform::fromTranslate(-box.width() / 2, -box.height() / 2));
    return label;
}

QGraphicsItem* addMarker(QGraphicsItem* parent, QPointF position, const QString& letter,
                         const QColor& color, const QString& toolTip) {
    constexpr double radius = 9.0; // pixels
    auto* disc = new QGraphicsEllipseItem(-radius, -radius, 2 * radius, 2 * radius, parent);
    disc->setPen(QPen(Qt::white, 2));
    disc->setBrush(color);
    disc->setPos(position);
    disc->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    disc->setToolTip(toolTip);
    disc->setData(kFixedLabelKey, true);
    auto* text = new QGraphicsSimpleTextItem(letter, disc);
    QFont font = text->font();
    font.setBold(true);
    text->setFont(font);
    text->setBrush(Qt::white);
    const QRectF box = text->boundingRect();
    text->setPos(-box.width() / 2, -box.height() / 2);
    return disc;
}

} // namespace fc::ui::style
