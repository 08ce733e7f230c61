#include "window/PdfReport.h"

#include "canvas/OverlayLayer.h"
#include "canvas/PlanScene.h"
#include "document/Conversions.h"
#include "document/Document.h"
#include "metrics/RoomBreakdown.h"
#include "pipeline/Planner.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <algorithm>
#include <cmath>

namespace fc::ui {

namespace {

// The translation context of this file's messages (lupdate reads the macro).
struct PdfReportText {
    Q_DECLARE_TR_FUNCTIONS(fc::ui::PdfReport)
};

QString metres(double v) {
    return PdfReportText::tr("%1 m").arg(QLocale().toString(v, 'f', 1));
}

QString duration(double seconds) {
    const int minutes = static_cast<int>(std::lround(seconds / 60.0));
    if (seconds > 0 && minutes == 0)
        return PdfReportText::tr("< 1 min");
    if (minutes < 60)
        return PdfReportText::tr("%1 min").arg(minutes);
    return PdfReportText::tr("%1 h %2 min")
        .arg(minutes / 60)
        .arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

QString point(Vec2 p) {
    return PdfReportText::tr("(%1, %2) m")
        .arg(QLocale().toString(p.x, 'f', 2), QLocale().toString(p.y, 'f', 2));
}

} // namespace

QList<QPair<QString, QString>> reportSummary(const Document& document, const PlanResult& result) {
    const Metrics& m = result.metrics;
    const Project& project = document.project();
    const QString solver =
        fromStd(result.solution.solver.empty() ? project.solver : result.solution.solver);
    const QString angle =
        result.parts.size() > 1
            ? PdfReportText::tr("per room, along its walls")
            : PdfReportText::tr("%1°").arg(QLocale().toString(result.stripeAngleDeg, 'f', 0));
    const int rooms = static_cast<int>(project.plan.rooms.size());
    const int planned =
        project.selectedRooms.empty() ? rooms : static_cast<int>(project.selectedRooms.size());
    QList<QPair<QString, QString>> rows = {
        {PdfReportText::tr("Rooms planned"), PdfReportText::tr("%1 of %2").arg(planned).arg(rooms)},
        {PdfReportText::tr("Estimated time"), duration(m.time)},
        {PdfReportText::tr("Path length"), metres(m.length)},
        {PdfReportText::tr("Extra distance"),
         PdfReportText::tr("%1 (%2 % over the ideal %3)")
             .arg(metres(m.extra))
             .arg(m.ideal > 0 ? QLocale().toString(100.0 * m.extra / m.ideal, 'f', 0)
                              : QStringLiteral("–"))
             .arg(metres(m.ideal))},
        {PdfReportText::tr("Turns"), QString::number(m.turns)},
        {PdfReportText::tr("Coverage"), PdfReportText::tr("%1 % of the floor the robot can reach")
                                            .arg(QLocale().toString(100.0 * m.coverage, 'f', 1))},
    };
    if (m.uncoveredArea > 0.005)
        rows.append({PdfReportText::tr("Missed"),
                     PdfReportText::tr("%1 m²").arg(QLocale().toString(m.uncoveredArea, 'f', 2))});
    if (m.unreachableArea > 0.005)
        rows.append(
            {PdfReportText::tr("Too narrow for the robot"),
             PdfReportText::tr("%1 m²").arg(QLocale().toString(m.unreachableArea, 'f', 2))});
    const CoveragePath& path = result.path;
    if (!path.empty()) {
        rows.append(
            {PdfReportText::tr("Start"),
             project.hasStart
                 ? point(path.points.front())
                 : PdfReportText::tr("%1, chosen by the planner").arg(point(path.points.front()))});
        rows.append({PdfReportText::tr("End"), point(path.points.back())});
    }
    rows.append(
        {PdfReportText::tr("Planner"), PdfReportText::tr("%1, stripes %2").arg(solver, angle)});
    return rows;
}

QList<QPair<QString, QString>> reportRobot(const PlanResult& result) {
    const RobotProfile& robot = result.prepared.robot;
    const auto m2 = [](double v) {
        return PdfReportText::tr("%1 m").arg(QLocale().toString(v, 'f', 2));
    };
    return {
        {PdfReportText::tr("Robot diameter L"), m2(robot.robotDiameter)},
        {PdfReportText::tr("Cleaning diameter D"), m2(robot.cleaningDiameter)},
        {PdfReportText::tr("Coverage width W"), m2(robot.coverageWidth)},
        {PdfReportText::tr("Speed"),
         PdfReportText::tr("%1 m/s").arg(QLocale().toString(robot.speed, 'f', 2))},
        {PdfReportText::tr("Time per 90° turn"),
         PdfReportText::tr("%1 s").arg(QLocale().toString(robot.turnTime, 'f', 1))},
    };
}

QList<QStringList> reportRoomTable(const Document& document, const PlanResult& result) {
    const auto visits = roomBreakdown(document.plan(), result.path, result.prepared.robot,
                                      &result.prepared.decomposition);
    QList<QStringList> table = {{PdfReportText::tr("Order"), PdfReportText::tr("Room"),
                                 PdfReportText::tr("Area"), PdfReportText::tr("Path"),
                                 PdfReportText::tr("Turns"), PdfReportText::tr("Time")}};
    double area = 0, length = 0, time = 0;
    int turns = 0;
    for (const RoomVisit& visit : visits) {
        const bool outside = visit.room.empty();
        const bool planned = outside || document.isRoomSelected(fromStd(visit.room));
        QString order = visit.order > 0 ? QString::number(visit.order) : QString();
        if (!outside && !planned)
            order = PdfReportText::tr("not planned");
        table.append({order, outside ? PdfReportText::tr("Between rooms") : fromStd(visit.room),
                      outside
                          ? QString()
                          : PdfReportText::tr("%1 m²").arg(QLocale().toString(visit.area, 'f', 1)),
                      metres(visit.length), QString::number(visit.turns), duration(visit.time)});
        area += visit.area;
        length += visit.length;
        time += visit.time;
        turns += visit.turns;
    }
    table.append({QString(), PdfReportText::tr("Total"),
                  PdfReportText::tr("%1 m²").arg(QLocale().toString(area, 'f', 1)), metres(length),
                  QString::number(turns), duration(time)});
    return table;
}

namespace {

// Page coordinates are points (1/72 inch); fonts are sized in points through pixel sizes.
class ReportPainter {
public:
    ReportPainter(QPainter& painter, double width, double height)
        : p_(painter), width_(width), height_(height) {}

    void setFont(int points, bool bold = false) {
        QFont font = p_.font();
        font.setPixelSize(points);
        font.setBold(bold);
        p_.setFont(font);
    }
    double lineHeight() const { return p_.fontMetrics().height() + 1; }
    QPainter& painter() { return p_; }
    double width() const { return width_; }
    double height() const { return height_; }

    // Label and value rows; returns the y below them.
    double drawRows(const QList<QPair<QString, QString>>& rows, double x, double y, double w,
                    const QString& title, double labelShare) {
        setFont(10, true);
        p_.drawText(QRectF(x, y, w, lineHeight()), Qt::AlignLeft, title);
        y += lineHeight() + 2;
        setFont(8);
        for (const auto& [label, value] : rows) {
            const QRectF valueBox(x + labelShare * w, y, (1 - labelShare) * w, 200);
            const QRectF used = p_.boundingRect(valueBox, Qt::TextWordWrap, value);
            p_.drawText(QRectF(x, y, labelShare * w - 4, lineHeight()), Qt::AlignLeft, label);
            p_.drawText(valueBox, Qt::TextWordWrap, value);
            y += std::max(lineHeight(), used.height() + 1);
        }
        return y;
    }

private:
    QPainter& p_;
    double width_, height_;
};

// One legend entry: a swatch drawn like the canvas, then its name; returns the x after it.
double drawLegendEntry(QPainter& p, double x, double y, int kind, const QString& text) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    const QPointF a(x, y + 5), b(x + 22, y + 5);
    const auto widen = [](QPen pen, double width) {
        pen.setCosmetic(false);
        pen.setWidthF(width);
        return pen;
    };
    switch (kind) {
    case 0:
        p.setPen(widen(overlayStyle(OverlayKind::Path).pen, 1.2));
        p.drawLine(a, b);
        break;
    case 1:
        p.setPen(widen(transitStyle().pen, 1.2));
        p.drawLine(a, b);
        break;
    case 2:
        p.setPen(widen(overlayStyle(OverlayKind::Overlaps).pen, 3.0));
        p.drawLine(a, b);
        break;
    case 3:
        p.setPen(Qt::NoPen);
        p.setBrush(overlayStyle(OverlayKind::CoverageGaps).brush);
        for (double dx : {4.0, 11.0, 18.0})
            p.drawRect(QRectF(x + dx - 1.5, y + 3.5, 3, 3)); // as the canvas draws them
        break;
    case 4:
        p.setPen(widen(overlayStyle(OverlayKind::Unreachable).pen, 1.2));
        p.drawLine(QPointF(x + 7, y + 1), QPointF(x + 15, y + 9));
        p.drawLine(QPointF(x + 7, y + 9), QPointF(x + 15, y + 1));
        break;
    default: { // 5 start, 6 end
        p.setPen(QPen(Qt::white, 1));
        p.setBrush(kind == 5 ? QColor(0, 150, 60) : QColor(200, 40, 40));
        p.drawEllipse(QPointF(x + 11, y + 5), 6, 6);
        p.setPen(Qt::white);
        QFont font = p.font();
        font.setBold(true);
        font.setPixelSize(7);
        p.setFont(font);
        p.drawText(QRectF(x + 5, y - 1, 12, 12), Qt::AlignCenter,
                   kind == 5 ? PdfReportText::tr("S") : PdfReportText::tr("E"));
        break;
    }
    }
    p.restore();
    p.drawText(QRectF(x + 26, y - 1, 200, 12), Qt::AlignLeft | Qt::AlignVCenter, text);
    return x + 26 + p.fontMetrics().horizontalAdvance(text) + 14;
}

double drawLegend(ReportPainter& r, double y) {
    r.setFont(8);
    const QStringList names = {PdfReportText::tr("Cleaning path"),
                               PdfReportText::tr("Transit"),
                               PdfReportText::tr("Overlap"),
                               PdfReportText::tr("Missed spots"),
                               PdfReportText::tr("Too narrow"),
                               PdfReportText::tr("Start"),
                               PdfReportText::tr("End")};
    double x = 0;
    for (int i = 0; i < names.size(); ++i) {
        const double needed = 40 + r.painter().fontMetrics().horizontalAdvance(names[i]);
        if (x + needed > r.width()) {
            x = 0;
            y += 14;
        }
        x = drawLegendEntry(r.painter(), x, y, i, names[i]);
    }
    return y + 18;
}

// The room table from y on, continuing on new pages; returns false if a page failed.
bool drawRoomTable(ReportPainter& r, QPdfWriter& writer, const QList<QStringList>& table,
                   double y) {
    QPainter& p = r.painter();
    const QList<double> columns = {0.0, 0.14, 0.46, 0.62, 0.76, 0.86};
    const auto drawRow = [&](const QStringList& row, double top, bool bold) {
        r.setFont(8, bold);
        for (int c = 0; c < row.size() && c < columns.size(); ++c) {
            const double left = columns[c] * r.width();
            const double right = c + 1 < columns.size() ? columns[c + 1] * r.width() : r.width();
            const Qt::Alignment align = c >= 2 ? Qt::AlignRight : Qt::AlignLeft;
            p.drawText(QRectF(left, top, right - left - 6, r.lineHeight()),
                       align | Qt::AlignVCenter, row[c]);
        }
    };
    r.setFont(10, true);
    p.drawText(QRectF(0, y, r.width(), r.lineHeight()), Qt::AlignLeft,
               PdfReportText::tr("Rooms in cleaning order"));
    y += r.lineHeight() + 2;
    for (int i = 0; i < table.size(); ++i) {
        if (y + 2 * r.lineHeight() > r.height()) {
            if (!writer.newPage())
                return false;
            y = 0;
            drawRow(table.front(), y, true); // the header again
            y += r.lineHeight();
        }
        const bool header = i == 0, total = i + 1 == table.size();
        if (total) {
            p.drawLine(QPointF(0, y), QPointF(r.width(), y));
        }
        drawRow(table[i], y, header || total);
        y += r.lineHeight();
        if (header)
            p.drawLine(QPointF(0, y - 1), QPointF(r.width(), y - 1));
    }
    return true;
}

} // namespace

bool writePdfReport(const QString& path, const Document& document, const PlanResult& result,
                    PlanScene& scene, const QPageSize& pageSize, QString* error) {
    const auto fail = [&](const QString& why) {
        if (error)
            *error = why;
        return false;
    };
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(PdfReportText::tr("Cannot write %1: %2").arg(path, file.errorString()));
    QPdfWriter writer(&file);
    writer.setPageSize(pageSize);
    writer.setPageOrientation(QPageLayout::Portrait);
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setResolution(300);
    const QString title = PdfReportText::tr("Cleaning plan: %1").arg(document.displayName());
    writer.setTitle(title);
    writer.setCreator(QStringLiteral("FloorCover"));
    QPainter painter;
    if (!painter.begin(&writer))
        return fail(PdfReportText::tr("Cannot write %1.").arg(path));
    painter.setRenderHint(QPainter::Antialiasing);
    const double toPoints = writer.resolution() / 72.0;
    painter.scale(toPoints, toPoints);
    const QRect device = painter.viewport();
    ReportPainter r(painter, device.width() / toPoints, device.height() / toPoints);

    r.setFont(16, true);
    painter.drawText(QRectF(0, 0, r.width(), 22), Qt::AlignLeft | Qt::AlignVCenter, title);
    r.setFont(8);
    painter.drawText(QRectF(0, 0, r.width(), 22), Qt::AlignRight | Qt::AlignVCenter,
                     QLocale().toString(QDateTime::currentDateTime(), QLocale::ShortFormat));

    // The map in the Path view: about half the page, in screen pixels at 96 dpi so that
    // labels and markers keep the size they have on screen, rendered at 3x for print.
    const QRectF map(0, 30, r.width(), (r.height() > 1000 ? 0.5 : 0.45) * r.height());
    const QImage image = scene.renderPathView(
        QSize(static_cast<int>(map.width() * 96 / 72), static_cast<int>(map.height() * 96 / 72)),
        3.0);
    painter.drawImage(map, image);
    painter.setPen(QPen(QColor(160, 160, 160), 0.5));
    painter.drawRect(map);
    painter.setPen(Qt::black);

    double y = drawLegend(r, map.bottom() + 8);
    const double column = 0.5 * r.width() - 10;
    const double left = r.drawRows(reportSummary(document, result), 0, y, column,
                                   PdfReportText::tr("Summary"), 0.34);
    const double right = r.drawRows(reportRobot(result), column + 20, y, column,
                                    PdfReportText::tr("Robot profile"), 0.5);
    y = std::max(left, right) + 12;
    const bool tableDone = drawRoomTable(r, writer, reportRoomTable(document, result), y);
    if (!painter.end() || !tableDone)
        return fail(PdfReportText::tr("Cannot write %1.").arg(path));
    if (!file.commit())
        return fail(PdfReportText::tr("Cannot write %1: %2").arg(path, file.errorString()));
    return true;
}

} // namespace fc::ui
