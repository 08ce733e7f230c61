#include "document/PlannerMessages.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace fc::ui {

QString plainMessage(const QString& message) {
    static const QRegularExpression exactLimit(
        QStringLiteral("^exact solver: (\\d+) required cells exceed its limit of (\\d+); use "
                       "`--solver heuristic` for this query$"));
    static const QRegularExpression exactBudget(
        QStringLiteral("^exact solver: (\\d+) required cells: no proof of optimality within its "
                       "budget \\((.*)\\); use `--solver heuristic` for this query$"));
    static const QRegularExpression dqnModel(
        QStringLiteral("^solver dqn needs a trained model \\(--model FILE; make one with "
                       "floorcover-cli train\\)$"));
    if (const auto m = exactLimit.match(message); m.hasMatch())
        return QCoreApplication::translate(
                   "PlannerMessages",
                   "The exact solver orders at most %1 cells, and these rooms have %2. Choose the "
                   "heuristic solver in the Planning panel.")
            .arg(m.captured(2), m.captured(1));
    if (const auto m = exactBudget.match(message); m.hasMatch())
        return QCoreApplication::translate(
                   "PlannerMessages",
                   "The exact solver could not prove the best order of %1 cells within its "
                   "budget (%2). Choose the heuristic solver in the Planning panel.")
            .arg(m.captured(1), m.captured(2));
    if (dqnModel.match(message).hasMatch())
        return QCoreApplication::translate(
            "PlannerMessages",
            "The dqn solver needs a trained model: train one in the Training panel (or "
            "load one there), or choose another solver.");
    return message;
}

} // namespace fc::ui
