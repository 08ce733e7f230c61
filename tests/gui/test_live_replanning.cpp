// Live replanning (issue 16, item 1): an edit of the floor or the query replans in the
// background without F5, a quick draft first and the full plan after it; the old path stays
// greyed until the new one arrives; edits in a row plan once; turned off, nothing replans.
#include "EditorFixture.h"
#include "canvas/OverlayLayer.h"
#include "canvas/PlanScene.h"
#include "tasks/PlanningController.h"

#include <QAction>
#include <QCoreApplication>
#include <QLabel>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

using namespace fc;
using namespace fc::ui;
using namespace fc::ui::test;

class LiveReplanningTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void openingAPlanPlansIt();
    void queryEditReplansWithoutF5();
    void geometryEditReplansWithTheOldPathGreyed();
    void editsInARowPlanOnce();
    void turnedOffAnEditWaitsForF5();
    void menuActionIsRemembered();
    void aPlanOfRingsSaysSo();
};

namespace {

std::unique_ptr<MainWindow> windowOn(const char* plan) {
    auto window = makeWindow();
    if (!window->openFile(QStringLiteral(FC_PLANS_DIR "/") + QLatin1String(plan)))
        qWarning("%s did not open", plan);
    return window;
}

// Waits for the full plan (not the draft) of the document as it is now.
bool waitForFullPlan(PlanningController* planner, int ms = 60000) {
    return QTest::qWaitFor([&] { return planner->result() && !planner->isDraft(); }, ms);
}

QAction* liveAction(MainWindow& window) {
    return window.findChild<QAction*>(QStringLiteral("liveReplanning"));
}

} // namespace

void LiveReplanningTest::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverTests"));
    QCoreApplication::setApplicationName(QStringLiteral("gui_live_replanning"));
}

void LiveReplanningTest::openingAPlanPlansIt() {
    auto window = windowOn("simple.geojson");
    PlanningController* planner = window->planningController();
    QVERIFY(planner->liveReplanning());
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    QVERIFY(planner->result()->metrics.coverage >= 0.99);
    QVERIFY(window->scene()->overlays()->itemCount(OverlayKind::Path) > 0);
}

void LiveReplanningTest::queryEditReplansWithoutF5() {
    auto window = windowOn("office.geojson");
    PlanningController* planner = window->planningController();
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));

    // Results in the order they arrive: the draft first, then the full plan.
    std::vector<bool> drafts;
    bool draftHinted = false; // the sketch was warm-started from the path shown before
    connect(planner, &PlanningController::resultChanged, this, [&] {
        if (!planner->result())
            return;
        drafts.push_back(planner->isDraft());
        if (planner->isDraft()) {
            draftHinted = !planner->result()->query.orderHint.empty();
            for (const PlanPart& part : planner->result()->parts)
                draftHinted = draftHinted || !part.query.orderHint.empty();
        }
    });
    const QStringList rooms = window->document()->roomNames();
    QVERIFY(rooms.size() > 2);
    QVERIFY(window->document()->toggleRoomSelection(rooms.first()));
    QVERIFY(!planner->result());
    QVERIFY(planner->staleResult());
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    QCOMPARE(drafts, (std::vector<bool>{true, false}));
    QVERIFY(draftHinted);
    QVERIFY(!planner->staleResult());
    // The new plan is of the new query: the unticked room is not required.
    const auto& parts = planner->result()->parts;
    for (const PlanPart& part : parts)
        QVERIFY(std::find(part.rooms.begin(), part.rooms.end(), rooms.first().toStdString()) ==
                part.rooms.end());
    QVERIFY(planner->result()->metrics.coverage >= 0.99);
}

void LiveReplanningTest::geometryEditReplansWithTheOldPathGreyed() {
    auto window = windowOn("simple.geojson");
    PlanningController* planner = window->planningController();
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    const auto before = planner->result();
    const double areaBefore = before->metrics.requiredArea;

    // A 2 m pillar between the west wall and the obstacle.
    const BoundingBox box = window->document()->plan().bounds();
    const Vec2 c{box.minX + 2.5, 0.5 * (box.minY + box.maxY)};
    QVERIFY(window->document()->addPolygon(
        PolygonRole::Obstacle,
        Ring{{c.x - 1, c.y - 1}, {c.x + 1, c.y - 1}, {c.x + 1, c.y + 1}, {c.x - 1, c.y + 1}}));
    QVERIFY(!planner->result());
    QCOMPARE(planner->staleResult(), before);
    OverlayLayer* overlays = window->scene()->overlays();
    QVERIFY(overlays->itemCount(OverlayKind::Path) > 0); // faded
    QVERIFY(overlays->opacity(OverlayKind::Path) < 0.5);
    QCOMPARE(overlays->opacity(OverlayKind::CoverageGaps), 0.0); // of the old floor: hidden
    // Built again from scratch (a new palette), the stale path is drawn grey, gaps omitted.
    overlays->rebuild();
    QVERIFY(overlays->itemCount(OverlayKind::Path) > 0);
    QCOMPARE(overlays->itemCount(OverlayKind::CoverageGaps), 0);

    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    QVERIFY(planner->result()->metrics.requiredArea < areaBefore - 3.0);
    QVERIFY(planner->result()->metrics.coverage >= 0.99);
}

void LiveReplanningTest::editsInARowPlanOnce() {
    auto window = windowOn("simple.geojson");
    PlanningController* planner = window->planningController();
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    int drafts = 0, plans = 0;
    connect(planner, &PlanningController::resultChanged, this, [&] {
        if (planner->result())
            ++(planner->isDraft() ? drafts : plans);
    });
    // Five start positions in a row (a drag): one replan, for the last of them.
    const BoundingBox box = window->document()->plan().bounds();
    Vec2 last;
    for (int i = 1; i <= 5; ++i) {
        last = {box.minX + 0.1 * i * (box.maxX - box.minX), box.minY + 1.0};
        QVERIFY(window->document()->setStart(last));
    }
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    QTest::qWait(3 * PlanningController::kLiveDelayMs);
    QCOMPARE(drafts, 1);
    QCOMPARE(plans, 1);
    QVERIFY(distance(planner->result()->path.points.front(), last) < 1e-6);
}

void LiveReplanningTest::turnedOffAnEditWaitsForF5() {
    auto window = windowOn("simple.geojson");
    PlanningController* planner = window->planningController();
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    liveAction(*window)->setChecked(false);
    QVERIFY(!planner->liveReplanning());
    const auto before = planner->result();
    const BoundingBox box = window->document()->plan().bounds();
    QVERIFY(window->document()->setStart(Vec2{box.minX + 1.5, box.minY + 1.5}));
    QTest::qWait(20 * PlanningController::kLiveDelayMs);
    QVERIFY(!planner->result());
    QCOMPARE(planner->staleResult(), before); // still shown, greyed
    QVERIFY(!planner->isBusy());
    QVERIFY2(planner->planAndWait(), qPrintable(planner->errorMessage()));
    QVERIFY(!planner->isDraft());
    liveAction(*window)->setChecked(true);
}

void LiveReplanningTest::menuActionIsRemembered() {
    {
        auto window = makeWindow();
        QAction* live = liveAction(*window);
        QVERIFY(live && live->isChecked());
        live->setChecked(false);
    }
    {
        auto window = makeWindow();
        QVERIFY(!liveAction(*window)->isChecked());
        QVERIFY(!window->planningController()->liveReplanning());
        liveAction(*window)->setChecked(true);
    }
    auto window = makeWindow();
    QVERIFY(window->planningController()->liveReplanning());
}

// A corridor on a 120-degree arc plans as loops along its walls (pipeline/RingsOffer.h): the
// Planning dock says so under the Plan button, and its Planned column shows no angle.
void LiveReplanningTest::aPlanOfRingsSaysSo() {
    auto window = makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_TEST_DATA_DIR "/curved-corridor.geojson")));
    PlanningController* planner = window->planningController();
    QVERIFY2(waitForFullPlan(planner), qPrintable(planner->errorMessage()));
    QVERIFY(planner->result()->rings);
    auto* status = window->findChild<QLabel*>(QStringLiteral("planningStatus"));
    QVERIFY(status);
    QTRY_VERIFY2(status->text().contains(QStringLiteral("loops along the walls")),
                 qPrintable(status->text()));
    auto* angles = window->findChild<QTableWidget*>(QStringLiteral("roomAngles"));
    QVERIFY(angles);
    for (int row = 0; row < angles->rowCount(); ++row)
        QCOMPARE(angles->item(row, 3)->text(), QStringLiteral("–"));
}

QTEST_MAIN(LiveReplanningTest)
#include "test_live_replanning.moc"
