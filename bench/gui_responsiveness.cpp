// floorcover-gui-bench: how responsive the editor stays while the DQN trains (issue 4: no
// frame over 50 ms). Opens PLAN (default: office) in the real main window, starts training
// in the training dock and, for SECONDS, measures the gaps between ticks of a 10 ms timer on
// the GUI thread while the reward plot updates; also how long each replot takes.
//   QT_QPA_PLATFORM=offscreen floorcover-gui-bench [PLAN] [SECONDS]
#include "window/MainWindow.h"
#include "tasks/PlanningController.h"
#include "learning/dqn/DqnSolver.h"
#include "docks/TrainingDock.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <qcustomplot.h>
#include <vector>

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    fc::registerDqnSolver();
    const QString plan =
        argc > 1 ? QString(argv[1]) : QStringLiteral(FC_PLANS_DIR "/office.geojson");
    const double seconds = argc > 2 ? std::atof(argv[2]) : 20.0;

    fc::ui::MainWindow window;
    window.setDialogsEnabled(false);
    window.resize(1280, 800);
    window.show();
    if (!window.openFile(plan)) {
        std::fprintf(stderr, "cannot open %s\n", qPrintable(plan));
        return 2;
    }
    fc::ui::TrainingDock* dock = window.trainingDock();
    dock->show();
    dock->raise();
    QElapsedTimer wait;
    wait.start();
    while (!window.planningController()->prepared() && wait.elapsed() < 30000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);

    std::vector<double> gaps;
    std::vector<double> replots;
    QObject::connect(dock->plot(), &QCustomPlot::afterReplot,
                     [&] { replots.push_back(dock->plot()->replotTime(false)); });
    dock->start();
    QElapsedTimer clock;
    clock.start();
    qint64 last = clock.nsecsElapsed();
    QTimer tick;
    tick.setInterval(10);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        const double gap = 1e-6 * static_cast<double>(now - last);
        gaps.push_back(gap);
        if (gap > 50.0)
            std::printf("frame over 50 ms: %.1f ms at %.2f s\n", gap,
                        1e-9 * static_cast<double>(now));
        last = now;
        if (clock.elapsed() >= seconds * 1000.0) {
            dock->stop();
            app.quit();
        }
    });
    tick.start();
    app.exec();

    std::sort(gaps.begin(), gaps.end());
    std::sort(replots.begin(), replots.end());
    auto percentile = [](const std::vector<double>& v, double p) {
        return v.empty() ? 0.0 : v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
    };
    std::printf("plan %s, %.0f s of training, %ld episodes, %d points plotted\n", qPrintable(plan),
                seconds, dock->episodes(), dock->plottedPoints());
    std::printf("GUI thread tick gaps (10 ms timer): median %.1f ms, p99 %.1f ms, max %.1f ms "
                "(%zu ticks)\n",
                percentile(gaps, 0.5), percentile(gaps, 0.99), gaps.empty() ? 0.0 : gaps.back(),
                gaps.size());
    std::printf("replot: median %.1f ms, max %.1f ms (%zu replots)\n", percentile(replots, 0.5),
                replots.empty() ? 0.0 : replots.back(), replots.size());
    return 0;
}
