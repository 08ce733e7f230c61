// One undoable edit of the project. It keeps the project before and after the edit
// (plans are small values, so a snapshot is cheaper than per-field bookkeeping and
// cannot get out of step with the model) and which parts changed.
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
    Document* document_;
    Project before_;
    Project after_;
    unsigned changes_;
    int mergeId_;
};

} // namespace fc::ui
