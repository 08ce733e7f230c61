// Helpers for the GUI tests: a main window without modal dialogs, and mouse input on the
// canvas in plan coordinates (metres), sent to the real view's viewport.
#pragma once

#include "canvas/CanvasView.h"
#include "document/Document.h"
#include "window/MainWindow.h"
#include "tools/AbstractTool.h"
#include "tools/ToolManager.h"

#include <QTest>
#include <memory>

namespace fc::ui::test {

inline std::unique_ptr<MainWindow> makeWindow() {
    auto window = std::make_unique<MainWindow>();
    window->setDialogsEnabled(false);
    window->resize(1400, 900);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        qWarning("window not exposed");
    return window;
}

// A fixed zoom (32 pixels per metre: a 0.5 m grid, so clicks at half metres snap exactly)
// centred on a 20 x 14 m drawing, whatever the docks leave to the canvas.
inline void useDrawingScale(MainWindow& window) {
    window.view()->setTransform(QTransform::fromScale(32.0, -32.0));
    window.view()->centerOn(10.0, 7.0);
}

inline QPoint viewPoint(MainWindow& window, QPointF plan) {
    return window.view()->mapFromScene(plan);
}

inline void useTool(MainWindow& window, const char* objectName) {
    AbstractTool* tool = window.toolManager()->findTool(QLatin1String(objectName));
    QVERIFY2(tool, objectName);
    window.toolManager()->setActiveTool(tool);
}

inline void click(MainWindow& window, QPointF plan, Qt::MouseButton button = Qt::LeftButton) {
    QTest::mouseClick(window.view()->viewport(), button, {}, viewPoint(window, plan));
}

inline void clickPolygon(MainWindow& window, const std::vector<QPointF>& vertices) {
    for (QPointF p : vertices)
        click(window, p);
    click(window, vertices.front()); // clicking the first vertex closes the polygon
}

inline void drag(MainWindow& window, QPointF from, QPointF to) {
    QWidget* viewport = window.view()->viewport();
    QTest::mousePress(viewport, Qt::LeftButton, {}, viewPoint(window, from));
    const QPointF middle = (from + to) / 2;
    QTest::mouseMove(viewport, viewPoint(window, middle));
    QTest::mouseMove(viewport, viewPoint(window, to));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, viewPoint(window, to));
}

} // namespace fc::ui::test
