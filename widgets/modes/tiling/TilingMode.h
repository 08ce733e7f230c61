// The editor's tiling-robot mode (issue 7): a checkable "Tiling Robot Mode" action that
// shows the tiling dock and the tiles on the canvas. Owns the mode's controller, dock and
// canvas item, so the main window only creates it and hands it the document.
#pragma once

#include <QGraphicsScene>
#include <QObject>
#include <QPointer>

class QAction;
class QMainWindow;

namespace fc::ui {

class Document;
class TilingController;
class TilingDock;
class TilingItem;

class TilingMode : public QObject {
    Q_OBJECT
public:
    TilingMode(QMainWindow* window, QGraphicsScene* scene);
    ~TilingMode() override;

    void setDocument(Document* document);
    QAction* action() const { return action_; }
    TilingController* controller() const { return controller_; }
    TilingDock* dock() const { return dock_; }
    TilingItem* item() const { return item_; }
    bool isActive() const;

private:
    void updateItem();
    void shareATab(QMainWindow* window);

    QPointer<QGraphicsScene> scene_; // owns item_ while it lives
    TilingController* controller_;
    TilingDock* dock_;
    TilingItem* item_;
    QAction* action_;
    bool showTiles_ = true;
};

} // namespace fc::ui
