#include "dialogs/SiteBuildingChoice.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QLocale>

namespace fc::ui {

namespace {
struct SiteBuildingText {
    Q_DECLARE_TR_FUNCTIONS(fc::ui::SiteBuildingChoice)
};
} // namespace

QStringList siteBuildingNames(const std::vector<double>& areas) {
    QStringList names;
    for (std::size_t i = 0; i < areas.size(); ++i)
        names << SiteBuildingText::tr("Building %1 (%2 m²)")
                     .arg(i + 1)
                     .arg(QLocale().toString(areas[i], 'f', 0));
    return names;
}

std::optional<int> askForSiteBuilding(QWidget* parent, const QString& fileName,
                                      const std::vector<double>& areas) {
    bool ok = false;
    const QStringList names = siteBuildingNames(areas);
    const QString chosen =
        QInputDialog::getItem(parent, SiteBuildingText::tr("Choose a Building"),
                              SiteBuildingText::tr("%1 holds %2 buildings, and a plan holds one.\n"
                                                   "Which building do you want to open?")
                                  .arg(fileName)
                                  .arg(areas.size()),
                              names, 0, false, &ok);
    if (!ok)
        return std::nullopt;
    const int index = static_cast<int>(names.indexOf(chosen));
    return index >= 0 ? std::optional<int>(index + 1) : std::nullopt;
}

} // namespace fc::ui
