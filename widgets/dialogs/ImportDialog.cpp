#include "dialogs/ImportDialog.h"

#include "dialogs/SiteBuildingChoice.h"
#include "document/Conversions.h"
#include "document/PlannerMessages.h"
#include "formats/PlanIO.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGraphicsPolygonItem>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace fc::ui {

const QStringList ImportDialog::kRoles{QStringLiteral("auto"), QStringLiteral("boundary"),
                                       QStringLiteral("obstacles"), QStringLiteral("rooms"),
                                       QStringLiteral("ignored")};

namespace {

QString roleLabel(const QString& role) {
    if (role == QLatin1String("boundary"))
        return ImportDialog::tr("Boundary");
    if (role == QLatin1String("obstacles"))
        return ImportDialog::tr("Obstacles");
    if (role == QLatin1String("rooms"))
        return ImportDialog::tr("Rooms");
    if (role == QLatin1String("ignored"))
        return ImportDialog::tr("Ignored");
    return ImportDialog::tr("Auto (by shape)");
}

} // namespace

ImportDialog::ImportDialog(const QString& path, QWidget* parent)
    : QDialog(parent), path_(path), layerTable_(new QTableWidget(0, 2, this)),
      units_(new QDoubleSpinBox(this)), gap_(new QDoubleSpinBox(this)),
      scene_(new QGraphicsScene(this)), view_(new QGraphicsView(scene_, this)),
      warnings_(new QListWidget(this)), summary_(new QLabel(this)),
      newDocument_(new QCheckBox(tr("Open as a new document"), this)),
      buildingLabel_(new QLabel(tr("Building:"), this)), building_(new QComboBox(this)),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setWindowTitle(tr("Import %1").arg(QFileInfo(path).fileName()));
    layerTable_->setHorizontalHeaderLabels({tr("Layer"), tr("Role")});
    layerTable_->horizontalHeader()->setStretchLastSection(true);
    layerTable_->verticalHeader()->hide();
    units_->setDecimals(6);
    units_->setRange(1e-6, 1e5);
    units_->setSuffix(tr(" m per unit"));
    units_->setValue(1.0);
    gap_->setDecimals(3);
    gap_->setRange(0.0, 10.0);
    gap_->setSingleStep(0.01);
    gap_->setSuffix(tr(" m"));
    gap_->setValue(ImportOptions{}.gapTolerance);
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setMinimumSize(360, 260);
    view_->scale(1, -1); // y up, as on the canvas
    summary_->setWordWrap(true);
    layerTable_->setToolTip(tr("The drawing's layers: choose what each holds (walls, obstacles, "
                               "rooms, or nothing to import)."));
    units_->setToolTip(tr("How many metres one drawing unit is (0.001 for a drawing in mm)."));
    gap_->setToolTip(tr("Lines whose ends are at most this far apart are joined into closed "
                        "outlines."));
    warnings_->setToolTip(tr("What the import left out or guessed, and why."));
    newDocument_->setToolTip(tr("Open the import as its own document instead of replacing the "
                                "plan of the current one."));

    auto* form = new QFormLayout;
    form->addRow(tr("Units:"), units_);
    form->addRow(tr("Close gaps up to:"), gap_);
    form->addRow(buildingLabel_, building_);
    building_->setToolTip(tr("The file holds several buildings (outer walls); a plan holds one. "
                             "Largest first."));
    buildingLabel_->hide();
    building_->hide();
    auto* left = new QVBoxLayout;
    left->addWidget(layerTable_);
    left->addLayout(form);
    left->addWidget(buildMapGroup());
    auto* right = new QVBoxLayout;
    right->addWidget(view_, 1);
    right->addWidget(summary_);
    right->addWidget(warnings_);
    auto* columns = new QHBoxLayout;
    columns->addLayout(left);
    columns->addLayout(right, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns);
    layout->addWidget(newDocument_);
    layout->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

    try {
        const ImportPreview preview = previewImport(path.toStdString());
        if (preview.metresPerUnit)
            units_->setValue(*preview.metresPerUnit);
        const bool cad = preview.format == "dxf" || preview.format == "wkt";
        units_->setEnabled(cad);
        gap_->setEnabled(preview.format == "dxf");
        mapGroup_->setVisible(preview.format == "ros-map");
        buildLayerTable(preview);
    } catch (const InputError& e) {
        error_ = plainMessage(fromStd(e.what()));
        unreadable_ = true;
    }
    connect(units_, &QDoubleSpinBox::editingFinished, this, &ImportDialog::refresh);
    connect(gap_, &QDoubleSpinBox::editingFinished, this, &ImportDialog::refresh);
    connect(building_, qOverload<int>(&QComboBox::activated), this, &ImportDialog::refresh);
    refresh();
}

void ImportDialog::setBuilding(int building) {
    building_->setCurrentIndex(building - 1);
    refresh();
}

int ImportDialog::building() const {
    return building_->count() > 0 ? building_->currentIndex() + 1 : 0;
}

QGroupBox* ImportDialog::buildMapGroup() {
    const ImportOptions defaults;
    mapGroup_ = new QGroupBox(tr("Clean the map"), this);
    mapGroup_->setCheckable(true);
    mapGroup_->setChecked(defaults.cleaning.enabled);
    mapGroup_->setVisible(false);
    unknown_ = new QComboBox(mapGroup_);
    unknown_->addItem(tr("Walls"), false);
    unknown_->addItem(tr("Floor"), true);
    unknown_->setToolTip(tr("What the map's unknown (grey) cells are: walls, or floor the robot "
                            "may clean."));
    auto spin = [this](double value, double max, const QString& suffix, const QString& tip) {
        auto* box = new QDoubleSpinBox(mapGroup_);
        box->setDecimals(3);
        box->setRange(0.0, max);
        box->setSingleStep(0.01);
        box->setSuffix(suffix);
        box->setValue(value);
        box->setToolTip(tip);
        connect(box, &QDoubleSpinBox::editingFinished, this, &ImportDialog::refresh);
        return box;
    };
    speckle_ = spin(defaults.cleaning.speckleArea, 100, tr(" m²"),
                    tr("Obstacle specks smaller than this become floor (sensor noise)"));
    fragment_ = spin(defaults.cleaning.fragmentArea, 1000, tr(" m²"),
                     tr("Free islands smaller than this are dropped"));
    opening_ = spin(defaults.robotDiameter / 2, 5, tr(" m"),
                    tr("Notches and slivers narrower than twice this are filled (the robot's "
                       "radius: what its body cannot enter)"));
    closing_ = spin(defaults.cleaning.closingRadius, 5, tr(" m"),
                    tr("Obstacles thinner than twice this vanish (0: off; thin walls too)"));
    straighten_ = new QCheckBox(tr("Along the map's two main directions"), mapGroup_);
    straighten_->setChecked(defaults.cleaning.straightenWalls);
    straighten_->setToolTip(tr("Each ragged wall becomes one line within a cell of its scan, "
                               "so the path runs along it instead of zigzagging"));
    notch_ = spin(defaults.cleaning.notchDepth, 1, tr(" m"),
                  tr("Notches in a straightened wall up to this deep are filled"));
    rooms_ = new QComboBox(this);
    rooms_->addItem(tr("At doorways (distance)"),
                    static_cast<int>(RoomSegmentationMethod::Distance));
    rooms_->addItem(tr("At doorways (morphological)"),
                    static_cast<int>(RoomSegmentationMethod::Morphological));
    rooms_->addItem(tr("One room"), static_cast<int>(RoomSegmentationMethod::None));
    rooms_->setToolTip(tr("How the map's free space is split into rooms: at doorways (two "
                          "methods), or kept as one room."));
    minRoom_ = spin(defaults.roomSegmentation.minRoomArea, 1000, tr(" m²"),
                    tr("Smaller rooms (alcoves, door recesses) join a neighbour"));
    auto* form = new QFormLayout(mapGroup_);
    form->addRow(tr("Unknown cells are:"), unknown_);
    form->addRow(tr("Remove specks below:"), speckle_);
    form->addRow(tr("Drop islands below:"), fragment_);
    form->addRow(tr("Fill notches up to:"), opening_);
    form->addRow(tr("Remove obstacles up to:"), closing_);
    form->addRow(tr("Straighten walls:"), straighten_);
    form->addRow(tr("Fill notches in straight walls up to:"), notch_);
    form->addRow(tr("Split into rooms:"), rooms_);
    form->addRow(tr("Smallest room:"), minRoom_);
    connect(mapGroup_, &QGroupBox::toggled, this, &ImportDialog::refresh);
    connect(unknown_, &QComboBox::currentIndexChanged, this, &ImportDialog::refresh);
    connect(straighten_, &QCheckBox::toggled, this, &ImportDialog::refresh);
    connect(rooms_, &QComboBox::currentIndexChanged, this, &ImportDialog::refresh);
    return mapGroup_;
}

bool ImportDialog::mapOptionsShown() const {
    return mapGroup_ && !mapGroup_->isHidden();
}

void ImportDialog::setMapCleaning(const MapCleaningOptions& cleaning) {
    const QSignalBlocker blockGroup(mapGroup_), blockUnknown(unknown_),
        blockStraighten(straighten_);
    straighten_->setChecked(cleaning.straightenWalls);
    notch_->setValue(cleaning.notchDepth);
    mapGroup_->setChecked(cleaning.enabled);
    unknown_->setCurrentIndex(cleaning.unknownIsFree ? 1 : 0);
    speckle_->setValue(cleaning.speckleArea);
    fragment_->setValue(cleaning.fragmentArea);
    if (cleaning.openingRadius >= 0)
        opening_->setValue(cleaning.openingRadius);
    closing_->setValue(cleaning.closingRadius);
    refresh();
}

void ImportDialog::setRoomSegmentation(RoomSegmentationMethod method) {
    rooms_->setCurrentIndex(rooms_->findData(static_cast<int>(method))); // refreshes
}

void ImportDialog::buildLayerTable(const ImportPreview& preview) {
    layerTable_->setRowCount(static_cast<int>(preview.layers.size()));
    for (int row = 0; row < layerTable_->rowCount(); ++row) {
        const QString layer = fromStd(preview.layers[static_cast<size_t>(row)]);
        auto* name = new QTableWidgetItem(layer);
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        layerTable_->setItem(row, 0, name);
        auto* combo = new QComboBox(layerTable_);
        combo->setToolTip(tr("What layer %1 holds").arg(layer));
        for (const QString& role : kRoles)
            combo->addItem(roleLabel(role), role);
        const QString guess = fromStd(guessLayerRole(layer.toStdString()));
        combo->setCurrentIndex(std::max(0, static_cast<int>(kRoles.indexOf(guess))));
        connect(combo, &QComboBox::currentIndexChanged, this, [this]() {
            mappingEdited_ = true;
            refresh();
        });
        layerTable_->setCellWidget(row, 1, combo);
    }
    layerTable_->setVisible(!preview.layers.empty());
    layerTable_->resizeColumnToContents(0);
}

QStringList ImportDialog::layers() const {
    QStringList names;
    for (int row = 0; row < layerTable_->rowCount(); ++row)
        names << layerTable_->item(row, 0)->text();
    return names;
}

QString ImportDialog::layerRole(const QString& layer) const {
    const int row = static_cast<int>(layers().indexOf(layer));
    if (row < 0)
        return {};
    return static_cast<QComboBox*>(layerTable_->cellWidget(row, 1))->currentData().toString();
}

void ImportDialog::setLayerRole(const QString& layer, const QString& role) {
    const int row = static_cast<int>(layers().indexOf(layer));
    const int index = static_cast<int>(kRoles.indexOf(role));
    if (row >= 0 && index >= 0) // the combo's signal marks the mapping edited and refreshes
        static_cast<QComboBox*>(layerTable_->cellWidget(row, 1))->setCurrentIndex(index);
}

void ImportDialog::setMetresPerUnit(double metres) {
    units_->setValue(metres);
    refresh();
}

void ImportDialog::setGapTolerance(double metres) {
    gap_->setValue(metres);
    refresh();
}

void ImportDialog::setOpenAsNewDocument(bool newDocument) {
    newDocument_->setChecked(newDocument);
}

bool ImportDialog::openAsNewDocument() const {
    return newDocument_->isChecked();
}

ImportOptions ImportDialog::options() const {
    ImportOptions options;
    options.keepInvalid = true; // opened for repair in the editor
    if (units_->isEnabled())
        options.metresPerUnit = units_->value();
    options.gapTolerance = gap_->value();
    if (building_->count() > 0)
        options.building = building_->currentIndex() + 1;
    options.cleaning.enabled = mapGroup_->isChecked();
    options.cleaning.unknownIsFree = unknown_->currentData().toBool();
    options.cleaning.speckleArea = speckle_->value();
    options.cleaning.fragmentArea = fragment_->value();
    options.cleaning.openingRadius = opening_->value();
    options.cleaning.closingRadius = closing_->value();
    options.cleaning.straightenWalls = straighten_->isChecked();
    options.cleaning.notchDepth = notch_->value();
    options.roomSegmentation.method =
        static_cast<RoomSegmentationMethod>(rooms_->currentData().toInt());
    options.roomSegmentation.minRoomArea = minRoom_->value();
    if (!mappingEdited_) // the layer-name guesses, as the combos show them
        return options;
    const QStringList names = layers();
    for (const QString& layer : names) {
        const QString role = layerRole(layer);
        const std::string name = layer.toStdString();
        if (role == QLatin1String("boundary"))
            options.layers.boundary.push_back(name);
        else if (role == QLatin1String("obstacles"))
            options.layers.obstacles.push_back(name);
        else if (role == QLatin1String("rooms"))
            options.layers.rooms.push_back(name);
        else if (role == QLatin1String("ignored"))
            options.layers.ignored.push_back(name);
    }
    return options;
}

QStringList ImportDialog::warnings() const {
    QStringList list;
    for (int i = 0; i < warnings_->count(); ++i)
        list << warnings_->item(i)->text();
    return list;
}

void ImportDialog::refresh() {
    result_.reset();
    if (!unreadable_) {
        try {
            result_ = importPlanFile(path_.toStdString(), options());
            error_.clear();
        } catch (const SiteError& e) {
            // A site: the largest building first, the others a choice away.
            if (building_->count() == 0 && !e.buildingAreas().empty()) {
                building_->addItems(siteBuildingNames(e.buildingAreas()));
                buildingLabel_->show();
                building_->show();
                refresh();
                return;
            }
            error_ = plainMessage(fromStd(e.what()));
        } catch (const InputError& e) {
            error_ = plainMessage(fromStd(e.what()));
        }
    }
    warnings_->clear();
    if (result_) {
        for (const std::string& w : result_->warnings)
            warnings_->addItem(plainMessage(fromStd(w)));
        const Plan& plan = result_->project.plan;
        summary_->setText(tr("Free area %1 m², %2 obstacles, %3 rooms")
                              .arg(freeAreaOf(plan), 0, 'f', 2)
                              .arg(plan.obstacles.size())
                              .arg(plan.rooms.size()));
        if (const auto& c = result_->cleaning)
            summary_->setText(
                summary_->text() + QLatin1Char('\n') +
                tr("Cleaning removed %1 specks (%2 m²) and %3 free islands (%4 m²); filling "
                   "notches took %5 m², removing thin obstacles gave %6 m².")
                    .arg(c->specksRemoved)
                    .arg(c->speckArea, 0, 'f', 2)
                    .arg(c->fragmentsDropped)
                    .arg(c->fragmentArea, 0, 'f', 2)
                    .arg(c->openedArea, 0, 'f', 2)
                    .arg(c->closedArea, 0, 'f', 2));
        if (const auto& c = result_->cleaning; c && c->obstaclesJoined > 0)
            summary_->setText(summary_->text() + QLatin1Char(' ') +
                              tr("Obstacles joined to their neighbours across gaps "
                                 "narrower than the robot: %n (%1 m²).",
                                 nullptr, c->obstaclesJoined)
                                  .arg(c->passageArea, 0, 'f', 2));
        if (const auto& c = result_->cleaning; c && c->wallAngle)
            summary_->setText(summary_->text() + QLatin1Char('\n') +
                              tr("%1 walls straightened at %2°: %3 m² of floor gained, %4 m² "
                                 "lost (%5 notches filled); %6 unknown gaps became floor.")
                                  .arg(c->wallsStraightened)
                                  .arg(c->wallAngle.value(), 0, 'f', 1)
                                  .arg(c->straightenedAdded, 0, 'f', 2)
                                  .arg(c->straightenedRemoved, 0, 'f', 2)
                                  .arg(c->notchesFilled)
                                  .arg(c->gapsFilled));
        if (const auto& c = result_->cleaning; c && c->doorwaysAligned > 0)
            summary_->setText(summary_->text() + QLatin1Char(' ') +
                              tr("Doorway borders between rooms laid along the walls: %n.", nullptr,
                                 c->doorwaysAligned));
    } else {
        summary_->setText(error_);
    }
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(result_.has_value());
    drawPreview();
}

void ImportDialog::drawPreview() {
    scene_->clear();
    if (!result_)
        return;
    const Plan& plan = result_->project.plan;
    QPen pen(Qt::black);
    pen.setCosmetic(true);
    scene_->addPolygon(toPolygon(plan.boundary), pen, QColor(235, 240, 250));
    for (const Ring& obstacle : plan.obstacles)
        scene_->addPolygon(toPolygon(obstacle), pen, QColor(150, 150, 150));
    QPen roomPen(QColor(40, 120, 200), 0, Qt::DashLine);
    roomPen.setCosmetic(true);
    for (size_t i = 0; i < plan.rooms.size(); ++i) // tinted, so neighbours stand apart
        scene_->addPolygon(toPolygon(plan.rooms[i].outline), roomPen,
                           QColor::fromHsv(static_cast<int>(i * 137) % 360, 60, 255, 110));
    fitPreview();
}

void ImportDialog::fitPreview() {
    if (!scene_->items().isEmpty())
        view_->fitInView(scene_->itemsBoundingRect(), Qt::KeepAspectRatio);
}

void ImportDialog::showEvent(QShowEvent* event) {
    QDialog::showEvent(event);
    fitPreview();
}

void ImportDialog::resizeEvent(QResizeEvent* event) {
    QDialog::resizeEvent(event);
    fitPreview();
}

} // namespace fc::ui
