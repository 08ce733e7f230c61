#include "document/PlannerMessages.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <vector>

namespace fc::ui {

namespace {

// Not named tr(): lupdate would file the strings under the enclosing namespace. The texts
// are marked with QT_TRANSLATE_NOOP in the "PlannerMessages" context instead.
QString translated(const char* text) {
    return QCoreApplication::translate("PlannerMessages", text);
}

// "boundary", "obstacle 3", "room \"Kitchen\"" as the editor names them.
QString ringName(const QString& planner) {
    static const QRegularExpression obstacle(QStringLiteral("^obstacle (\\d+)$"));
    static const QRegularExpression room(QStringLiteral("^room \"(.*)\"$"));
    if (planner == QLatin1String("boundary"))
        return translated(QT_TRANSLATE_NOOP("PlannerMessages", "The outer wall"));
    if (const auto m = obstacle.match(planner); m.hasMatch())
        return translated(QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1")).arg(m.captured(1));
    if (const auto m = room.match(planner); m.hasMatch())
        return translated(QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1”")).arg(m.captured(1));
    return planner;
}

// One planner message form: its pattern and the editor's sentence, whose %1, %2... are the
// pattern's captures in order (a capture named "ring" is put in the editor's words).
struct MessageForm {
    QRegularExpression pattern;
    const char* sentence;
};

const std::vector<MessageForm>& forms() {
    // The sentences are marked for lupdate here and translated when used.
    static const std::vector<MessageForm> table = {
        {QRegularExpression(
             QStringLiteral("^exact solver: (\\d+) required cells exceed its limit of (\\d+); use "
                            "`--solver heuristic` for this query$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "These rooms have %1 cells, and the exact solver orders at most %2. "
                           "Choose the heuristic solver in the Planning panel.")},
        {QRegularExpression(QStringLiteral(
             "^exact solver: (\\d+) required cells: no proof of optimality within its "
             "budget \\((.*)\\); use `--solver heuristic` for this query$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The exact solver could not prove the best order of %1 cells within "
                           "its budget (%2). Choose the heuristic solver in the Planning panel.")},
        {QRegularExpression(QStringLiteral("^solver dqn needs a trained model \\(--model FILE; "
                                           "make one with floorcover-cli train\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The dqn solver needs a trained model: train one in the Training "
                           "panel (or load one there), or choose another solver.")},
        {QRegularExpression(QStringLiteral("^obstacle (\\d+) crosses the boundary near (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1 crosses the outer wall near %2.")},
        {QRegularExpression(QStringLiteral("^obstacle (\\d+) touches the boundary at (.*); "
                                           "obstacles must lie strictly inside it$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "Obstacle %1 touches the outer wall at %2; obstacles must lie "
                           "inside the walls.")},
        {QRegularExpression(QStringLiteral("^obstacles (\\d+) and (\\d+) overlap near (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Obstacles %1 and %2 overlap near %3.")},
        {QRegularExpression(QStringLiteral(
             "^obstacles (\\d+) and (\\d+) touch at (.*); merge them into one obstacle$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "Obstacles %1 and %2 touch at %3; draw them as one obstacle.")},
        {QRegularExpression(
             QStringLiteral("^obstacle (\\d+) lies outside the boundary, near (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1 lies outside the walls, near %2.")},
        {QRegularExpression(QStringLiteral("^obstacle (\\d+) lies inside obstacle (\\d+)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1 lies inside obstacle %2.")},
        {QRegularExpression(QStringLiteral("^(?<ring>.+) intersects itself near (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "%1 crosses itself near %2.")},
        {QRegularExpression(QStringLiteral("^(?<ring>.+) touches itself at (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "%1 touches itself at %2.")},
        {QRegularExpression(
             QStringLiteral("^(?<ring>.+) folds back on itself \\(a spike\\) at (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "%1 folds back on itself (a spike) at %2.")},
        {QRegularExpression(
             QStringLiteral("^rooms \"(.*)\" and \"(.*)\" overlap by (.*) m\\^2 near (.*)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Rooms “%1” and “%2” overlap by %3 m² near %4.")},
        {QRegularExpression(QStringLiteral("^rooms \"(.*)\" and \"(.*)\" overlap by (.*) m\\^2$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Rooms “%1” and “%2” overlap by %3 m².")},
        {QRegularExpression(QStringLiteral("^room \"(.*)\" lies outside the boundary$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1” lies outside the walls.")},
        {QRegularExpression(QStringLiteral("^room \"(.*)\" lies inside obstacle (\\d+)$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1” lies inside obstacle %2.")},
        {QRegularExpression(
             QStringLiteral("^obstacles (\\d+) and (\\d+) are identical \\(duplicate "
                            "obstacle\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "Obstacles %1 and %2 are the same: delete one of them.")},
        {QRegularExpression(QStringLiteral("^room \"(.*)\" does not overlap the free space \\(it "
                                           "covers only obstacles\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "Room “%1” covers only obstacles: there is no floor in it to clean.")},
        {QRegularExpression(QStringLiteral("^room (\\d+) has no name$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Room %1 has no name: give it one.")},
        {QRegularExpression(
             QStringLiteral("^free area (.*) m\\^2 \\(boundary minus obstacles\\) is "
                            "smaller than the robot footprint (.*) m\\^2 \\(L = (.*) "
                            "m\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The free floor (%1 m²) is smaller than the robot (%2 m², L = %3 m).")},
        {QRegularExpression(QStringLiteral("^duplicate room name \"(.*)\"$")),
         QT_TRANSLATE_NOOP("PlannerMessages", "Two rooms are named “%1”: rename one.")},
        {QRegularExpression(QStringLiteral(
             "^(\\d+) cells \\((.*) m\\^2\\) cannot be reached from the start and are left out$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "%1 cells (%2 m²) cannot be reached from the start and are left "
                           "out.")},
        {QRegularExpression(QStringLiteral("^room (.*) cannot be reached from the start and is "
                                           "left out$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "Room %1 cannot be reached from the start and is left out.")},
        {QRegularExpression(QStringLiteral("^(.*) m\\^2 \\((.*)% of the selected floor\\) the "
                                           "robot could sweep but the path does not cover$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "%1 m² (%2 % of the selected floor) the robot could clean but the "
                           "path misses.")},
        {QRegularExpression(QStringLiteral(
             "^(.*) m\\^2 \\((.*)% of the selected floor\\) the robot cannot reach \\(gaps "
             "narrower than the robot, corners beyond its head\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "%1 m² (%2 % of the selected floor) the robot cannot reach (gaps "
                           "narrower than the robot, corners beyond its head).")},
        {QRegularExpression(QStringLiteral("^no selected (?:area|room) can be reached from the "
                                           "start point$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "No selected room can be reached from the start: move the start "
                           "(Place Start) or pick other rooms.")},
        {QRegularExpression(
             QStringLiteral("^the end point cannot be reached from the start point$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The end cannot be reached from the start: move one of them.")},
        {QRegularExpression(QStringLiteral("^the selected rooms contain no area the robot can "
                                           "sweep$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The selected rooms have no floor the robot can clean: pick other "
                           "rooms or a smaller robot.")},
        {QRegularExpression(QStringLiteral("^robot diameter L = (.*) m exceeds coverage width "
                                           "W = (.*) m \\(need L <= W <= D\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The robot diameter L (%1 m) is larger than the coverage width W "
                           "(%2 m): L ≤ W ≤ D.")},
        {QRegularExpression(QStringLiteral("^coverage width W = (.*) m exceeds cleaning "
                                           "diameter D = (.*) m \\(need L <= W <= D\\)$")),
         QT_TRANSLATE_NOOP("PlannerMessages",
                           "The coverage width W (%1 m) is larger than the cleaning diameter D "
                           "(%2 m): L ≤ W ≤ D.")},
    };
    return table;
}

} // namespace

QString plainMessage(const QString& message) {
    for (const MessageForm& form : forms()) {
        const QRegularExpressionMatch m = form.pattern.match(message);
        if (!m.hasMatch())
            continue;
        QString sentence = translated(form.sentence);
        const QStringList names = form.pattern.namedCaptureGroups();
        for (int i = 1; i <= form.pattern.captureCount(); ++i) {
            QString value = m.captured(i);
            if (i < names.size() && names[i] == QLatin1String("ring"))
                value = ringName(value);
            sentence = sentence.arg(value);
        }
        return sentence;
    }
    return message;
}

} // namespace fc::ui
