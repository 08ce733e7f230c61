#include "modes/tiling/PpoTrainer.h"

#include "document/Conversions.h"
#include "tiling/ppo/PpoOrdering.h"
#include "tiling/ppo/torch/PointerPpo.h"

#include <QDir>
#include <QElapsedTimer>
#include <QStandardPaths>

namespace fc::ui {

PpoTrainingJob::PpoTrainingJob(quint64 seed, double seconds, QString modelPath,
                               std::shared_ptr<std::atomic<bool>> cancelled)
    : seed_(seed), seconds_(seconds), modelPath_(std::move(modelPath)),
      cancelled_(std::move(cancelled)) {}

void PpoTrainingJob::run() {
    int updates = 0;
    try {
        PointerPpoOptions options;
        options.seed = seed_;
        PointerPpo network(options);
        QElapsedTimer clock;
        clock.start();
        // One update at a time (about a third of a second each), so Stop answers at once.
        while (!*cancelled_ && clock.elapsed() < seconds_ * 1000.0) {
            network.train(1, [&](const PointerPpoProgress& p) {
                emit progress(updates + 1, p.meanCost, clock.elapsed() / 1000.0);
            });
            ++updates;
        }
        if (updates == 0)
            throw std::runtime_error("stopped before the first update");
        network.save(modelPath_.toStdString());
    } catch (const std::exception& e) {
        emit finished(QString(), updates, fromStd(e.what()));
        return;
    }
    emit finished(modelPath_, updates, QString());
}

PpoTrainer::PpoTrainer(QObject* parent) : QObject(parent) {}

PpoTrainer::~PpoTrainer() {
    if (thread_) {
        *cancelled_ = true;
        thread_->quit();
        thread_->wait();
    }
}

void PpoTrainer::start(quint64 seed, double seconds) {
    if (thread_)
        return;
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::CacheLocation);
    QDir().mkpath(folder);
    const QString path = QDir(folder).filePath(QStringLiteral("ppo-seed%1.fcppo").arg(seed));
    cancelled_ = std::make_shared<std::atomic<bool>>(false);
    thread_ = new QThread(this);
    auto* job = new PpoTrainingJob(seed, seconds, path, cancelled_);
    job->moveToThread(thread_);
    connect(thread_, &QThread::started, job, &PpoTrainingJob::run);
    connect(thread_, &QThread::finished, job, &QObject::deleteLater);
    connect(job, &PpoTrainingJob::progress, this, &PpoTrainer::progress);
    connect(job, &PpoTrainingJob::finished, this, &PpoTrainer::finish);
    thread_->start(QThread::LowPriority);
    emit runningChanged(true);
}

void PpoTrainer::stop() {
    if (cancelled_)
        *cancelled_ = true;
}

void PpoTrainer::finish(const QString& modelPath, int updates, const QString& error) {
    thread_->quit();
    thread_->wait();
    thread_->deleteLater();
    thread_ = nullptr;
    emit runningChanged(false);
    if (!error.isEmpty()) {
        emit failed(error);
        return;
    }
    modelPath_ = modelPath;
    PpoOrderingSettings settings; // "ppo" and "ppo-policy" now plan with this network
    settings.modelPath = modelPath.toStdString();
    configurePpoOrdering(settings);
    emit trained(modelPath, updates);
}

} // namespace fc::ui
