#include "modes/tiling/PpoTrainingPanel.h"

#include "modes/tiling/PpoTrainer.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

namespace fc::ui {

PpoTrainingPanel::PpoTrainingPanel(QWidget* parent)
    : QWidget(parent), trainer_(new PpoTrainer(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* controls = new QHBoxLayout;
    seconds_ = new QDoubleSpinBox;
    seconds_->setRange(5, 3600);
    seconds_->setValue(60);
    seconds_->setSuffix(tr(" s"));
    seconds_->setToolTip(tr("Training time for the ppo policy (it learns on random rooms, so "
                            "one model serves every floor)"));
    train_ = new QPushButton(tr("Train ppo"));
    stop_ = new QPushButton(tr("Stop"));
    train_->setToolTip(tr("Train the learnt ordering (ppo) in the background for the time set."));
    stop_->setToolTip(tr("End training; what was learnt so far is kept."));
    controls->addWidget(seconds_);
    controls->addWidget(train_);
    controls->addWidget(stop_);
    layout->addLayout(controls);
    status_ = new QLabel(tr("ppo trains on first use (about a minute); train it here to watch "
                            "it learn."));
    status_->setWordWrap(true);
    layout->addWidget(status_);
    plot_ = new QCustomPlot(this);
    plot_->setMinimumHeight(160);
    plot_->xAxis->setLabel(tr("PPO update"));
    plot_->yAxis->setLabel(tr("Energy per waypoint (kg m)"));
    QCPGraph* cost = plot_->addGraph();
    cost->setPen(QPen(QColor(20, 90, 200), 2));
    layout->addWidget(plot_, 1);

    connect(train_, &QPushButton::clicked, this, &PpoTrainingPanel::start);
    connect(stop_, &QPushButton::clicked, trainer_, &PpoTrainer::stop);
    connect(trainer_, &PpoTrainer::progress, this, &PpoTrainingPanel::addPoint);
    connect(trainer_, &PpoTrainer::runningChanged, this, &PpoTrainingPanel::setRunning);
    connect(trainer_, &PpoTrainer::trained, this, [this](const QString& path, int updates) {
        status_->setText(tr("Trained for %1 updates; ppo now plans with %2.")
                             .arg(updates)
                             .arg(QDir::toNativeSeparators(path)));
    });
    connect(trainer_, &PpoTrainer::failed, this, [this](const QString& message) {
        status_->setText(tr("<b>Training failed:</b> %1").arg(message));
    });
    connect(trainer_, &PpoTrainer::cancelled, this, [this] {
        status_->setText(tr("Training cancelled before its first update; no model."));
    });
    setRunning(false);
}

void PpoTrainingPanel::setSeconds(double seconds) {
    seconds_->setValue(seconds);
}

int PpoTrainingPanel::plottedPoints() const {
    return plot_->graph(0)->dataCount();
}

QString PpoTrainingPanel::statusText() const {
    return status_->text();
}

void PpoTrainingPanel::start() {
    plot_->graph(0)->data()->clear();
    plot_->replot();
    status_->setText(tr("Training…"));
    trainer_->start(seed_, seconds_->value());
}

void PpoTrainingPanel::addPoint(int update, double cost, double seconds) {
    plot_->graph(0)->addData(update, cost);
    plot_->rescaleAxes();
    plot_->replot(QCustomPlot::rpQueuedReplot);
    status_->setText(tr("Update %1, %2 kg m per waypoint, %3 s")
                         .arg(update)
                         .arg(cost, 0, 'f', 3)
                         .arg(seconds, 0, 'f', 0));
}

void PpoTrainingPanel::setRunning(bool running) {
    train_->setEnabled(!running);
    seconds_->setEnabled(!running);
    stop_->setEnabled(running);
}

} // namespace fc::ui
