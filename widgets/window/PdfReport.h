// The PDF report for the people who run the robot: the plan in the Path view with a legend
// and the start and end, the summary and the robot profile, and a table of the rooms in
// the order they are cleaned with their area and estimated time. Laid out for the page
// size chosen (A4 or A3, portrait); a long room table continues on further pages.
#pragma once

#include <QList>
#include <QPageSize>
#include <QPair>
#include <QString>
#include <QStringList>

namespace fc {
struct PlanResult;
}

namespace fc::ui {

class Document;
class PlanScene;

// Label and value rows of the report's summary and robot profile.
QList<QPair<QString, QString>> reportSummary(const Document& document, const PlanResult& result);
QList<QPair<QString, QString>> reportRobot(const PlanResult& result);
// The room table: a header row, then one row per room in visit order (rooms not cleaned
// last, marked "not planned"), then the moves outside every room, then the total.
QList<QStringList> reportRoomTable(const Document& document, const PlanResult& result);

// Written atomically (QSaveFile). Throws nothing; returns false and sets *error when the
// file cannot be written.
bool writePdfReport(const QString& path, const Document& document, const PlanResult& result,
                    PlanScene& scene, const QPageSize& pageSize, QString* error);

} // namespace fc::ui
