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
            painter.drawEllipse(QPointF(x, 8), 2, 2);
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
        QAction* action = actions[i];
        box->setChecked(action->isChecked());
        connect(box, &QCheckBox::toggled, action, &QAction::setChecked);
        connect(action, &QAction::toggled, box, &QCheckBox::setChecked);
        grid->addWidget(picture, i, 0);
        grid->addWidget(box, i, 1);
        boxes_[i] = box;
    }
    grid->setRowStretch(kOverlayKindCount, 1);
    setWidget(content);
}

} // namespace fc::ui
