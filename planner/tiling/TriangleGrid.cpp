#include "tiling/TriangleGrid.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace fc::tiling {

bool LatticeTriangle::operator<(const LatticeTriangle& o) const {
    return std::tie(ry, rx, sy, sx) < std::tie(o.ry, o.rx, o.sy, o.sx);
}

bool LatticeTriangle::operator==(const LatticeTriangle& o) const {
    return rx == o.rx && ry == o.ry && sx == o.sx && sy == o.sy;
}

TriangleGrid::TriangleGrid(Vec2 origin, double leg, int nx, int ny)
    : origin_(origin), leg_(leg), nx_(nx), ny_(ny),
      free_(static_cast<std::size_t>(2) * nx * ny, 0) {}

bool TriangleGrid::contains(const LatticeTriangle& t) const {
    const int i = t.squareI(), j = t.squareJ();
    return i >= 0 && j >= 0 && i < nx_ && j < ny_;
}

LatticeTriangle TriangleGrid::triangle(int cell) const {
    const int half = cell & 1;
    const int square = cell >> 1;
    const int i = square % nx_, j = square / nx_;
    const bool backslash = ((i + j) & 1) == 0;
    if (backslash)
        return half == 0 ? LatticeTriangle{i, j, 1, 1} : LatticeTriangle{i + 1, j + 1, -1, -1};
    return half == 0 ? LatticeTriangle{i + 1, j, -1, 1} : LatticeTriangle{i, j + 1, 1, -1};
}

std::array<Vec2, 3> TriangleGrid::vertices(int cell) const {
    const LatticeTriangle t = triangle(cell);
    const Vec2 r = origin_ + Vec2(t.rx, t.ry) * leg_;
    return {r, r + Vec2(t.sx * leg_, 0.0), r + Vec2(0.0, t.sy * leg_)};
}

Vec2 TriangleGrid::centroid(int cell) const {
    const auto v = vertices(cell);
    return (v[0] + v[1] + v[2]) * (1.0 / 3.0);
}

int TriangleGrid::freeCount() const {
    return static_cast<int>(std::count(free_.begin(), free_.end(), 1));
}

namespace {

int orientation(Vec2 a, Vec2 b, Vec2 c) {
    const double v = cross(b - a, c - a);
    return (v > 0) - (v < 0);
}

bool onSegment(Vec2 a, Vec2 b, Vec2 p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
    const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    if (o1 != o2 && o3 != o4)
        return true;
    return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
           (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

bool insideTriangle(const std::array<Vec2, 3>& t, Vec2 p) {
    const int a = orientation(t[0], t[1], p), b = orientation(t[1], t[2], p);
    const int c = orientation(t[2], t[0], p);
    return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

// A wall meets the triangle's interior. The triangle is shrunk by a hair first so that
// walls along grid lines (touching the cell) do not block it.
bool wallCrossesCell(const std::array<Vec2, 3>& cell, Vec2 a, Vec2 b) {
    const Vec2 c = (cell[0] + cell[1] + cell[2]) * (1.0 / 3.0);
    std::array<Vec2, 3> t;
    for (int k = 0; k < 3; ++k)
        t[k] = c + (cell[k] - c) * (1.0 - 1e-7);
    if (insideTriangle(t, a) || insideTriangle(t, b))
        return true;
    for (int k = 0; k < 3; ++k)
        if (segmentsIntersect(a, b, t[k], t[(k + 1) % 3]))
            return true;
    return false;
}

bool inFreeSpace(const Plan& plan, Vec2 p) {
    if (!pointInRing(plan.boundary, p))
        return false;
    for (const Ring& obstacle : plan.obstacles)
        if (pointInRing(obstacle, p))
            return false;
    return true;
}

} // namespace

TriangleGrid buildTriangleGrid(const Plan& plan, double leg) {
    const BoundingBox box = plan.bounds();
    const int nx = std::max(1, static_cast<int>(std::ceil(box.width() / leg - 1e-9)));
    const int ny = std::max(1, static_cast<int>(std::ceil(box.height() / leg - 1e-9)));
    TriangleGrid grid({box.minX, box.minY}, leg, nx, ny);
    std::vector<std::uint8_t> blocked(grid.cellCount(), 0);
    std::vector<const Ring*> rings{&plan.boundary};
    for (const Ring& obstacle : plan.obstacles)
        rings.push_back(&obstacle);
    // Each wall only visits the squares of its own bounding box.
    for (const Ring* ring : rings) {
        for (std::size_t k = 0; k < ring->size(); ++k) {
            const Vec2 a = (*ring)[k], b = (*ring)[(k + 1) % ring->size()];
            const int i0 = std::max(0, static_cast<int>((std::min(a.x, b.x) - box.minX) / leg) - 1);
            const int i1 =
                std::min(nx - 1, static_cast<int>((std::max(a.x, b.x) - box.minX) / leg) + 1);
            const int j0 = std::max(0, static_cast<int>((std::min(a.y, b.y) - box.minY) / leg) - 1);
            const int j1 =
                std::min(ny - 1, static_cast<int>((std::max(a.y, b.y) - box.minY) / leg) + 1);
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i)
                    for (int half = 0; half < 2; ++half) {
                        const int cell = grid.cellId(i, j, half);
                        if (!blocked[cell] && wallCrossesCell(grid.vertices(cell), a, b))
                            blocked[cell] = 1;
                    }
        }
    }
    for (int cell = 0; cell < grid.cellCount(); ++cell)
        grid.setFree(cell, !blocked[cell] && inFreeSpace(plan, grid.centroid(cell)));
    return grid;
}

} // namespace fc::tiling
