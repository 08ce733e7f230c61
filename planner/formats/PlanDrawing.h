// Internal: the plan + path drawing shared by the SVG and PDF writers, in metres (y up).
#pragma once

#include "formats/PathIO.h"
#include "model/Plan.h"

#include <string>
#include <vector>

namespace fc::formats {

struct Rgb {
    double r = 0, g = 0, b = 0; // 0..1
};

struct DrawItem {
    Polyline points;
    bool closed = false;
    bool filled = false;
    Rgb fill;
    Rgb stroke;
    double width = 0.0; // m; 0 = no stroke
    double dash = 0.0;  // m; 0 = solid
};

struct DrawLabel {
    Vec2 at; // baseline start, m
    std::string text;
    double size = 0.0; // m
};

struct PlanDrawing {
    BoundingBox bounds;          // of everything drawn, with a margin
    std::vector<DrawItem> items; // in painting order
    std::vector<DrawLabel> labels;
    std::string title;
    std::string caption; // units and frame
    std::string legend;  // path metrics and colours; empty without a path
};

// Floor, obstacles, rooms (dashed, with names), the path coloured by segment kind
// (stripe green, contour orange, transit red dashed), overlaps in blue, a scale bar.
PlanDrawing drawingOf(const Plan& plan, const CoveragePath& path, const PathExportInfo& info);

} // namespace fc::formats
