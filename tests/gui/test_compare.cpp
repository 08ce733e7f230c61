// Plan > Compare Solvers: every solver on the same query, the table, the paper's ratios and
// the paths side by side with overlaps in blue.
#include "EditorFixture.h"
#include "dialogs/CompareDialog.h"
#include "tasks/Task.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest>

using namespace fc;
using namespace fc::ui;

class CompareDialogTest : public QObject {
    Q_OBJECT
private slots:
    void comparesEverySolverWithTheBaselines();
    void menuOpensTheDialog();
    void stopButtonStopsAndCloseReturnsAtOnce();
    void columnsAreExplained();
};

void CompareDialogTest::comparesEverySolverWithTheBaselines() {
    PlanRequest request =
        planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/simple.geojson"));
    CompareDialog dialog(request);
    QVERIFY(dialog.runAndWait());
    std::vector<std::string> names;
    for (const SolverRun& run : dialog.runs())
        names.push_back(run.solver);
    for (const char* expected : {"exact", "heuristic", "greedy", "reeb-cpp", "adjacency-ga"})
        QVERIFY2(std::find(names.begin(), names.end(), expected) != names.end(), expected);
    QVERIFY(std::find(names.begin(), names.end(), "dqn") == names.end()); // no model given
    QCOMPARE(dialog.table()->rowCount(), static_cast<int>(dialog.runs().size()));
    for (std::size_t i = 0; i < dialog.runs().size(); ++i) {
        const SolverRun& run = dialog.runs()[i];
        QVERIFY2(run.result, run.error.c_str());
        QVERIFY(run.result->metrics.coverage >= 0.99);
        QVERIFY(!dialog.table()->item(static_cast<int>(i), 1)->text().isEmpty());
        // Something besides the white background was drawn, and overlaps show in blue.
        const QImage image = dialog.pathImage(i);
        QVERIFY(!image.isNull());
        bool blue = false;
        for (int y = 0; y < image.height() && !blue; ++y)
            for (int x = 0; x < image.width() && !blue; ++x) {
                const QColor c = image.pixelColor(x, y);
                blue = c.blue() > 180 && c.red() < 100;
            }
        QCOMPARE(blue, !run.result->metrics.overlaps.empty());
    }
    QVERIFY2(dialog.ratiosText().contains("reeb-cpp"), qPrintable(dialog.ratiosText()));
    QVERIFY(dialog.ratiosText().contains("adjacency-ga"));
}

void CompareDialogTest::menuOpensTheDialog() {
    auto window = fc::ui::test::makeWindow();
    QVERIFY(window->openFile(QStringLiteral(FC_PLANS_DIR "/simple.geojson")));
    QAction* compare = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text().contains("Compare"))
            compare = action;
    QVERIFY(compare);
    compare->trigger();
    CompareDialog* dialog = window->findChild<CompareDialog*>();
    QVERIFY(dialog);
    QSignalSpy done(dialog, &CompareDialog::finished);
    QVERIFY(done.wait(120000));
    QVERIFY(dialog->table()->rowCount() >= 5);
    dialog->close();
}

// Issue 16 trap: Compare could not be stopped, and closing it blocked the window until
// every solver had ended.
void CompareDialogTest::stopButtonStopsAndCloseReturnsAtOnce() {
    PlanRequest request =
        planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/ward.geojson"));
    {
        CompareDialog dialog(request);
        dialog.show();
        QVERIFY(!dialog.stopButton()->isEnabled());
        QSignalSpy done(&dialog, &CompareDialog::finished);
        dialog.start();
        QVERIFY(dialog.stopButton()->isEnabled());
        QTest::mouseClick(dialog.stopButton(), Qt::LeftButton);
        QVERIFY(done.wait(30000));
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.stopButton()->isEnabled(), 10000);
        QVERIFY(!dialog.task());
    }
    CompareDialog dialog(request);
    dialog.show();
    dialog.start();
    QPointer<Task> task = dialog.task();
    QVERIFY(task);
    QElapsedTimer closing;
    closing.start();
    dialog.close();
    QVERIFY2(closing.elapsed() < 2000, "closing waited for the solvers");
    QTRY_VERIFY_WITH_TIMEOUT(!task, 60000); // the work ends on its own, cancelled
}

void CompareDialogTest::columnsAreExplained() {
    CompareDialog dialog(
        planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/simple.geojson")));
    for (int c = 0; c < dialog.table()->columnCount(); ++c)
        QVERIFY(!dialog.table()->horizontalHeaderItem(c)->toolTip().isEmpty());
    QVERIFY(dialog.runAndWait());
    QVERIFY2(dialog.ratiosText().contains(QStringLiteral("below 100 % is better")),
             qPrintable(dialog.ratiosText()));
}

QTEST_MAIN(CompareDialogTest)
#include "test_compare.moc"
