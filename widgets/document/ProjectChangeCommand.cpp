#include "document/ProjectChangeCommand.h"

#include "document/Document.h"

namespace fc::ui {

ProjectChangeCommand::ProjectChangeCommand(Document* document, Project after, unsigned changes,
                                           const QString& text, int mergeId)
    : QUndoCommand(text), document_(document), before_(document->project()),
      after_(std::move(after)), changes_(changes), mergeId_(mergeId) {
    // Only geometry and room edits change the plan, the one large part: the others keep
    // no copy of it and leave the document's plan as it is.
    keepsPlan_ = (changes & (GeometryChange | RoomsChange)) != 0;
    if (!keepsPlan_)
        before_.plan = after_.plan = Plan{};
}

void ProjectChangeCommand::apply(const Project& state) {
    if (keepsPlan_) {
        document_->applyProject(state, changes_);
        return;
    }
    Project withPlan = state;
    withPlan.plan = document_->plan();
    document_->applyProject(withPlan, changes_);
}

void ProjectChangeCommand::undo() {
    apply(before_);
}

void ProjectChangeCommand::redo() {
    apply(after_);
}

bool ProjectChangeCommand::mergeWith(const QUndoCommand* other) {
    if (other->id() != id() || mergeId_ < 0)
        return false;
    const auto* change = static_cast<const ProjectChangeCommand*>(other);
    if (change->keepsPlan_ != keepsPlan_)
        return false;
    after_ = change->after_;
    changes_ |= change->changes_;
    return true;
}

} // namespace fc::ui
