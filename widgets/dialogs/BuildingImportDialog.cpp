// The 3D building-model import dialog (see BuildingImportDialog.h).
#include "dialogs/BuildingImportDialog.h"

#include "document/Conversions.h"
#include "document/PlannerMessages.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace fc::ui {

namespace {

struct UnitChoice {
    const char* label;
    double metresPerUnit; // 0: the file's own unit
};
const UnitChoice kUnits[] = {
    {QT_TRANSLATE_NOOP("fc::ui::BuildingImportDialog", "File's unit"), 0},
    {QT_TRANSLATE_NOOP("fc::ui::BuildingImportDialog", "Metres"), 1},
    {QT_TRANSLATE_NOOP("fc::ui::BuildingImportDialog", "Centimetres"), 0.01},
    {QT_TRANSLATE_NOOP("fc::ui::BuildingImportDialog", "Millimetres"), 0.001},
    {QT_TRANSLATE_NOOP("fc::ui::BuildingImportDialog", "Feet"), 0.3048},
    {QT_TRANSLATE_NOOP("fc::ui::BuildingImportDialog", "Inches"), 0.0254}};

} // namespace

BuildingImportDialog::BuildingImportDialog(const QString& path, QWidget* parent)
    : QDialog(parent), path_(path), storey_(new QComboBox), height_(new QDoubleSpinBox),
      ignoreDoors_(new QCheckBox(tr("Door leaves do not block"))), unit_(new QComboBox),
      upAxis_(new QComboBox), scene_(new QGraphicsScene(this)), view_(new QGraphicsView(scene_)),
      warnings_(new QListWidget), status_(new QLabel),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel)) {
    setWindowTitle(tr("Import 3D Building Model — %1").arg(QFileInfo(path).fileName()));
    height_->setRange(0.01, 100.0);
    height_->setDecimals(2);
    height_->setSingleStep(0.05);
    height_->setSuffix(tr(" m"));
    height_->setValue(ImportOptions{}.sliceHeight);
    ignoreDoors_->setChecked(ImportOptions{}.ignoreDoorLeaves);
    for (const UnitChoice& unit : kUnits)
        unit_->addItem(tr(unit.label), unit.metresPerUnit);
    upAxis_->addItem(tr("Automatic"), static_cast<int>(UpAxis::Automatic));
    upAxis_->addItem(tr("Y up"), static_cast<int>(UpAxis::Y));
    upAxis_->addItem(tr("Z up"), static_cast<int>(UpAxis::Z));
    view_->scale(1, -1); // plan y up
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(360, 260);
    warnings_->setMaximumHeight(90);
    status_->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(tr("Storey:"), storey_);
    form->addRow(tr("Cut above the floor:"), height_);
    form->addRow(QString(), ignoreDoors_);
    form->addRow(tr("Unit:"), unit_);
    form->addRow(tr("Up axis:"), upAxis_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(view_, 1);
    layout->addWidget(status_);
    layout->addWidget(warnings_);
    layout->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

    try {
        const ImportPreview preview = previewBuildingModel(path.toStdString());
        for (const std::string& name : preview.storeys)
            storey_->addItem(QString::fromStdString(name));
        if (!preview.metresPerUnit) // unitless formats: metres unless the user says otherwise
            unit_->setCurrentIndex(1);
    } catch (const InputError& e) {
        status_->setText(plainMessage(QString::fromStdString(e.what())));
    }
    connect(storey_, &QComboBox::currentIndexChanged, this, &BuildingImportDialog::refresh);
    connect(height_, &QDoubleSpinBox::valueChanged, this, &BuildingImportDialog::refresh);
    connect(ignoreDoors_, &QCheckBox::toggled, this, &BuildingImportDialog::refresh);
    connect(unit_, &QComboBox::currentIndexChanged, this, &BuildingImportDialog::refresh);
    connect(upAxis_, &QComboBox::currentIndexChanged, this, &BuildingImportDialog::refresh);
    if (storey_->count() > 0)
        refresh();
    else
        buttons_->button(QDialogButtonBox::Ok)->setEnabled(false);
}

ImportOptions BuildingImportDialog::options() const {
    ImportOptions options;
    options.storey = storey_->currentText().toStdString();
    options.sliceHeight = height_->value();
    options.ignoreDoorLeaves = ignoreDoors_->isChecked();
    if (const double scale = unit_->currentData().toDouble(); scale > 0)
        options.metresPerUnit = scale;
    return options;
}

BuildingModelSettings BuildingImportDialog::settings() const {
    return {static_cast<UpAxis>(upAxis_->currentData().toInt())};
}

QString BuildingImportDialog::errorText() const {
    return hasResult() ? QString() : status_->text();
}

void BuildingImportDialog::refresh() {
    warnings_->clear();
    scene_->clear();
    try {
        result_ = importBuildingModel(path_.toStdString(), options(), settings());
        const Plan& plan = result_->project.plan;
        for (const std::string& warning : result_->warnings)
            warnings_->addItem(plainMessage(QString::fromStdString(warning)));
        status_->setText(
            tr("%1 obstacles, %2 rooms").arg(plan.obstacles.size()).arg(plan.rooms.size()));
        drawPlan(plan);
    } catch (const InputError& e) {
        result_.reset();
        status_->setText(plainMessage(QString::fromStdString(e.what())));
    }
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(hasResult());
}

void BuildingImportDialog::drawPlan(const Plan& plan) {
    QPainterPath free;
    free.setFillRule(Qt::OddEvenFill);
    addRing(free, plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        addRing(free, obstacle);
    QPen wall(Qt::black, 0);
    scene_->addPath(free, wall, QColor(235, 242, 250));
    for (const Room& room : plan.rooms) {
        QPainterPath outline;
        addRing(outline, room.outline);
        scene_->addPath(outline, QPen(QColor(40, 110, 200), 0, Qt::DashLine));
    }
    view_->fitInView(scene_->itemsBoundingRect(), Qt::KeepAspectRatio);
}

} // namespace fc::ui
