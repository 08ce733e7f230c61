// The editor's main window: canvas, tools, planning dock, menus and file handling.
// The dialog-free entry points (openFile, saveFile, exportPath, ...) are what the menus
// call after asking for a file name, and what the GUI tests and --screenshot drive.
#pragma once

#include "canvas/OverlayLayer.h"
#include "formats/Export.h"
#include "importers/Import.h"

#include <QMainWindow>
#include <QPageSize>
#include <array>
#include <memory>
#include <optional>

class QAction;
class QLabel;
class QMenu;
class QUndoGroup;

namespace fc::ui {

class CanvasView;
class Autosaver;
class Document;
class LegendDock;
class ProblemsDock;
class PathPreview;
class PlanScene;
class PlanningController;
class PlanningDock;
class TaskListWidget;
class TaskManager;
class TilingMode;
class ToolManager;
class TrainingDock;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return document_.get(); }
    CanvasView* view() const { return view_; }
    PlanScene* scene() const { return scene_; }
    ToolManager* toolManager() const { return tools_; }
    PlanningController* planningController() const { return planner_; }
    // The window's long work (tasks/Task.h) and its list in the status bar.
    TaskManager* taskManager() const { return tasks_; }
    TaskListWidget* taskList() const { return taskList_; }
    PlanningDock* planningDock() const { return planningDock_; }
    TrainingDock* trainingDock() const { return trainingDock_; }
    TilingMode* tilingMode() const { return tilingMode_; }
    LegendDock* legendDock() const { return legendDock_; }
    ProblemsDock* problemsDock() const { return problemsDock_; }
    // Path or Graph view (View menu, Ctrl+1 and Ctrl+2; remembered).
    void setViewMode(ViewMode mode);
    PathPreview* pathPreview() const { return preview_; }
    QAction* overlayAction(OverlayKind kind) const {
        return overlayActions_[static_cast<int>(kind)];
    }

    // Replaces the document by the file's; on failure shows the message and keeps the
    // current document. A GeoJSON site of several buildings opens `building` (1 = the
    // largest), or the one the user picks when dialogs are on.
    bool openFile(const QString& path, std::optional<int> building = std::nullopt);
    // File > Import without the dialog: the imported plan replaces the current document's
    // (one undoable edit, robot settings kept) or opens as a new, unsaved document.
    bool applyImport(const QString& path, const ImportResult& imported, bool asNewDocument);
    // One of samplePlans() by its resource path; the office when empty.
    void openSample(const QString& path = QString());
    // Help > Welcome Page and Getting Started (MainWindowHelp.cpp). The welcome page is
    // shown at start unless the user turned it off; never while dialogs are disabled.
    void showWelcome();
    void showWelcomeAtStart();
    void showHelp();
    void newDocument();
    bool saveFile(const QString& path);
    // Path in the format its extension implies (.geojson .csv .json .yaml .svg .pdf .wkt).
    bool exportPath(const QString& path);
    // Any export of the CLI's `export` command (MainWindowExport.cpp): the planned path, the
    // plan or its zones; the path subject needs a planned document.
    bool exportFile(const QString& path, ExportFormat format, ExportSubject subject);
    // Where the export dialog starts: the last export's folder (else the project's) and
    // the last format chosen for the subject (else the first).
    struct ExportDefaults {
        QString path;
        QString filter;
    };
    ExportDefaults exportDefaults(ExportSubject subject) const;
    // The visible canvas as .png or .svg.
    bool exportView(const QString& path);
    // One-page PDF report of the plan, path, metrics and robot profile.
    bool exportReport(const QString& path, const QPageSize& pageSize = QPageSize(QPageSize::A4));
    // Opens PLAN (or the sample), plans, and saves the whole window as a PNG.
    bool renderScreenshot(const QString& path, const QString& planPath, QString* error,
                          std::optional<int> building = std::nullopt);

    // Offers the document of a session that ended without saving (asks first when dialogs
    // are on). Returns true when it was recovered.
    bool recoverAutosave();
    // The recovery prompt: which file the changes belong to and when they were saved.
    static QString recoveryQuestion();
    Autosaver* autosaver() const { return autosaver_; }
    // Edit > Redo's keys: the platform's Redo keys and Ctrl+Shift+Z, each once.
    static QList<QKeySequence> redoShortcuts();

    // Modal dialogs off (tests, --screenshot): errors go to the status bar and lastError(),
    // and unsaved changes are discarded without asking.
    void setDialogsEnabled(bool enabled) { dialogsEnabled_ = enabled; }
    QString lastError() const { return lastError_; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override; // palette changes restyle the scene
    // Dropping a plan or project file on the window opens it.
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createTools();
    void createMenus();
    void createFileMenu();
    void createViewMenu();
    void createHelpMenu();
    void createStatusBar();
    void setDocument(std::unique_ptr<Document> document);
    void showError(const QString& message);
    void showProblem(const QString& message);
    void loadPendingModel();
    bool maybeSave();
    bool save();
    bool saveAs();
    void openWithDialog();
    void importWithDialog(); // MainWindowImport.cpp
    void exportWithDialog(ExportSubject subject);
    void exportViewWithDialog(const QString& suffix);
    void addRecentFile(const QString& path);
    void updateRecentFilesMenu();
    void updateTitle();

    std::unique_ptr<Document> document_;
    QUndoGroup* undoGroup_;
    PlanScene* scene_;
    CanvasView* view_;
    TaskManager* tasks_;
    PlanningController* planner_;
    ToolManager* tools_;
    PlanningDock* planningDock_;
    TrainingDock* trainingDock_ = nullptr;
    LegendDock* legendDock_ = nullptr;
    ProblemsDock* problemsDock_ = nullptr;
    QAction* pathViewAction_ = nullptr;
    QAction* graphViewAction_ = nullptr;
    PathPreview* preview_ = nullptr;
    TilingMode* tilingMode_ = nullptr;
    Autosaver* autosaver_;
    QMenu* recentFilesMenu_ = nullptr;
    QLabel* coordinates_ = nullptr;
    QLabel* problem_ = nullptr;
    TaskListWidget* taskList_ = nullptr;
    std::array<QAction*, kOverlayKindCount> overlayActions_{};
    bool dialogsEnabled_ = true;
    QString lastError_;
    // The model beside the project just opened, loaded once its plan is prepared.
    QString pendingModel_;
};

} // namespace fc::ui
