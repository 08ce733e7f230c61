#include "docks/PlanningDock.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"
#include "pipeline/PerRoomSweep.h"
#include "tasks/PlanningController.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace fc::ui {

namespace {

QDoubleSpinBox* spinBox(double minimum, double maximum, double step, const QString& suffix,
                        int decimals = 2) {
    auto* box = new QDoubleSpinBox;
    box->setRange(minimum, maximum);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false); // one edit per finished value, not per keystroke
    return box;
}

void setValueQuietly(QDoubleSpinBox* box, double value) {
    const QSignalBlocker blocker(box);
    box->setValue(value);
}

} // namespace

PlanningDock::PlanningDock(QWidget* parent) : QDockWidget(tr("Planning"), parent) {
    setObjectName(QStringLiteral("PlanningDock"));
    auto* content = new QWidget;
    auto* layout = layout_ = new QVBoxLayout(content);
    layout->addWidget(createRobotGroup());
    layout->addWidget(createSweepGroup());

    auto* roomsGroup = new QGroupBox(tr("Rooms to plan"));
    auto* roomsLayout = new QVBoxLayout(roomsGroup);
    rooms_ = new QListWidget;
    rooms_->setToolTip(tr("Check the rooms to cover; double-click a name to rename the room. "
                          "Select two rooms (Ctrl+click) to merge them; split a room with "
                          "the Split Room tool (K)."));
    rooms_->setMinimumHeight(120);
    rooms_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    roomsLayout->addWidget(rooms_);
    mergeButton_ = new QPushButton(tr("Merge Selected Rooms"));
    mergeButton_->setObjectName(QStringLiteral("mergeRooms"));
    mergeButton_->setToolTip(tr("Join the two selected rooms into one (they must share a wall "
                                "or a doorway); the first keeps its name."));
    mergeButton_->setEnabled(false);
    roomsLayout->addWidget(mergeButton_);
    connect(rooms_, &QListWidget::itemSelectionChanged, this, &PlanningDock::updateMergeButton);
    connect(mergeButton_, &QPushButton::clicked, this, &PlanningDock::mergeSelectedRooms);
    layout->addWidget(roomsGroup);
    connect(rooms_, &QListWidget::itemChanged, this, &PlanningDock::roomItemChanged);

    layout->addWidget(createMetricsGroup());
    layout->addStretch(1);

    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    // The Plan button and the status line stay in view below the scrolling part: a warning
    // of lost coverage used to sit under the fold, cut in half by the dock's bottom edge.
    planButton_ = new QPushButton(tr("Plan"));
    planButton_->setToolTip(tr("Plan the coverage path for the checked rooms (F5)."));
    status_ = new QLabel;
    status_->setObjectName(QStringLiteral("planningStatus"));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* frame = new QWidget;
    auto* frameLayout = new QVBoxLayout(frame);
    frameLayout->setContentsMargins(0, 0, 0, 0);
    frameLayout->addWidget(scroll, 1);
    auto* footer = new QVBoxLayout;
    footer->setContentsMargins(layout->contentsMargins().left(), 0,
                               layout->contentsMargins().right(),
                               layout->contentsMargins().bottom());
    footer->addWidget(planButton_);
    footer->addWidget(status_);
    frameLayout->addLayout(footer);
    setWidget(frame);
    connect(planButton_, &QPushButton::clicked, this, [this]() {
        if (controller_)
            controller_->plan();
    });
}

QWidget* PlanningDock::createRobotGroup() {
    auto* group = new QGroupBox(tr("Robot"));
    auto* form = new QFormLayout(group);
    robotDiameter_ = spinBox(0.05, 10, 0.05, tr(" m"));
    cleaningDiameter_ = spinBox(0.05, 10, 0.05, tr(" m"));
    width_ = spinBox(0.05, 10, 0.05, tr(" m"));
    speed_ = spinBox(0.01, 10, 0.05, tr(" m/s"));
    turnTime_ = spinBox(0, 60, 0.5, tr(" s"), 1);
    robotDiameter_->setToolTip(tr("The robot's body, L: its centre keeps L/2 from walls, and "
                                  "doors narrower than L are not passed."));
    cleaningDiameter_->setToolTip(tr("The width the cleaning head reaches, D (at least W)."));
    width_->setToolTip(tr("Distance between neighbouring stripes, W (between L and D): smaller "
                          "overlaps more, larger risks gaps."));
    speed_->setToolTip(tr("Driving speed, for the estimated time."));
    turnTime_->setToolTip(tr("Seconds the robot needs to turn by 90°, for the estimated time."));
    form->addRow(tr("Robot diameter L"), robotDiameter_);
    form->addRow(tr("Cleaning diameter D"), cleaningDiameter_);
    form->addRow(tr("Coverage width W"), width_);
    form->addRow(tr("Speed"), speed_);
    form->addRow(tr("Time per 90° turn"), turnTime_);
    for (QDoubleSpinBox* box : {robotDiameter_, cleaningDiameter_, width_, speed_, turnTime_})
        connect(box, &QDoubleSpinBox::valueChanged, this, &PlanningDock::commitRobot);
    return group;
}

QWidget* PlanningDock::createSweepGroup() {
    auto* group = new QGroupBox(tr("Sweep"));
    auto* form = new QFormLayout(group);
    angle_ = spinBox(0, 180, 5, tr("°"), 1);
    sweepMode_ = new QComboBox;
    sweepMode_->addItem(tr("Per room, along its walls"));
    sweepMode_->addItem(tr("Auto: fastest full coverage"));
    sweepMode_->addItem(tr("One angle for the floor"));
    sweepMode_->setToolTip(
        tr("Per room: each room's stripes follow its own walls (set a room's angle below to "
           "override it). Auto: tries several angles for the whole floor and keeps the fastest "
           "plan that covers everything the robot can reach. One angle: the stripe angle "
           "below for every room."));
    roomAngles_ = new QTableWidget(0, 4);
    roomAngles_->setObjectName(QStringLiteral("roomAngles"));
    roomAngles_->setHorizontalHeaderLabels(
        {tr("Room"), tr("From walls"), tr("Fixed"), tr("Planned")});
    roomAngles_->horizontalHeader()->setStretchLastSection(true);
    roomAngles_->verticalHeader()->hide();
    roomAngles_->setMaximumHeight(140);
    roomAngles_->setToolTip(tr("Type an angle in degrees to fix a room's stripes; clear it to "
                               "follow the room's walls again. Planned: the angle the last plan "
                               "swept the room at (the planner may turn a room by 90° or along "
                               "its other walls where that plans faster)."));
    solver_ = new QComboBox;
    for (const std::string& name : solverNames())
        solver_->addItem(fromStd(name));
    solver_->setToolTip(tr("How the order of the cells is chosen: heuristic is fast and close "
                           "to the best; exact proves the best order on small floors; greedy "
                           "is the quickest sketch; dqn uses the model trained in the Training "
                           "panel, or the built-in generalist model when none is; dqn-search "
                           "lets that model guide a search for 2 seconds per part of the floor "
                           "(better than heuristic on large floors)."));
    angle_->setToolTip(tr("The stripes' direction in degrees (90 = vertical), for One angle "
                          "for the floor."));
    form->addRow(tr("Sweep"), sweepMode_);
    form->addRow(tr("Stripe angle"), angle_);
    form->addRow(roomAngles_);
    form->addRow(tr("Solver"), solver_);
    connect(angle_, &QDoubleSpinBox::valueChanged, this, &PlanningDock::commitSweep);
    connect(sweepMode_, &QComboBox::currentIndexChanged, this, &PlanningDock::commitSweep);
    connect(roomAngles_, &QTableWidget::itemChanged, this, &PlanningDock::roomAngleEdited);
    connect(solver_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        if (document_ && fromStd(document_->project().solver) != name)
            document_->setSolver(name);
    });
    return group;
}

QWidget* PlanningDock::createMetricsGroup() {
    auto* group = new QGroupBox(tr("Metrics"));
    auto* form = new QFormLayout(group);
    const std::pair<const char*, QString> rows[] = {
        {"length", tr("Length")},       {"extra", tr("Extra distance")},
        {"turns", tr("Turns")},         {"coverage", tr("Coverage")},
        {"uncovered", tr("Uncovered")}, {"unreachable", tr("Unreachable")},
        {"time", tr("Estimated time")}, {"cells", tr("Cells")},
        {"angle", tr("Stripe angle")},  {"seconds", tr("Planning time")},
    };
    for (const auto& [key, label] : rows) {
        auto* value = new QLabel(QStringLiteral("–"));
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        form->addRow(label, value);
        metrics_.insert(QLatin1String(key), value);
    }
    return group;
}

void PlanningDock::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    if (document_) {
        connect(document_, &Document::robotChanged, this, &PlanningDock::refreshRobot);
        connect(document_, &Document::sweepChanged, this, &PlanningDock::refreshSweep);
        connect(document_, &Document::solverChanged, this, &PlanningDock::refreshSolver);
        connect(document_, &Document::roomsChanged, this, &PlanningDock::refreshRooms);
        connect(document_, &Document::geometryChanged, this, &PlanningDock::refreshStatus);
        // A refused edit puts the document's values back into the widgets.
        connect(document_, &Document::editRejected, this, &PlanningDock::refreshRobot);
        connect(document_, &Document::editRejected, this, &PlanningDock::refreshSweep);
        connect(document_, &Document::editRejected, this, &PlanningDock::refreshRooms);
    }
    setEnabled(document_ != nullptr);
    refreshRobot();
    refreshSweep();
    refreshSolver();
    refreshRooms();
    refreshStatus();
}

void PlanningDock::setPlanningController(PlanningController* controller) {
    if (controller_)
        disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    if (controller_) {
        connect(controller_, &PlanningController::resultChanged, this,
                &PlanningDock::refreshMetrics);
        connect(controller_, &PlanningController::resultChanged, this,
                &PlanningDock::refreshRoomAngles);
        connect(controller_, &PlanningController::resultChanged, this,
                &PlanningDock::refreshStatus);
        connect(controller_, &PlanningController::errorChanged, this, &PlanningDock::refreshStatus);
        connect(controller_, &PlanningController::busyChanged, this, &PlanningDock::refreshStatus);
    }
    refreshMetrics();
    refreshRoomAngles();
    refreshStatus();
}

void PlanningDock::refreshRobot() {
    if (!document_)
        return;
    const RobotProfile& robot = document_->project().robot;
    setValueQuietly(robotDiameter_, robot.robotDiameter);
    setValueQuietly(cleaningDiameter_, robot.cleaningDiameter);
    setValueQuietly(width_, robot.coverageWidth);
    setValueQuietly(speed_, robot.speed);
    setValueQuietly(turnTime_, robot.turnTime);
}

void PlanningDock::refreshSweep() {
    if (!document_)
        return;
    const SweepOptions& sweep = document_->project().sweep;
    setValueQuietly(angle_, sweep.angleDeg);
    const QSignalBlocker blocker(sweepMode_);
    sweepMode_->setCurrentIndex(sweep.automatic ? 1 : sweep.perRoom ? 0 : 2);
    angle_->setEnabled(!sweep.automatic && !sweep.perRoom);
    refreshRoomAngles();
}

void PlanningDock::refreshRoomAngles() {
    // Rows are updated in place when the rooms are the same in number: this runs inside
    // itemChanged of the cell the user edits, which must not be deleted under Qt's feet.
    const QSignalBlocker blocker(roomAngles_);
    const std::vector<Room> rooms =
        document_ ? document_->project().plan.rooms : std::vector<Room>{};
    if (roomAngles_->rowCount() != static_cast<int>(rooms.size())) {
        roomAngles_->setRowCount(0);
        for (size_t i = 0; i < rooms.size(); ++i) {
            roomAngles_->insertRow(static_cast<int>(i));
            for (int column : {0, 1, 3}) {
                auto* readOnly = new QTableWidgetItem;
                readOnly->setFlags(readOnly->flags() & ~Qt::ItemIsEditable);
                roomAngles_->setItem(static_cast<int>(i), column, readOnly);
            }
            roomAngles_->setItem(static_cast<int>(i), 2, new QTableWidgetItem);
        }
    }
    if (!document_)
        return;
    const Project& project = document_->project();
    roomAngles_->setEnabled(project.sweep.perRoom && !project.sweep.automatic);
    SweepOptions wallsOnly = project.sweep;
    wallsOnly.roomAngles.clear();
    const std::map<std::string, double> walls = roomSweepAngles(project.plan, wallsOnly);
    const auto result = controller_ ? controller_->result() : nullptr;
    const std::map<std::string, double> planned =
        result ? roomAnglesOf(*result, project.plan) : std::map<std::string, double>();
    const QLocale locale;
    for (size_t i = 0; i < rooms.size(); ++i) {
        const std::string& room = rooms[i].name;
        const int row = static_cast<int>(i);
        roomAngles_->item(row, 0)->setText(fromStd(room));
        roomAngles_->item(row, 1)->setText(tr("%1°").arg(locale.toString(walls.at(room), 'f', 1)));
        // An empty "Fixed" cell follows the room's walls.
        QTableWidgetItem* fixed = roomAngles_->item(row, 2);
        auto it = project.sweep.roomAngles.find(room);
        fixed->setText(it != project.sweep.roomAngles.end() ? locale.toString(it->second, 'f', 1)
                                                            : QString());
        fixed->setData(Qt::UserRole, fromStd(room));
        const auto swept = planned.find(room);
        roomAngles_->item(row, 3)->setText(
            swept != planned.end() ? tr("%1°").arg(locale.toString(swept->second, 'f', 1))
                                   : QStringLiteral("–"));
    }
}

void PlanningDock::roomAngleEdited(QTableWidgetItem* item) {
    if (!document_ || item->column() != 2)
        return;
    SweepOptions sweep = document_->project().sweep;
    const std::string room = item->data(Qt::UserRole).toString().toStdString();
    const QString text = item->text().trimmed();
    bool ok = true;
    const double value = QLocale().toDouble(text, &ok);
    if (text.isEmpty()) {
        sweep.roomAngles.erase(room);
    } else if (ok && std::isfinite(value)) {
        sweep.roomAngles[room] = value;
    } else {
        status_->setStyleSheet(QStringLiteral("color: #d03030"));
        status_->setText(tr("\"%1\" is not an angle in degrees.").arg(text));
        refreshRoomAngles();
        return;
    }
    document_->setSweep(sweep);
}

void PlanningDock::refreshSolver() {
    if (!document_)
        return;
    const QSignalBlocker blocker(solver_);
    const QString name = fromStd(document_->project().solver);
    if (solver_->findText(name) < 0)
        solver_->addItem(name); // a solver this build lacks still shows what the file asks
    solver_->setCurrentText(name);
}

void PlanningDock::refreshRooms() {
    const QSignalBlocker blocker(rooms_);
    const QStringList names = document_ ? document_->roomNames() : QStringList();
    // Items are updated in place when the rooms are the same in number: this runs inside
    // itemChanged of an item the user edits, which must not be deleted under Qt's feet.
    if (rooms_->count() != names.size()) {
        rooms_->clear();
        for (int i = 0; i < names.size(); ++i)
            new QListWidgetItem(rooms_);
    }
    const bool named = document_ && document_->polygonCount(PolygonRole::Room) > 0;
    for (int i = 0; i < names.size(); ++i) {
        QListWidgetItem* item = rooms_->item(i);
        item->setText(names[i]);
        item->setData(Qt::UserRole, names[i]);
        Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable;
        if (named) // "Floor" is the planner's name for a plan without rooms
            flags |= Qt::ItemIsEditable;
        item->setFlags(flags);
        item->setCheckState(document_->isRoomSelected(names[i]) ? Qt::Checked : Qt::Unchecked);
    }
    updateMergeButton();
    refreshRoomAngles();
}

void PlanningDock::updateMergeButton() {
    mergeButton_->setEnabled(document_ && document_->polygonCount(PolygonRole::Room) > 1 &&
                             rooms_->selectedItems().size() == 2);
}

void PlanningDock::mergeSelectedRooms() {
    const QList<QListWidgetItem*> selected = rooms_->selectedItems();
    if (!document_ || selected.size() != 2)
        return;
    int first = rooms_->row(selected[0]), second = rooms_->row(selected[1]);
    if (first > second)
        std::swap(first, second);
    document_->mergeRooms(first, second);
}

void PlanningDock::roomItemChanged(QListWidgetItem* item) {
    if (!document_)
        return;
    const QString name = item->data(Qt::UserRole).toString();
    if (item->text() != name) {
        document_->renameRoom(rooms_->row(item), item->text());
        return;
    }
    if ((item->checkState() == Qt::Checked) != document_->isRoomSelected(name))
        document_->toggleRoomSelection(name);
}

void PlanningDock::commitRobot() {
    if (!document_)
        return;
    RobotProfile robot = document_->project().robot;
    robot.robotDiameter = robotDiameter_->value();
    robot.cleaningDiameter = cleaningDiameter_->value();
    robot.coverageWidth = width_->value();
    robot.speed = speed_->value();
    robot.turnTime = turnTime_->value();
    document_->setRobot(robot);
}

void PlanningDock::commitSweep() {
    if (!document_)
        return;
    SweepOptions sweep = document_->project().sweep; // keeps the per-room overrides
    sweep.angleDeg = angle_->value();
    sweep.automatic = sweepMode_->currentIndex() == 1;
    sweep.perRoom = sweepMode_->currentIndex() == 0;
    angle_->setEnabled(sweepMode_->currentIndex() == 2);
    document_->setSweep(sweep);
}

void PlanningDock::addSection(QWidget* section) {
    layout_->insertWidget(layout_->count() - 1, section); // above the stretch
}

QString PlanningDock::metricText(const QString& key) const {
    const QLabel* label = metrics_.value(key);
    return label ? label->text() : QString();
}

void PlanningDock::refreshMetrics() {
    const auto result = controller_ ? controller_->result() : nullptr;
    for (QLabel* label : std::as_const(metrics_)) {
        label->setText(QStringLiteral("–"));
        label->setStyleSheet(QString());
    }
    if (!result)
        return;
    const Metrics& m = result->metrics;
    const QLocale locale; // decimal separators as in the spin boxes
    const auto number = [&locale](double value, int decimals) {
        return locale.toString(value, 'f', decimals);
    };
    metrics_[QStringLiteral("length")]->setText(tr("%1 m").arg(number(m.length, 1)));
    metrics_[QStringLiteral("extra")]->setText(tr("%1 m").arg(number(m.extra, 1)));
    metrics_[QStringLiteral("turns")]->setText(locale.toString(m.turns));
    metrics_[QStringLiteral("coverage")]->setText(tr("%1 %").arg(number(100.0 * m.coverage, 2)));
    // Losses above the reported threshold in red: they are what a supervisor must not miss.
    const auto showLoss = [&](const char* key, double area) {
        QLabel* label = metrics_[QLatin1String(key)];
        const double share = m.requiredArea > 0.0 ? area / m.requiredArea : 0.0;
        label->setText(tr("%1 m² (%2 %)").arg(number(area, 2), number(100.0 * share, 1)));
        label->setStyleSheet(share > kReportedLossFraction ? QStringLiteral("color: #d03030")
                                                           : QString());
    };
    showLoss("uncovered", m.uncoveredArea);
    showLoss("unreachable", m.unreachableArea);
    const int seconds = static_cast<int>(std::lround(m.time));
    metrics_[QStringLiteral("time")]->setText(
        tr("%1 min %2 s").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0')));
    metrics_[QStringLiteral("cells")]->setText(locale.toString(m.cells));
    metrics_[QStringLiteral("angle")]->setText(tr("%1°").arg(number(result->stripeAngleDeg, 1)));
    metrics_[QStringLiteral("seconds")]->setText(tr("%1 s").arg(number(m.seconds, 2)));
}

void PlanningDock::refreshStatus() {
    if (!controller_) {
        status_->clear();
        return;
    }
    const QString error = controller_->errorMessage();
    planButton_->setEnabled(true);
    if (!error.isEmpty()) {
        status_->setStyleSheet(QStringLiteral("color: #d03030"));
        status_->setText(error);
    } else {
        status_->setStyleSheet(QString());
        if (controller_->isDraft())
            status_->setText(tr("A quick sketch of the path is shown; the planner is "
                                "refining it…"));
        else if (controller_->isBusy())
            status_->setText(tr("Planning…"));
        else if (document_ && document_->plan().boundary.empty())
            status_->setText(tr("Draw the boundary of the floor to see cells and plan a path."));
        else if (const auto result = controller_->result(); result && result->shavedTeeth > 0)
            status_->setText(tr("Wall teeth cut back to their walls for planning: %n (pilasters, "
                                "bumps of traced walls); the path keeps clear of them.",
                                nullptr, result->shavedTeeth));
        else if (const auto ringed = controller_->result(); ringed && ringed->rings)
            status_->setText(tr("Planned as loops along the walls, each one coverage width "
                                "further in: estimated faster than stripes on this floor."));
        else
            status_->clear();
    }
    if (const auto result = controller_->result(); result && !result->warnings.empty()) {
        QStringList lines;
        for (const std::string& warning : result->warnings)
            lines << plainMessage(fromStd(warning));
        status_->setStyleSheet(QStringLiteral("color: #d03030"));
        status_->setText(lines.join(QLatin1Char('\n')));
    }
}

} // namespace fc::ui
