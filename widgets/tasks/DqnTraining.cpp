#include "tasks/DqnTraining.h"

#include "document/PlannerMessages.h"
#include "tasks/Task.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QVariant>
#include <stdexcept>

namespace fc::ui {
namespace {

TrainingRun trainLocked(DqnSession& session, double seconds, TaskFeedback& feedback) {
    if (!session.trainer)
        throw InputError("there is no model to continue");
    QElapsedTimer clock;
    clock.start();
    TrainingStop stop = TrainingStop::TimeLimit;
    try {
        stop = session.trainer->train(
            0, seconds,
            [&](const TrainingProgress& p) {
                feedback.post(QVariant::fromValue(
                    TrainingPoint{p.episode, p.totalSteps, p.elapsedSeconds, p.reward,
                                  p.movingAverage, p.loss, p.epsilon, p.stepsPerSecond}));
                feedback.setProgress(clock.elapsed() / (1000.0 * seconds));
            },
            feedback.cancelledFunction());
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
