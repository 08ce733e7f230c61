// Reshaping rooms in the editor (issue 15: the rooms found in a map are corrected by hand):
// the Split Room tool, merging two rooms selected in the Planning panel, renaming, undo.
#include "EditorFixture.h"
#include "docks/PlanningDock.h"

#include <QListWidget>
#include <QPushButton>
#include <QUndoStack>

using namespace fc::ui;
using namespace fc::ui::test;

class RoomsTest : public QObject {
    Q_OBJECT

private:
    // A 20 x 14 m floor with one 10 x 14 m room (left half), all by mouse.
    void drawFloor(MainWindow& window);
    static void selectRooms(MainWindow& window, int first, int second);

private slots:
    void splitRoomByDragAndUndo();
    void mergeTheTwoSelectedRooms();
    void roomsApartAreNotMerged();
    void aCutThatMissesIsRefused();
    void renameAndMergeKeepAFixedAngle();
};

void RoomsTest::drawFloor(MainWindow& window) {
    window.newDocument();
    useDrawingScale(window);
    useTool(window, "drawBoundary");
    clickPolygon(window, {{0, 0}, {20, 0}, {20, 14}, {0, 14}});
    useTool(window, "drawRoom");
    clickPolygon(window, {{0, 0}, {10, 0}, {10, 14}, {0, 14}});
}

void RoomsTest::selectRooms(MainWindow& window, int first, int second) {
    QListWidget* list = window.planningDock()->roomList();
    list->clearSelection();
    list->item(first)->setSelected(true);
    list->item(second)->setSelected(true);
}

void RoomsTest::splitRoomByDragAndUndo() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "splitRoom");
    drag(*window, {4, -1}, {4, 15}); // from below the floor to above it
    const fc::Plan& plan = window->document()->plan();
    QCOMPARE(plan.rooms.size(), size_t(2));
    // The larger part keeps the name; the new one is named like a drawn room.
    QCOMPARE(QString::fromStdString(plan.rooms[0].name), QStringLiteral("Room 1"));
    QCOMPARE(QString::fromStdString(plan.rooms[1].name), QStringLiteral("Room 2"));
    QCOMPARE(fc::ringArea(plan.rooms[0].outline), 84.0);
    QCOMPARE(fc::ringArea(plan.rooms[1].outline), 56.0);
    QCOMPARE(window->planningDock()->roomList()->count(), 2);
    QVERIFY(window->document()->undoStack()->undoText().startsWith(QLatin1String("Split room")));
    window->document()->undoStack()->undo();
    QCOMPARE(window->document()->plan().rooms.size(), size_t(1));
    QCOMPARE(fc::ringArea(window->document()->plan().rooms[0].outline), 140.0);
}

void RoomsTest::mergeTheTwoSelectedRooms() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "splitRoom");
    drag(*window, {4, -1}, {4, 15});
    QPushButton* merge = window->planningDock()->mergeButton();
    QVERIFY(!merge->isEnabled()); // nothing selected
    selectRooms(*window, 0, 1);
    QVERIFY(merge->isEnabled());
    QTest::mouseClick(merge, Qt::LeftButton);
    const fc::Plan& plan = window->document()->plan();
    QCOMPARE(plan.rooms.size(), size_t(1));
    QCOMPARE(QString::fromStdString(plan.rooms[0].name), QStringLiteral("Room 1"));
    QCOMPARE(fc::ringArea(plan.rooms[0].outline), 140.0);
    QCOMPARE(plan.rooms[0].outline.size(), size_t(4)); // the cut's ends are gone
    window->document()->undoStack()->undo();
    QCOMPARE(window->document()->plan().rooms.size(), size_t(2));
}

void RoomsTest::roomsApartAreNotMerged() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "drawRoom");
    clickPolygon(*window, {{12, 0}, {20, 0}, {20, 4}, {12, 4}});
    selectRooms(*window, 0, 1);
    QTest::mouseClick(window->planningDock()->mergeButton(), Qt::LeftButton);
    QCOMPARE(window->document()->plan().rooms.size(), size_t(2));
    QVERIFY2(window->lastError().contains(QLatin1String("do not share a border")),
             qPrintable(window->lastError()));
}

void RoomsTest::aCutThatMissesIsRefused() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "splitRoom");
    const int before = window->document()->undoStack()->count();
    drag(*window, {15, 2}, {15, 12});  // beside the room
    drag(*window, {9.5, 2}, {9.5, 2}); // a click, not a cut
    QCOMPARE(window->document()->plan().rooms.size(), size_t(1));
    QCOMPARE(window->document()->undoStack()->count(), before);
}

void RoomsTest::renameAndMergeKeepAFixedAngle() {
    auto window = makeWindow();
    drawFloor(*window);
    useTool(*window, "splitRoom");
    drag(*window, {4, -1}, {4, 15});
    Document* document = window->document();
    fc::SweepOptions sweep = document->project().sweep;
    sweep.roomAngles["Room 2"] = 30.0;
    sweep.roomAngles["Room 1"] = 45.0;
    QVERIFY(document->setSweep(sweep));
    QVERIFY(document->renameRoom(0, QStringLiteral("Office")));
    QCOMPARE(document->project().sweep.roomAngles.at("Office"), 45.0);
    QCOMPARE(document->project().sweep.roomAngles.count("Room 1"), size_t(0));
    QVERIFY(document->mergeRooms(0, 1));
    // The merged room keeps the first room's angle; the second's is dropped.
    QCOMPARE(document->project().sweep.roomAngles.size(), size_t(1));
    QCOMPARE(document->project().sweep.roomAngles.at("Office"), 45.0);
}

QTEST_MAIN(RoomsTest)
#include "test_rooms.moc"
