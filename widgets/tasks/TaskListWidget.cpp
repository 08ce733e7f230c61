#include "tasks/TaskListWidget.h"

#include "tasks/Task.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>
#include <cmath>

namespace fc::ui {

TaskListWidget::TaskListWidget(TaskManager* tasks, QWidget* parent)
    : QWidget(parent), layout_(new QHBoxLayout(this)) {
    setObjectName(QStringLiteral("TaskList"));
    layout_->setContentsMargins(0, 0, 0, 0);
    connect(tasks, &TaskManager::taskAdded, this, &TaskListWidget::add);
    connect(tasks, &TaskManager::taskRemoved, this, &TaskListWidget::remove);
    for (Task* task : tasks->tasks())
        add(task);
    setVisible(!rows_.isEmpty());
}

void TaskListWidget::add(Task* task) {
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(task->description(), row);
    auto* bar = new QProgressBar(row);
    bar->setRange(0, 0); // busy until the work reports how far it is
    bar->setMaximumWidth(120);
    bar->setTextVisible(false);
    auto* cancel = new QToolButton(row);
    cancel->setObjectName(QStringLiteral("CancelTask"));
    cancel->setText(tr("Cancel"));
    cancel->setToolTip(tr("Cancel: %1").arg(task->description()));
    layout->addWidget(label);
    layout->addWidget(bar);
    layout->addWidget(cancel);
    connect(task, &Task::progressChanged, bar, [bar](double fraction) {
        if (fraction > 0.0)
            bar->setRange(0, 1000);
        bar->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
    });
    connect(task, &Task::statusChanged, label, [label, task](const QString& status) {
        label->setText(status.isEmpty() ? task->description()
                                        : tr("%1: %2").arg(task->description(), status));
    });
    connect(cancel, &QToolButton::clicked, task, [task, cancel, label] {
        task->cancel();
        cancel->setEnabled(false);
        label->setText(tr("%1 (cancelling…)").arg(task->description()));
    });
    layout_->addWidget(row);
    rows_.insert(task, row);
    show();
}

void TaskListWidget::remove(Task* task) {
    if (QWidget* row = rows_.take(task))
        row->deleteLater();
    setVisible(!rows_.isEmpty());
}

} // namespace fc::ui
