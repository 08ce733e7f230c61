#include "tasks/TrainingWorker.h"

#include <QElapsedTimer>
#include <cmath>

namespace fc::ui {

TrainingWorker::TrainingWorker(QObject* parent) : QObject(parent) {
    qRegisterMetaType<QVector<fc::ui::TrainingPoint>>();
    qRegisterMetaType<fc::ui::TrainingEnd>();
    qRegisterMetaType<fc::ui::TrainingEvaluation>();
}

TrainingWorker::~TrainingWorker() = default;

void TrainingWorker::setPlan(std::shared_ptr<const PreparedPlan> prepared) {
    prepared_ = std::move(prepared);
}

void TrainingWorker::start(std::shared_ptr<const PreparedPlan> prepared, TrainingOptions options,
                           double seconds) {
    prepared_ = std::move(prepared);
    trainer_.reset();
    if (!prepared_) {
        emit failed(tr("There is no valid plan to train for."));
        emit finished(TrainingEnd::Failed, 0.0, 0);
        return;
    }
    try {
        trainer_ = std::make_unique<DqnTrainer>(prepared_->graph, options,
                                                prepared_->decomposition.frame.stripeAngleDeg(),
                                                prepared_->robot.coverageWidth);
    } catch (const std::exception& e) {
        emit failed(tr("Training cannot start: %1").arg(QString::fromStdString(e.what())));
        emit finished(TrainingEnd::Failed, 0.0, 0);
        return;
    }
    run(seconds);
}

void TrainingWorker::resume(double seconds, QString modelPath) {
    try {
        if (!modelPath.isEmpty()) {
            if (!prepared_)
                throw InputError("there is no valid plan to load the model for");
            const std::string path = modelPath.toStdString();
            trainer_ = std::make_unique<DqnTrainer>(prepared_->graph, loadDqnModelFile(path), path);
            emit modelLoaded(modelPath, trainer_->episodes());
            if (seconds <= 0.0)
                return;
        }
        if (!trainer_)
            throw InputError("there is no model to continue");
    } catch (const std::exception& e) {
        emit failed(QString::fromStdString(e.what()));
        if (seconds > 0.0)
            emit finished(TrainingEnd::Failed, 0.0, 0);
        return; // a model that failed to load leaves the current one in place
    }
    run(seconds);
}

void TrainingWorker::run(double seconds) {
    stopRequested_ = false;
    QVector<TrainingPoint> batch;
    QElapsedTimer sinceEmit;
    sinceEmit.start();
    TrainingStop stop = TrainingStop::TimeLimit;
    try {
        stop = trainer_->train(
            0, seconds,
            [&](const TrainingProgress& p) {
                batch.push_back({p.episode, p.totalSteps, p.elapsedSeconds, p.reward,
                                 p.movingAverage, p.loss, p.epsilon, p.stepsPerSecond});
                if (sinceEmit.elapsed() >= 100) {
                    emit progress(batch);
                    batch.clear();
                    sinceEmit.restart();
                }
            },
            [this] { return stopRequested_.load(); });
    } catch (const std::exception& e) {
        emit failed(tr("Training failed: %1").arg(QString::fromStdString(e.what())));
        emit finished(TrainingEnd::Failed, 0.0, trainer_->episodes());
        return;
    }
    if (!batch.isEmpty())
        emit progress(batch);
    emit finished(stop == TrainingStop::Cancelled ? TrainingEnd::Interrupted
                                                  : TrainingEnd::BudgetReached,
                  trainer_->modelInfo().trainingSeconds, trainer_->episodes());
}

void TrainingWorker::save(QString path) {
    if (!trainer_) {
        emit saved(path, tr("there is no trained model yet"));
        return;
    }
    try {
        trainer_->save(path.toStdString());
        emit saved(path, {});
    } catch (const std::exception& e) {
        emit saved(path, QString::fromStdString(e.what()));
    }
}

void TrainingWorker::evaluate() {
    if (!trainer_) {
        emit evaluationFailed(tr("there is no trained model yet"));
        return;
    }
    SolveControl control;
    control.cancelled = [this] { return evaluationCancelled_.load(); };
    try {
        const EvaluationReport report = trainer_->evaluate(control);
        TrainingEvaluation result;
        result.queries = report.queries;
        result.failures = report.failures;
        result.policyGap = 100.0 * report.meanGap;
        result.plannedGap = 100.0 * report.meanRefinedGap;
        result.milliseconds = report.meanMilliseconds;
        result.reference = QString::fromStdString(report.reference);
        emit evaluated(result);
    } catch (const std::exception& e) {
        emit evaluationFailed(evaluationCancelled_ ? QString() : QString::fromStdString(e.what()));
    }
}

} // namespace fc::ui
