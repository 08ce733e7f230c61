// File > Import for 3D building models (issue 5): choose the storey, the cutting height above
// its floor, whether door leaves block, the model's unit and up axis; the sliced plan is
// previewed and the importer's warnings listed. The caller takes result() after accept().
#pragma once

#include "importers/BuildingModelImport.h"

#include <QDialog>
#include <QString>
#include <optional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QGraphicsScene;
class QGraphicsView;
class QLabel;
class QListWidget;

namespace fc::ui {

class BuildingImportDialog : public QDialog {
    Q_OBJECT
public:
    explicit BuildingImportDialog(const QString& path, QWidget* parent = nullptr);

    // The plan sliced with the current settings; valid when hasResult().
    ImportResult result() const { return result_.value_or(ImportResult{}); }
    bool hasResult() const { return result_.has_value(); }
    QString errorText() const; // the importer's message, empty when the slice worked
    ImportOptions options() const;
    BuildingModelSettings settings() const;

    QComboBox* storeyBox() const { return storey_; }
    QDoubleSpinBox* heightBox() const { return height_; }
    QCheckBox* doorLeavesBox() const { return ignoreDoors_; }
    QComboBox* unitBox() const { return unit_; }
    QComboBox* upAxisBox() const { return upAxis_; }
    QListWidget* warningsList() const { return warnings_; }
    QGraphicsScene* previewScene() const { return scene_; }

public slots:
    void refresh(); // slices again with the current settings

private:
    void drawPlan(const Plan& plan);

    QString path_;
    std::optional<ImportResult> result_;
    QComboBox* storey_;
    QDoubleSpinBox* height_;
    QCheckBox* ignoreDoors_;
    QComboBox* unit_;
    QComboBox* upAxis_;
    QGraphicsScene* scene_;
    QGraphicsView* view_;
    QListWidget* warnings_;
    QLabel* status_;
    QDialogButtonBox* buttons_;
};

} // namespace fc::ui
