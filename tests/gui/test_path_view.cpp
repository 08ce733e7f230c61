// The Path view for people (issue 16, item 2): graph internals hidden, start and end marked
// even when the planner chose them, labels that never overlap at any zoom, and the PDF
// report built on it (legend, room table, A4 and A3).
#include "EditorFixture.h"
#include "canvas/LabelPlacement.h"
#include "canvas/OverlayLayer.h"
#include "canvas/PlanScene.h"
#include "canvas/SceneStyle.h"
#include "document/Conversions.h"
#include "tasks/PlanningController.h"
#include "window/PdfReport.h"

#include <QAction>
#include <QFile>
#include <QGraphicsItem>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

using namespace fc::ui;
using namespace fc::ui::test;

namespace {

// Every label or marker the scene shows, as screen rectangles of the view.
QList<QRectF> shownLabelRects(MainWindow& window, QStringList* texts = nullptr) {
    QList<QRectF> rects;
    for (QGraphicsItem* item : window.scene()->items()) {
        const bool label = item->data(style::kLabelPriorityKey).isValid() ||
                           item->data(style::kFixedLabelKey).toBool();
        if (!label || !item->isVisible())
            continue;
        bool parentsShown = true;
        for (QGraphicsItem* p = item->parentItem(); p; p = p->parentItem())
            parentsShown = parentsShown && p->isVisible();
        if (!parentsShown)
            continue;
        const QTransform device = item->deviceTransform(window.view()->viewportTransform());
        rects.push_back(device.mapRect(item->boundingRect()));
        if (texts)
            if (auto* text = dynamic_cast<QGraphicsSimpleTextItem*>(item))
                texts->push_back(text->text());
    }
    return rects;
}

bool anyOverlap(const QList<QRectF>& rects) {
    for (int i = 0; i < rects.size(); ++i)
        for (int j = i + 1; j < rects.size(); ++j)
            if (rects[i].adjusted(0.5, 0.5, -0.5, -0.5).intersects(rects[j]))
                return true;
    return false;
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class PathViewTest : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("FloorCoverTests"));
        QSettings().remove(QStringLiteral("view/mode"));
        QVERIFY(dir_.isValid());
    }

    void placementKeepsLabelsApart() {
        // Three labels on one spot: the first keeps it, the others move aside or hide.
        std::vector<LabelRequest> requests(4);
        for (auto& request : requests)
            request.candidates = labelCandidates(QPointF(100, 100), QSizeF(40, 12));
        requests[1].priority = 5; // placed first
        requests[3].fixed = true; // a marker: always placed
        requests[3].candidates = {QRectF(150, 60, 18, 18)};
        const std::vector<int> chosen = placeLabels(requests);
        QCOMPARE(chosen[3], 0);
        QVERIFY(chosen[1] >= 0);
        QList<QRectF> placed;
        for (size_t i = 0; i < requests.size(); ++i)
            if (chosen[i] >= 0)
                placed.push_back(requests[i].candidates[chosen[i]]);
        QVERIFY(!anyOverlap(placed));
        QVERIFY(placed.size() >= 3);
    }

    void pathViewHidesTheGraphAndMarksStartAndEnd() {
        auto window = makeWindow();
        QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/office.geojson")));
        QVERIFY(window->planningController()->planAndWait());
        OverlayLayer* overlays = window->scene()->overlays();
        QCOMPARE(overlays->viewMode(), ViewMode::Path);              // the default for a supervisor
        // Not even built: the Path view's new paths never wait for the graph's items.
        QCOMPARE(overlays->itemCount(OverlayKind::PrimaryCells), 0);
        QVERIFY(!overlays->isShown(OverlayKind::PrimaryCells));
        QVERIFY(!overlays->isShown(OverlayKind::CornerNodes));
        QVERIFY(overlays->isShown(OverlayKind::Path));
        QVERIFY(!window->overlayAction(OverlayKind::PrimaryCells)->isEnabled());
        // The office has no start of its own: the path's ends are marked all the same.
        const auto result = window->planningController()->result();
        QVERIFY(result && !result->path.empty());
        int markers = 0;
        for (QGraphicsItem* item : window->scene()->items())
            if (item->data(style::kFixedLabelKey).toBool()) {
                ++markers;
                const QPointF at = item->pos();
                QVERIFY(at == fc::ui::toQt(result->path.points.front()) ||
                        at == fc::ui::toQt(result->path.points.back()));
            }
        QCOMPARE(markers, 2);

        auto* graphView = window->findChild<QAction*>(QStringLiteral("graphView"));
        QVERIFY(graphView);
        graphView->trigger();
        QVERIFY(overlays->isShown(OverlayKind::PrimaryCells));
        QVERIFY(overlays->itemCount(OverlayKind::PrimaryCells) > 0); // built on the switch
        QVERIFY(overlays->itemCount(OverlayKind::CornerNodes) > 0);
        QVERIFY(window->overlayAction(OverlayKind::PrimaryCells)->isEnabled());
        QCOMPARE(QSettings().value(QStringLiteral("view/mode")).toString(),
                 QStringLiteral("graph"));
        window->findChild<QAction*>(QStringLiteral("pathView"))->trigger();
        QCOMPARE(QSettings().value(QStringLiteral("view/mode")).toString(), QStringLiteral("path"));
    }

    void labelsNeverOverlapAtAnyZoom() {
        auto window = makeWindow();
        QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/office.geojson")));
        QVERIFY(window->planningController()->planAndWait());
        window->findChild<QAction*>(QStringLiteral("graphView"))->trigger(); // names + cell ids
        window->view()->fitToPlan();
        QStringList texts;
        QList<QRectF> rects = shownLabelRects(*window, &texts);
        QVERIFY(!anyOverlap(rects));
        // At the fitted zoom every room keeps its name.
        for (const fc::Room& room : window->document()->plan().rooms)
            QVERIFY2(texts.contains(QString::fromStdString(room.name)), room.name.c_str());
        // Zoomed far out, labels give way instead of printing over each other.
        for (int i = 0; i < 6; ++i)
            window->view()->zoomOut();
        rects = shownLabelRects(*window);
        QVERIFY(!anyOverlap(rects));
        window->view()->fitToPlan();
        QVERIFY(shownLabelRects(*window).size() >= rects.size());
        window->findChild<QAction*>(QStringLiteral("pathView"))->trigger();
        QVERIFY(!anyOverlap(shownLabelRects(*window)));
    }

    void reportHasLegendRoomTableAndFitsA4AndA3() {
        auto window = makeWindow();
        QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/office.geojson")));
        QVERIFY(window->document()->toggleRoomSelection(QStringLiteral("N02")));
        QVERIFY(window->planningController()->planAndWait());
        const auto result = window->planningController()->result();
        const QList<QStringList> table = reportRoomTable(*window->document(), *result);
        const int rooms = static_cast<int>(window->document()->plan().rooms.size());
        QVERIFY(table.size() >= rooms + 2); // header, rooms, (between rooms), total
        QCOMPARE(table.last().at(1), QStringLiteral("Total"));
        QStringList order;
        for (int i = 1; i <= rooms - 1; ++i) // the planned rooms come first, numbered
            QCOMPARE(table[i].at(0), QString::number(i));
        bool unplannedListed = false;
        for (const QStringList& row : table)
            unplannedListed = unplannedListed || (row.at(1) == QStringLiteral("N02") &&
                                                  row.at(0) == QStringLiteral("not planned"));
        QVERIFY(unplannedListed);
        bool startListed = false;
        for (const auto& [label, value] : reportSummary(*window->document(), *result))
            startListed = startListed || (label == QStringLiteral("Start") &&
                                          value.contains(QStringLiteral("chosen by the planner")));
        QVERIFY(startListed);

        const QString a4 = dir_.filePath(QStringLiteral("a4.pdf"));
        const QString a3 = dir_.filePath(QStringLiteral("a3.pdf"));
        QVERIFY2(window->exportReport(a4, QPageSize(QPageSize::A4)),
                 qPrintable(window->lastError()));
        QVERIFY(window->exportReport(a3, QPageSize(QPageSize::A3)));
        const QByteArray pdfA4 = readAll(a4), pdfA3 = readAll(a3);
        QVERIFY(pdfA4.startsWith("%PDF-"));
        const auto mediaBox = [](const QByteArray& pdf, const char* size) {
            const QRegularExpression box(
                QStringLiteral(R"(/MediaBox \[0 0 %1\])").arg(QString::fromLatin1(size)));
            return box.match(QString::fromLatin1(pdf)).hasMatch();
        };
        QVERIFY(mediaBox(pdfA4, R"(595(\.0+)? 842(\.0+)?)"));
        QVERIFY(mediaBox(pdfA3, R"(842(\.0+)? 1191(\.0+)?)"));
        QVERIFY(pdfA4.size() > 50000); // the map is in it
        // The view is back as it was: still the Path view, labels laid out for the screen.
        QCOMPARE(window->scene()->viewMode(), ViewMode::Path);
        QVERIFY(!anyOverlap(shownLabelRects(*window)));
    }
};

QTEST_MAIN(PathViewTest)
#include "test_path_view.moc"
