// A canvas tool (Tiled's model): the view forwards mouse and key events in plan
// coordinates to the active tool, which edits the document through its undoable API.
#pragma once

#include <QCursor>
#include <QIcon>
#include <QKeySequence>
#include <QObject>
#include <QPointF>
#include <QString>

class QKeyEvent;

namespace fc::ui {

class CanvasView;
class Document;
class PlanScene;

struct ToolMouseEvent {
    QPointF position;                      // plan metres, unsnapped
    QPointF snapped;                       // after grid / vertex snapping
    Qt::MouseButton button = Qt::NoButton; // the button pressed or released
    Qt::MouseButtons buttons;              // buttons held
    Qt::KeyboardModifiers modifiers;
    double metresPerPixel = 0.01; // for hit tolerances in screen pixels
};

class AbstractTool : public QObject {
    Q_OBJECT
public:
    AbstractTool(const QString& name, const QKeySequence& shortcut, QObject* parent = nullptr);

    QString name() const { return name_; }
    QKeySequence shortcut() const { return shortcut_; }
    // One line for the status bar telling how to use the tool.
    virtual QString usageHint() const = 0;
    // The canvas cursor while the tool is active.
    virtual QCursor cursor() const { return QCursor(Qt::ArrowCursor); }

    // Called when the tool becomes (in)active or the document is replaced.
    virtual void activate(Document* document, PlanScene* scene);
    virtual void deactivate();

    virtual void mousePressed(const ToolMouseEvent&) {}
    virtual void mouseMoved(const ToolMouseEvent&) {}
    virtual void mouseReleased(const ToolMouseEvent&) {}
    virtual void mouseDoubleClicked(const ToolMouseEvent&) {}
    // Returns true when the tool used the key.
    virtual bool keyPressed(QKeyEvent*) { return false; }

signals:
    void statusMessage(const QString& message);

protected:
    Document* document() const { return document_; }
    PlanScene* scene() const { return scene_; }
    // Asks the user through the tool manager (ToolManager::setConfirmation); yes when the
    // tool is not registered.
    bool confirm(const QString& question) const;

private:
    QString name_;
    QKeySequence shortcut_;
    Document* document_ = nullptr;
    PlanScene* scene_ = nullptr;
};

} // namespace fc::ui
