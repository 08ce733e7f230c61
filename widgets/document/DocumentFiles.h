// Opening and saving documents with the planner's readers and writers.
#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace fc::ui {

class Document;

// The sample floor plan embedded in the program (resources/plans/office.geojson).
extern const char* const kSamplePlanPath;

// Reads a .fcproj project or a .geojson/.json plan (also from Qt resources, ":/..."),
// validates the robot profile, and returns a new document (a plan with problems opens
// needing repair, see Document::needsRepair). On failure returns null
// and sets *error to a one-line message naming the file. *notes (when given) gets what
// reading did that the user should hear of (longitude/latitude reprojected to metres).
// A GeoJSON site of several buildings opens one building: `building` (1 = the largest), or
// the one `chooseBuilding` picks from their areas (m^2, largest first); when it picks none,
// nothing opens and *error is left empty. Without either, the site is refused.
using BuildingChooser = std::function<std::optional<int>(const std::vector<double>& areas)>;
std::unique_ptr<Document> loadDocument(const QString& path, QString* error,
                                       QStringList* notes = nullptr,
                                       std::optional<int> building = std::nullopt,
                                       const BuildingChooser& chooseBuilding = {});

// Writes the project atomically (temporary file + rename) as .fcproj, then marks the
// document saved under that name. Returns false and sets *error on failure.
bool saveDocument(Document& document, const QString& path, QString* error);

// The trained DQN model kept beside a project: "site.fcproj" has "site.fcdqn" in the same
// folder. Saving the project writes it (when a model was trained or loaded), opening the
// project loads it back, so a model outlives the session it was trained in.
QString modelFileFor(const QString& projectPath);

} // namespace fc::ui
