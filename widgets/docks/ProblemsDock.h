// The problems of a plan the planner refuses (self-intersections, obstacles across the
// wall, overlapping rooms...): listed with where they are, the plan held read-only, and one
// click to repair it (Document::repair). After a repair it lists what changed.
#pragma once

#include <QDockWidget>
#include <QPointF>
#include <QPointer>
#include <QStringList>

class QAction;
class QLabel;
class QListWidget;
class QPushButton;

namespace fc::ui {

class Document;

class ProblemsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ProblemsDock(QWidget* parent = nullptr);

    void setDocument(Document* document);
    // Plan > Repair Plan; enabled while the document needs a repair.
    QAction* repairAction() const { return repair_; }
    QListWidget* list() const { return list_; }
    QString summary() const;

public slots:
    bool repair();

signals:
    // A problem was clicked: show this plan point.
    void locate(QPointF planPoint);

private:
    void refresh();

    QPointer<Document> document_;
    QLabel* summary_;
    QListWidget* list_;
    QPushButton* button_;
    QAction* repair_;
    QStringList notes_; // what the last repair changed
};

} // namespace fc::ui
