// Repair instead of refuse (issue 16, item 4): a plan the planner refuses opens read-only
// with its problems listed and circled, planning and edits wait, one click repairs it (an
// undoable edit), and then it plans.
#include "EditorFixture.h"
#include "canvas/PlanScene.h"
#include "dialogs/ImportDialog.h"
#include "docks/ProblemsDock.h"
#include "tasks/PlanningController.h"

#include <QAction>
#include <QGraphicsEllipseItem>
#include <QListWidget>
#include <QPointer>
#include <QStandardPaths>
#include <QUndoStack>

using namespace fc::ui;
using namespace fc::ui::test;

namespace {

// Red rings the scene draws at the problems (their tooltips are the messages).
int problemRings(MainWindow& window) {
    int rings = 0;
    for (QGraphicsItem* item : window.scene()->items())
        if (dynamic_cast<QGraphicsEllipseItem*>(item) && !item->toolTip().isEmpty() &&
            item->zValue() == 0 && item->parentItem() &&
            item->parentItem()->zValue() == z::Markers - 1)
            ++rings;
    return rings;
}

} // namespace

class RepairTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void brokenPlanOpensReadOnlyAndRepairs() {
        auto window = makeWindow();
        QVERIFY(window->openFile(QStringLiteral(FC_TEST_DATA_DIR "/hole-crossing.geojson")));
        Document* document = window->document();
        QVERIFY(document->needsRepair());
        ProblemsDock* dock = window->problemsDock();
        QVERIFY(dock->isVisible());
        QVERIFY(dock->list()->count() >= 1);
        // In the editor's words ("the outer wall"), not the planner's ("the boundary").
    QVERIFY2(dock->list()->item(0)->text().contains(QStringLiteral("outer wall")),
             qPrintable(dock->list()->item(0)->text()));
        QVERIFY(problemRings(*window) >= 1);
        QVERIFY(dock->repairAction()->isEnabled());

        // Read-only: no edit, no planning, and both say what to do.
        QVERIFY(!document->addPolygon(PolygonRole::Obstacle, {{1, 1}, {2, 1}, {2, 2}}));
        QVERIFY(window->lastError().contains(QStringLiteral("repair")));
        QVERIFY(!window->planningController()->planAndWait(5000));
        QVERIFY(window->planningController()->errorMessage().contains(QStringLiteral("repair")));

        // A problem clicked is shown: the view centres on it.
        QListWidgetItem* first = dock->list()->item(0);
        dock->list()->itemClicked(first);
        const QPointF centre =
            window->view()->mapToScene(window->view()->viewport()->rect().center());
        QVERIFY(centre.x() > -5 && centre.y() > -5);

        // One click repairs; the plan plans; the dock says what changed.
        dock->repairAction()->trigger();
        QVERIFY(!document->needsRepair());
        QVERIFY(!dock->repairAction()->isEnabled());
        QVERIFY(dock->summary().contains(QStringLiteral("Repaired")));
        QVERIFY(dock->list()->count() >= 1);
        QCOMPARE(problemRings(*window), 0);
        QVERIFY2(window->planningController()->planAndWait(), qPrintable(window->lastError()));
        QVERIFY(window->planningController()->result()->metrics.coverage > 0.9);

        // Undo brings the original back, read-only again; redo repairs again.
        document->undoStack()->undo();
        QVERIFY(document->needsRepair());
        QVERIFY(dock->repairAction()->isEnabled());
        document->undoStack()->redo();
        QVERIFY(!document->needsRepair());
    }

    void everyBrokenTestFileOpensAndRepairs() {
        auto window = makeWindow();
        for (const char* name :
             {"selfintersecting.geojson", "hole-outside.geojson", "overlapping-holes.geojson",
              "overlapping-rooms.geojson", "spike.geojson", "room-outside.geojson"}) {
            const QString path = QStringLiteral(FC_TEST_DATA_DIR "/") + QLatin1String(name);
            QVERIFY2(window->openFile(path), name);
            QVERIFY2(window->document()->needsRepair(), name);
            QVERIFY2(window->problemsDock()->repair(), qPrintable(window->lastError()));
            QVERIFY2(!window->document()->needsRepair(), name);
            QVERIFY2(window->planningController()->planAndWait(), name);
        }
    }

    void importOfABrokenPlanOpensForRepair() {
        auto window = makeWindow();
        window->openSample();
        QPointer<Document> sample = window->document();
        const QString path = QStringLiteral(FC_TEST_DATA_DIR "/overlapping-holes.geojson");
        ImportDialog dialog(path);
        QVERIFY2(dialog.result(), qPrintable(dialog.error())); // a warning, not a refusal
        bool warned = false;
        for (const std::string& warning : dialog.result()->warnings)
            warned = warned || warning.find("needs repair") != std::string::npos;
        QVERIFY(warned);
        // Asked into the current document, it still comes as a new one: the sample stays.
        QVERIFY(window->applyImport(path, *dialog.result(), false));
        QVERIFY(sample.isNull()); // replaced (asked first when modified), not edited
        QVERIFY(window->document()->needsRepair());
        QVERIFY(window->problemsDock()->repair());
        QVERIFY(window->planningController()->planAndWait());
    }

    void validPlanHasNoProblems() {
        auto window = makeWindow();
        window->openSample();
        QVERIFY(!window->document()->needsRepair());
        QVERIFY(!window->problemsDock()->isVisible());
        QVERIFY(!window->problemsDock()->repairAction()->isEnabled());
    }
};

QTEST_MAIN(RepairTest)
#include "test_repair.moc"
