// MainWindow: File > Export Path / Zones / Plan, through the planner's writers (the same
// code as `floorcover-cli export`).
#include "document/Conversions.h"
#include "document/Document.h"
#include "formats/FileIO.h"
#include "tasks/PlanningController.h"
#include "window/MainWindow.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QStatusBar>

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

} // namespace

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
        showError(tr("Cannot export to %1: %2").arg(path, fromStd(e.what())));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1 to %2").arg(fromStd(exportFormatName(format)), path),
                             5000);
    return true;
}

void MainWindow::exportWithDialog(ExportSubject subject) {
    const std::vector<ExportChoice> choices = choicesFor(subject);
    QStringList filters;
    for (const ExportChoice& choice : choices)
        filters << filterOf(choice);
    const char* what = subject == ExportSubject::Path    ? "path"
                       : subject == ExportSubject::Zones ? "zones"
                                                         : "plan";
    QString selected = filters.front();
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export"),
        document_->displayName() + QLatin1Char('-') + QLatin1String(what) + QLatin1Char('.') +
            QString::fromUtf8(choices.front().suffix),
        filters.join(QStringLiteral(";;")), &selected);
    if (path.isEmpty())
        return;
    const auto index = static_cast<size_t>(std::max<qsizetype>(0, filters.indexOf(selected)));
    const ExportChoice& choice = choices[std::min(index, choices.size() - 1)];
    QString target = path;
    if (QFileInfo(path).suffix().isEmpty())
        target += QLatin1Char('.') + QString::fromUtf8(choice.suffix);
    exportFile(target, choice.format, subject);
}

} // namespace fc::ui
