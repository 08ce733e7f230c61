// File > Import: previews a DXF drawing, ROS occupancy map, WKT or GeoJSON file as a plan.
// The user maps DXF layers to roles, sets the unit and the gap tolerance, sees the result
// and its warnings (for occupancy maps: the cleaning steps, what they removed and the rooms
// found, live), and chooses whether it replaces the current plan or opens as a new
// document. The setters are the dialog's API for tests and scripts; each re-imports.
#pragma once

#include "importers/Import.h"

#include <QDialog>
#include <optional>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QGraphicsScene;
class QGraphicsView;
class QLabel;
class QListWidget;
class QTableWidget;

namespace fc::ui {

class ImportDialog : public QDialog {
    Q_OBJECT
public:
    // Roles offered per layer; "auto" follows the layer-name guess and the shape rule.
    static const QStringList kRoles; // auto, boundary, obstacles, rooms, ignored

    explicit ImportDialog(const QString& path, QWidget* parent = nullptr);

    QString path() const { return path_; }
    QStringList layers() const;
    QString layerRole(const QString& layer) const;
    void setLayerRole(const QString& layer, const QString& role);
    void setMetresPerUnit(double metres);
    void setGapTolerance(double metres);
    void setOpenAsNewDocument(bool newDocument);
    // A GeoJSON site of several buildings: which one (1 = the largest, the first shown);
    // 0 while the file is no site.
    void setBuilding(int building);
    int building() const;
    // Occupancy maps: the cleaning steps and the room segmentation, each re-imports.
    void setMapCleaning(const MapCleaningOptions& cleaning);
    void setRoomSegmentation(RoomSegmentationMethod method);
    bool mapOptionsShown() const;
    bool openAsNewDocument() const;

    ImportOptions options() const;
    // The latest import with the current options; empty when it failed (see error()).
    const std::optional<ImportResult>& result() const { return result_; }
    QString error() const { return error_; }
    QStringList warnings() const;

public slots:
    void refresh();

protected:
    // The preview is fitted to the view's size, known only once the dialog is laid out.
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitPreview();
    void buildLayerTable(const ImportPreview& preview);
    QGroupBox* buildMapGroup();
    void drawPreview();

    QString path_;
    bool mappingEdited_ = false;
    bool unreadable_ = false; // the preview failed: nothing to import
    std::optional<ImportResult> result_;
    QString error_;
    QTableWidget* layerTable_;
    QDoubleSpinBox* units_;
    QDoubleSpinBox* gap_;
    QGraphicsScene* scene_;
    QGraphicsView* view_;
    QListWidget* warnings_;
    QLabel* summary_;
    QCheckBox* newDocument_;
    QLabel* buildingLabel_;
    QComboBox* building_;           // shown for a site of several buildings
    QGroupBox* mapGroup_ = nullptr; // occupancy maps only
    QComboBox* unknown_ = nullptr;
    QDoubleSpinBox* speckle_ = nullptr;
    QDoubleSpinBox* fragment_ = nullptr;
    QDoubleSpinBox* opening_ = nullptr;
    QDoubleSpinBox* closing_ = nullptr;
    QCheckBox* straighten_ = nullptr;
    QDoubleSpinBox* notch_ = nullptr;
    QComboBox* rooms_ = nullptr;
    QDoubleSpinBox* minRoom_ = nullptr;
    QDialogButtonBox* buttons_;
};

} // namespace fc::ui
