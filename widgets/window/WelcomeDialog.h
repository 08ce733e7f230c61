// The first thing a new user sees: what FloorCover does in three steps, the sample plans to
// try, and the ways to start (draw, import, open), with the Getting Started page one click
// away. Shown at start until the user unticks "Show at start" (Help > Welcome brings it back).
#pragma once

#include <QDialog>

class QCheckBox;
class QListWidget;

namespace fc::ui {

class WelcomeDialog : public QDialog {
    Q_OBJECT
public:
    explicit WelcomeDialog(QWidget* parent = nullptr);

    static bool showAtStart();
    QListWidget* samples() const { return samples_; }

signals:
    void sampleChosen(const QString& path);
    void newFloorChosen();
    void importChosen();
    void openChosen();
    void helpChosen();

private:
    QListWidget* samples_;
    QCheckBox* showAtStart_;
};

} // namespace fc::ui
