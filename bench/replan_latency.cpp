// floorcover-replan-bench: live replanning in the real editor (issue 16, item 1). For each
// plan, repeated edits of four kinds (tick or untick a room, move the start, move one
// room's vertex by 10 cm, move a wall's vertex by 10 cm) are made through the document as the tools
// make them; measured is the time from the edit to the new path drawn on the canvas (the draft), to
// the full plan, and the longest the GUI thread went without serving its 10 ms timer meanwhile.
//   QT_QPA_PLATFORM=offscreen floorcover-replan-bench [--edits N] [--paint] [PLAN...]
// --paint: also what each overlay costs to draw.
#include "canvas/CanvasView.h"
#include "canvas/OverlayLayer.h"
#include "canvas/PlanScene.h"
#include "document/Document.h"
#include "model/RobotPlacement.h"
#include "tasks/PlanningController.h"
#include "window/MainWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <optional>
#include <random>
#include <vector>

using namespace fc;
using namespace fc::ui;

namespace {

struct Samples {
    std::vector<double> draft, full;
    double longestGap = 0.0;
};

double median(std::vector<double> v) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double maximum(const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

// Runs the event loop until `done` or `ms`; the GUI thread's longest gap between 10 ms
// timer ticks goes into `gap`.
bool runUntil(const std::function<bool()>& done, int ms, double& gap) {
    QElapsedTimer clock;
    clock.start();
    qint64 last = clock.nsecsElapsed();
    QTimer tick;
    tick.setInterval(10);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        gap = std::max(gap, 1e-6 * static_cast<double>(now - last));
        last = now;
    });
    tick.start();
    // Sleeps until an event comes (the tick wakes it at least every 10 ms), as the editor's
    // own event loop does: a polling loop would take a core from the planner's threads.
    while (!done() && clock.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    return done();
}

// One edit: applies it, then times the draft on screen and the full plan.
void measureEdit(MainWindow& window, const std::function<bool()>& edit, Samples& out) {
    PlanningController* planner = window.planningController();
    QElapsedTimer clock;
    double draftMs = -1.0;
    QMetaObject::Connection shown =
        QObject::connect(planner, &PlanningController::resultChanged, [&] {
            if (planner->result() && draftMs < 0.0) {
                window.view()->viewport()->repaint(); // the path as drawn, not only computed
                draftMs = 1e-6 * static_cast<double>(clock.nsecsElapsed());
            }
        });
    clock.start();
    if (!edit()) {
        QObject::disconnect(shown);
        return;
    }
    const bool ok =
        runUntil([&] { return planner->result() && !planner->isDraft() && !planner->isBusy(); },
                 120000, out.longestGap);
    QObject::disconnect(shown);
    if (!ok) {
        std::printf("  no plan after an edit (result %d, draft %d, busy %d): %s\n",
                    planner->result() != nullptr, planner->isDraft(), planner->isBusy(),
                    qPrintable(planner->errorMessage()));
        return;
    }
    out.draft.push_back(draftMs);
    out.full.push_back(1e-6 * static_cast<double>(clock.nsecsElapsed()));
}

void report(const char* kind, const Samples& s) {
    std::printf("  %-16s %3zu edits  path on screen: median %6.0f ms, max %6.0f ms   full plan: "
                "median %6.0f ms, max %6.0f ms   longest GUI gap %4.0f ms\n",
                kind, s.draft.size(), median(s.draft), maximum(s.draft), median(s.full),
                maximum(s.full), s.longestGap);
}

// What each overlay costs the GUI thread to draw: once when it is new (rendered into its
// item cache) and again when nothing changed (the cache blitted).
void printPaintBreakdown(MainWindow& window) {
    OverlayLayer* overlays = window.scene()->overlays();
    auto paintMs = [&] {
        QElapsedTimer t;
        t.start();
        window.view()->viewport()->repaint();
        return 1e-6 * static_cast<double>(t.nsecsElapsed());
    };
    std::array<bool, kOverlayKindCount> was{};
    for (int k = 0; k < kOverlayKindCount; ++k) {
        was[k] = overlays->isVisible(static_cast<OverlayKind>(k));
        overlays->setVisible(static_cast<OverlayKind>(k), false);
    }
    paintMs();
    std::printf("  canvas without overlays: %.1f ms\n", paintMs());
    for (int k = 0; k < kOverlayKindCount; ++k) {
        const auto kind = static_cast<OverlayKind>(k);
        overlays->setVisible(kind, true);
        overlays->rebuild();
        const double first = paintMs();
        std::printf("  %-18s first paint %5.1f ms, again %4.1f ms (%d items)\n",
                    qPrintable(overlayName(kind)), first, paintMs(), overlays->itemCount(kind));
        overlays->setVisible(kind, false);
    }
    for (int k = 0; k < kOverlayKindCount; ++k)
        overlays->setVisible(static_cast<OverlayKind>(k), was[k]);
    overlays->rebuild();
    const double all = paintMs();
    std::printf("  default overlays: first paint %.1f ms, again %.1f ms\n", all, paintMs());
}

void benchPlan(const QString& path, int edits, bool paintBreakdown) {
    MainWindow window;
    window.setDialogsEnabled(false);
    window.resize(1280, 800);
    window.show();
    if (!window.openFile(path)) {
        std::printf("%s: cannot open\n", qPrintable(path));
        return;
    }
    PlanningController* planner = window.planningController();
    double ignored = 0.0;
    if (!runUntil([&] { return planner->result() && !planner->isDraft() && !planner->isBusy(); },
                  120000, ignored)) {
        std::printf("%s: no plan: %s\n", qPrintable(path), qPrintable(planner->errorMessage()));
        return;
    }
    Document* document = window.document();
    std::printf("%s (%zu rooms)\n", qPrintable(path), document->plan().rooms.size());
    std::fflush(stdout);
    std::mt19937 random(7);
    const QStringList rooms = document->roomNames();

    Samples toggles, starts, vertices;
    for (int i = 0; i < edits; ++i) {
        const QString room = rooms[static_cast<int>(random() % rooms.size())];
        measureEdit(
            window, [&] { return document->toggleRoomSelection(room); }, toggles);
        if (!document->isRoomSelected(room)) // back to every room, also measured
            measureEdit(
                window, [&] { return document->toggleRoomSelection(room); }, toggles);
    }
    const Plan& plan = document->plan();
    const RobotProfile& robot = document->project().robot;
    const double robotDiameter =
        robot.robotDiameter > 0.0 ? robot.robotDiameter : robot.coverageWidth;
    for (int i = 0; i < edits; ++i) {
        // A random point of a random room, placed as the Place Start tool places it.
        const Room& room = plan.rooms.empty() ? Room{} : plan.rooms[random() % plan.rooms.size()];
        const Ring& outline = room.outline.empty() ? plan.boundary : room.outline;
        const BoundingBox box = boundsOf(outline);
        std::uniform_real_distribution<double> x(box.minX, box.maxX), y(box.minY, box.maxY);
        std::optional<Vec2> start;
        for (int attempt = 0; attempt < 100 && !start; ++attempt) {
            const Vec2 clicked{x(random), y(random)};
            if (!pointInRing(outline, clicked))
                continue;
            const RobotPlacement placed = placeRobot(plan, clicked, robotDiameter);
            if (placed.problem == PlacementProblem::None)
                start = placed.position;
        }
        if (!start)
            continue;
        measureEdit(
            window, [&] { return document->setStart(*start); }, starts);
    }
    for (int i = 0; i < edits && !plan.rooms.empty(); ++i) {
        const int index = static_cast<int>(random() % plan.rooms.size());
        const Ring& outline = plan.rooms[index].outline;
        const int vertex = static_cast<int>(random() % outline.size());
        // 10 cm towards the room's inside and back: the room stays valid.
        Vec2 centre;
        for (const Vec2& p : outline)
            centre = centre + p * (1.0 / static_cast<double>(outline.size()));
        const Vec2 from = outline[vertex];
        const Vec2 to = from + (centre - from) * (0.1 / std::max(0.1, distance(centre, from)));
        const PolygonRef ref{PolygonRole::Room, index};
        measureEdit(
            window, [&] { return document->moveVertex(ref, vertex, to); }, vertices);
        measureEdit(
            window, [&] { return document->moveVertex(ref, vertex, from); }, vertices);
    }
    // A wall edit changes the free space, so nothing of the floor is reused: an obstacle's
    // vertex 10 cm towards its middle (it shrinks, the plan stays valid), or without
    // obstacles a boundary vertex 10 cm outwards.
    Samples walls;
    for (int i = 0; i < edits; ++i) {
        const bool obstacle = !plan.obstacles.empty();
        const int index = obstacle ? static_cast<int>(random() % plan.obstacles.size()) : 0;
        const Ring& outline = obstacle ? plan.obstacles[index] : plan.boundary;
        const int vertex = static_cast<int>(random() % outline.size());
        Vec2 centre;
        for (const Vec2& p : outline)
            centre = centre + p * (1.0 / static_cast<double>(outline.size()));
        const Vec2 from = outline[vertex];
        const Vec2 inwards = (centre - from) * (1.0 / std::max(1e-9, distance(centre, from)));
        const Vec2 to = from + inwards * (obstacle ? 0.1 : -0.1);
        const PolygonRef ref{obstacle ? PolygonRole::Obstacle : PolygonRole::Boundary, index};
        measureEdit(
            window, [&] { return document->moveVertex(ref, vertex, to); }, walls);
        measureEdit(
            window, [&] { return document->moveVertex(ref, vertex, from); }, walls);
    }
    if (paintBreakdown)
        printPaintBreakdown(window);
    report("room ticked", toggles);
    report("start moved", starts);
    report("room vertex", vertices);
    report(plan.obstacles.empty() ? "boundary vertex" : "obstacle vertex", walls);
}

} // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverBench"));
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    int edits = 10;
    bool paintBreakdown = false;
    QStringList plans;
    for (int i = 1; i < argc; ++i) {
        const QString arg = QString::fromLocal8Bit(argv[i]);
        if (arg == QLatin1String("--paint"))
            paintBreakdown = true;
        else if (arg == QLatin1String("--edits") && i + 1 < argc)
            edits = std::max(1, std::atoi(argv[++i]));
        else
            plans << arg;
    }
    if (plans.isEmpty())
        plans << QStringLiteral(FC_PLANS_DIR "/office.geojson")
              << QStringLiteral(FC_PLANS_DIR "/ward.geojson");
    std::printf("live replanning (debounce %d ms included), %d edits of each kind\n",
                PlanningController::kLiveDelayMs, edits);
    for (const QString& plan : plans)
        benchPlan(plan, edits, paintBreakdown);
    return 0;
}
