// One undoable edit of the project. It keeps the project before and after the edit (a
// snapshot cannot get out of step with the model the way per-field bookkeeping can) and
// which parts changed; edits that leave the plan alone keep no copy of it.
#pragma once

#include "formats/PlanIO.h"

#include <QUndoCommand>

namespace fc::ui {

class Document;

class ProjectChangeCommand : public QUndoCommand {
public:
    // mergeId >= 0 lets consecutive commands of that id merge into one (spin box steps).
    ProjectChangeCommand(Document* document, Project after, unsigned changes, const QString& text,
                         int mergeId = -1);

    void undo() override;
    void redo() override;
    int id() const override { return mergeId_; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const Project& state);

    Document* document_;
    Project before_;
    Project after_;
    unsigned changes_;
    int mergeId_;
    bool keepsPlan_ = true;
};

} // namespace fc::ui
