// The overlay legend: one row per overlay kind with its swatch and a check box that shows
// or hides it, in step with the View > Overlays actions, then rows without a box for the
// transit moves and the start and end markers.
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
    // The Path view lists only what it draws; the Graph view lists every overlay.
    void setViewMode(ViewMode mode);

private:
    std::array<QCheckBox*, kOverlayKindCount> boxes_{};
    std::array<QWidget*, kOverlayKindCount> swatches_{};
};

} // namespace fc::ui
