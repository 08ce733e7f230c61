#include "tools/AbstractTool.h"

namespace fc::ui {

AbstractTool::AbstractTool(const QString& name, const QKeySequence& shortcut, QObject* parent)
    : QObject(parent), name_(name), shortcut_(shortcut) {}

void AbstractTool::activate(Document* document, PlanScene* scene) {
    document_ = document;
    scene_ = scene;
}

void AbstractTool::deactivate() {
    document_ = nullptr;
    scene_ = nullptr;
}

} // namespace fc::ui
