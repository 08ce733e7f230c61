// The training dock (issue 4, item 6): start, pause/resume and stop the DQN training for the
// current plan as a task of the window (tasks/DqnTraining.h: Pause and Stop cancel the task,
// which keeps the model so far; Resume starts a new task on the same trainer), a live
// QCustomPlot of episode reward and its moving
// average with loss and epsilon, a progress bar with the time left, and saving/loading the
// model. When a model is ready it is saved (to the chosen file, or to the cache) and offered
// to the planner through modelReady(), so that solver "dqn" uses it.
#pragma once

#include "tasks/DqnTraining.h"
#include "tasks/Task.h"

#include <QDockWidget>
#include <QPointer>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace fc::ui {

class TrainingDock : public QDockWidget {
    Q_OBJECT
public:
    enum class State { Idle, Running, Paused, Finished };

    explicit TrainingDock(QWidget* parent = nullptr);
    ~TrainingDock() override;

    // The plan to train for; a different graph invalidates the current model.
    void setPreparedPlan(std::shared_ptr<const fc::PreparedPlan> prepared);
    // Small networks for tests and quick demonstrations.
    void setTrainingOptions(const fc::TrainingOptions& options) {
        options_ = options;
        customOptions_ = true;
    }

    State state() const { return state_; }
    QString modelPath() const { return modelPath_; }
    // Whether there is a model to save (trained here, paused or finished, or loaded).
    bool hasModel() const { return state_ == State::Paused || state_ == State::Finished; }
    long episodes() const { return episodes_; }
    QCustomPlot* plot() const { return plot_; }
    int plottedPoints() const;
    // Points of the policy-gap curve (evaluations of the policy alone while training).
    int plottedEvaluations() const;
    QString lastError() const { return lastError_; }
    bool evaluating() const { return evaluating_; }
    const std::optional<TrainingEvaluation>& lastEvaluation() const { return lastEvaluation_; }
    // The running training and evaluation tasks (null when none).
    Task* trainingTask() const { return training_; }
    Task* evaluationTask() const { return evaluation_; }

public slots:
    void start();
    void pause();
    void resumeTraining();
    void stop();
    // Saves synchronously (waits for a pausing training to end its episode).
    bool saveModel(const QString& path);
    bool loadModel(const QString& path);
    // Measures the model on the trainer's fixed test queries as a task
    // (TrainingEvaluation.cpp); the result shows in the status line.
    void evaluate();

signals:
    void stateChanged(fc::ui::TrainingDock::State state);
    void modelReady(const QString& path); // empty when the model no longer fits the plan
    void errorOccurred(const QString& message);

private:
    void buildUi();
    void setState(State state);
    void runTraining(Task* task);
    void appendPoints(const QVariantList& points);
    void onFinished(const TrainingRun& run);
    void onFailed(const QString& message);
    void updateProgress(double seconds);
    void clearPlot();
    void onEvaluated(const fc::ui::TrainingEvaluation& result);
    void onEvaluationFailed(const QString& message);
    void saveWithDialog();
    void loadWithDialog();
    QString cacheModelPath() const;
    double budgetSeconds() const;

    TaskManager* tasks_;
    // A new session for every new model, so a task still ending keeps the old one.
    std::shared_ptr<DqnSession> session_ = std::make_shared<DqnSession>();
    QPointer<Task> training_;
    QPointer<Task> evaluation_;
    std::shared_ptr<const fc::PreparedPlan> prepared_;
    fc::TrainingOptions options_;
    bool customOptions_ = false;
    State state_ = State::Idle;
    QString modelPath_;
    QString lastError_;
    long episodes_ = 0;
    double runStartSeconds_ = 0.0; // trained seconds when this run began
    double lastSeconds_ = 0.0;
    bool evaluating_ = false;
    std::optional<TrainingEvaluation> lastEvaluation_;
    std::optional<double> lastGap_; // the latest policy gap on the curve, percent

    QComboBox* setting_ = nullptr;
    QCheckBox* fromGeneralist_ = nullptr;
    QDoubleSpinBox* budget_ = nullptr;
    QPushButton* startButton_ = nullptr;
    QPushButton* pauseButton_ = nullptr;
    QPushButton* stopButton_ = nullptr;
    QPushButton* saveButton_ = nullptr;
    QPushButton* loadButton_ = nullptr;
    QPushButton* evaluateButton_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QCustomPlot* plot_ = nullptr;
};

} // namespace fc::ui
