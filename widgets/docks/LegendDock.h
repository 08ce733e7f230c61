// The overlay legend: one row per overlay kind with its swatch and a check box that shows
// or hides it, in step with the View > Overlays actions.
#pragma once

#include "canvas/OverlayLayer.h"

#include <QDockWidget>
#include <array>

class QAction;
class QCheckBox;

namespace fc::ui {

class LegendDock : public QDockWidget {
    Q_OBJECT
public:
    // actions: the View menu's checkable overlay actions, indexed by OverlayKind.
    LegendDock(const std::array<QAction*, kOverlayKindCount>& actions, QWidget* parent = nullptr);

    QCheckBox* checkBox(OverlayKind kind) const { return boxes_[static_cast<int>(kind)]; }

private:
    std::array<QCheckBox*, kOverlayKindCount> boxes_{};
};

} // namespace fc::ui
