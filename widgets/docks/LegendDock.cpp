#include "docks/LegendDock.h"

#include <QAction>
#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>

namespace fc::ui {

namespace {

// A small picture of the overlay: a filled box for areas, a line for edges and the path.
QPixmap swatch(OverlayKind kind) {
    const OverlayStyle look = overlayStyle(kind);
    QPixmap pixmap(28, 16);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(look.pen);
    painter.setBrush(look.brush);
    switch (kind) {
    case OverlayKind::PrimaryCells:
    case OverlayKind::TransitionCells:
        painter.drawRect(QRectF(2, 2, 24, 12));
        break;
    case OverlayKind::CornerNodes:
        painter.drawEllipse(QPointF(14, 8), 4, 4);
        break;
    case OverlayKind::CoverageGaps:
        for (double x : {8.0, 14.0, 20.0})
            painter.drawRect(QRectF(x - 2, 6, 4, 4)); // as the canvas draws them
        break;
    case OverlayKind::Unreachable:
        painter.drawLine(QPointF(9, 3), QPointF(19, 13));
        painter.drawLine(QPointF(9, 13), QPointF(19, 3));
        break;
    default:
        painter.drawLine(QPointF(2, 8), QPointF(26, 8));
        break;
    }
    return pixmap;
}

QPixmap lineSwatch(const QPen& pen) {
    QPixmap pixmap(28, 16);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(pen);
    painter.drawLine(QPointF(2, 8), QPointF(26, 8));
    return pixmap;
}

// The start and end markers as the canvas draws them.
QPixmap markerSwatch(const QColor& colour, const QString& letter) {
    QPixmap pixmap(28, 20);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(Qt::white, 2));
    painter.setBrush(colour);
    painter.drawEllipse(QPointF(14, 10), 8, 8);
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    painter.setPen(Qt::white);
    painter.drawText(QRectF(6, 2, 16, 16), Qt::AlignCenter, letter);
    return pixmap;
}

} // namespace

LegendDock::LegendDock(const std::array<QAction*, kOverlayKindCount>& actions, QWidget* parent)
    : QDockWidget(tr("Legend"), parent) {
    setObjectName(QStringLiteral("LegendDock"));
    auto* content = new QWidget;
    auto* grid = new QGridLayout(content);
    for (int i = 0; i < kOverlayKindCount; ++i) {
        const auto kind = static_cast<OverlayKind>(i);
        auto* picture = new QLabel;
        picture->setPixmap(swatch(kind));
        auto* box = new QCheckBox(overlayName(kind));
        box->setToolTip(overlayDescription(kind));
        QAction* action = actions[i];
        box->setChecked(action->isChecked());
        connect(box, &QCheckBox::toggled, action, &QAction::setChecked);
        connect(action, &QAction::toggled, box, &QCheckBox::setChecked);
        grid->addWidget(picture, i, 0);
        grid->addWidget(box, i, 1);
        boxes_[i] = box;
        swatches_[i] = picture;
    }
    int row = kOverlayKindCount;
    const auto addRow = [&](const QPixmap& pixmap, const QString& text, const QString& tip) {
        auto* picture = new QLabel;
        picture->setPixmap(pixmap);
        auto* label = new QLabel(text);
        label->setToolTip(tip);
        grid->addWidget(picture, row, 0);
        grid->addWidget(label, row, 1);
        ++row;
    };
    addRow(lineSwatch(transitStyle().pen), tr("Transit"),
           tr("Moves between cells and rooms without cleaning (part of the Path)"));
    addRow(markerSwatch(QColor(0, 150, 60), tr("S")), tr("Start"),
           tr("Where the robot starts: yours, or the planner's choice when none is placed"));
    addRow(markerSwatch(QColor(200, 40, 40), tr("E")), tr("End"), tr("Where the path ends"));
    grid->setRowStretch(row, 1);
    setWidget(content);
}

} // namespace fc::ui

namespace fc::ui {

void LegendDock::setViewMode(ViewMode mode) {
    for (int i = 0; i < kOverlayKindCount; ++i) {
        const bool shown = mode == ViewMode::Graph || !isGraphOverlay(static_cast<OverlayKind>(i));
        boxes_[i]->setVisible(shown);
        swatches_[i]->setVisible(shown);
    }
}

} // namespace fc::ui
