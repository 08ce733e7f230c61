// The table behind plainMessage (PlannerMessages.h): each planner message as the planner
// words it (a pattern) and as the editor says it (a sentence, marked for translation in the
// "PlannerMessages" context).
#pragma once

#include <QRegularExpression>
#include <vector>

namespace fc::ui::messages {

// One planner message form. The sentence's %1, %2... are the pattern's captures in order; a
// capture named "ring" (written {ring} in a pattern: the boundary, an obstacle, a room or a
// feature of a file) is put in the editor's words, one named "message" is itself a planner
// message and reworded in turn.
struct MessageForm {
    QRegularExpression pattern;
    const char* sentence;
};

// A form from a pattern written as a raw string, {ring} standing for a named part of the plan.
MessageForm messageForm(const char* pattern, const char* sentence);

// The plan's checks, the robot, room edits, planning, the solvers and the dqn models.
std::vector<MessageForm> planningMessageForms();
// Reading, importing and writing files; the tiling robot.
std::vector<MessageForm> fileMessageForms();
// 3D building models (reading, cutting) and separating an occupancy map's rooms.
std::vector<MessageForm> modelMessageForms();

} // namespace fc::ui::messages
