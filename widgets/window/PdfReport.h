// The one-page PDF report: the plan with its overlays and path, the metrics (SPEC sect. 6),
// the robot profile, the solver and the date.
#pragma once

#include <QString>

class QGraphicsScene;

namespace fc {
struct PlanResult;
}

namespace fc::ui {

class Document;

// Throws nothing; returns false and sets *error when the file cannot be written.
bool writePdfReport(const QString& path, const Document& document, const PlanResult& result,
                    QGraphicsScene& scene, QString* error);

} // namespace fc::ui
