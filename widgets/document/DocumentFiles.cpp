#include "document/DocumentFiles.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace fc::ui {

const char* const kSamplePlanPath = ":/plans/office.geojson";

namespace {

// The translation context of this file's messages (lupdate reads the macro).
struct DocumentFilesText {
    Q_DECLARE_TR_FUNCTIONS(fc::ui::DocumentFiles)
};

// Qt resources are not visible to the planner's file functions: read them here.
Project loadResource(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw InputError(path.toStdString() + ": cannot read the embedded file");
    const std::string text = file.readAll().toStdString();
    try {
        Project project;
        if (path.endsWith(QLatin1String(".fcproj")))
            project = readProject(text);
        else
            project.plan = readGeoJsonPlan(text);
        project.plan.name = QFileInfo(path).completeBaseName().toStdString();
        return project;
    } catch (const InputError& e) {
        throw InputError(path.toStdString() + ": " + e.what());
    }
}

// The project of `path`, or of one building of a site (see loadDocument). False: the user
// chose none.
bool loadProjectOrBuilding(const QString& path, std::optional<int> building,
                           const BuildingChooser& chooseBuilding, Project& project) {
    if (path.startsWith(QLatin1Char(':'))) {
        project = loadResource(path);
        return true;
    }
    try {
        project = loadProjectFile(path.toStdString(), building);
    } catch (const SiteError& e) {
        if (!chooseBuilding)
            throw;
        building = chooseBuilding(e.buildingAreas());
        if (!building)
            return false;
        project = loadProjectFile(path.toStdString(), building);
    }
    // Saved beside the site under its own name ("site-building-2.fcproj").
    if (building && !path.endsWith(QLatin1String(".fcproj"), Qt::CaseInsensitive))
        project.plan.name += "-building-" + std::to_string(*building);
    return true;
}

} // namespace

std::unique_ptr<Document> loadDocument(const QString& path, QString* error, QStringList* notes,
                                       std::optional<int> building,
                                       const BuildingChooser& chooseBuilding) {
    if (error)
        error->clear();
    try {
        Project project;
        if (!loadProjectOrBuilding(path, building, chooseBuilding, project))
            return nullptr;
        if (notes)
            for (const std::string& note : project.notes)
                notes->append(fromStd(note));
        try {
            // A plan the planner refuses still opens, read-only with its problems listed
            // (Document::needsRepair), so that it can be repaired rather than lost.
            project.robot.validate();
        } catch (const InputError& e) {
            throw InputError(path.toStdString() + ": " + e.what());
        }
        auto document = std::make_unique<Document>(std::move(project));
        if (path.endsWith(QLatin1String(".fcproj"), Qt::CaseInsensitive) &&
            !path.startsWith(QLatin1Char(':')))
            document->setFileName(QFileInfo(path).absoluteFilePath());
        return document;
    } catch (const std::exception& e) {
        if (error)
            *error = plainMessage(fromStd(e.what())); // the path stays, the rest reworded
        return nullptr;
    }
}

QString modelFileFor(const QString& projectPath) {
    const QFileInfo info(projectPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".fcdqn"));
}

bool saveDocument(Document& document, const QString& path, QString* error) {
    try {
        writeFileAtomically(path.toStdString(), writeProject(document.project()));
    } catch (const std::exception& e) {
        if (error) {
            // The planner names the file too: said once, in front.
            QString reason = fromStd(e.what());
            const QString named = path + QStringLiteral(": ");
            if (reason.startsWith(named))
                reason = reason.mid(named.size());
            *error = DocumentFilesText::tr("Cannot save %1: %2").arg(path, plainMessage(reason));
        }
        return false;
    }
    document.setFileName(QFileInfo(path).absoluteFilePath());
    document.markSaved();
    return true;
}

} // namespace fc::ui
