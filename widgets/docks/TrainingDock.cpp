#include "docks/TrainingDock.h"

#include "document/PlannerMessages.h"
#include "learning/dqn/GeneralistModel.h"
#include "tasks/Task.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStandardPaths>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <cstdio>
#include <optional>
#include <qcustomplot.h>

namespace fc::ui {
namespace {

constexpr int kRewardGraph = 0, kAverageGraph = 1, kLossGraph = 2, kEpsilonGraph = 3, kGapGraph = 4;

QString minutesAndSeconds(double seconds) {
    const int s = static_cast<int>(std::lround(std::max(0.0, seconds)));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

} // namespace

TrainingDock::TrainingDock(QWidget* parent)
    : QDockWidget(tr("Training"), parent), tasks_(TaskManager::forObject(this)) {
    setObjectName(QStringLiteral("TrainingDock"));
    buildUi();
    setState(State::Idle);
}

TrainingDock::~TrainingDock() {
    // The tasks keep the session; they see the cancellation and end on their own.
    if (training_)
        training_->cancel();
    if (evaluation_)
        evaluation_->cancel();
}

void TrainingDock::buildUi() {
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);

    auto* controls = new QHBoxLayout;
    setting_ = new QComboBox(body);
    // Graph state first: the default, the one that learns on floors of many corners.
    setting_->addItem(tr("Graph state"), QStringLiteral("graph"));
    setting_->addItem(tr("Improved"), QStringLiteral("improved"));
    setting_->addItem(tr("Paper"), QStringLiteral("paper"));
    setting_->setToolTip(tr("Improved: masking, graph-cost reward, cost channels and a refined "
                            "walk. Graph state: the same with per-corner features and a "
                            "per-corner network (faster on large floors). Paper: the published "
                            "setting."));
    fromGeneralist_ = new QCheckBox(tr("From the generalist"), body);
    fromGeneralist_->setChecked(true);
    fromGeneralist_->setToolTip(
        tr("Start from the built-in generalist model, trained on generated floors (what solver "
           "dqn uses before any training), and fine-tune it for this plan. Off: start from "
           "random weights. Graph state only."));
    connect(setting_, &QComboBox::currentIndexChanged, this, [this] { setState(state_); });
    budget_ = new QDoubleSpinBox(body);
    budget_->setRange(5.0, 24 * 3600.0);
    budget_->setValue(300.0);
    budget_->setSuffix(tr(" s"));
    budget_->setToolTip(tr("Training time for one run"));
    startButton_ = new QPushButton(tr("Start"), body);
    pauseButton_ = new QPushButton(tr("Pause"), body);
    stopButton_ = new QPushButton(tr("Stop"), body);
    startButton_->setToolTip(tr("Train the learnt planner (solver dqn) for this plan in the "
                                "background; the curve shows its reward per episode."));
    pauseButton_->setToolTip(tr("Pause training and keep the model so far; Resume goes on."));
    stopButton_->setToolTip(tr("End training; the model so far is kept for solver dqn."));
    controls->addWidget(setting_);
    controls->addWidget(budget_);
    controls->addWidget(startButton_);
    controls->addWidget(pauseButton_);
    controls->addWidget(stopButton_);
    layout->addLayout(controls);
    layout->addWidget(fromGeneralist_); // its own row: the dock stays as narrow as before

    progress_ = new QProgressBar(body);
    progress_->setRange(0, 1000);
    layout->addWidget(progress_);
    status_ = new QLabel(tr("No model yet"), body);
    status_->setWordWrap(true);
    layout->addWidget(status_);

    plot_ = new QCustomPlot(body);
    plot_->setMinimumHeight(220);
    plot_->setNoAntialiasingOnDrag(true);
    plot_->xAxis->setLabel(tr("Episode"));
    plot_->yAxis->setLabel(tr("Reward"));
    plot_->yAxis2->setLabel(tr("Loss / epsilon"));
    plot_->yAxis2->setVisible(true);
    plot_->legend->setVisible(true);
    plot_->legend->setFont(QFont(font().family(), 8));
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
    QCPGraph* reward = plot_->addGraph();
    reward->setName(tr("Episode reward"));
    reward->setLineStyle(QCPGraph::lsNone);
    reward->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(120, 150, 200), 2));
    QCPGraph* average = plot_->addGraph();
    average->setName(tr("Moving average (100)"));
    average->setPen(QPen(QColor(20, 90, 200), 2));
    QCPGraph* loss = plot_->addGraph(plot_->xAxis, plot_->yAxis2);
    loss->setName(tr("Loss"));
    loss->setPen(QPen(QColor(220, 100, 30), 1));
    QCPGraph* epsilon = plot_->addGraph(plot_->xAxis, plot_->yAxis2);
    epsilon->setName(tr("Epsilon"));
    epsilon->setPen(QPen(QColor(120, 120, 120), 1, Qt::DashLine));
    // What training buys: the policy alone on the model's fixed test queries, on its own axis.
    QCPAxis* gapAxis = plot_->axisRect()->addAxis(QCPAxis::atRight);
    gapAxis->setLabel(tr("Policy gap (%)"));
    gapAxis->setLabelColor(QColor(40, 140, 60));
    gapAxis->setTickLabelColor(QColor(40, 140, 60));
    QCPGraph* gap = plot_->addGraph(plot_->xAxis, gapAxis);
    gap->setName(tr("Policy alone, % above the reference"));
    gap->setPen(QPen(QColor(40, 140, 60), 2));
    gap->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QColor(40, 140, 60), 6));
    layout->addWidget(plot_, 1);

    auto* files = new QHBoxLayout;
    saveButton_ = new QPushButton(tr("Save Model…"), body);
    loadButton_ = new QPushButton(tr("Load Model…"), body);
    saveButton_->setToolTip(tr("Save the trained model to a .fcdqn file (saving the project "
                               "also saves it beside the project)."));
    loadButton_->setToolTip(tr("Load a model trained for this plan from a .fcdqn file."));
    evaluateButton_ = new QPushButton(tr("Evaluate"), body);
    evaluateButton_->setToolTip(tr("Plan the model's test queries with it and compare with the "
                                   "exact or heuristic solver"));
    files->addWidget(saveButton_);
    files->addWidget(loadButton_);
    files->addWidget(evaluateButton_);
    files->addStretch(1);
    layout->addLayout(files);
    setWidget(body);

    connect(startButton_, &QPushButton::clicked, this, &TrainingDock::start);
    connect(pauseButton_, &QPushButton::clicked, this, [this] {
        if (state_ == State::Running)
            pause();
        else if (state_ == State::Paused)
            resumeTraining();
    });
    connect(stopButton_, &QPushButton::clicked, this, &TrainingDock::stop);
    connect(saveButton_, &QPushButton::clicked, this, &TrainingDock::saveWithDialog);
    connect(loadButton_, &QPushButton::clicked, this, &TrainingDock::loadWithDialog);
    connect(evaluateButton_, &QPushButton::clicked, this, &TrainingDock::evaluate);
}

void TrainingDock::setPreparedPlan(std::shared_ptr<const PreparedPlan> prepared) {
    const bool sameGraph = prepared && prepared_ &&
                           graphFingerprint(prepared->graph) == graphFingerprint(prepared_->graph);
    prepared_ = std::move(prepared);
    if (sameGraph)
        return;
    lastEvaluation_.reset();
    if (evaluation_)
        evaluation_->cancel(); // its figures would be for the old plan
    if (training_)
        training_->cancel();
    session_ = std::make_shared<DqnSession>(); // the old model no longer fits
    if (state_ == State::Running || state_ == State::Paused) {
        status_->setText(tr("The plan changed: the model no longer fits it. Start to train for "
                            "the new plan."));
    }
    if (state_ != State::Idle) {
        setState(State::Idle);
        modelPath_.clear();
        emit modelReady(QString());
    }
    startButton_->setEnabled(prepared_ != nullptr);
}

double TrainingDock::budgetSeconds() const {
    return budget_->value();
}

void TrainingDock::start() {
    if (!prepared_) {
        lastError_ = tr("There is no valid plan to train for.");
        status_->setText(lastError_);
        emit errorOccurred(lastError_);
        return;
    }
    if (state_ == State::Running)
        return;
    TrainingOptions options = options_;
    if (!customOptions_)
        options = TrainingOptions::named(setting_->currentData().toString().toStdString());
    const bool fromGeneralist = fromGeneralist_->isChecked() && fromGeneralist_->isEnabled() &&
                                options.environment.graphState;
    clearPlot();
    episodes_ = 0;
    runStartSeconds_ = 0.0;
    lastSeconds_ = 0.0;
    modelPath_.clear();
    lastError_.clear();
    lastEvaluation_.reset();
    const double seconds = budgetSeconds();
    setState(State::Running);
    session_ = std::make_shared<DqnSession>();
    runTraining(tasks_->run(
        tr("Training the DQN"),
        [session = session_, prepared = prepared_, options, seconds,
         fromGeneralist](TaskFeedback& feedback) {
            TrainingOptions run = options;
            if (fromGeneralist)
                run.initialModel = generalistModel(); // parsed once, off the GUI thread
            return startDqn(*session, *prepared, run, seconds, feedback);
        },
        TaskOptions{QString(), true}));
}

void TrainingDock::runTraining(Task* task) {
    training_ = task;
    // A task of an older model (the plan changed) or one a resumed run followed is past.
    const auto current = [this, task, session = session_] {
        return task == training_ && session == session_;
    };
    connect(task, &Task::posted, this, [this, current](const QVariantList& points) {
        if (current())
            appendPoints(points);
    });
    connect(task, &Task::finished, this, [this, task, current] {
        if (current())
            onFinished(*task->result<TrainingRun>());
    });
    connect(task, &Task::failed, this, [this, current](const QString& message) {
        if (current())
            onFailed(message);
    });
    connect(task, &Task::ended, this, [this, task] {
        if (task == training_)
            training_ = nullptr;
    });
}

void TrainingDock::onFailed(const QString& message) {
    lastError_ = message;
    status_->setText(message);
    emit errorOccurred(message);
    setState(State::Idle);
}

void TrainingDock::pause() {
    if (state_ != State::Running)
        return;
    if (training_)
        training_->cancel();
    setState(State::Paused); // the task confirms with finished(Interrupted)
}

void TrainingDock::resumeTraining() {
    if (state_ != State::Paused && state_ != State::Finished)
        return;
    runStartSeconds_ = lastSeconds_;
    lastEvaluation_.reset(); // the model is about to change
    const double seconds = budgetSeconds();
    setState(State::Running);
    // Waits in the pool for the paused task to end its episode (the session's lock).
    runTraining(tasks_->run(
        tr("Training the DQN"),
        [session = session_, seconds](TaskFeedback& feedback) {
            return trainDqn(*session, seconds, feedback);
        },
        TaskOptions{QString(), true}));
}

void TrainingDock::stop() {
    if (evaluating_) { // Stop cancels an evaluation; the model stays as it is
        if (evaluation_)
            evaluation_->cancel();
        return;
    }
    if (state_ == State::Running && training_)
        training_->cancel();
    if (state_ == State::Running || state_ == State::Paused)
        setState(State::Finished);
}

void TrainingDock::appendPoints(const QVariantList& values) {
    if (values.isEmpty())
        return;
    std::optional<TrainingPoint> last;
    for (const QVariant& value : values) {
        const auto p = value.value<TrainingPoint>();
        const double x = static_cast<double>(p.episode);
        if (!std::isnan(p.policyGap)) {
            plot_->graph(kGapGraph)->addData(x, p.policyGap);
            lastGap_ = p.policyGap;
        }
        if (std::isnan(p.reward))
            continue; // an evaluation only
        last = p;
        plot_->graph(kRewardGraph)->addData(x, p.reward);
        plot_->graph(kAverageGraph)->addData(x, p.average);
        if (!std::isnan(p.loss))
            plot_->graph(kLossGraph)->addData(x, p.loss);
        plot_->graph(kEpsilonGraph)->addData(x, p.epsilon);
    }
    plot_->rescaleAxes();
    plot_->replot(QCustomPlot::rpQueuedReplot);
    if (!last)
        return;
    episodes_ = last->episode;
    lastSeconds_ = last->seconds;
    updateProgress(last->seconds);
    QString text = tr("Episode %1 · %2 steps/s · epsilon %3 · average reward %4")
                       .arg(last->episode)
                       .arg(last->stepsPerSecond, 0, 'f', 0)
                       .arg(last->epsilon, 0, 'f', 2)
                       .arg(last->average, 0, 'f', 3);
    if (lastGap_)
        text += tr(" · policy alone %1 % above the reference").arg(*lastGap_, 0, 'f', 1);
    status_->setText(text);
}

void TrainingDock::updateProgress(double seconds) {
    const double budget = budgetSeconds();
    const double done = std::clamp((seconds - runStartSeconds_) / budget, 0.0, 1.0);
    progress_->setValue(static_cast<int>(std::lround(1000.0 * done)));
    progress_->setFormat(tr("%1% · %2 left")
                             .arg(static_cast<int>(100.0 * done))
                             .arg(minutesAndSeconds(budget * (1.0 - done))));
}

void TrainingDock::onFinished(const TrainingRun& run) {
    const TrainingEnd end = run.end;
    const double trainedSeconds = run.trainedSeconds;
    const long episodes = run.episodes;
    episodes_ = episodes;
    lastSeconds_ = trainedSeconds;
    if (state_ == State::Running)
        setState(end == TrainingEnd::BudgetReached ? State::Finished : State::Paused);
    if (end == TrainingEnd::BudgetReached) {
        // The last progress report comes a moment before the end: the bar must not stay at
        // "96% · 0:01 left" once training is done.
        progress_->setValue(progress_->maximum());
        progress_->setFormat(tr("Done · %1 trained").arg(minutesAndSeconds(trainedSeconds)));
    } else {
        progress_->setFormat(
            tr("Paused at %p% · %1 trained").arg(minutesAndSeconds(trainedSeconds)));
    }
    // Offer the model to the planner: to its file if it has one, else to the cache.
    const QString path = modelPath_.isEmpty() ? cacheModelPath() : modelPath_;
    if (saveModel(path))
        status_->setText(tr("Model after %1 episodes (%2 of training) ready for solver dqn")
                             .arg(episodes)
                             .arg(minutesAndSeconds(trainedSeconds)));
}

bool TrainingDock::saveModel(const QString& path) {
    if (state_ == State::Running) {
        lastError_ = tr("Pause the training before saving the model.");
        return false;
    }
    QString error;
    {
        const std::lock_guard<std::mutex> guard(session_->mutex);
        try {
            if (!session_->trainer)
                throw InputError(tr("there is no trained model yet").toStdString());
            // Atomic, as projects are saved: a crash leaves the old model or the new one.
            const QString partial = path + QStringLiteral(".part");
            session_->trainer->save(partial.toStdString());
            if (std::rename(QFile::encodeName(partial).constData(),
                            QFile::encodeName(path).constData()) != 0) {
                QFile::remove(partial);
                throw InputError(tr("cannot replace the file").toStdString());
            }
        } catch (const std::exception& e) {
            error = plainMessage(QString::fromStdString(e.what()));
        }
    }
    if (!error.isEmpty()) {
        lastError_ = tr("Cannot save the model to %1: %2").arg(path, error);
        status_->setText(lastError_);
        emit errorOccurred(lastError_);
        return false;
    }
    modelPath_ = path;
    emit modelReady(path);
    return true;
}

bool TrainingDock::loadModel(const QString& path) {
    if (state_ == State::Running) {
        lastError_ = tr("Stop the training before loading a model.");
        return false;
    }
    try {
        if (!prepared_)
            throw InputError(tr("there is no valid plan to load the model for").toStdString());
        const std::string file = path.toStdString();
        auto trainer = std::make_unique<DqnTrainer>(prepared_->graph, loadDqnModelFile(file), file);
        const std::lock_guard<std::mutex> guard(session_->mutex);
        session_->trainer = std::move(trainer);
        episodes_ = session_->trainer->episodes();
    } catch (const std::exception& e) {
        lastError_ = plainMessage(QString::fromStdString(e.what())); // the current model stays
        return false;
    }
    clearPlot();
    modelPath_ = path;
    lastEvaluation_.reset();
    setState(State::Finished);
    status_->setText(tr("Loaded %1 (%2 episodes of training)").arg(path).arg(episodes_));
    emit modelReady(path);
    return true;
}

void TrainingDock::saveWithDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Model"), modelPath_,
                                                      tr("FloorCover DQN model (*.fcdqn)"));
    if (!path.isEmpty() && !saveModel(path))
        QMessageBox::warning(this, tr("Save Model"), lastError_);
}

void TrainingDock::loadWithDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load Model"), modelPath_,
                                                      tr("FloorCover DQN model (*.fcdqn)"));
    if (!path.isEmpty() && !loadModel(path))
        QMessageBox::warning(this, tr("Load Model"), lastError_);
}

QString TrainingDock::cacheModelPath() const {
    QDir dir(QStandardPaths::writableLocation(QStandardPaths::CacheLocation));
    dir.mkpath(QStringLiteral("."));
    return dir.filePath(QStringLiteral("current-plan.fcdqn"));
}

void TrainingDock::clearPlot() {
    for (int i = 0; i < plot_->graphCount(); ++i)
        plot_->graph(i)->data()->clear();
    lastGap_.reset();
    plot_->replot();
    progress_->setValue(0);
    progress_->setFormat(tr("%p%"));
}

int TrainingDock::plottedPoints() const {
    return plot_->graph(kRewardGraph)->dataCount();
}

int TrainingDock::plottedEvaluations() const {
    return plot_->graph(kGapGraph)->dataCount();
}

void TrainingDock::setState(State state) {
    state_ = state;
    // An evaluation holds the worker: nothing else starts until it answers.
    const bool running = state == State::Running || evaluating_;
    startButton_->setEnabled(!running && prepared_ != nullptr);
    pauseButton_->setEnabled(!evaluating_ && (running || state == State::Paused));
    pauseButton_->setText(state == State::Paused ? tr("Resume") : tr("Pause"));
    stopButton_->setEnabled(running || state == State::Paused);
    setting_->setEnabled(!running);
    fromGeneralist_->setEnabled(!running &&
                                setting_->currentData().toString() == QLatin1String("graph"));
    saveButton_->setEnabled(!evaluating_ && (state == State::Paused || state == State::Finished));
    loadButton_->setEnabled(!running);
    evaluateButton_->setEnabled(!running && (state == State::Paused || state == State::Finished));
    emit stateChanged(state);
}

} // namespace fc::ui
