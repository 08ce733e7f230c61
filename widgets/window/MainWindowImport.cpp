// MainWindow: File > Import (DXF drawings, ROS occupancy maps, WKT, GeoJSON, and 3D building
// models through their own dialog: storey, cut height, door leaves).
#include "dialogs/BuildingImportDialog.h"
#include "dialogs/ImportDialog.h"
#include "document/Conversions.h"
#include "document/Document.h"
#include "model/Validation.h"
#include "window/MainWindow.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QStatusBar>
#include <algorithm>

namespace fc::ui {

void MainWindow::importWithDialog() {
    QStringList patterns;
    for (const std::string& extension : importableExtensions())
        patterns << QStringLiteral("*.") + fromStd(extension);
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import Plan"), QString(),
        tr("Importable plans (%1);;DXF drawings (*.dxf);;ROS occupancy maps (*.yaml *.yml);;"
           "WKT polygons (*.wkt);;GeoJSON plans (*.geojson *.json);;"
           "3D building models (*.ifc *.obj *.gltf *.glb *.stl)")
            .arg(patterns.join(QLatin1Char(' '))));
    if (path.isEmpty())
        return;
    const std::vector<std::string> models = buildingModelExtensions();
    if (std::find(models.begin(), models.end(), QFileInfo(path).suffix().toLower().toStdString()) !=
        models.end()) {
        BuildingImportDialog dialog(path, this);
        if (dialog.exec() != QDialog::Accepted || !dialog.hasResult())
            return;
        const bool asNew = !document_->plan().boundary.empty();
        if (asNew && !maybeSave())
            return;
        applyImport(path, dialog.result(), asNew);
        return;
    }
    ImportDialog dialog(path, this);
    // An untouched empty document is simply replaced by the import.
    dialog.setOpenAsNewDocument(!document_->plan().boundary.empty());
    if (dialog.exec() != QDialog::Accepted || !dialog.result())
        return;
    if (dialog.openAsNewDocument() && !maybeSave())
        return;
    applyImport(path, *dialog.result(), dialog.openAsNewDocument());
}

bool MainWindow::applyImport(const QString& path, const ImportResult& imported,
                             bool asNewDocument) {
    const QString name = QFileInfo(path).fileName();
    // A plan with problems always comes as a new document, read-only until repaired: the
    // current one stays as it is.
    if (!asNewDocument &&
        !planProblems(normalizedPlan(imported.project.plan), RobotProfile{}).empty()) {
        if (!maybeSave())
            return false;
        asNewDocument = true;
    }
    if (asNewDocument) {
        auto document = std::make_unique<Document>(imported.project);
        document->markModified(); // nothing saved yet: closing asks
        setDocument(std::move(document));
    } else {
        Project project = document_->project(); // keep robot, sweep and solver
        project.plan = imported.project.plan;
        project.selectedRooms.clear();
        project.hasStart = imported.project.hasStart;
        project.start = imported.project.start;
        project.hasEnd = false;
        if (!document_->replaceProject(project, tr("Import %1").arg(name)))
            return false; // the document said why (editRejected)
    }
    statusBar()->showMessage(
        tr("Imported %1 (%n warning(s))", nullptr, static_cast<int>(imported.warnings.size()))
            .arg(name),
        5000);
    return true;
}

} // namespace fc::ui
