// MainWindow: File > Export Path / Zones / Plan, through the planner's writers (the same
// code as `floorcover-cli export`).
#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"
#include "formats/FileIO.h"
#include "tasks/PlanningController.h"
#include "window/MainWindow.h"

#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QUrl>

namespace fc::ui {

namespace {

struct ExportChoice {
    const char* label; // file-dialog filter text, without the pattern
    const char* suffix;
    ExportFormat format;
};

std::vector<ExportChoice> choicesFor(ExportSubject subject) {
    switch (subject) {
    case ExportSubject::Path:
        return {{"GeoJSON", "geojson", ExportFormat::GeoJson},
                {"CSV: x, y, heading, kind", "csv", ExportFormat::Csv},
                {"JSON waypoints", "json", ExportFormat::Json},
                {"ROS 2 nav_msgs/Path", "yaml", ExportFormat::RosPath},
                {"Nav2 waypoint follower", "yaml", ExportFormat::Nav2},
                {"Fields2Cover path", "txt", ExportFormat::Fields2Cover},
                {"VDA 5050 order", "json", ExportFormat::Vda5050},
                {"WGS84 GeoJSON", "geojson", ExportFormat::Wgs84GeoJson},
                {"WKT line", "wkt", ExportFormat::Wkt},
                {"SVG drawing of plan and path", "svg", ExportFormat::Svg},
                {"PDF drawing of plan and path", "pdf", ExportFormat::Pdf}};
    case ExportSubject::Zones:
        return {{"Zones JSON: name, polygon, area", "json", ExportFormat::Zones},
                {"Zones GeoJSON", "geojson", ExportFormat::GeoJson},
                {"Zones WGS84 GeoJSON", "geojson", ExportFormat::Wgs84GeoJson},
                {"Zones WKT", "wkt", ExportFormat::Wkt}};
    case ExportSubject::Plan:
        break;
    }
    return {{"WGS84 GeoJSON", "geojson", ExportFormat::Wgs84GeoJson},
            {"GeoJSON in the plan's frame", "geojson", ExportFormat::GeoJson},
            {"WKT", "wkt", ExportFormat::Wkt},
            {"SVG drawing", "svg", ExportFormat::Svg},
            {"PDF drawing", "pdf", ExportFormat::Pdf}};
}

QString filterOf(const ExportChoice& choice) {
    return QStringLiteral("%1 (*.%2)")
        .arg(QString::fromUtf8(choice.label), QString::fromUtf8(choice.suffix));
}

const char* subjectName(ExportSubject subject) {
    return subject == ExportSubject::Path    ? "path"
           : subject == ExportSubject::Zones ? "zones"
                                             : "plan";
}

// The last export's choice per subject and its folder, remembered across sessions.
QString choiceKey(ExportSubject subject) {
    return QStringLiteral("export/%1/choice").arg(QLatin1String(subjectName(subject)));
}
const QString kExportFolderKey = QStringLiteral("export/folder");

void rememberExport(ExportSubject subject, ExportFormat format, const QString& path) {
    QSettings settings;
    for (const ExportChoice& choice : choicesFor(subject))
        if (choice.format == format)
            settings.setValue(choiceKey(subject), QString::fromUtf8(choice.label));
    settings.setValue(kExportFolderKey, QFileInfo(path).absolutePath());
}

} // namespace

MainWindow::ExportDefaults MainWindow::exportDefaults(ExportSubject subject) const {
    const std::vector<ExportChoice> choices = choicesFor(subject);
    QSettings settings;
    const QString label = settings.value(choiceKey(subject)).toString();
    ExportChoice chosen = choices.front();
    for (const ExportChoice& choice : choices)
        if (QString::fromUtf8(choice.label) == label)
            chosen = choice;
    QString folder = settings.value(kExportFolderKey).toString();
    if (folder.isEmpty() || !QFileInfo(folder).isDir())
        folder = document_->fileName().isEmpty() ? QDir::homePath()
                                                 : QFileInfo(document_->fileName()).absolutePath();
    ExportDefaults defaults;
    defaults.path = QDir(folder).filePath(document_->displayName() + QLatin1Char('-') +
                                          QLatin1String(subjectName(subject)) + QLatin1Char('.') +
                                          QString::fromUtf8(chosen.suffix));
    defaults.filter = filterOf(chosen);
    return defaults;
}

bool MainWindow::exportPath(const QString& path) {
    const auto format = exportFormatForExtension(path.toStdString());
    if (!format) {
        showError(tr("Cannot export the path to %1: unknown file extension").arg(path));
        return false;
    }
    return exportFile(path, *format, ExportSubject::Path);
}

bool MainWindow::exportFile(const QString& path, ExportFormat format, ExportSubject subject) {
    PathExportInfo info;
    CoveragePath coveragePath;
    if (exportNeedsPath(subject)) {
        const auto result = planner_->result();
        if (!result) {
            showError(tr("There is no path to export: plan the current document first."));
            return false;
        }
        info.solver =
            result->solution.solver.empty() ? document_->project().solver : result->solution.solver;
        info.robot = result->prepared.robot;
        info.metrics = result->metrics;
        coveragePath = result->path;
    }
    info.epsg = document_->plan().epsg;
    info.orderId = document_->displayName().toStdString() + "-coverage";
    try {
        writeFileAtomically(path.toStdString(),
                            exportToFormat(format, subject, document_->plan(), coveragePath, info));
    } catch (const std::exception& e) {
        showError(tr("Cannot export to %1: %2").arg(path, plainMessage(fromStd(e.what()))));
        return false;
    }
    rememberExport(subject, format, path);
    statusBar()->showMessage(tr("Exported %1 to %2 (%3)")
                                 .arg(fromStd(exportFormatName(format)), path,
                                      QLocale().formattedDataSize(QFileInfo(path).size())),
                             15000);
    return true;
}

void MainWindow::exportWithDialog(ExportSubject subject) {
    const std::vector<ExportChoice> choices = choicesFor(subject);
    QStringList filters;
    for (const ExportChoice& choice : choices)
        filters << filterOf(choice);
    const ExportDefaults defaults = exportDefaults(subject);
    QString selected = defaults.filter;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export"), defaults.path, filters.join(QStringLiteral(";;")), &selected);
    if (path.isEmpty())
        return;
    const auto index = static_cast<size_t>(std::max<qsizetype>(0, filters.indexOf(selected)));
    const ExportChoice& choice = choices[std::min(index, choices.size() - 1)];
    QString target = path;
    if (QFileInfo(path).suffix().isEmpty())
        target += QLatin1Char('.') + QString::fromUtf8(choice.suffix);
    if (!exportFile(target, choice.format, subject) || !dialogsEnabled_)
        return;
    // Said plainly, with the way to the file: the status bar alone was easy to miss.
    const QString text = subject == ExportSubject::Path    ? tr("Exported the path as %1 to\n%2")
                         : subject == ExportSubject::Zones ? tr("Exported the zones as %1 to\n%2")
                                                           : tr("Exported the plan as %1 to\n%2");
    QMessageBox done(QMessageBox::Information, tr("Export"),
                     text.arg(QString::fromUtf8(choice.label), QDir::toNativeSeparators(target)),
                     QMessageBox::Ok, this);
    QPushButton* show = done.addButton(tr("Show in Folder"), QMessageBox::ActionRole);
    done.exec();
    if (done.clickedButton() == show)
        QDesktopServices::openUrl(QUrl::fromLocalFile(QFileInfo(target).absolutePath()));
}

} // namespace fc::ui
