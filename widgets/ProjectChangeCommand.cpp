#include "ProjectChangeCommand.h"

#include "Document.h"

namespace fc::ui {

ProjectChangeCommand::ProjectChangeCommand(Document* document, Project after, unsigned changes,
                                           const QString& text, int mergeId)
    : QUndoCommand(text), document_(document), before_(document->project()),
      after_(std::move(after)), changes_(changes), mergeId_(mergeId) {}

void ProjectChangeCommand::undo() {
    document_->applyProject(before_, changes_);
}

void ProjectChangeCommand::redo() {
    document_->applyProject(after_, changes_);
}

bool ProjectChangeCommand::mergeWith(const QUndoCommand* other) {
    if (other->id() != id() || mergeId_ < 0)
        return false;
    const auto* change = static_cast<const ProjectChangeCommand*>(other);
    after_ = change->after_;
    changes_ |= change->changes_;
    return true;
}

} // namespace fc::ui
