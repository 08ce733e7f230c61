// The planner's messages about the plan, the robot, room edits, planning, the solvers and the
// dqn models, and the editor's sentences for them. The patterns follow the planner's wording
// in planner/model, planner/pipeline, planner/solvers and planner/learning/dqn.
#include "document/PlannerMessageForms.h"

#include <QCoreApplication>

namespace fc::ui::messages {

MessageForm messageForm(const char* pattern, const char* sentence) {
    // How the planner names a part of the plan: "boundary", "obstacle 3", "room \"Hall\"",
    // "room 2", "feature 4 (obstacle)", "obstacle 2 (hole 1 of the boundary)",
    // "boundary (feature 1, part 2)" (a site's second building)...
    static const QString ring = QStringLiteral(
        R"re((?<ring>(?:boundary|obstacle \d+|room(?: ".*"| \d+)?|an unnamed room|feature \d+))re"
        R"re((?: \((?:feature \d+(?:, part \d+)?|hole \d+ of the boundary(?:, part \d+)?|)re"
        R"re(boundary|obstacle|room)\))?))re");
    QString text = QString::fromUtf8(pattern);
    text.replace(QLatin1String("{ring}"), ring);
    return {QRegularExpression(text), sentence};
}

std::vector<MessageForm> planningMessageForms() {
    return {
        // Solvers that speak of the command line.
        messageForm(R"re(^exact solver: (\d+) required cells exceed its limit of (\d+); use )re"
                    R"re(`--solver heuristic` for this query$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "These rooms have %1 cells, and the exact solver orders at "
                                      "most %2. Choose the heuristic solver in the Planning "
                                      "panel.")),
        messageForm(R"re(^exact solver: (\d+) required cells: no proof of optimality within its )re"
                    R"re(budget \((.*)\); use `--solver heuristic` for this query$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The exact solver could not prove the best order of %1 "
                                      "cells within its budget (%2). Choose the heuristic solver "
                                      "in the Planning panel.")),

        // The plan's checks (model/Validation.cpp, model/ValidationSupport.cpp).
        messageForm(
            R"re(^obstacle (\d+) crosses the boundary near (.*)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1 crosses the outer wall near %2.")),
        messageForm(R"re(^obstacle (\d+) touches the boundary at (.*); obstacles must lie )re"
                    R"re(strictly inside it$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Obstacle %1 touches the outer wall at %2; obstacles must "
                                      "lie inside the walls.")),
        messageForm(R"re(^obstacles (\d+) and (\d+) overlap near (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Obstacles %1 and %2 overlap near %3.")),
        messageForm(
            R"re(^obstacles (\d+) and (\d+) touch at (.*); merge them into one obstacle$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "Obstacles %1 and %2 touch at %3; draw them as one "
                              "obstacle.")),
        messageForm(
            R"re(^obstacle (\d+) lies outside the boundary, near (.*)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1 lies outside the walls, near %2.")),
        messageForm(R"re(^obstacle (\d+) lies inside obstacle (\d+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1 lies inside obstacle %2.")),
        messageForm(R"re(^{ring} intersects itself near (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1 crosses itself near %2.")),
        messageForm(R"re(^{ring} touches itself at (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "%1 touches itself at %2.")),
        messageForm(
            R"re(^{ring} folds back on itself \(a spike\) at (.*)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "%1 folds back on itself (a spike) at %2.")),
        messageForm(
            R"re(^rooms "(.*)" and "(.*)" overlap by (.*) m\^2 near (.*)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "Rooms “%1” and “%2” overlap by %3 m² near %4.")),
        messageForm(R"re(^rooms "(.*)" and "(.*)" overlap by (.*) m\^2$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Rooms “%1” and “%2” overlap by %3 m².")),
        messageForm(R"re(^room "(.*)" lies outside the boundary$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1” lies outside the walls.")),
        messageForm(R"re(^room "(.*)" lies inside obstacle (\d+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1” lies inside obstacle %2.")),
        messageForm(R"re(^obstacles (\d+) and (\d+) are identical \(duplicate obstacle\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Obstacles %1 and %2 are the same: delete one of them.")),
        messageForm(R"re(^room "(.*)" does not overlap the free space \(it covers only )re"
                    R"re(obstacles\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Room “%1” covers only obstacles: there is no floor in it "
                                      "to clean.")),
        messageForm(R"re(^room (\d+) has no name$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Room %1 has no name: give it one.")),
        messageForm(R"re(^free area (.*) m\^2 \(boundary minus obstacles\) is smaller than the )re"
                    R"re(robot footprint (.*) m\^2 \(L = (.*) m\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The free floor (%1 m²) is smaller than the robot (%2 m², "
                                      "L = %3 m).")),
        messageForm(R"re(^free area (.*) m\^2 \(boundary minus obstacles\) is smaller than one )re"
                    R"re(coverage square W\^2 = (.*) m\^2$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The free floor (%1 m²) is smaller than one coverage square "
                                      "W² (%2 m²): make the coverage width W smaller in the "
                                      "Planning panel.")),
        messageForm(R"re(^duplicate room name "(.*)"$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "Two rooms are named “%1”: rename one.")),
        messageForm(R"re(^{ring} has a non-finite coordinate at vertex (\d+)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1: vertex %2 has a coordinate that is not a finite "
                                      "number.")),
        messageForm(
            R"re(^{ring} has only (\d+) distinct (?:vertices|points); a ring needs at )re"
            R"re(least 3$)re",
            QT_TRANSLATE_NOOP(
                "PlannerMessages",
                "%1 has too few different vertices (%2); an outline needs at least three.")),
        messageForm(R"re(^{ring} repeats vertex (\d+) at (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 has two vertices on top of each other at %3 (vertex "
                                      "%2): delete one of them (Edit Vertices, right-click).")),
        messageForm(R"re(^{ring} has zero area \(its vertices lie on one line\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 has no area: all its vertices lie on one line.")),

        // The robot (model/Plan.cpp).
        messageForm(R"re(^robot diameter L = (.*) m exceeds coverage width W = (.*) m )re"
                    R"re(\(need L <= W <= D\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The robot diameter L (%1 m) is larger than the coverage "
                                      "width W (%2 m): L ≤ W ≤ D.")),
        messageForm(R"re(^coverage width W = (.*) m exceeds cleaning diameter D = (.*) m )re"
                    R"re(\(need L <= W <= D\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The coverage width W (%1 m) is larger than the cleaning "
                                      "diameter D (%2 m): L ≤ W ≤ D.")),
        messageForm(R"re(^robot diameter L must be a positive number \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The robot diameter L must be a positive number, not %1: "
                                      "change it in the Planning panel.")),
        messageForm(R"re(^coverage width W must be a positive number \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The coverage width W must be a positive number, not %1: "
                                      "change it in the Planning panel.")),
        messageForm(R"re(^cleaning diameter D must be a positive number \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The cleaning diameter D must be a positive number, not %1: "
                                      "change it in the Planning panel.")),
        messageForm(R"re(^speed must be a positive number \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The speed must be a positive number, not %1: change it in "
                                      "the Planning panel.")),
        messageForm(R"re(^turn time must be zero or positive \(got (.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The robot's turn time must be zero or positive, not %1.")),
        messageForm(R"re(^speed (.*) m/s is not a plausible robot speed \(0\.001 to 100 m/s\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "A speed of %1 m/s is not plausible for a robot (0.001 to "
                                      "100 m/s): change it in the Planning panel.")),
        messageForm(R"re(^turn time (.*) s is not plausible \(at most an hour per turn\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "A turn time of %1 s is not plausible (at most an hour per "
                                      "turn): change it in the Planning panel.")),
        messageForm(
            R"re(^{ring} has a coordinate of (.*) m at vertex (\d+), beyond any map projection's range: is the plan in metres\?$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "%1: vertex %3 has a coordinate of %2 m, beyond the range "
                              "of any map projection: is the plan in metres?")),
        messageForm(
            R"re(^the boundary spans (.*) km, more than the (.*) km of any site on Earth: is the plan in metres\?$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The boundary spans %1 km, more than the %2 km of any site "
                              "on Earth: is the plan in metres?")),
        messageForm(R"re(^coverage width W = (.*) m is not a plausible robot size$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "A coverage width W of %1 m is not a plausible robot size: "
                                      "change it in the Planning panel.")),

        // Merging and splitting rooms (model/RoomEdits.cpp): said after "Kitchen and Hall
        // cannot be merged:" or "Kitchen cannot be split:".
        messageForm(
            R"re(^a room to merge has fewer than 3 corners$)re",
            QT_TRANSLATE_NOOP("PlannerMessages", "one of the rooms has fewer than three corners")),
        messageForm(
            R"re(^the rooms do not share a border; merge rooms that meet along a wall or )re"
            R"re(a doorway$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "they do not share a border; merge rooms that meet along a "
                              "wall or a doorway")),
        messageForm(R"re(^the merged room would be in several pieces$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "the merged room would fall apart into several pieces")),
        messageForm(R"re(^the merged room would enclose a hole; merge the room inside it too$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "the merged room would enclose a hole; merge the room "
                                      "inside it as well")),
        messageForm(R"re(^the room has fewer than 3 corners$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "the room has fewer than three corners")),
        messageForm(R"re(^draw the cut as a line across the room$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "drag the cut as a line across the room (Split Room)")),
        messageForm(R"re(^the cut does not cross the room$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "the cut does not cross the room; drag it from one wall of "
                                      "the room to another")),
        messageForm(
            R"re(^the cut crosses the room more than once; draw it where one straight line )re"
            R"re(divides the room in two$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "the cut crosses the room more than once; drag it where one "
                              "straight line divides the room in two")),
        messageForm(R"re(^the cut would leave a sliver of the room; draw it across the room$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "the cut would cut off only a sliver of the room; drag it "
                                      "across the middle of the room")),

        // Planning (pipeline/Planner.cpp, pipeline/PerRoomSweep.cpp).
        messageForm(R"re(^(\d+) cells \((.*) m\^2\) cannot be reached from the start and are )re"
                    R"re(left out$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "%1 cells (%2 m²) cannot be reached from the start and are "
                                      "left out.")),
        messageForm(R"re(^room (.*) cannot be reached from the start and is left out$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "Room %1 cannot be reached from the start and is left "
                                      "out.")),
        messageForm(
            R"re(^(.*) m\^2 \((.*)% of the selected floor\) the robot could sweep but the )re"
            R"re(path does not cover$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "%1 m² (%2 % of the selected floor) the robot could clean "
                              "but the path misses.")),
        messageForm(
            R"re(^(.*) m\^2 \((.*)% of the selected floor\) the robot cannot reach \(gaps )re"
            R"re(narrower than the robot, corners beyond its head\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "%1 m² (%2 % of the selected floor) the robot cannot reach "
                              "(gaps narrower than the robot, corners beyond its "
                              "head).")),
        messageForm(R"re(^no selected (?:area|room) can be reached from the start point$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "No selected room can be reached from the start: move the "
                                      "start (Place Start) or pick other rooms.")),
        messageForm(R"re(^the end point cannot be reached from the start point$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The end cannot be reached from the start: move one of "
                                      "them.")),
        messageForm(R"re(^the selected rooms contain no area the robot can sweep$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The selected rooms have no floor the robot can clean: pick "
                                      "other rooms or a smaller robot.")),
        messageForm(R"re(^the sweep angle must be a finite number of degrees$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The sweep angle must be a finite number of degrees: set it "
                                      "in the Planning panel.")),
        messageForm(R"re(^unknown room "(.*)" \(rooms: ?(.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "There is no room “%1” in this plan (its rooms: %2): check "
                                      "the rooms to plan in the Planning panel.")),
        messageForm(R"re(^unknown solver "(.*)" \(available: ?(.*)\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "There is no solver “%1” (available: %2): choose one in the "
                                      "Planning panel.")),
        messageForm(
            R"re(^the rooms cannot be joined: no collision-free way from (.*)'s neighbour )re"
            R"re(into it$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The robot finds no way into room “%1” from the room before "
                              "it: widen the passage, or sweep the floor at one angle "
                              "(Sweep in the Planning panel).")),
        messageForm(R"re(^cancelled$)re", QT_TRANSLATE_NOOP("PlannerMessages", "Cancelled.")),

        // The solvers' checks of their query (solvers/SolverCommon.cpp).
        messageForm(R"re(^(\S+)(?: solver)?: cancelled$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages", "The %1 solver was cancelled.")),
        messageForm(
            R"re(^(\S+) solver: (\d+) required cell\(s\) cannot be reached from the start )re"
            R"re(node \d+ \(separate part of the graph\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The %1 solver cannot reach %2 cells from the start: move "
                              "the start (Place Start) or pick other rooms.")),
        messageForm(R"re(^(\S+) solver: the end node \d+ cannot be reached from the start node )re"
                    R"re(\d+$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The %1 solver cannot reach the end from the start: move "
                                      "one of them.")),
        messageForm(
            R"re(^(\S+) solver: (start node -?\d+ or end node -?\d+ is not a node of the )re"
            R"re(graph .*|the query lists .*|graph adjacency does not match its nodes|)re"
            R"re(required cell \d+ has no coverage edge|internal error: .*)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The %1 solver stopped on an internal error (%2): please "
                              "report it, and choose another solver in the Planning "
                              "panel meanwhile.")),

        // Solver dqn and its models (learning/dqn/DqnPolicy.cpp, DqnModelFile.cpp); the model
        // file's messages follow its path ("model.fcdqn: ...").
        messageForm(R"re(^dqn: the model's network does not fit its state kind \(image/graph\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The dqn model is inconsistent (its network does not fit "
                                      "its kind of state): train a new model in the Training "
                                      "panel.")),
        messageForm(R"re(^dqn: the model was trained on a graph of another size$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The dqn model was trained on a plan of another size: train "
                                      "a model for this plan in the Training panel.")),
        messageForm(R"re(^dqn: CoverageEnvironment: (.*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The dqn solver cannot plan this query (%1): choose another "
                                      "solver in the Planning panel.")),
        messageForm(R"re(^dqn: no corner of an uncovered cell can be reached$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The dqn solver finds no way to the rooms still to clean: "
                                      "choose another solver in the Planning panel.")),
        messageForm(R"re(^dqn: the policy ran out of steps$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The dqn model ran out of steps before it covered the "
                                      "rooms: train it longer in the Training panel, or choose "
                                      "another solver.")),
        messageForm(R"re(^dqn: the policy's walk does not cover the query \(internal error\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The path of the dqn solver does not cover the rooms (an "
                                      "internal error): choose another solver in the Planning "
                                      "panel.")),
        messageForm(R"re(^randomQueries: the graph has no reachable cell$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The plan has no floor the robot can reach: there is "
                                      "nothing to train on.")),
        messageForm(R"re(^truncated model file \(.*\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model file is incomplete: load another model or train "
                                      "a new one in the Training panel.")),
        messageForm(R"re(^corrupt model (?:file \(.*\)|metadata: .*|weights: .*)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model file is damaged: load another model or train a "
                                      "new one in the Training panel.")),
        messageForm(R"re(^not a FloorCover DQN model \(missing the .* header\)$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "This is not a FloorCover dqn model file (.fcdqn).")),
        messageForm(
            R"re(^model format version (-?\d+) is not supported \(this build reads up to )re"
            R"re(version (\d+)\)$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "The model file has format version %1, and this FloorCover "
                              "reads versions up to %2: update FloorCover or train a new "
                              "model.")),
        messageForm(R"re(^cannot open the model file$)re",
                    QT_TRANSLATE_NOOP("PlannerMessages",
                                      "The model file cannot be opened: check that it exists and "
                                      "can be read.")),
        messageForm(
            R"re(^the model was trained for another floor plan or robot profile \(it )re"
            R"re(knows (\d+) corners in (\d+) cells at sweep angle (.*) deg and coverage )re"
            R"re(width (.*) m; this plan has (\d+) corners in (\d+) cells\); train a model )re"
            R"re(for this plan$)re",
            QT_TRANSLATE_NOOP("PlannerMessages",
                              "This model was trained for another floor plan or robot "
                              "(%1 corners in %2 cells, sweep angle %3°, coverage width "
                              "%4 m; this plan has %5 corners in %6 cells): train a "
                              "model for this plan in the Training panel.")),
    };
}

} // namespace fc::ui::messages
