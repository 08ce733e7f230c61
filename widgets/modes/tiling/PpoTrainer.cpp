#include "modes/tiling/PpoTrainer.h"

#include "document/Conversions.h"
#include "tasks/Task.h"
#include "tiling/ppo/PpoOrdering.h"
#include "tiling/ppo/torch/PointerPpo.h"

#include <QDir>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <stdexcept>

namespace fc::ui {
namespace {

struct PpoTraining {
    QString modelPath;
    int updates = 0;
};

} // namespace

PpoTrainer::PpoTrainer(QObject* parent) : QObject(parent) {}

void PpoTrainer::start(quint64 seed, double seconds) {
    if (task_)
        return;
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::CacheLocation);
    QDir().mkpath(folder);
    const QString path = QDir(folder).filePath(QStringLiteral("ppo-seed%1.fcppo").arg(seed));
    TaskOptions options;
    options.keepResultWhenCancelled = true; // Stop keeps the updates done so far
    task_ = TaskManager::forObject(this)->run(
        tr("Training ppo"),
        [seed, seconds, path](TaskFeedback& feedback) {
            PointerPpoOptions ppo;
            ppo.seed = seed;
            PointerPpo network(ppo);
            QElapsedTimer clock;
            clock.start();
            PpoTraining done;
            done.modelPath = path;
            // One update at a time (about a third of a second each), so Cancel answers soon.
            while (!feedback.isCancelled() && clock.elapsed() < seconds * 1000.0) {
                network.train(1, [&](const PointerPpoProgress& p) {
                    const double elapsed = clock.elapsed() / 1000.0;
                    feedback.post(QVariantList{done.updates + 1, p.meanCost, elapsed});
                    feedback.setProgress(elapsed / seconds);
                });
                ++done.updates;
            }
            if (done.updates == 0)
                throw std::runtime_error("stopped before the first update");
            network.save(path.toStdString());
            return done;
        },
        options);
    connect(task_, &Task::posted, this, [this](const QVariantList& values) {
        for (const QVariant& value : values) {
            const QVariantList point = value.toList();
            emit progress(point[0].toInt(), point[1].toDouble(), point[2].toDouble());
        }
    });
    connect(task_, &Task::finished, this, [this, task = task_.data()] {
        const auto done = task->result<PpoTraining>();
        modelPath_ = done->modelPath;
        PpoOrderingSettings settings; // "ppo" and "ppo-policy" now plan with this network
        settings.modelPath = modelPath_.toStdString();
        configurePpoOrdering(settings);
        emit trained(modelPath_, done->updates);
    });
    connect(task_, &Task::failed, this, &PpoTrainer::failed);
    connect(task_, &Task::cancelled, this, &PpoTrainer::cancelled);
    connect(task_, &Task::ended, this, [this] {
        task_ = nullptr;
        emit runningChanged(false);
    });
    emit runningChanged(true);
}

void PpoTrainer::stop() {
    if (task_)
        task_->cancel();
}

} // namespace fc::ui
