#include "docks/ProblemsDock.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "document/PlannerMessages.h"

#include <QAction>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace fc::ui {

namespace {
constexpr int kLocationRole = Qt::UserRole + 1;
}

ProblemsDock::ProblemsDock(QWidget* parent)
    : QDockWidget(tr("Problems"), parent), summary_(new QLabel), list_(new QListWidget),
      button_(new QPushButton(tr("Repair Plan"))), repair_(new QAction(tr("&Repair Plan"), this)) {
    setObjectName(QStringLiteral("ProblemsDock"));
    summary_->setWordWrap(true);
    list_->setWordWrap(true);
    list_->setObjectName(QStringLiteral("problemList"));
    list_->setToolTip(tr("Click a problem to see where it is on the plan."));
    const QString explanation =
        tr("Makes the plan valid: walls that cross themselves are split where they cross, "
           "obstacles that overlap or cross the wall are merged or clipped, rooms are fitted "
           "to the floor. Undo (Ctrl+Z) brings the plan back as it was.");
    button_->setToolTip(explanation);
    repair_->setToolTip(explanation);
    repair_->setStatusTip(explanation);
    repair_->setObjectName(QStringLiteral("repairPlan"));
    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(summary_);
    layout->addWidget(list_, 1);
    layout->addWidget(button_);
    setWidget(content);
    connect(button_, &QPushButton::clicked, this, &ProblemsDock::repair);
    connect(repair_, &QAction::triggered, this, &ProblemsDock::repair);
    connect(list_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        const QVariant at = item->data(kLocationRole);
        if (at.isValid())
            emit locate(at.toPointF());
    });
    refresh();
}

void ProblemsDock::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    notes_.clear();
    if (document_) {
        connect(document_, &Document::geometryChanged, this, &ProblemsDock::refresh);
        connect(document_, &Document::roomsChanged, this, &ProblemsDock::refresh);
    }
    refresh();
}

QString ProblemsDock::summary() const {
    return summary_->text();
}

bool ProblemsDock::repair() {
    if (!document_ || !document_->needsRepair())
        return false;
    QStringList notes;
    if (!document_->repair(&notes))
        return false; // the document said why (editRejected)
    notes_ = notes;
    refresh();
    return true;
}

void ProblemsDock::refresh() {
    list_->clear();
    const bool broken = document_ && document_->needsRepair();
    repair_->setEnabled(broken);
    button_->setEnabled(broken);
    if (broken) {
        notes_.clear(); // an undone repair: the problems are back
        const auto& problems = document_->problems();
        summary_->setText(
            tr("This plan cannot be planned as it is: %n problem(s). It is open read-only and "
               "nothing is lost; repair it to plan.",
               nullptr, static_cast<int>(problems.size())));
        for (const PlanProblem& problem : problems) {
            auto* item = new QListWidgetItem(plainMessage(fromStd(problem.message)), list_);
            if (problem.hasLocation)
                item->setData(kLocationRole, toQt(problem.location));
        }
        show();
        raise();
        return;
    }
    if (!notes_.isEmpty()) {
        summary_->setText(tr("Repaired. What changed (Edit > Undo brings the old plan back):"));
        list_->addItems(notes_);
        return;
    }
    summary_->setText(tr("No problems: the plan can be planned."));
}

} // namespace fc::ui
