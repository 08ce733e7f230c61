#include "docks/PathPreviewBar.h"

#include "canvas/PathPreview.h"

#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>

namespace fc::ui {

namespace {
constexpr int kPositionSteps = 1000;
}

PathPreviewBar::PathPreviewBar(PathPreview* preview, QWidget* parent)
    : QGroupBox(tr("Preview"), parent), preview_(preview) {
    play_ = new QPushButton(tr("Play"));
    play_->setCheckable(true);
    play_->setToolTip(tr("Drive the robot along the planned path."));
    speed_ = new QSlider(Qt::Horizontal);
    speed_->setRange(1, 100);
    speed_->setToolTip(tr("Speed-up over the robot's real speed."));
    speedLabel_ = new QLabel;
    position_ = new QSlider(Qt::Horizontal);
    position_->setRange(0, kPositionSteps);
    position_->setToolTip(tr("Position along the path."));

    auto* grid = new QGridLayout(this);
    grid->addWidget(play_, 0, 0);
    grid->addWidget(position_, 0, 1, 1, 2);
    grid->addWidget(new QLabel(tr("Speed")), 1, 0);
    grid->addWidget(speed_, 1, 1);
    grid->addWidget(speedLabel_, 1, 2);

    connect(play_, &QPushButton::toggled, preview_, &PathPreview::setPlaying);
    connect(preview_, &PathPreview::playingChanged, this, [this](bool playing) {
        const QSignalBlocker blocker(play_);
        play_->setChecked(playing);
        play_->setText(playing ? tr("Pause") : tr("Play"));
    });
    connect(speed_, &QSlider::valueChanged, this, &PathPreviewBar::showSpeed);
    connect(position_, &QSlider::valueChanged, this,
            [this](int value) { preview_->setProgress(double(value) / kPositionSteps); });
    connect(preview_, &PathPreview::progressChanged, this, [this](double progress) {
        const QSignalBlocker blocker(position_);
        position_->setValue(static_cast<int>(std::lround(progress * kPositionSteps)));
    });
    connect(preview_, &PathPreview::availabilityChanged, this, &QWidget::setEnabled);
    speed_->setValue(static_cast<int>(preview_->speedFactor()));
    showSpeed(speed_->value());
    setEnabled(preview_->hasPath());
}

void PathPreviewBar::showSpeed(int factor) {
    preview_->setSpeedFactor(factor);
    speedLabel_->setText(tr("×%1").arg(factor));
}

} // namespace fc::ui
