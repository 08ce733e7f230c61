// floorcover-plot-curves: renders the learning curves written by floorcover-dqn-report as
// one PNG per plan (QCustomPlot, off screen): reward and gap to the reference, against
// episodes and against training seconds, for the paper's, the improved and (when its curves
// exist) the graph-state setting.
//   floorcover-plot-curves DIR CASE[,CASE..] OUTDIR
#include <QApplication>
#include <QFile>
#include <QTextStream>
#include <algorithm>
#include <cstdio>
#include <qcustomplot.h>
#include <stdexcept>
#include <utility>
#include <vector>

namespace {

// The gaps span from the optimum (0) to several hundred percent: a log axis, 0 drawn here.
constexpr double kLowestGapPercent = 0.1;

struct Curve {
    QVector<double> episode, seconds, reward, average, gapEpisode, gapSeconds, gap;
};

// Throws std::runtime_error for a missing file or a malformed number, so that a broken run
// never becomes a plausible-looking figure.
Curve readCurve(const QString& path) {
    Curve c;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        throw std::runtime_error("cannot read " + path.toStdString());
    QTextStream in(&file);
    in.readLine(); // header
    int line = 1;
    auto value = [&](const QString& field) {
        bool ok = false;
        const double v = field.toDouble(&ok);
        if (!ok)
            throw std::runtime_error(path.toStdString() + ":" + std::to_string(line) +
                                     ": not a number: " + field.toStdString());
        return v;
    };
    while (!in.atEnd()) {
        ++line;
        const QStringList f = in.readLine().split(',');
        if (f.size() != 8)
            throw std::runtime_error(path.toStdString() + ":" + std::to_string(line) +
                                     ": expected 8 fields");
        const double episode = value(f[0]), seconds = value(f[1]);
        if (!f[3].isEmpty()) { // a training episode (the last row only has the final gap)
            c.episode << episode;
            c.seconds << seconds;
            c.reward << value(f[2]);
            c.average << value(f[3]);
        }
        if (!f[6].isEmpty()) { // an evaluation of the policy
            c.gapEpisode << episode;
            c.gapSeconds << seconds;
            c.gap << std::max(kLowestGapPercent, 100.0 * value(f[6]));
        }
    }
    return c;
}

void addLine(QCPAxisRect* rect, QCPAxis* valueAxis, const QVector<double>& x,
             const QVector<double>& y, const QColor& color, const QString& name, QCustomPlot& plot,
             bool dots = false) {
    QCPGraph* g = plot.addGraph(rect->axis(QCPAxis::atBottom), valueAxis);
    g->setData(x, y, true);
    g->setPen(QPen(color, dots ? 1.0 : 2.0));
    g->setName(name);
    if (dots) {
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDot));
    }
    valueAxis->setVisible(true);
    valueAxis->rescale();
    rect->axis(QCPAxis::atBottom)->rescale();
}

} // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    if (argc != 4) {
        std::fprintf(stderr, "usage: floorcover-plot-curves DIR CASE[,CASE..] OUTDIR\n");
        return 2;
    }
    const QString dir = argv[1];
    // The paper's reward on the left axis; improved and graph share theirs (minus the added
    // graph cost) on the right. The graph setting is drawn when its curves exist.
    const struct {
        const char* name;
        QColor color;
        bool optional;
    } settings[] = {{"paper", QColor(0xd9, 0x5f, 0x02), false},
                    {"improved", QColor(0x1b, 0x9e, 0x77), false},
                    {"graph", QColor(0x75, 0x70, 0xb3), true}};
    for (const QString& name : QString(argv[2]).split(',')) {
        std::vector<std::pair<int, Curve>> curves; // index into settings
        try {
            for (int i = 0; i < 3; ++i) {
                const QString path = dir + "/curves-" + name + "-" + settings[i].name + ".csv";
                if (settings[i].optional && !QFile::exists(path))
                    continue;
                curves.emplace_back(i, readCurve(path));
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "floorcover-plot-curves: %s\n", e.what());
            return 2;
        }
        QCustomPlot plot;
        plot.setAutoAddPlottableToLegend(false); // each panel has its own legend
        plot.plotLayout()->clear();
        plot.plotLayout()->addElement(
            0, 0,
            new QCPTextElement(&plot, "DQN learning curves: " + name + " (one CPU thread)",
                               QFont("Sans", 12, QFont::Bold)));
        auto* grid = new QCPLayoutGrid;
        plot.plotLayout()->addElement(1, 0, grid);
        const struct {
            const char* x;
            bool seconds;
        } axes[] = {{"episodes", false}, {"training CPU seconds (one thread)", true}};
        for (int column = 0; column < 2; ++column) {
            const bool bySeconds = axes[column].seconds;
            // Reward: the paper's setting has its own reward function, so its own axis.
            auto* reward = new QCPAxisRect(&plot);
            grid->addElement(0, column, reward);
            reward->axis(QCPAxis::atBottom)->setLabel(axes[column].x);
            reward->axis(QCPAxis::atLeft)->setLabel("paper: episode reward (avg of 100)");
            reward->axis(QCPAxis::atRight)->setLabel("improved, graph: -graph cost / longest edge");
            double lastX = 0.0;
            QCPRange left(0, 0), right(0, 0); // the data's own ranges, with a margin below
            bool anyLeft = false, anyRight = false;
            for (const auto& [index, c] : curves) {
                const QVector<double>& x = bySeconds ? c.seconds : c.episode;
                addLine(reward, reward->axis(index == 0 ? QCPAxis::atLeft : QCPAxis::atRight), x,
                        c.average, settings[index].color, settings[index].name, plot);
                lastX = std::max(lastX, x.isEmpty() ? 0.0 : x.back());
                for (double y : c.average) {
                    QCPRange& range = index == 0 ? left : right;
                    bool& any = index == 0 ? anyLeft : anyRight;
                    range = any ? QCPRange(std::min(range.lower, y), std::max(range.upper, y))
                                : QCPRange(y, y);
                    any = true;
                }
            }
            reward->axis(QCPAxis::atBottom)->setRange(0, lastX);
            // QCustomPlot's rescale clipped a short line on a long key axis: set them here.
            for (auto [axis, range] : {std::pair{reward->axis(QCPAxis::atLeft), left},
                                       std::pair{reward->axis(QCPAxis::atRight), right}}) {
                const double margin = 0.04 * std::max(range.size(), 1e-6);
                axis->setRange(range.lower - margin, range.upper + margin);
            }
            // Gap of the greedy policy (no refinement) to the reference solver.
            auto* gap = new QCPAxisRect(&plot);
            grid->addElement(1, column, gap);
            gap->axis(QCPAxis::atBottom)->setLabel(axes[column].x);
            gap->axis(QCPAxis::atLeft)
                ->setLabel("policy gap to exact/heuristic (%, log; 0 drawn at 0.1)");
            gap->axis(QCPAxis::atLeft)->setScaleType(QCPAxis::stLogarithmic);
            gap->axis(QCPAxis::atLeft)->setTicker(QSharedPointer<QCPAxisTickerLog>::create());
            for (const auto& [index, c] : curves)
                addLine(gap, gap->axis(QCPAxis::atLeft), bySeconds ? c.gapSeconds : c.gapEpisode,
                        c.gap, settings[index].color, settings[index].name, plot);
            gap->axis(QCPAxis::atLeft)->setRangeLower(kLowestGapPercent);
            gap->axis(QCPAxis::atBottom)->setRange(reward->axis(QCPAxis::atBottom)->range());
            auto* legend = new QCPLegend;
            gap->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
            legend->setLayer(QStringLiteral("legend"));
            const int lines = static_cast<int>(curves.size());
            for (int i = plot.graphCount() - lines; i < plot.graphCount(); ++i)
                legend->addItem(new QCPPlottableLegendItem(legend, plot.graph(i)));
        }
        const QString out = QString(argv[3]) + "/dqn-curves-" + name + ".png";
        if (!plot.savePng(out, 1200, 800)) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(out));
            return 1;
        }
        std::printf("%s\n", qPrintable(out));
    }
    return 0;
}
