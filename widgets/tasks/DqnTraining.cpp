#include "tasks/DqnTraining.h"

#include "document/PlannerMessages.h"
#include "tasks/Task.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QVariant>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fc::ui {
namespace {

// Evaluations of the policy alone per run, and the least training time between two.
constexpr double kEvaluations = 20.0;
constexpr double kMinEvaluationSeconds = 10.0;

// The policy alone on the trainer's test queries (percent above the reference); NaN when
// cancelled meanwhile.
double policyGap(DqnTrainer& trainer, TaskFeedback& feedback) {
    try {
        return 100.0 * trainer.evaluate(feedback.solveControl()).meanGap;
    } catch (const SolverError&) { // cancelled: the training loop stops next
        return std::numeric_limits<double>::quiet_NaN();
    }
}

TrainingRun trainLocked(DqnSession& session, double seconds, TaskFeedback& feedback) {
    if (!session.trainer)
        throw InputError("there is no model to continue");
    QElapsedTimer clock;
    clock.start();
    const double evaluationEvery = std::max(kMinEvaluationSeconds, seconds / kEvaluations);
    double nextEvaluation = 0.0; // the first episode: where training starts from
    // A point of the gap curve alone (posted after the episode's point, so that the reward
    // curve and the progress never wait for an evaluation).
    auto postGap = [&](long episode) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        TrainingPoint point{episode, 0, 0.0, nan, nan, nan, nan, 0.0};
        point.policyGap = policyGap(*session.trainer, feedback);
        if (!std::isnan(point.policyGap))
            feedback.post(QVariant::fromValue(point));
    };
    TrainingStop stop = TrainingStop::TimeLimit;
    try {
        stop = session.trainer->train(
            0, seconds,
            [&](const TrainingProgress& p) {
                feedback.post(QVariant::fromValue(
                    TrainingPoint{p.episode, p.totalSteps, p.elapsedSeconds, p.reward,
                                  p.movingAverage, p.loss, p.epsilon, p.stepsPerSecond}));
                feedback.setProgress(clock.elapsed() / (1000.0 * seconds));
                if (clock.elapsed() / 1000.0 >= nextEvaluation) {
                    postGap(p.episode);
                    nextEvaluation = clock.elapsed() / 1000.0 + evaluationEvery;
                }
            },
            feedback.cancelledFunction());
        if (stop == TrainingStop::TimeLimit) // where the budget left the policy
            postGap(session.trainer->episodes());
        // However the run ended (budget, Pause or Stop), solver dqn and Save get the best
        // evaluated weights, and a resumed run continues from them: the policy swings between
        // evaluations (DqnTrainer::restoreBestEvaluated).
        session.trainer->restoreBestEvaluated();
    } catch (const std::exception& e) {
        throw std::runtime_error(
            QCoreApplication::translate("fc::ui::TrainingDock", "Training failed: %1")
                .arg(plainMessage(QString::fromStdString(e.what())))
                .toStdString());
    }
    return {stop == TrainingStop::Cancelled ? TrainingEnd::Interrupted : TrainingEnd::BudgetReached,
            session.trainer->modelInfo().trainingSeconds, session.trainer->episodes()};
}

} // namespace

TrainingRun startDqn(DqnSession& session, const PreparedPlan& prepared,
                     const TrainingOptions& options, double seconds, TaskFeedback& feedback) {
    const std::lock_guard<std::mutex> guard(session.mutex);
    try {
        session.trainer = std::make_unique<DqnTrainer>(
            prepared.graph, options, prepared.decomposition.frame.stripeAngleDeg(),
            prepared.robot.coverageWidth);
    } catch (const std::exception& e) {
        throw std::runtime_error(
            QCoreApplication::translate("fc::ui::TrainingDock", "Training cannot start: %1")
                .arg(plainMessage(QString::fromStdString(e.what())))
                .toStdString());
    }
    return trainLocked(session, seconds, feedback);
}

TrainingRun trainDqn(DqnSession& session, double seconds, TaskFeedback& feedback) {
    const std::lock_guard<std::mutex> guard(session.mutex);
    return trainLocked(session, seconds, feedback);
}

TrainingEvaluation evaluateDqn(DqnSession& session, TaskFeedback& feedback) {
    const std::lock_guard<std::mutex> guard(session.mutex);
    if (!session.trainer)
        throw std::runtime_error(
            QCoreApplication::translate("fc::ui::TrainingDock", "there is no trained model yet")
                .toStdString());
    const EvaluationReport report = session.trainer->evaluate(feedback.solveControl());
    TrainingEvaluation result;
    result.queries = report.queries;
    result.failures = report.failures;
    result.policyGap = 100.0 * report.meanGap;
    result.plannedGap = 100.0 * report.meanRefinedGap;
    result.milliseconds = report.meanMilliseconds;
    result.reference = QString::fromStdString(report.reference);
    return result;
}

} // namespace fc::ui
