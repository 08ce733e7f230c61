// Plan > Compare Solvers (issue 6): every solver, the paper's baselines included, on the same
// plan, robot, start, end and rooms, planned as one task (tasks/Task.h) of the window; a
// table of the SPEC's metrics and planning time, the paper's ratios against each baseline,
// and the paths side by side with their overlaps in blue. Closing the dialog cancels the
// task and returns at once.
#pragma once

#include "pipeline/Planner.h"
#include "tasks/Task.h"

#include <QDialog>
#include <QImage>
#include <QPointer>
#include <QString>
#include <vector>

class QGridLayout;
class QLabel;
class QPushButton;
class QTableWidget;

namespace fc::ui {

struct SolverRun {
    std::string solver;
    std::optional<PlanResult> result;
    std::string error; // set when the solver refused
};

class CompareDialog : public QDialog {
    Q_OBJECT
public:
    // dqn uses the request's model, or the built-in generalist when it names none.
    explicit CompareDialog(PlanRequest request, QWidget* parent = nullptr);
    ~CompareDialog() override;

    void start();
    void cancel();                           // the table stays as it is
    void done(int result) override;          // closing cancels
    bool runAndWait(int timeoutMs = 120000); // for tests
    Task* task() const { return task_; }     // the running comparison (null when none)
    const std::vector<SolverRun>& runs() const { return runs_; }
    QTableWidget* table() const { return table_; }
    QString ratiosText() const;
    QPushButton* stopButton() const { return stop_; } // enabled while comparing
    QImage pathImage(std::size_t index) const { return images_.at(index); }

    // The plan's walls with the path in dark red and its overlaps in blue.
    static QImage renderPath(const Plan& plan, const PlanResult& result, QSize size);

signals:
    void finished();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void showRuns();

    PlanRequest request_;
    std::vector<SolverRun> runs_;
    std::vector<QImage> images_;
    QPointer<Task> task_;
    QTableWidget* table_;
    QPushButton* stop_ = nullptr;
    QLabel* ratios_;
    QLabel* status_;
    QGridLayout* paths_;
};

} // namespace fc::ui
