#include "dialogs/CompareDialog.h"

#include "document/PlannerMessages.h"
#include "pipeline/Comparison.h"
#include "tasks/Task.h"

#include <QCloseEvent>
#include <QDialogButtonBox>
#include <QEventLoop>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace fc::ui {
namespace {

std::vector<SolverRun> planAll(const PlanRequest& base, TaskFeedback& feedback) {
    // dqn without a trained model plans with the built-in generalist.
    const std::vector<std::string> names = solverNames();
    std::vector<SolverRun> runs;
    for (std::size_t i = 0; i < names.size(); ++i) {
        feedback.throwIfCancelled();
        feedback.setStatus(QString::fromStdString(names[i]));
        SolverRun run;
        run.solver = names[i];
        PlanRequest request = base;
        request.solver = names[i];
        SolveControl control; // this solver's share of the whole
        control.cancelled = feedback.cancelledFunction();
        control.progress = [&feedback, i, n = names.size()](double fraction) {
            feedback.setProgress((static_cast<double>(i) + fraction) / static_cast<double>(n));
        };
        try {
            run.result = planCoverage(request, control);
        } catch (const std::exception& e) {
            run.error = e.what();
        }
        runs.push_back(std::move(run));
        feedback.setProgress(static_cast<double>(i + 1) / static_cast<double>(names.size()));
    }
    feedback.throwIfCancelled(); // a cancelled solver "refused": not a comparison
    return runs;
}

QString number(double value, int decimals) {
    return QString::number(value, 'f', decimals);
}

} // namespace

CompareDialog::CompareDialog(PlanRequest request, QWidget* parent)
    : QDialog(parent), request_(std::move(request)), table_(new QTableWidget(this)),
      ratios_(new QLabel(this)), status_(new QLabel(tr("Planning with every solver…"), this)),
      paths_(new QGridLayout) {
    setWindowTitle(tr("Compare Solvers"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(status_);
    table_->setColumnCount(7);
    table_->setHorizontalHeaderLabels({tr("Solver"), tr("Length (m)"), tr("Extra (m)"), tr("Turns"),
                                       tr("Coverage"), tr("Time (s)"), tr("Planning (s)")});
    // What each column means, in the words of the floor rather than the paper.
    const QStringList tips{
        tr("The method that ordered the rooms' cells"),
        tr("How far the robot drives in all"),
        tr("Distance beyond the stripes themselves (floor area / coverage width): the "
           "moves between stripes and rooms. Less is better."),
        tr("Turns the robot makes; each costs the turn time"),
        tr("Share of the floor the robot can reach that the path sweeps"),
        tr("Estimated cleaning time: length / speed + turns × turn time"),
        tr("How long the computer took to plan")};
    for (int c = 0; c < tips.size(); ++c)
        table_->horizontalHeaderItem(c)->setToolTip(tips[c]);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(table_);
    ratios_->setWordWrap(true);
    ratios_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(ratios_);
    auto* pathsWidget = new QWidget;
    pathsWidget->setLayout(paths_);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(pathsWidget);
    scroll->setWidgetResizable(true);
    layout->addWidget(scroll, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    stop_ = buttons->addButton(tr("Stop"), QDialogButtonBox::ActionRole);
    stop_->setToolTip(tr("Stop comparing; solvers that answered stay in the table"));
    stop_->setEnabled(false);
    if (QPushButton* close = buttons->button(QDialogButtonBox::Close))
        close->setToolTip(tr("Close; a comparison still running is cancelled at once"));
    table_->setToolTip(tr("One row per solver; hover a column's title for what it means."));
    connect(stop_, &QPushButton::clicked, this, &CompareDialog::cancel);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(1000, 760);
}

CompareDialog::~CompareDialog() {
    cancel(); // the window's manager lets the work end; nothing waits here
}

void CompareDialog::start() {
    cancel();
    status_->setText(tr("Planning with every solver…"));
    task_ = TaskManager::forObject(this)->run(
        tr("Comparing the solvers"),
        [request = request_](TaskFeedback& feedback) { return planAll(request, feedback); });
    stop_->setEnabled(true);
    connect(task_, &Task::statusChanged, this, [this](const QString& solver) {
        status_->setText(tr("Planning with every solver… (%1)").arg(solver));
    });
    connect(task_, &Task::finished, this, [this, task = task_.data()] {
        runs_ = *task->result<std::vector<SolverRun>>();
        showRuns();
        emit finished();
    });
    connect(task_, &Task::failed, this, [this](const QString& message) {
        status_->setText(tr("The comparison failed: %1").arg(plainMessage(message)));
        emit finished();
    });
    connect(task_, &Task::cancelled, this, [this] {
        status_->setText(tr("The comparison was cancelled."));
        emit finished();
    });
    connect(task_, &Task::ended, this, [this] {
        task_ = nullptr;
        stop_->setEnabled(false);
    });
}

void CompareDialog::cancel() {
    if (task_)
        task_->cancel();
}

void CompareDialog::closeEvent(QCloseEvent* event) {
    cancel();
    QDialog::closeEvent(event);
}

void CompareDialog::done(int result) {
    cancel();
    QDialog::done(result);
}

bool CompareDialog::runAndWait(int timeoutMs) {
    QEventLoop loop;
    connect(this, &CompareDialog::finished, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    start();
    loop.exec();
    return !task_ && !runs_.empty();
}

void CompareDialog::showRuns() {
    table_->setRowCount(static_cast<int>(runs_.size()));
    images_.clear();
    std::vector<std::pair<std::string, Metrics>> answered;
    int column = 0, row = 0;
    for (std::size_t i = 0; i < runs_.size(); ++i) {
        const SolverRun& run = runs_[i];
        const int r = static_cast<int>(i);
        table_->setItem(r, 0, new QTableWidgetItem(QString::fromStdString(run.solver)));
        if (!run.result) {
            // Across the figures' columns, so a long reason does not widen "Length".
            const QString reason = plainMessage(QString::fromStdString(run.error));
            auto* item = new QTableWidgetItem(tr("Did not plan: %1").arg(reason));
            item->setToolTip(reason);
            table_->setItem(r, 1, item);
            table_->setSpan(r, 1, 1, table_->columnCount() - 1);
            images_.emplace_back();
            continue;
        }
        const Metrics& m = run.result->metrics;
        answered.emplace_back(run.solver, m);
        const QStringList cells{number(m.length, 1),      number(m.extra, 1),
                                QString::number(m.turns), number(100.0 * m.coverage, 2) + " %",
                                number(m.time, 0),        number(m.seconds, 2)};
        for (int c = 0; c < cells.size(); ++c)
            table_->setItem(r, c + 1, new QTableWidgetItem(cells[c]));
        images_.push_back(renderPath(request_.plan, *run.result, QSize(300, 220)));
        auto* caption = new QLabel(QString::fromStdString(run.solver));
        auto* picture = new QLabel;
        picture->setPixmap(QPixmap::fromImage(images_.back()));
        paths_->addWidget(caption, 2 * row, column);
        paths_->addWidget(picture, 2 * row + 1, column);
        if (++column == 3) {
            column = 0;
            ++row;
        }
    }
    QStringList lines;
    for (const BaselineRatio& ratio : baselineRatios(answered))
        lines << tr("%1 drives %3 % of the extra distance of %2 (a published method) and makes "
                    "%4 % of its turns; below 100 % is better. The published comparison: %5.")
                     .arg(QString::fromStdString(ratio.ours),
                          QString::fromStdString(ratio.baseline),
                          number(100.0 * ratio.extraRatio, 1), number(100.0 * ratio.turnsRatio, 1),
                          QString::fromStdString(paperRatiosText(ratio.baseline)));
    ratios_->setText(lines.join('\n'));
    status_->setText(tr("%1 of %2 solvers answered; overlaps are drawn in blue.")
                         .arg(answered.size())
                         .arg(runs_.size()));
}

QString CompareDialog::ratiosText() const {
    return ratios_->text();
}

QImage CompareDialog::renderPath(const Plan& plan, const PlanResult& result, QSize size) {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec2& p : plan.boundary) {
        x0 = std::min(x0, p.x);
        y0 = std::min(y0, p.y);
        x1 = std::max(x1, p.x);
        y1 = std::max(y1, p.y);
    }
    if (!(x1 > x0 && y1 > y0))
        return image;
    const double margin = 6.0;
    const double scale =
        std::min((size.width() - 2 * margin) / (x1 - x0), (size.height() - 2 * margin) / (y1 - y0));
    auto map = [&](Vec2 p) { // y up
        return QPointF(margin + (p.x - x0) * scale, size.height() - margin - (p.y - y0) * scale);
    };
    auto ring = [&](const Ring& r) {
        QPolygonF polygon;
        for (const Vec2& p : r)
            polygon << map(p);
        return polygon;
    };
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QPainterPath free;
    free.addPolygon(ring(plan.boundary));
    for (const Ring& obstacle : plan.obstacles) {
        QPainterPath hole;
        hole.addPolygon(ring(obstacle));
        free = free.subtracted(hole);
    }
    painter.fillPath(free, QColor(235, 235, 235));
    painter.setPen(QPen(QColor(60, 60, 60), 1.2));
    painter.drawPath(free);
    QPolygonF path;
    for (const Vec2& p : result.path.points)
        path << map(p);
    painter.setPen(QPen(QColor(150, 30, 30), 1.0));
    painter.drawPolyline(path);
    painter.setPen(QPen(QColor(30, 90, 230), 2.0));
    for (const Segment& s : result.metrics.overlaps)
        painter.drawLine(map(s.a), map(s.b));
    return image;
}

} // namespace fc::ui
