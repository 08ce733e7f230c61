// The plan + path drawing shared by the SVG and PDF exports.
#include "formats/PlanDrawing.h"

#include "formats/WriterSupport.h"

#include <algorithm>
#include <cmath>

namespace fc::formats {

namespace {

constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kFloor{0.97, 0.97, 0.95};
constexpr Rgb kObstacle{0.55, 0.55, 0.55};
constexpr Rgb kRoom{0.45, 0.45, 0.6};
constexpr Rgb kOverlap{0.1, 0.3, 0.95}; // the paper draws overlaps in blue

Rgb kindColour(SegmentKind kind) {
    switch (kind) {
    case SegmentKind::Stripe:
        return {0.1, 0.55, 0.2};
    case SegmentKind::Contour:
        return {0.9, 0.5, 0.05};
    case SegmentKind::Transit:
        break;
    }
    return {0.8, 0.1, 0.1};
}

// 1, 2 or 5 times a power of ten, about a fifth of `span`.
double scaleBarLength(double span) {
    const double target = span / 5.0;
    const double power = std::pow(10.0, std::floor(std::log10(target)));
    for (double step : {5.0, 2.0, 1.0})
        if (step * power <= target)
            return step * power;
    return power;
}

// Runs of consecutive segments with the same kind, as polylines.
void addPath(PlanDrawing& drawing, const CoveragePath& path, double width) {
    size_t start = 0;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) {
        const SegmentKind kind = path.kinds.empty() ? SegmentKind::Transit : path.kinds[i];
        const bool last =
            i + 2 >= path.points.size() || (!path.kinds.empty() && path.kinds[i + 1] != kind);
        if (!last)
            continue;
        DrawItem run;
        run.points.assign(path.points.begin() + static_cast<std::ptrdiff_t>(start),
                          path.points.begin() + static_cast<std::ptrdiff_t>(i) + 2);
        run.stroke = kindColour(kind);
        run.width = width;
        run.dash = kind == SegmentKind::Transit ? 4 * width : 0.0;
        drawing.items.push_back(std::move(run));
        start = i + 1;
    }
}

} // namespace

PlanDrawing drawingOf(const Plan& plan, const CoveragePath& path, const PathExportInfo& info) {
    PlanDrawing drawing;
    BoundingBox box = plan.bounds();
    const double span = std::max({box.maxX - box.minX, box.maxY - box.minY, 1e-3});
    const double line = span / 500.0;
    const double margin = span / 20.0;

    DrawItem floor{plan.boundary, true, true, kFloor, kBlack, 2 * line, 0.0};
    drawing.items.push_back(floor);
    for (const Ring& obstacle : plan.obstacles)
        drawing.items.push_back({obstacle, true, true, kObstacle, kBlack, line, 0.0});
    for (const Room& room : plan.rooms) {
        drawing.items.push_back({room.outline, true, false, {}, kRoom, line, 3 * line});
        const BoundingBox r = boundsOf(room.outline);
        drawing.labels.push_back({{r.minX + span / 100, r.maxY - span / 40}, room.name, span / 50});
    }
    addPath(drawing, path, 1.5 * line);
    for (const Segment& overlap : info.metrics.overlaps)
        drawing.items.push_back({{overlap.a, overlap.b}, false, false, {}, kOverlap, 3 * line, 0});

    const double bar = scaleBarLength(span);
    const Vec2 barStart{box.minX, box.minY - margin / 2};
    drawing.items.push_back(
        {{barStart, barStart + Vec2{bar, 0}}, false, false, {}, kBlack, 3 * line, 0.0});
    drawing.labels.push_back(
        {barStart + Vec2{bar + span / 100, -span / 150}, fixedNumber(bar, 3) + " m", span / 50});

    box.add({box.minX - margin, box.minY - margin});
    box.add({box.maxX + margin, box.maxY + margin});
    drawing.bounds = box;
    drawing.title = "FloorCover: " + (plan.name.empty() ? std::string("plan") : plan.name);
    drawing.caption = "units: metres; frame: " + frameDescription(plan.epsg);
    if (!path.empty())
        drawing.legend = "path " + fixedNumber(info.metrics.length, 1) + " m (" + info.solver +
                         "), coverage " + fixedNumber(100.0 * info.metrics.coverage, 1) +
                         "%; stripes green, contours orange, transit red dashed, overlaps blue";
    return drawing;
}

} // namespace fc::formats
