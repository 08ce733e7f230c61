#include "window/MainWindow.h"

#include "canvas/CanvasView.h"
#include "canvas/PathPreview.h"
#include "canvas/PlanScene.h"
#include "dialogs/CompareDialog.h"
#include "dialogs/PreferencesDialog.h"
#include "dialogs/SiteBuildingChoice.h"
#include "docks/LegendDock.h"
#include "docks/PathPreviewBar.h"
#include "docks/PlanningDock.h"
#include "docks/ProblemsDock.h"
#include "docks/TrainingDock.h"
#include "document/Autosaver.h"
#include "document/Document.h"
#include "document/DocumentFiles.h"
#include "modes/tiling/TilingMode.h"
#include "tasks/PlanningController.h"
#include "tasks/Task.h"
#include "tasks/TaskListWidget.h"
#include "tools/DrawPolygonTool.h"
#include "tools/EditVerticesTool.h"
#include "tools/PickRoomTool.h"
#include "tools/PlaceEndpointTool.h"
#include "tools/SplitRoomTool.h"
#include "tools/ToolManager.h"
#include "window/WheelGuard.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoGroup>
#include <QUndoStack>
#include <QUndoView>

namespace fc::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), undoGroup_(new QUndoGroup(this)), scene_(new PlanScene(this)),
      view_(new CanvasView(this)), tasks_(new TaskManager(this)),
      planner_(new PlanningController(tasks_, this)), tools_(new ToolManager(this)),
      planningDock_(new PlanningDock(this)), autosaver_(new Autosaver(this)) {
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    WheelGuard::install();
    view_->setScene(scene_);
    setCentralWidget(view_);
    scene_->setPlanningController(planner_);
    planningDock_->setPlanningController(planner_);
    addDockWidget(Qt::RightDockWidgetArea, planningDock_);
    preview_ = new PathPreview(scene_, planner_, this);
    planningDock_->addSection(new PathPreviewBar(preview_));
    trainingDock_ = new TrainingDock(this);
    addDockWidget(Qt::RightDockWidgetArea, trainingDock_);
    // Training follows the plan's graph; its model serves solver "dqn".
    connect(planner_, &PlanningController::preparedChanged, this, [this] {
        trainingDock_->setPreparedPlan(planner_->prepared());
        loadPendingModel();
    });
    connect(trainingDock_, &TrainingDock::modelReady, planner_, &PlanningController::setModelPath);
    tilingMode_ = new TilingMode(this, scene_);
    problemsDock_ = new ProblemsDock(this);
    addDockWidget(Qt::RightDockWidgetArea, problemsDock_);
    problemsDock_->hide(); // shown when a plan needs repair
    connect(problemsDock_, &ProblemsDock::locate, this, [this](QPointF at) {
        view_->centerOn(at);
        scene_->setProblemFocus(at);
    });

    createTools();
    createMenus();
    createStatusBar();
    connect(planner_, &PlanningController::errorChanged, this, &MainWindow::showProblem);
    setDocument(std::make_unique<Document>());
    resize(1280, 800);
}

MainWindow::~MainWindow() {
    delete preview_; // its robot item lives in the scene
    // The scene and the tools refer to the document: detach them before it goes.
    tools_->setContext(nullptr, nullptr);
    scene_->setDocument(nullptr);
    planner_->setDocument(nullptr);
}

void MainWindow::createTools() {
    tools_->setConfirmation([this](const QString& question) {
        return !dialogsEnabled_ ||
               QMessageBox::question(this, tr("FloorCover"), question) == QMessageBox::Yes;
    });
    tools_->registerTool(new EditVerticesTool);
    tools_->registerTool(new DrawPolygonTool(PolygonRole::Boundary));
    tools_->registerTool(new DrawPolygonTool(PolygonRole::Obstacle));
    tools_->registerTool(new DrawPolygonTool(PolygonRole::Room));
    tools_->registerTool(new PickRoomTool);
    tools_->registerTool(new SplitRoomTool);
    tools_->registerTool(new PlaceEndpointTool(Endpoint::Start));
    tools_->registerTool(new PlaceEndpointTool(Endpoint::End));
    connect(tools_, &ToolManager::activeToolChanged, view_, &CanvasView::setTool);
    connect(tools_, &ToolManager::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, 10000); });
    view_->setTool(tools_->activeTool());

    auto* toolBar = addToolBar(tr("Tools"));
    toolBar->setObjectName(QStringLiteral("ToolsToolBar"));
    toolBar->addActions(tools_->actions());
}

QList<QKeySequence> MainWindow::redoShortcuts() {
    // The platform's Redo keys plus Ctrl+Shift+Z, each once: a key bound twice, even to the
    // same action, is an "ambiguous shortcut overload" and does nothing.
    QList<QKeySequence> keys = QKeySequence::keyBindings(QKeySequence::Redo);
    const QKeySequence ctrlShiftZ(Qt::CTRL | Qt::SHIFT | Qt::Key_Z);
    if (!keys.contains(ctrlShiftZ))
        keys.append(ctrlShiftZ);
    return keys;
}

void MainWindow::createMenus() {
    createFileMenu();

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = undoGroup_->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = undoGroup_->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts(redoShortcuts());
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QAction* preferences = edit->addAction(tr("&Preferences…"), this, [this]() {
        PreferencesDialog dialog(this);
        dialog.exec();
    });
    preferences->setMenuRole(QAction::PreferencesRole);

    createViewMenu();

    QMenu* toolsMenu = menuBar()->addMenu(tr("&Tools"));
    toolsMenu->addActions(tools_->actions());

    QMenu* planMenu = menuBar()->addMenu(tr("&Plan"));
    QAction* plan = planMenu->addAction(tr("&Plan Path"), planner_, &PlanningController::plan);
    planMenu->addAction(tr("&Compare Solvers…"), this, [this] {
        PlanRequest request = planRequestFor(document_->project());
        request.modelPath = planner_->modelPath();
        auto* dialog = new CompareDialog(std::move(request), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
        dialog->start();
    });
    plan->setShortcut(Qt::Key_F5);
    // Live replanning: remembered across sessions, on unless the user turned it off.
    QAction* live = planMenu->addAction(tr("&Replan After Each Edit"));
    live->setObjectName(QStringLiteral("liveReplanning"));
    live->setCheckable(true);
    live->setToolTip(tr("Plan the path again in the background whenever the floor, the rooms "
                        "or the start and end change; the old path stays greyed until then."));
    live->setChecked(QSettings().value(QStringLiteral("planning/live"), true).toBool());
    planner_->setLiveReplanning(live->isChecked());
    connect(live, &QAction::toggled, this, [this](bool on) {
        planner_->setLiveReplanning(on);
        QSettings().setValue(QStringLiteral("planning/live"), on);
    });
    planMenu->addAction(problemsDock_->repairAction());
    planMenu->addSeparator();
    planMenu->addAction(tilingMode_->action());

    createHelpMenu();
}

void MainWindow::createViewMenu() {
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->addAction(tr("&Fit to Plan"), QKeySequence(Qt::CTRL | Qt::Key_0), view_,
                        &CanvasView::fitToPlan);
    viewMenu->addAction(tr("Zoom &In"), QKeySequence::ZoomIn, view_, &CanvasView::zoomIn);
    viewMenu->addAction(tr("Zoom &Out"), QKeySequence::ZoomOut, view_, &CanvasView::zoomOut);
    viewMenu->addSeparator();
    QAction* grid = viewMenu->addAction(tr("Show &Grid"));
    grid->setCheckable(true);
    grid->setChecked(view_->isGridVisible());
    connect(grid, &QAction::toggled, view_, &CanvasView::setGridVisible);
    QAction* snapGrid = viewMenu->addAction(tr("Snap to G&rid"));
    snapGrid->setCheckable(true);
    snapGrid->setChecked(view_->snapper().snapToGrid);
    connect(snapGrid, &QAction::toggled, this,
            [this](bool on) { view_->snapper().snapToGrid = on; });
    QAction* snapVertices = viewMenu->addAction(tr("Snap to &Vertices"));
    snapVertices->setCheckable(true);
    snapVertices->setChecked(view_->snapper().snapToVertices);
    connect(snapVertices, &QAction::toggled, this,
            [this](bool on) { view_->snapper().snapToVertices = on; });

    viewMenu->addSeparator();
    // Path for the people who clean, Graph for whoever studies the planner's internals.
    auto* modes = new QActionGroup(this);
    const auto addMode = [&](const QString& text, ViewMode mode, const QKeySequence& keys,
                             const QString& name, const QString& tip) {
        QAction* action = viewMenu->addAction(text);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setShortcut(keys);
        action->setStatusTip(tip);
        action->setToolTip(tip);
        modes->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode]() { setViewMode(mode); });
        return action;
    };
    pathViewAction_ = addMode(tr("&Path View"), ViewMode::Path, QKeySequence(Qt::CTRL | Qt::Key_1),
                              QStringLiteral("pathView"),
                              tr("The floor, the rooms and the path with its start and end"));
    graphViewAction_ = addMode(tr("&Graph View"), ViewMode::Graph,
                               QKeySequence(Qt::CTRL | Qt::Key_2), QStringLiteral("graphView"),
                               tr("Adds the planner's cells, corners and graph edges"));

    QMenu* overlays = viewMenu->addMenu(tr("&Overlays"));
    for (int i = 0; i < kOverlayKindCount; ++i) {
        const auto kind = static_cast<OverlayKind>(i);
        QAction* action = overlays->addAction(overlayName(kind));
        action->setCheckable(true);
        action->setChecked(scene_->overlays()->isVisible(kind));
        connect(action, &QAction::toggled, this,
                [this, kind](bool on) { scene_->overlays()->setVisible(kind, on); });
        overlayActions_[i] = action;
    }
    viewMenu->addSeparator();
    viewMenu->addAction(planningDock_->toggleViewAction());
    legendDock_ = new LegendDock(overlayActions_, this);
    addDockWidget(Qt::RightDockWidgetArea, legendDock_);
    // The undo history, as in Tiled: click an entry to go back to that state.
    auto* history = new QDockWidget(tr("History"), this);
    history->setObjectName(QStringLiteral("HistoryDock"));
    history->setWidget(new QUndoView(undoGroup_));
    addDockWidget(Qt::RightDockWidgetArea, history);
    tabifyDockWidget(legendDock_, history);
    tabifyDockWidget(history, trainingDock_);
    tabifyDockWidget(trainingDock_, planningDock_);
    planningDock_->raise(); // the planning panel in front
    viewMenu->addAction(legendDock_->toggleViewAction());
    viewMenu->addAction(history->toggleViewAction());
    viewMenu->addAction(trainingDock_->toggleViewAction());
    viewMenu->addAction(problemsDock_->toggleViewAction());
    const bool graph =
        QSettings().value(QStringLiteral("view/mode")).toString() == QLatin1String("graph");
    setViewMode(graph ? ViewMode::Graph : ViewMode::Path);
}

void MainWindow::setViewMode(ViewMode mode) {
    scene_->setViewMode(mode);
    (mode == ViewMode::Path ? pathViewAction_ : graphViewAction_)->setChecked(true);
    for (int i = 0; i < kOverlayKindCount; ++i)
        overlayActions_[i]->setEnabled(mode == ViewMode::Graph ||
                                       !isGraphOverlay(static_cast<OverlayKind>(i)));
    legendDock_->setViewMode(mode);
    QSettings().setValue(QStringLiteral("view/mode"), mode == ViewMode::Graph
                                                          ? QStringLiteral("graph")
                                                          : QStringLiteral("path"));
}

void MainWindow::createStatusBar() {
    problem_ = new QLabel;
    problem_->setStyleSheet(QStringLiteral("color: #d03030"));
    coordinates_ = new QLabel;
    coordinates_->setMinimumWidth(200);
    taskList_ = new TaskListWidget(tasks_);
    statusBar()->addPermanentWidget(problem_, 1);
    statusBar()->addPermanentWidget(taskList_);
    statusBar()->addPermanentWidget(coordinates_);
    connect(view_, &CanvasView::cursorMoved, this, [this](QPointF p) {
        coordinates_->setText(tr("x %1 m   y %2 m").arg(p.x(), 0, 'f', 2).arg(p.y(), 0, 'f', 2));
    });
}

void MainWindow::setDocument(std::unique_ptr<Document> document) {
    std::unique_ptr<Document> previous = std::move(document_);
    document_ = std::move(document);
    Document* doc = document_.get();
    undoGroup_->addStack(doc->undoStack());
    undoGroup_->setActiveStack(doc->undoStack());
    scene_->setDocument(doc);
    view_->setDocument(doc);
    planner_->setDocument(doc);
    tilingMode_->setDocument(doc);
    planningDock_->setDocument(doc);
    problemsDock_->setDocument(doc);
    tools_->setContext(doc, scene_);
    autosaver_->setDocument(doc);
    connect(doc, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(doc, &Document::fileNameChanged, this, &MainWindow::updateTitle);
    connect(doc, &Document::editRejected, this, &MainWindow::showProblem);
    // A successful edit (or undo) clears the last refusal; the planner then reports anew.
    connect(doc->undoStack(), &QUndoStack::indexChanged, this,
            [this]() { showProblem(planner_->errorMessage()); });
    showProblem(QString());
    updateTitle();
    view_->fitToPlan();
    previous.reset(); // after everything points at the new document
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] – FloorCover").arg(document_->displayName()));
    setWindowModified(document_->isModified());
}

void MainWindow::showError(const QString& message) {
    lastError_ = message;
    statusBar()->showMessage(message, 15000);
    if (dialogsEnabled_)
        QMessageBox::critical(this, tr("FloorCover"), message);
}

void MainWindow::showProblem(const QString& message) {
    problem_->setText(message);
    if (!message.isEmpty())
        lastError_ = message;
}

bool MainWindow::maybeSave() {
    if (!document_->isModified() || !dialogsEnabled_)
        return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"),
        tr("%1 has unsaved changes. Save them?").arg(document_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    autosaver_->discard(); // a normal end: nothing to recover next time
    tasks_->cancelAll();   // returns at once; the pool waits for them when the window goes
    event->accept();
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::PaletteChange) {
        scene_->restyle();
        view_->resetCachedContent(); // the grid's colours
    }
    QMainWindow::changeEvent(event);
}

QString MainWindow::recoveryQuestion() {
    const QString original = Autosaver::recoveryOriginalFile();
    const QString what =
        original.isEmpty() ? tr("an untitled plan")
                           : tr("%1 (in %2)")
                                 .arg(QFileInfo(original).fileName(),
                                      QDir::toNativeSeparators(QFileInfo(original).absolutePath()));
    return tr("FloorCover did not close normally last time. Recover the unsaved changes to %1, "
              "saved automatically %2?")
        .arg(what, QLocale().toString(Autosaver::recoveryTime(), QLocale::ShortFormat));
}

bool MainWindow::recoverAutosave() {
    if (!Autosaver::hasRecovery())
        return false;
    if (dialogsEnabled_ && QMessageBox::question(this, tr("Recover unsaved changes"),
                                                 recoveryQuestion()) != QMessageBox::Yes) {
        autosaver_->discard();
        return false;
    }
    QString error;
    std::unique_ptr<Document> document = Autosaver::recover(&error);
    if (!document) {
        showError(error);
        return false;
    }
    setDocument(std::move(document));
    statusBar()->showMessage(tr("Recovered the unsaved changes of the last session."), 10000);
    return true;
}

void MainWindow::newDocument() {
    setDocument(std::make_unique<Document>());
    tools_->setActiveTool(tools_->findTool(QStringLiteral("drawBoundary")));
}

bool MainWindow::openFile(const QString& path, std::optional<int> building) {
    QString error;
    QStringList notes;
    BuildingChooser chooseBuilding;
    if (dialogsEnabled_) // a site of several buildings: which one (else refused with its list)
        chooseBuilding = [this, &path](const std::vector<double>& areas) {
            return askForSiteBuilding(this, QFileInfo(path).fileName(), areas);
        };
    std::unique_ptr<Document> document =
        loadDocument(path, &error, &notes, building, chooseBuilding);
    if (!document) {
        if (!error.isEmpty()) // empty: no building chosen
            showError(error);
        return false;
    }
    setDocument(std::move(document));
    pendingModel_.clear();
    if (path.endsWith(QLatin1String(".fcproj"), Qt::CaseInsensitive) &&
        QFileInfo::exists(modelFileFor(path)))
        pendingModel_ = modelFileFor(path);
    if (!path.startsWith(QLatin1Char(':')))
        addRecentFile(path);
    if (notes.isEmpty())
        statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
    else // e.g. longitude/latitude reprojected: the plan is not where the file had it
        statusBar()->showMessage(tr("Opened %1: %2").arg(path, notes.join(QStringLiteral("; "))),
                                 20000);
    return true;
}

void MainWindow::loadPendingModel() {
    if (pendingModel_.isEmpty() || !planner_->prepared())
        return;
    const QString path = pendingModel_;
    pendingModel_.clear();
    if (trainingDock_->loadModel(path))
        statusBar()->showMessage(tr("Loaded the trained model %1").arg(path), 5000);
    else // e.g. trained for another plan: the project opens without it
        showProblem(tr("The trained model beside the project was not loaded (%1): %2")
                        .arg(QFileInfo(path).fileName(), trainingDock_->lastError()));
}

void MainWindow::openSample(const QString& path) {
    openFile(path.isEmpty() ? QString::fromLatin1(kSamplePlanPath) : path);
}

} // namespace fc::ui
