// The main window's task list (in the status bar): each running task with its description,
// a progress bar (busy until the work reports progress) and a Cancel button; hidden when
// nothing runs.
#pragma once

#include <QHash>
#include <QWidget>

class QHBoxLayout;

namespace fc::ui {

class Task;
class TaskManager;

class TaskListWidget : public QWidget {
    Q_OBJECT
public:
    explicit TaskListWidget(TaskManager* tasks, QWidget* parent = nullptr);

    int rowCount() const { return static_cast<int>(rows_.size()); }
    // The row of `task` (null when it is not listed), for tests.
    QWidget* rowOf(Task* task) const { return rows_.value(task); }

private:
    void add(Task* task);
    void remove(Task* task);

    QHBoxLayout* layout_;
    QHash<Task*, QWidget*> rows_;
};

} // namespace fc::ui
