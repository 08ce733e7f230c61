// File > Import: the import dialog on the ezdxf office drawing (made by the
// import_make_dxf_fixtures test), and the window applying its result.
#include "EditorFixture.h"
#include "dialogs/ImportDialog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <fstream>

using namespace fc::ui;
using namespace fc::ui::test;

namespace {

const QString kOffice = QStringLiteral(FC_IMPORT_FIXTURES_DIR "/office.dxf");

double expectedOfficeArea() {
    std::ifstream in(FC_IMPORT_FIXTURES_DIR "/expected.txt");
    std::string name;
    double area = 0;
    while (in >> name >> area)
        if (name == "office.dxf")
            return area;
    return -1;
}

} // namespace

class ImportTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void dialogPreviewsLayersAndGuessesRoles();
    void changingARoleReimports();
    void unreadableFileDisablesOk();
    void importReplacesThePlanAsOneUndoStep();
    void importOpensAsNewDocument();
    void occupancyMapCleaningIsLive();
};

void ImportTest::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverTests"));
    QCoreApplication::setApplicationName(QStringLiteral("gui_import"));
}

void ImportTest::dialogPreviewsLayersAndGuessesRoles() {
    ImportDialog dialog(kOffice);
    const QStringList layers = dialog.layers();
    for (const char* layer : {"WALLS", "COLUMNS", "FURNITURE", "OBSTACLES", "ROOMS", "NOTES"})
        QVERIFY2(layers.contains(QLatin1String(layer)), layer);
    QCOMPARE(dialog.layerRole(QStringLiteral("WALLS")), QStringLiteral("boundary"));
    QCOMPARE(dialog.layerRole(QStringLiteral("COLUMNS")), QStringLiteral("obstacles"));
    QCOMPARE(dialog.layerRole(QStringLiteral("NOTES")), QStringLiteral("auto"));
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QCOMPARE(dialog.result()->project.plan.obstacles.size(), size_t(6));
    QCOMPARE(dialog.result()->project.plan.rooms.size(), size_t(2));
    const double expected = expectedOfficeArea();
    QVERIFY(std::abs(fc::freeAreaOf(dialog.result()->project.plan) - expected) < 0.01 * expected);
    QVERIFY(dialog.options().metresPerUnit && *dialog.options().metresPerUnit == 0.001);
    bool strayReported = false;
    for (const QString& w : dialog.warnings())
        strayReported |= w.contains(QLatin1String("NOTES"));
    QVERIFY(strayReported);
}

void ImportTest::changingARoleReimports() {
    ImportDialog dialog(kOffice);
    dialog.setLayerRole(QStringLiteral("FURNITURE"), QStringLiteral("ignored"));
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QCOMPARE(dialog.result()->project.plan.obstacles.size(), size_t(4)); // the two desks gone
    dialog.setGapTolerance(0.005);                                       // the cabinet opens
    QCOMPARE(dialog.result()->project.plan.obstacles.size(), size_t(3));
    dialog.setMetresPerUnit(1.0); // metres: 20 km wide, still a valid plan
    QVERIFY(dialog.result());
    QVERIFY(dialog.result()->project.plan.bounds().width() > 20000);
}

void ImportTest::unreadableFileDisablesOk() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.dxf"));
    std::ofstream(path.toStdString()) << "0\nSECTION\n2\nENTITIES\n0\nLINE\n";
    ImportDialog dialog(path);
    QVERIFY(!dialog.result());
    QVERIFY(dialog.error().startsWith(path));
    auto* buttons = dialog.findChild<QDialogButtonBox*>();
    QVERIFY(!buttons->button(QDialogButtonBox::Ok)->isEnabled());
}

void ImportTest::importReplacesThePlanAsOneUndoStep() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple-diamond.geojson")));
    const fc::Plan before = window->document()->plan();
    const int steps = window->document()->undoStack()->count();
    ImportDialog dialog(kOffice);
    QVERIFY(dialog.result());
    QVERIFY(window->applyImport(kOffice, *dialog.result(), false));
    QCOMPARE(window->document()->undoStack()->count(), steps + 1);
    QCOMPARE(window->document()->plan().rooms.size(), size_t(2));
    QCOMPARE(window->document()->roomNames().front(), QStringLiteral("Office A"));
    window->document()->undoStack()->undo();
    QCOMPARE(window->document()->plan().boundary.size(), before.boundary.size());
    QCOMPARE(window->document()->plan().obstacles.size(), before.obstacles.size());
}

void ImportTest::importOpensAsNewDocument() {
    auto window = makeWindow();
    ImportDialog dialog(kOffice);
    QVERIFY(dialog.result());
    QVERIFY(window->applyImport(kOffice, *dialog.result(), true));
    QCOMPARE(window->document()->plan().obstacles.size(), size_t(6));
    QVERIFY(window->document()->fileName().isEmpty());
    QVERIFY(window->document()->isModified());
    QCOMPARE(window->document()->undoStack()->count(), 0);
}

// A real laser map (tests/data/real-maps): the cleaning steps are offered, change the
// preview live, and their report is shown.
void ImportTest::occupancyMapCleaningIsLive() {
    ImportDialog dialog(QStringLiteral(FC_REAL_MAPS_DIR "/uwb-localization-demo.yaml"));
    QVERIFY(dialog.mapOptionsShown());
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    const size_t cleanedObstacles = dialog.result()->project.plan.obstacles.size();
    QVERIFY(dialog.result()->cleaning);
    QVERIFY(dialog.result()->cleaning->specksRemoved + dialog.result()->cleaning->gapsFilled > 50);
    QVERIFY(dialog.result()->project.plan.rooms.size() != 1); // none: one room
    // The dotted lines its tracing left between desks are joined, and the summary says so.
    QVERIFY(dialog.result()->cleaning->obstaclesJoined > 0);
    bool joinedShown = false;
    for (const QLabel* label : dialog.findChildren<QLabel*>())
        joinedShown = joinedShown || label->text().contains(QStringLiteral("joined"));
    QVERIFY(joinedShown);
    if (const QByteArray dir = qgetenv("FC_SCREENSHOT_DIR"); !dir.isEmpty()) {
        dialog.resize(1100, 760);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        dialog.grab().save(QString::fromLocal8Bit(dir) + QStringLiteral("/import-map.png"));
        dialog.hide();
    }
    fc::MapCleaningOptions off;
    off.enabled = false;
    dialog.setMapCleaning(off);
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QVERIFY(dialog.result()->project.plan.obstacles.size() > 5 * cleanedObstacles);
    dialog.setMapCleaning(fc::MapCleaningOptions{});
    dialog.setRoomSegmentation(fc::RoomSegmentationMethod::None);
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QCOMPARE(dialog.result()->project.plan.obstacles.size(), cleanedObstacles);
    QVERIFY(dialog.result()->project.plan.rooms.empty());
    // Straightening the walls is a switch too: off, the ragged outline keeps more corners.
    QVERIFY(dialog.result()->cleaning->wallAngle);
    const size_t straightCorners = dialog.result()->project.plan.boundary.size();
    fc::MapCleaningOptions ragged;
    ragged.straightenWalls = false;
    dialog.setMapCleaning(ragged);
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QVERIFY(!dialog.result()->cleaning->wallAngle);
    QVERIFY(dialog.result()->project.plan.boundary.size() > straightCorners);
    // A DXF drawing offers no map cleaning.
    ImportDialog drawing(kOffice);
    QVERIFY(!drawing.mapOptionsShown());
}

QTEST_MAIN(ImportTest)
#include "test_import.moc"
