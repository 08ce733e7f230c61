#include "tools/AbstractTool.h"

#include "tools/ToolManager.h"

namespace fc::ui {

AbstractTool::AbstractTool(const QString& name, const QKeySequence& shortcut, QObject* parent)
    : QObject(parent), name_(name), shortcut_(shortcut) {}

bool AbstractTool::confirm(const QString& question) const {
    const auto* manager = qobject_cast<const ToolManager*>(parent());
    return !manager || manager->confirm(question);
}

void AbstractTool::activate(Document* document, PlanScene* scene) {
    document_ = document;
    scene_ = scene;
}

void AbstractTool::deactivate() {
    document_ = nullptr;
    scene_ = nullptr;
}

} // namespace fc::ui
