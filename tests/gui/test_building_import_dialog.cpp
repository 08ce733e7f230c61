// File > Import for 3D models: the dialog slices a generated OBJ room, previews it, reports a
// plane that cuts nothing and follows its unit setting.
#include "../planner/BuildingModels.h"
#include "dialogs/BuildingImportDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGraphicsScene>
#include <QListWidget>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

using namespace fc;
using namespace fc::ui;

class BuildingImportDialogTest : public QObject {
    Q_OBJECT
private slots:
    void slicesAndPreviewsAGeneratedRoom();
    void reportsAPlaneAboveTheWalls();
    void unreadableFileDisablesOk();
};

namespace {

double freeArea(const Plan& plan) {
    double area = ringArea(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        area -= ringArea(obstacle);
    return area;
}

QPushButton* okButton(QDialog& dialog) {
    return dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
}

} // namespace

void BuildingImportDialogTest::slicesAndPreviewsAGeneratedRoom() {
    QTemporaryDir dir;
    const QString path = dir.filePath("room.obj");
    test::writeText(path.toStdString(), test::objText(test::pillarRoom()));
    BuildingImportDialog dialog(path);
    QCOMPARE(dialog.storeyBox()->count(), 1);
    QCOMPARE(dialog.storeyBox()->currentText(), QString("whole model"));
    QCOMPARE(dialog.heightBox()->value(), 0.3);
    QVERIFY(dialog.doorLeavesBox()->isChecked());
    // The "kitchen" volume is a solid here (no room mapping): it fills the room.
    QVERIFY(!dialog.hasResult());
    QVERIFY(dialog.errorText().contains("encloses no free space"));
    QVERIFY(!okButton(dialog)->isEnabled());

    auto cuboids = test::pillarRoom();
    cuboids.pop_back();
    test::writeText(path.toStdString(), test::objText(cuboids));
    dialog.refresh();
    QVERIFY2(dialog.hasResult(), qPrintable(dialog.errorText()));
    QVERIFY(okButton(dialog)->isEnabled());
    QCOMPARE(dialog.result().project.plan.obstacles.size(), size_t(1));
    QVERIFY(std::abs(freeArea(dialog.result().project.plan) - 59.75) < 1e-9);
    QVERIFY(!dialog.previewScene()->items().isEmpty());
    const QRectF shown = dialog.previewScene()->itemsBoundingRect();
    QVERIFY(std::abs(shown.width() - 10.0) < 0.05);

    // Read as millimetres the walls are 2.5 mm high: a cut 0.3 m up misses them.
    dialog.unitBox()->setCurrentIndex(3);
    QVERIFY(!dialog.hasResult());
    QVERIFY2(dialog.errorText().contains("meets no wall"), qPrintable(dialog.errorText()));
    dialog.unitBox()->setCurrentIndex(1);
    QVERIFY(dialog.hasResult());
}

void BuildingImportDialogTest::reportsAPlaneAboveTheWalls() {
    QTemporaryDir dir;
    const QString path = dir.filePath("low.obj");
    auto cuboids = test::pillarRoom();
    cuboids.pop_back();
    test::writeText(path.toStdString(), test::objText(cuboids));
    BuildingImportDialog dialog(path);
    QVERIFY(dialog.hasResult());
    dialog.heightBox()->setValue(3.0);
    QVERIFY(!dialog.hasResult());
    QVERIFY2(dialog.errorText().contains(
                 "The cut at height 3 m (3 m above the floor of storey “whole model”) meets no "
                 "wall"),
             qPrintable(dialog.errorText()));
    QVERIFY(dialog.previewScene()->items().isEmpty());
    QVERIFY(!okButton(dialog)->isEnabled());
}

void BuildingImportDialogTest::unreadableFileDisablesOk() {
    QTemporaryDir dir;
    const QString path = dir.filePath("broken.stl");
    test::writeText(path.toStdString(), "solid broken\nfacet normal 0 0 1\nouter loop\nvertex 1");
    BuildingImportDialog dialog(path);
    QCOMPARE(dialog.storeyBox()->count(), 0);
    QVERIFY(!dialog.hasResult());
    QVERIFY(dialog.errorText().startsWith(path));
    QVERIFY(!okButton(dialog)->isEnabled());
}

QTEST_MAIN(BuildingImportDialogTest)
#include "test_building_import_dialog.moc"
