// The Training dock's evaluation: the current model plans the trainer's fixed test queries
// as a task (DqnTrainer::evaluate), and the dock reports how far the policy alone
// and solver dqn (the policy's walk after the model's refinement) are above the exact or
// heuristic solver. Stop cancels it; a result for a model that no longer fits is dropped.
#include "docks/TrainingDock.h"
#include "tasks/Task.h"

#include <QLabel>

namespace fc::ui {

void TrainingDock::evaluate() {
    if (evaluating_ || (state_ != State::Paused && state_ != State::Finished))
        return;
    evaluating_ = true;
    setState(state_);
    status_->setText(tr("Evaluating the model on its test queries…"));
    Task* task =
        tasks_->run(tr("Evaluating the DQN model"), [session = session_](TaskFeedback& feedback) {
            return evaluateDqn(*session, feedback);
        });
    evaluation_ = task;
    connect(task, &Task::finished, this,
            [this, task] { onEvaluated(*task->result<TrainingEvaluation>()); });
    connect(task, &Task::failed, this, &TrainingDock::onEvaluationFailed);
    connect(task, &Task::cancelled, this, [this] { onEvaluationFailed(QString()); });
}

void TrainingDock::onEvaluated(const TrainingEvaluation& result) {
    evaluating_ = false;
    setState(state_);
    if (state_ == State::Idle)
        return; // the plan changed meanwhile: the figures are for the old one
    lastEvaluation_ = result;
    QString text = tr("On %1 test queries: the policy alone is %2% above the %3 solver; "
                      "solver dqn is %4% above it, %5 ms per query.")
                       .arg(result.queries)
                       .arg(result.policyGap, 0, 'f', 1)
                       .arg(result.reference)
                       .arg(result.plannedGap, 0, 'f', 2)
                       .arg(result.milliseconds, 0, 'f', 0);
    if (result.failures > 0)
        text += QLatin1Char(' ') + tr("%n queries did not finish.", nullptr, result.failures);
    status_->setText(text);
}

void TrainingDock::onEvaluationFailed(const QString& message) {
    evaluating_ = false;
    setState(state_);
    if (state_ == State::Idle)
        return;
    lastError_ =
        message.isEmpty() ? tr("Evaluation cancelled.") : tr("Evaluation failed: %1").arg(message);
    status_->setText(lastError_);
}

} // namespace fc::ui
