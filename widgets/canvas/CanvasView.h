// The canvas: a QGraphicsView over the plan scene with y pointing up (plan metres), wheel
// zoom around the cursor, fit, panning (middle drag, or space + left drag), a metre grid
// with a scale bar, snapping, and the active tool receiving the mouse.
#pragma once

#include "canvas/Snapper.h"
#include "tools/AbstractTool.h"

#include <QGraphicsView>
#include <QPointer>

namespace fc::ui {

class Document;

class CanvasView : public QGraphicsView {
    Q_OBJECT
public:
    explicit CanvasView(QWidget* parent = nullptr);

    void setDocument(Document* document) { document_ = document; }
    void setTool(AbstractTool* tool);
    Snapper& snapper() { return snapper_; }

    double metresPerPixel() const;
    // The minor grid spacing at the current zoom (also the snapping step).
    double gridStep() const;
    void setGridVisible(bool visible);
    bool isGridVisible() const { return gridVisible_; }

public slots:
    void fitToPlan();
    void zoomIn() { zoomBy(1.25); }
    void zoomOut() { zoomBy(0.8); }

signals:
    void cursorMoved(QPointF planPosition);

protected:
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void drawBackground(QPainter* painter, const QRectF& rect) override;
    void drawForeground(QPainter* painter, const QRectF& rect) override;

private:
    void zoomBy(double factor);
    void layoutLabels();
    void scrollBy(QPoint pixels);
    ToolMouseEvent toolEvent(QMouseEvent* event) const;
    bool startsPan(QMouseEvent* event) const;
    void restoreToolCursor();

    QPointer<Document> document_;
    QPointer<AbstractTool> tool_;
    Snapper snapper_;
    bool gridVisible_ = true;
    bool spaceHeld_ = false;
    bool panning_ = false;
    QPoint lastPanPosition_;
};

} // namespace fc::ui
