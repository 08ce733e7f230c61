#include "modes/tiling/TilingMode.h"

#include "modes/tiling/TilingController.h"
#include "modes/tiling/TilingDock.h"
#include "modes/tiling/TilingItem.h"
#include "tasks/Task.h"

#include <QAction>
#include <QGraphicsScene>
#include <QMainWindow>

namespace fc::ui {

TilingMode::TilingMode(QMainWindow* window, QGraphicsScene* scene)
    : QObject(window), scene_(scene),
      controller_(new TilingController(TaskManager::forObject(window), this)),
      dock_(new TilingDock(controller_, window)), item_(new TilingItem) {
    scene_->addItem(item_);
    item_->setVisible(false);
    window->addDockWidget(Qt::RightDockWidgetArea, dock_);
    dock_->hide();
    action_ = new QAction(tr("&Tiling Robot Mode"), this);
    action_->setCheckable(true);
    action_->setToolTip(tr("Cover the floor with a shape-shifting tiling robot's tiles and "
                           "order them by energy"));
    connect(action_, &QAction::toggled, this, [this](bool on) {
        dock_->setVisible(on);
        if (on)
            dock_->raise();
        updateItem();
    });
    // Closing the dock leaves the mode.
    connect(dock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (!visible && !dock_->isVisible())
            action_->setChecked(false);
    });
    connect(dock_, &TilingDock::showTilesChanged, this, [this](bool show) {
        showTiles_ = show;
        updateItem();
    });
    connect(controller_, &TilingController::resultChanged, this,
            [this] { item_->setPlan(controller_->result()); });
}

TilingMode::~TilingMode() {
    if (scene_) // else the scene went first and deleted the item with it
        delete item_;
}

void TilingMode::setDocument(Document* document) {
    controller_->setDocument(document);
}

bool TilingMode::isActive() const {
    return action_->isChecked();
}

void TilingMode::updateItem() {
    item_->setVisible(isActive() && showTiles_);
}

} // namespace fc::ui
