// The planning panel: robot profile, sweep (per room, auto or fixed; per-room overrides),
// solver, the rooms to plan,
// the Plan button and the metrics of the last plan (SPEC sect. 6).
#pragma once

#include <QDockWidget>
#include <QPointer>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QListWidgetItem;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;
class QVBoxLayout;

namespace fc::ui {

class Document;
class PlanningController;

class PlanningDock : public QDockWidget {
    Q_OBJECT
public:
    explicit PlanningDock(QWidget* parent = nullptr);

    void setDocument(Document* document);
    void setPlanningController(PlanningController* controller);

    QPushButton* planButton() const { return planButton_; }
    QListWidget* roomList() const { return rooms_; }
    QPushButton* mergeButton() const { return mergeButton_; }
    QDoubleSpinBox* widthBox() const { return width_; }
    QComboBox* solverBox() const { return solver_; }
    // Sweep mode: 0 per room (each room along its own walls), 1 auto, 2 one fixed angle.
    QComboBox* sweepModeBox() const { return sweepMode_; }
    QTableWidget* roomAngleTable() const { return roomAngles_; }
    // The metric labels by key: length, extra, turns, coverage, time (tests).
    QString metricText(const QString& key) const;
    // Adds a section (e.g. the path preview) below the metrics.
    void addSection(QWidget* section);

private:
    QWidget* createRobotGroup();
    QWidget* createSweepGroup();
    QWidget* createMetricsGroup();
    void refreshRobot();
    void refreshSweep();
    void refreshSolver();
    void refreshRooms();
    void refreshMetrics();
    void refreshStatus();
    void commitRobot();
    void commitSweep();
    void refreshRoomAngles();
    void roomAngleEdited(QTableWidgetItem* item);
    void roomItemChanged(QListWidgetItem* item);
    void mergeSelectedRooms();
    void updateMergeButton();

    QPointer<Document> document_;
    QPointer<PlanningController> controller_;
    QDoubleSpinBox* robotDiameter_;
    QDoubleSpinBox* cleaningDiameter_;
    QDoubleSpinBox* width_;
    QDoubleSpinBox* speed_;
    QDoubleSpinBox* turnTime_;
    QDoubleSpinBox* angle_;
    QComboBox* sweepMode_;
    QTableWidget* roomAngles_;
    QComboBox* solver_;
    QListWidget* rooms_;
    QPushButton* planButton_;
    QPushButton* mergeButton_;
    QLabel* status_;
    QVBoxLayout* layout_;
    QMap<QString, QLabel*> metrics_;
};

} // namespace fc::ui
