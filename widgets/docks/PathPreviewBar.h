// Controls of the path preview: play/pause, a speed-up slider and a position slider.
#pragma once

#include <QGroupBox>

class QLabel;
class QPushButton;
class QSlider;

namespace fc::ui {

class PathPreview;

class PathPreviewBar : public QGroupBox {
    Q_OBJECT
public:
    explicit PathPreviewBar(PathPreview* preview, QWidget* parent = nullptr);

    QPushButton* playButton() const { return play_; }
    QSlider* speedSlider() const { return speed_; }

private:
    void showSpeed(int factor);

    PathPreview* preview_;
    QPushButton* play_;
    QSlider* speed_;
    QLabel* speedLabel_;
    QSlider* position_;
};

} // namespace fc::ui
