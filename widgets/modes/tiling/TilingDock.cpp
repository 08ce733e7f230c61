#include "modes/tiling/TilingDock.h"

#include "document/Conversions.h"
#include "document/PlannerMessages.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "modes/tiling/PpoTrainingPanel.h"
#include "modes/tiling/TilingController.h"
#include "modes/tiling/TilingItem.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>
#include <map>

namespace fc::ui {

namespace {

QDoubleSpinBox* spin(double min, double max, double step, int decimals, const QString& suffix) {
    auto* box = new QDoubleSpinBox;
    box->setRange(min, max);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    return box;
}

} // namespace

TilingDock::TilingDock(TilingController* controller, QWidget* parent)
    : QDockWidget(tr("Tiling Robot"), parent), controller_(controller) {
    setObjectName(QStringLiteral("TilingDock"));
    auto* body = new QWidget;
    auto* layout = new QVBoxLayout(body);
    auto* form = new QFormLayout;
    layout->addLayout(form);

    solver_ = new QComboBox;
    for (const std::string& name : tiling::orderingSolverNames())
        solver_->addItem(fromStd(name));
    solver_->setToolTip(tr("How the tiles are ordered: zigzag and spiral follow the rows, "
                           "greedy, aco and ga minimise the energy, exact only for a few tiles, "
                           "ppo is the learnt pointer network."));
    form->addRow(tr("Ordering:"), solver_);
    seed_ = new QSpinBox;
    seed_->setRange(0, 1000000);
    seed_->setToolTip(tr("Random seed of the ordering methods that use chance (aco, ga, ppo): "
                         "the same seed gives the same tour."));
    form->addRow(tr("Seed:"), seed_);
    blockLeg_ = spin(0.05, 2.0, 0.01, 3, tr(" m"));
    blockLeg_->setToolTip(tr("Side of one block of the tiling robot in metres."));
    form->addRow(tr("Block leg:"), blockLeg_);
    auto* massRow = new QHBoxLayout;
    for (int b = 0; b < 4; ++b) {
        masses_[b] = spin(0.01, 100.0, 0.1, 2, QString());
        masses_[b]->setToolTip(tr("Mass of block B%1 in kg").arg(b + 1));
        massRow->addWidget(masses_[b]);
    }
    form->addRow(tr("Block masses (kg):"), massRow);

    run_ = new QPushButton(tr("Tile and Order"));
    layout->addWidget(run_);
    showTiles_ = new QCheckBox(tr("Show tiles on the canvas"));
    showTiles_->setChecked(true);
    run_->setToolTip(tr("Tile the floor with the robot's shapes and order the tiles by energy."));
    showTiles_->setToolTip(tr("Draw the tiles and their tour over the plan."));
    layout->addWidget(showTiles_);
    metrics_ = new QLabel;
    metrics_->setWordWrap(true);
    metrics_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(metrics_);
    export_ = new QPushButton(tr("Export Waypoints…"));
    export_->setToolTip(tr("Write the ordered waypoints (position, shape, heading) as CSV or "
                           "JSON for the robot."));
    layout->addWidget(export_);
    auto* training = new QGroupBox(tr("Learnt ordering (ppo)"));
    auto* trainingLayout = new QVBoxLayout(training);
    training_ = new PpoTrainingPanel;
    trainingLayout->addWidget(training_);
    layout->addWidget(training, 1);
    setWidget(body);

    const tiling::TilingRobotProfile defaults;
    QSettings settings;
    settings.beginGroup(QStringLiteral("tiling"));
    setSolver(settings.value(QStringLiteral("solver"), QStringLiteral("aco")).toString());
    seed_->setValue(settings.value(QStringLiteral("seed"), 1).toInt());
    blockLeg_->setValue(settings.value(QStringLiteral("blockLeg"), defaults.blockLeg).toDouble());
    for (int b = 0; b < 4; ++b)
        masses_[b]->setValue(
            settings.value(QStringLiteral("mass%1").arg(b + 1), defaults.blockMass[b]).toDouble());
    settings.endGroup();
    commitRobot();
    training_->setSeed(static_cast<quint64>(seed_->value()));
    connect(seed_, qOverload<int>(&QSpinBox::valueChanged), this,
            [this](int seed) { training_->setSeed(static_cast<quint64>(seed)); });

    connect(run_, &QPushButton::clicked, this, &TilingDock::tileAndOrder);
    connect(export_, &QPushButton::clicked, this, &TilingDock::chooseExportFile);
    connect(showTiles_, &QCheckBox::toggled, this, &TilingDock::showTilesChanged);
    connect(blockLeg_, &QDoubleSpinBox::editingFinished, this, &TilingDock::commitRobot);
    for (QDoubleSpinBox* mass : masses_)
        connect(mass, &QDoubleSpinBox::editingFinished, this, &TilingDock::commitRobot);
    connect(controller_, &TilingController::resultChanged, this, &TilingDock::refresh);
    connect(controller_, &TilingController::errorChanged, this, &TilingDock::refresh);
    connect(controller_, &TilingController::busyChanged, this, &TilingDock::refresh);
    refresh();
}

QString TilingDock::solver() const {
    return solver_->currentText();
}

void TilingDock::setSolver(const QString& name) {
    const int index = solver_->findText(name);
    if (index >= 0)
        solver_->setCurrentIndex(index);
}

QString TilingDock::metricsText() const {
    return metrics_->text();
}

void TilingDock::commitRobot() {
    tiling::TilingRobotProfile robot;
    robot.blockLeg = blockLeg_->value();
    for (int b = 0; b < 4; ++b)
        robot.blockMass[b] = masses_[b]->value();
    const tiling::TilingRobotProfile& current = controller_->robot();
    if (robot.blockLeg != current.blockLeg || robot.blockMass != current.blockMass)
        controller_->setRobot(robot);
}

void TilingDock::tileAndOrder() {
    commitRobot();
    QSettings settings;
    settings.beginGroup(QStringLiteral("tiling"));
    settings.setValue(QStringLiteral("solver"), solver());
    settings.setValue(QStringLiteral("seed"), seed_->value());
    settings.setValue(QStringLiteral("blockLeg"), blockLeg_->value());
    for (int b = 0; b < 4; ++b)
        settings.setValue(QStringLiteral("mass%1").arg(b + 1), masses_[b]->value());
    controller_->run(solver(), static_cast<quint64>(seed_->value()));
    training_->setSeed(static_cast<quint64>(seed_->value()));
}

void TilingDock::refresh() {
    const bool busy = controller_->isBusy();
    run_->setEnabled(!busy);
    const auto plan = controller_->result();
    export_->setEnabled(plan != nullptr && !busy);
    if (busy) {
        metrics_->setText(solver() == QLatin1String("ppo")
                              ? tr("Tiling and ordering… (ppo trains its network first)")
                              : tr("Tiling and ordering…"));
        return;
    }
    if (!controller_->errorMessage().isEmpty()) {
        metrics_->setText(tr("<b>Cannot tile:</b> %1").arg(controller_->errorMessage()));
        return;
    }
    if (!plan) {
        metrics_->setText(tr("Press “Tile and Order” to cover the floor with the robot's "
                             "shapes and order the tiles by energy."));
        return;
    }
    std::map<tiling::Shape, int> counts;
    for (const tiling::Tile& tile : plan->tiling.tiles)
        ++counts[tile.shape];
    QString legend;
    for (const auto& [shape, count] : counts)
        legend += QStringLiteral("<span style=\"color:%1\">■</span> %2 %3<br>")
                      .arg(tileShapeColor(shape).name(), QString::number(count),
                           QString::fromLatin1(tiling::shapeName(shape)));
    metrics_->setText(
        tr("<b>%1</b>: energy %2 kg m (translation %3, shape changes %4, turns %5)<br>"
           "%6 waypoints, %7 m, %8 shape changes, ordered in %9 s<br>"
           "%10 cells free, %11 left untiled, %12 unreachable (red)<br>%13")
            .arg(fromStd(plan->solver))
            .arg(plan->energy.total(), 0, 'f', 1)
            .arg(plan->energy.translation, 0, 'f', 1)
            .arg(plan->energy.transformation, 0, 'f', 1)
            .arg(plan->energy.orientation, 0, 'f', 1)
            .arg(plan->problem.size())
            .arg(plan->length, 0, 'f', 1)
            .arg(plan->shapeChanges)
            .arg(plan->orderingSeconds, 0, 'f', 2)
            .arg(plan->tiling.freeCells)
            .arg(plan->tiling.untiled.size())
            .arg(plan->tiling.unreachable.size())
            .arg(legend));
}

bool TilingDock::exportWaypoints(const QString& path) {
    const auto plan = controller_->result();
    if (!plan) {
        lastError_ = tr("No tiling to export: press “Tile and Order” first.");
        return false;
    }
    try {
        writeFileAtomically(path.toStdString(),
                            tiling::waypointsToFormat(path.toStdString(), *plan));
    } catch (const std::exception& e) {
        lastError_ = plainMessage(fromStd(e.what()));
        return false;
    }
    lastError_.clear();
    return true;
}

void TilingDock::chooseExportFile() {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export Waypoints"), QStringLiteral("waypoints.csv"),
                                     tr("CSV (*.csv);;JSON (*.json)"));
    if (path.isEmpty())
        return;
    if (!exportWaypoints(path))
        metrics_->setText(tr("<b>Export failed:</b> %1").arg(lastError_));
}

} // namespace fc::ui
