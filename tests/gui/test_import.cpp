// File > Import: the import dialog on the ezdxf office drawing (made by the
// import_make_dxf_fixtures test), and the window applying its result.
#include "EditorFixture.h"
#include "dialogs/ImportDialog.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
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

// A site of two buildings (GeoJSON, one MultiPolygon boundary): 20 x 12 m, and 10 x 8 m with
// a pillar and a room.
QString writeSite(const QTemporaryDir& dir) {
    const QString path = dir.filePath(QStringLiteral("site.geojson"));
    std::ofstream(path.toStdString()) << R"({"type":"FeatureCollection","features":[
{"type":"Feature","properties":{"role":"boundary"},"geometry":{"type":"MultiPolygon","coordinates":[
 [[[0,0],[20,0],[20,12],[0,12],[0,0]]], [[[40,0],[50,0],[50,8],[40,8],[40,0]]]]}},
{"type":"Feature","properties":{"role":"obstacle"},"geometry":{"type":"Polygon","coordinates":[[[44,3],[46,3],[46,5],[44,5],[44,3]]]}},
{"type":"Feature","properties":{"role":"room","name":"Hall B"},"geometry":{"type":"Polygon","coordinates":[[[40,0],[50,0],[50,8],[40,8],[40,0]]]}}]})";
    return path;
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
    void aSiteOpensTheBuildingChosen();
    void theImportDialogOffersASitesBuildings();
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
    // So does the doorway between its two rooms, laid along the walls.
    QVERIFY(dialog.result()->cleaning->doorwaysAligned > 0);
    bool doorwaysShown = false;
    for (const QLabel* label : dialog.findChildren<QLabel*>())
        doorwaysShown = doorwaysShown || label->text().contains(QStringLiteral("Doorway borders"));
    QVERIFY(doorwaysShown);
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

// File > Open on a site of several buildings asks which one (a plan holds one building);
// without dialogs it names the buildings, and openFile(path, K) opens building K.
void ImportTest::aSiteOpensTheBuildingChosen() {
    QTemporaryDir dir;
    const QString site = writeSite(dir);
    auto window = makeWindow();
    QVERIFY(!window->openFile(site));
    QVERIFY2(window->lastError().contains(QStringLiteral("2 buildings")),
             qPrintable(window->lastError()));

    QVERIFY(window->openFile(site, 2));
    const fc::Plan& annex = window->document()->plan();
    QCOMPARE(fc::ringArea(annex.boundary), 80.0);
    QCOMPARE(annex.obstacles.size(), size_t(1));
    QCOMPARE(annex.rooms.size(), size_t(1));
    QCOMPARE(QString::fromStdString(annex.name), QStringLiteral("site-building-2"));

    // With dialogs on, the user picks from the buildings, largest first.
    window->setDialogsEnabled(true);
    QStringList offered;
    auto answer = [&](bool accept) {
        QTimer::singleShot(0, [&, accept] {
            auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            offered = dialog->comboBoxItems();
            if (accept) {
                dialog->setTextValue(offered.value(0));
                dialog->accept();
            } else {
                dialog->reject();
            }
        });
    };
    answer(true);
    QVERIFY(window->openFile(site));
    QCOMPARE(offered.size(), 2);
    QVERIFY2(offered[0].contains(QStringLiteral("240")), qPrintable(offered.join(',')));
    QVERIFY2(offered[1].contains(QStringLiteral("80")), qPrintable(offered.join(',')));
    QCOMPARE(fc::ringArea(window->document()->plan().boundary), 240.0);
    // Cancelled: the open document stays, and nothing is reported as an error.
    answer(false);
    QVERIFY(!window->openFile(site));
    QCOMPARE(fc::ringArea(window->document()->plan().boundary), 240.0);
    window->setDialogsEnabled(false);
}

// File > Import of a site: the largest building is previewed, the others a choice away.
void ImportTest::theImportDialogOffersASitesBuildings() {
    QTemporaryDir dir;
    ImportDialog dialog(writeSite(dir));
    QCOMPARE(dialog.building(), 1);
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QCOMPARE(fc::ringArea(dialog.result()->project.plan.boundary), 240.0);
    dialog.setBuilding(2);
    QVERIFY2(dialog.result(), qPrintable(dialog.error()));
    QCOMPARE(fc::ringArea(dialog.result()->project.plan.boundary), 80.0);
    QCOMPARE(dialog.result()->project.plan.rooms.size(), size_t(1));
    QCOMPARE(dialog.options().building, std::optional<int>(2));

    ImportDialog plain(kOffice); // no site: no choice
    QCOMPARE(plain.building(), 0);
    QVERIFY(!plain.options().building);
}

QTEST_MAIN(ImportTest)
#include "test_import.moc"
