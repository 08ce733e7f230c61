// Owns the tools, one checkable action per tool in an exclusive group, and the active tool.
#pragma once

#include <QObject>
#include <QPointer>
#include <functional>
#include <vector>

class QAction;
class QActionGroup;

namespace fc::ui {

class AbstractTool;
class Document;
class PlanScene;

class ToolManager : public QObject {
    Q_OBJECT
public:
    explicit ToolManager(QObject* parent = nullptr);

    // Takes ownership; the first registered tool becomes active.
    void registerTool(AbstractTool* tool);
    const std::vector<AbstractTool*>& tools() const { return tools_; }
    QList<QAction*> actions() const;
    AbstractTool* activeTool() const { return active_; }
    AbstractTool* findTool(const QString& name) const;

    void setActiveTool(AbstractTool* tool);
    // How tools ask before an edit that throws work away (replacing the boundary): the
    // window shows a question; unset, every question is answered yes.
    void setConfirmation(std::function<bool(const QString& question)> confirm);
    bool confirm(const QString& question) const { return !confirm_ || confirm_(question); }
    // Re-activates the tool on another document or scene.
    void setContext(Document* document, PlanScene* scene);

signals:
    void activeToolChanged(AbstractTool* tool);
    void statusMessage(const QString& message);

private:
    std::vector<AbstractTool*> tools_;
    QActionGroup* group_;
    AbstractTool* active_ = nullptr;
    std::function<bool(const QString&)> confirm_;
    QPointer<Document> document_;
    PlanScene* scene_ = nullptr;
};

} // namespace fc::ui
