// The Training dock's long work as task functions (tasks/Task.h): the Double-DQN training
// loop and the model's evaluation. The trainer lives in a DqnSession shared by the dock and
// its tasks; each task holds the session's lock while it works, so a resumed training or an
// evaluation waits for a pausing one to end its episode. The training posts its episodes
// (TrainingPoint) through the feedback; the dock plots them in batches. Every twentieth of
// the budget (at least every 10 s), and when it ends, the training also measures the policy
// alone on the trainer's fixed test queries, so the curve shows what training buys.
#pragma once

#include "learning/dqn/DqnTrainer.h"
#include "pipeline/Planner.h"

#include <QMetaType>
#include <QString>
#include <limits>
#include <memory>
#include <mutex>

namespace fc::ui {

class TaskFeedback;

struct TrainingPoint {
    long episode = 0;
    long steps = 0;
    double seconds = 0.0; // training time so far
    double reward = 0.0;
    double average = 0.0;
    double loss = 0.0; // NaN while not learning yet
    double epsilon = 0.0;
    double stepsPerSecond = 0.0;
    // The learnt rollout alone on the trainer's fixed test queries, percent above the
    // reference solver; NaN when this point was not evaluated. A point that carries only an
    // evaluation (the one when the budget is spent) has NaN reward too.
    double policyGap = std::numeric_limits<double>::quiet_NaN();
};

enum class TrainingEnd { BudgetReached, Interrupted };

// What a training task returns (also after Pause or Stop: the model so far).
struct TrainingRun {
    TrainingEnd end = TrainingEnd::BudgetReached;
    double trainedSeconds = 0.0;
    long episodes = 0;
};

// The model on the trainer's fixed test queries (DqnTrainer::evaluate), in percent.
struct TrainingEvaluation {
    int queries = 0;
    int failures = 0;
    double policyGap = 0.0;  // the learnt rollout alone, above the reference solver
    double plannedGap = 0.0; // what solver dqn returns (after the model's refinement)
    double milliseconds = 0.0;
    QString reference; // "exact", "heuristic" or "exact/heuristic"
};

struct DqnSession {
    std::mutex mutex; // held by the task (or the GUI thread) using the trainer
    std::unique_ptr<DqnTrainer> trainer;
};

// A new model for `prepared` (replacing the session's), then trainDqn.
TrainingRun startDqn(DqnSession& session, const PreparedPlan& prepared,
                     const TrainingOptions& options, double seconds, TaskFeedback& feedback);
// Trains the session's model for `seconds` more or until cancelled (between episodes).
TrainingRun trainDqn(DqnSession& session, double seconds, TaskFeedback& feedback);
// Cancellable (throws when cancelled).
TrainingEvaluation evaluateDqn(DqnSession& session, TaskFeedback& feedback);

} // namespace fc::ui

Q_DECLARE_METATYPE(fc::ui::TrainingPoint)
