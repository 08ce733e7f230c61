// The planner's messages as the editor says them. The planner library speaks to the command
// line ("use `--solver heuristic`", "--model FILE"); at the GUI boundary those messages are
// put in terms of the editor's own controls and translated. Messages with no editor wording
// pass through unchanged.
#pragma once

#include <QString>

namespace fc::ui {

QString plainMessage(const QString& plannerMessage);

} // namespace fc::ui
