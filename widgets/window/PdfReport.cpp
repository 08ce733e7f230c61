#include "window/PdfReport.h"

#include "document/Conversions.h"
#include "document/Document.h"
#include "pipeline/Planner.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QGraphicsScene>
#include <QLocale>
#include <QPainter>
#include <QPdfWriter>

namespace fc::ui {

namespace {

// The translation context of this file's messages (lupdate reads the macro).
struct PdfReportText {
    Q_DECLARE_TR_FUNCTIONS(fc::ui::PdfReport)
};

// Label and value rows of the report's table.
QList<QPair<QString, QString>> reportRows(const Document& document, const PlanResult& result) {
    const Metrics& m = result.metrics;
    const RobotProfile& robot = result.prepared.robot;
    const auto metres = [](double v) { return PdfReportText::tr("%1 m").arg(v, 0, 'f', 2); };
    return {
        {PdfReportText::tr("Solver"),
         fromStd(result.solution.solver.empty() ? document.project().solver
                                                : result.solution.solver)},
        {PdfReportText::tr("Stripe angle"), PdfReportText::tr("%1°").arg(result.stripeAngleDeg)},
        {PdfReportText::tr("Path length"), metres(m.length)},
        {PdfReportText::tr("Ideal length"), metres(m.ideal)},
        {PdfReportText::tr("Extra distance"), metres(m.extra)},
        {PdfReportText::tr("Turns"), QString::number(m.turns)},
        {PdfReportText::tr("Coverage"),
         PdfReportText::tr("%1 %").arg(100.0 * m.coverage, 0, 'f', 2)},
        {PdfReportText::tr("Estimated time"),
         PdfReportText::tr("%1 min").arg(m.time / 60.0, 0, 'f', 1)},
        {PdfReportText::tr("Cells covered"), QString::number(m.cells)},
        {PdfReportText::tr("Robot diameter L"), metres(robot.robotDiameter)},
        {PdfReportText::tr("Cleaning diameter D"), metres(robot.cleaningDiameter)},
        {PdfReportText::tr("Coverage width W"), metres(robot.coverageWidth)},
        {PdfReportText::tr("Speed"), PdfReportText::tr("%1 m/s").arg(robot.speed)},
        {PdfReportText::tr("Time per 90° turn"), PdfReportText::tr("%1 s").arg(robot.turnTime)},
    };
}

} // namespace

bool writePdfReport(const QString& path, const Document& document, const PlanResult& result,
                    QGraphicsScene& scene, QString* error) {
    QPdfWriter writer(path);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setResolution(150); // cosmetic pens stay visible; text is vector anyway
    writer.setTitle(PdfReportText::tr("Coverage plan: %1").arg(document.displayName()));
    writer.setCreator(QStringLiteral("FloorCover"));
    QPainter painter;
    if (!painter.begin(&writer)) {
        if (error)
            *error = PdfReportText::tr("Cannot write %1.").arg(path);
        return false;
    }
    painter.setRenderHint(QPainter::Antialiasing);
    const QRect page = painter.viewport();
    QFont font = painter.font();
    font.setPointSizeF(16);
    painter.setFont(font);
    painter.drawText(QRect(0, 0, page.width(), 60), Qt::AlignLeft | Qt::AlignVCenter,
                     PdfReportText::tr("Coverage plan: %1").arg(document.displayName()));
    font.setPointSizeF(9);
    painter.setFont(font);
    painter.drawText(QRect(0, 0, page.width(), 60), Qt::AlignRight | Qt::AlignVCenter,
                     QLocale().toString(QDateTime::currentDateTime(), QLocale::ShortFormat));

    // The plan, fitted into the upper part of the page; the scene has y up, the page down.
    const BoundingBox box = document.plan().bounds();
    const QRectF plan(QPointF(box.minX, box.minY), QPointF(box.maxX, box.maxY));
    const QRectF target(0, 80, page.width(), page.height() * 0.58);
    painter.save();
    painter.translate(0, target.top() + target.bottom());
    painter.scale(1, -1);
    scene.render(&painter, target, plan, Qt::KeepAspectRatio);
    painter.restore();

    int y = static_cast<int>(target.bottom()) + 40;
    const int rowHeight = painter.fontMetrics().height() + 6;
    for (const auto& [label, value] : reportRows(document, result)) {
        painter.drawText(QRect(0, y, page.width() / 2, rowHeight), Qt::AlignLeft, label);
        painter.drawText(QRect(page.width() / 3, y, page.width() / 2, rowHeight), Qt::AlignLeft,
                         value);
        y += rowHeight;
    }
    if (!painter.end()) {
        if (error)
            *error = PdfReportText::tr("Cannot write %1.").arg(path);
        return false;
    }
    return true;
}

} // namespace fc::ui
