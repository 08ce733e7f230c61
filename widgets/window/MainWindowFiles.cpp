// MainWindow: the File menu, recent files, saving, exports and the screenshot command.
#include "canvas/CanvasView.h"
#include "canvas/PlanScene.h"
#include "docks/TrainingDock.h"
#include "document/Conversions.h"
#include "document/Document.h"
#include "document/DocumentFiles.h"
#include "tasks/PlanningController.h"
#include "window/MainWindow.h"
#include "window/PdfReport.h"
#include "window/SamplePlans.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QPageSize>
#include <QPainter>
#include <QSettings>
#include <QStatusBar>
#include <QSvgGenerator>
#include <QUrl>

namespace fc::ui {

namespace {

const char* const kRecentFilesKey = "recentFiles";
constexpr int kMaxRecentFiles = 8;

QString withSuffix(const QString& path, const QString& suffix) {
    return QFileInfo(path).suffix().isEmpty() ? path + QLatin1Char('.') + suffix : path;
}

} // namespace

void MainWindow::createFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, [this]() {
        if (maybeSave())
            newDocument();
    });
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openWithDialog);
    QMenu* samples = file->addMenu(tr("Open &Sample"));
    for (const SamplePlan& sample : samplePlans()) {
        QAction* action = samples->addAction(sample.title, this, [this, path = sample.path]() {
            if (maybeSave())
                openSample(path);
        });
        action->setStatusTip(sample.description);
        action->setToolTip(sample.description);
    }
    file->addAction(tr("&Import…"), QKeySequence(Qt::CTRL | Qt::Key_I), this,
                    &MainWindow::importWithDialog);
    recentFilesMenu_ = file->addMenu(tr("Open &Recent"));
    updateRecentFilesMenu();
    file->addSeparator();
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save &As…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    file->addAction(tr("&Export Path…"), QKeySequence(Qt::CTRL | Qt::Key_E), this,
                    [this]() { exportWithDialog(ExportSubject::Path); });
    file->addAction(tr("Export &Zones…"), this,
                    [this]() { exportWithDialog(ExportSubject::Zones); });
    file->addAction(tr("Export P&lan (WGS84 GeoJSON, WKT)…"), this,
                    [this]() { exportWithDialog(ExportSubject::Plan); });
    file->addAction(tr("Export View as &PNG…"), this,
                    [this]() { exportViewWithDialog(QStringLiteral("png")); });
    file->addAction(tr("Export View as S&VG…"), this,
                    [this]() { exportViewWithDialog(QStringLiteral("svg")); });
    file->addAction(tr("Export &Report as PDF…"), this, [this]() {
        // The page size is chosen with the file type and remembered like the other exports.
        const QString a4 = tr("PDF report, A4 (*.pdf)"), a3 = tr("PDF report, A3 (*.pdf)");
        QSettings settings;
        QString filter =
            settings.value(QStringLiteral("export/report/page")).toString() == QLatin1String("A3")
                ? a3
                : a4;
        QString folder = settings.value(QStringLiteral("export/folder")).toString();
        if (folder.isEmpty() || !QFileInfo(folder).isDir())
            folder = QDir::homePath();
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export Report"),
            QDir(folder).filePath(document_->displayName() + QStringLiteral("-report.pdf")),
            a4 + QStringLiteral(";;") + a3, &filter);
        if (path.isEmpty())
            return;
        const bool large = filter == a3;
        settings.setValue(QStringLiteral("export/report/page"),
                          large ? QStringLiteral("A3") : QStringLiteral("A4"));
        settings.setValue(QStringLiteral("export/folder"), QFileInfo(path).absolutePath());
        exportReport(withSuffix(path, QStringLiteral("pdf")),
                     QPageSize(large ? QPageSize::A3 : QPageSize::A4));
    });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
}

namespace {

// The first local file of a drag with a plan's or project's extension, else empty.
QString droppedPlan(const QMimeData* data) {
    for (const QUrl& url : data->urls()) {
        const QString suffix = QFileInfo(url.toLocalFile()).suffix().toLower();
        if (url.isLocalFile() &&
            (suffix == QLatin1String("fcproj") || suffix == QLatin1String("geojson") ||
             suffix == QLatin1String("json")))
            return url.toLocalFile();
    }
    return {};
}

} // namespace

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (!droppedPlan(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QString path = droppedPlan(event->mimeData());
    if (path.isEmpty() || !maybeSave())
        return;
    event->acceptProposedAction();
    openFile(path);
}

void MainWindow::openWithDialog() {
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Plan"), QString(),
        tr("Plans and projects (*.fcproj *.geojson *.json);;FloorCover projects (*.fcproj);;"
           "GeoJSON plans (*.geojson *.json)"));
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::save() {
    if (document_->fileName().isEmpty())
        return saveAs();
    return saveFile(document_->fileName());
}

bool MainWindow::saveAs() {
    const QString suggestion = document_->displayName() + QStringLiteral(".fcproj");
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Project"), suggestion,
                                                      tr("FloorCover projects (*.fcproj)"));
    return !path.isEmpty() && saveFile(withSuffix(path, QStringLiteral("fcproj")));
}

bool MainWindow::saveFile(const QString& path) {
    QString error;
    if (!saveDocument(*document_, path, &error)) {
        showError(error);
        return false;
    }
    addRecentFile(path);
    // The trained model goes beside the project, so that it is there when it is opened.
    if (trainingDock_->hasModel() && !trainingDock_->saveModel(modelFileFor(path))) {
        showError(tr("The project was saved, but not its trained model: %1")
                      .arg(trainingDock_->lastError()));
        return true;
    }
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value(QLatin1String(kRecentFilesKey)).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(QLatin1String(kRecentFilesKey), files);
    updateRecentFilesMenu();
}

void MainWindow::updateRecentFilesMenu() {
    recentFilesMenu_->clear();
    const QStringList files = QSettings().value(QLatin1String(kRecentFilesKey)).toStringList();
    for (const QString& path : files) {
        recentFilesMenu_
            ->addAction(QFileInfo(path).fileName(), this,
                        [this, path]() {
                            if (maybeSave())
                                openFile(path);
                        })
            ->setToolTip(path);
    }
    recentFilesMenu_->setEnabled(!files.isEmpty());
}

bool MainWindow::exportView(const QString& path) {
    const QSize size = view_->viewport()->size();
    bool written = false;
    if (path.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive)) {
        QSvgGenerator generator;
        generator.setFileName(path);
        generator.setSize(size);
        generator.setViewBox(QRect(QPoint(0, 0), size));
        generator.setTitle(document_->displayName());
        generator.setDescription(tr("Floor plan exported by FloorCover"));
        QPainter painter;
        if (painter.begin(&generator)) {
            view_->render(&painter);
            written = painter.end();
        }
    } else {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        view_->render(&painter);
        painter.end();
        written = image.save(path);
    }
    if (!written) {
        showError(tr("Cannot write %1.").arg(path));
        return false;
    }
    statusBar()->showMessage(tr("Exported the view to %1").arg(path), 5000);
    return true;
}

void MainWindow::exportViewWithDialog(const QString& suffix) {
    const QString filter =
        suffix == QLatin1String("svg") ? tr("SVG images (*.svg)") : tr("PNG images (*.png)");
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export View"), document_->displayName() + QLatin1Char('.') + suffix, filter);
    if (!path.isEmpty())
        exportView(withSuffix(path, suffix));
}

bool MainWindow::exportReport(const QString& path, const QPageSize& pageSize) {
    const auto result = planner_->result();
    if (!result) {
        showError(tr("There is no plan to report: plan the current document first."));
        return false;
    }
    QString error;
    if (!writePdfReport(path, *document_, *result, *scene_, pageSize, &error)) {
        showError(error);
        return false;
    }
    statusBar()->showMessage(tr("Exported the report to %1").arg(path), 5000);
    return true;
}

bool MainWindow::renderScreenshot(const QString& path, const QString& planPath, QString* error,
                                  std::optional<int> building) {
    setDialogsEnabled(false);
    setAttribute(Qt::WA_DontShowOnScreen); // rendered, never mapped on a real display
    resize(1400, 900);
    show();
    if (planPath.isEmpty())
        openSample();
    else if (!openFile(planPath, building)) {
        *error = lastError_;
        return false;
    }
    if (document_->needsRepair()) { // the editor would open it for repair; nothing to plan
        *error = tr("%1: %2").arg(planPath, fromStd(document_->problems().front().message));
        return false;
    }
    if (!planner_->planAndWait()) {
        *error = tr("planning failed: %1").arg(planner_->errorMessage());
        return false;
    }
    QApplication::processEvents();
    view_->fitToPlan();
    QApplication::processEvents();
    if (!grab().toImage().save(path, "PNG")) {
        *error = tr("cannot write %1").arg(path);
        return false;
    }
    return true;
}

} // namespace fc::ui
