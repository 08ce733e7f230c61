// The tiling-robot mode's planner (issue 7): tiles the document's floor and orders the tiles
// with the chosen method off the GUI thread. A result is dropped when the geometry changes
// or a newer run starts, so a slow ordering (aco, ga, ppo) never shows a stale floor.
#pragma once

#include "tiling/TilingPlanner.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <memory>

namespace fc::ui {

class Document;

class TilingController : public QObject {
    Q_OBJECT
public:
    explicit TilingController(QObject* parent = nullptr);

    void setDocument(Document* document);
    void setRobot(const tiling::TilingRobotProfile& robot);
    const tiling::TilingRobotProfile& robot() const { return robot_; }

    std::shared_ptr<const tiling::TilingPlan> result() const { return result_; }
    QString errorMessage() const { return error_; }
    bool isBusy() const { return running_ > 0; }
    // Starts run() and waits for it (tests, scripts). False on failure or timeout.
    bool runAndWait(const QString& solver, quint64 seed, int timeoutMs = 120000);

public slots:
    void run(const QString& solver, quint64 seed);
    void clear();

signals:
    void resultChanged();
    void errorChanged(const QString& message); // empty after a successful run
    void busyChanged(bool busy);

private:
    void setError(const QString& message);

    QPointer<Document> document_;
    tiling::TilingRobotProfile robot_;
    std::shared_ptr<const tiling::TilingPlan> result_;
    QString error_;
    quint64 generation_ = 0;
    int running_ = 0;
};

} // namespace fc::ui
