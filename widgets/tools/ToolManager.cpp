#include "tools/ToolManager.h"

#include "document/Document.h"
#include "tools/AbstractTool.h"

#include <QAction>
#include <QActionGroup>

namespace fc::ui {

ToolManager::ToolManager(QObject* parent) : QObject(parent), group_(new QActionGroup(this)) {
    group_->setExclusive(true);
}

void ToolManager::setConfirmation(std::function<bool(const QString&)> confirm) {
    confirm_ = std::move(confirm);
}

void ToolManager::registerTool(AbstractTool* tool) {
    tool->setParent(this);
    tools_.push_back(tool);
    auto* action = new QAction(tool->name(), group_);
    action->setCheckable(true);
    action->setShortcut(tool->shortcut());
    action->setToolTip(tool->usageHint());
    action->setData(QVariant::fromValue(static_cast<QObject*>(tool)));
    connect(action, &QAction::triggered, this, [this, tool]() { setActiveTool(tool); });
    connect(tool, &AbstractTool::statusMessage, this, &ToolManager::statusMessage);
    if (!active_)
        setActiveTool(tool);
}

QList<QAction*> ToolManager::actions() const {
    return group_->actions();
}

AbstractTool* ToolManager::findTool(const QString& name) const {
    for (AbstractTool* tool : tools_)
        if (tool->name() == name || tool->objectName() == name)
            return tool;
    return nullptr;
}

void ToolManager::setActiveTool(AbstractTool* tool) {
    if (tool == active_)
        return;
    if (active_)
        active_->deactivate();
    active_ = tool;
    for (QAction* action : group_->actions())
        action->setChecked(action->data().value<QObject*>() == tool);
    if (active_ && document_ && scene_)
        active_->activate(document_, scene_);
    emit activeToolChanged(active_);
    if (active_)
        emit statusMessage(active_->usageHint());
}

void ToolManager::setContext(Document* document, PlanScene* scene) {
    if (active_)
        active_->deactivate();
    document_ = document;
    scene_ = scene;
    if (active_ && document_ && scene_)
        active_->activate(document_, scene_);
}

} // namespace fc::ui
