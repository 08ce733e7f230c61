#include "modes/tiling/TilingMode.h"

#include "modes/tiling/TilingController.h"
#include "modes/tiling/TilingDock.h"
#include "modes/tiling/TilingItem.h"
#include "tasks/Task.h"

#include <QAction>
#include <QDockWidget>
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
    connect(action_, &QAction::toggled, this, [this, window](bool on) {
        if (on)
            shareATab(window);
        dock_->setVisible(on);
        if (on)
            dock_->raise();
        updateItem();
    });
    // Closing the dock leaves the mode (its view action follows closing and showing, not a
    // tab of another panel coming to the front).
    connect(dock_->toggleViewAction(), &QAction::toggled, this, [this](bool shown) {
        if (!shown)
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

void TilingMode::shareATab(QMainWindow* window) {
    // Stacked under the other panels, the dock's minimum height added to theirs and pushed
    // the window past the screen (a maximised window was un-maximised). As a tab of a
    // visible panel on its side it takes no height of its own.
    if (!window->tabifiedDockWidgets(dock_).isEmpty() || dock_->isFloating())
        return;
    const Qt::DockWidgetArea area = window->dockWidgetArea(dock_);
    for (QDockWidget* other : window->findChildren<QDockWidget*>()) {
        if (other != dock_ && other->isVisible() && !other->isFloating() &&
            window->dockWidgetArea(other) == area) {
            window->tabifyDockWidget(other, dock_);
            return;
        }
    }
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
