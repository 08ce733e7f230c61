// A GeoJSON site holds several buildings (outer walls) and a plan one: which to open.
#pragma once

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

class QWidget;

namespace fc::ui {

// "Building 1 (1,234 m²)", ... for buildings of these areas (m², largest first).
QStringList siteBuildingNames(const std::vector<double>& areas);

// Asks which building of `fileName` to open; 1 = the largest, nullopt when cancelled.
std::optional<int> askForSiteBuilding(QWidget* parent, const QString& fileName,
                                      const std::vector<double>& areas);

} // namespace fc::ui
