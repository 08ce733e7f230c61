// Raster primitives for the coverage metrics (SPEC sect. 6): a regular grid over the sweep
// frame, scanline polygon fill, exact Euclidean distance transform, square dilation and
// flood fill. Masks are row-major std::vector<uint8_t> (0 or 1) of Grid::size() pixels.
#pragma once

#include "geometry/Geometry.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fc {

using Mask = std::vector<uint8_t>;

struct Grid {
    double originX = 0.0, originY = 0.0; // lower-left corner of pixel (0, 0)
    double resolution = 1.0;             // pixel side, m
    int cols = 0, rows = 0;

    // A grid covering `bounds` plus `margin` on every side.
    static Grid covering(const BoundingBox& bounds, double margin, double resolution);

    size_t size() const { return static_cast<size_t>(cols) * static_cast<size_t>(rows); }
    size_t index(int col, int row) const {
        return static_cast<size_t>(row) * static_cast<size_t>(cols) + static_cast<size_t>(col);
    }
    Vec2 centre(int col, int row) const {
        return {originX + (col + 0.5) * resolution, originY + (row + 0.5) * resolution};
    }
    // Pixel containing p; false when p lies outside the grid.
    // Inline: the metrics call it for every half pixel of path, W / resolution times.
    bool pixelOf(Vec2 p, int& col, int& row) const {
        const double fx = std::floor((p.x - originX) / resolution);
        const double fy = std::floor((p.y - originY) / resolution);
        if (!(fx >= 0.0 && fy >= 0.0 && fx < cols && fy < rows))
            return false;
        col = static_cast<int>(fx);
        row = static_cast<int>(fy);
        return true;
    }
    double pixelArea() const { return resolution * resolution; }
};

// A run of pixels [col0, col1) on one row.
struct Span {
    int row = 0;
    int col0 = 0, col1 = 0;
};

// Even-odd scanline fill sampled at pixel centres. Reuses its buffers between calls so
// that filling many small polygons allocates nothing after the first few.
class ScanlineFill {
public:
    explicit ScanlineFill(const Grid& grid) : grid_(grid) {}

    // Spans of pixels whose centres lie inside the rings (even-odd over all of them),
    // clipped to the grid. Valid until the next call.
    const std::vector<Span>& spans(const Ring* rings, size_t ringCount);
    const std::vector<Span>& spans(const Ring& ring) { return spans(&ring, 1); }

    // Sets the pixels inside the rings to 1.
    void paint(const Ring* rings, size_t ringCount, Mask& mask);

private:
    struct EdgeRows {
        int lo, hi; // rows [lo, hi) whose centre line the edge crosses
        Vec2 a;
        double slope; // dx / dy
    };
    const Grid& grid_;
    std::vector<EdgeRows> edges_;
    std::vector<size_t> rowEnd_; // per row; all zero between calls
    std::vector<double> xs_;     // crossings, grouped by row
    std::vector<Span> spans_;
};

// Squared Euclidean distance, in pixels^2, from each pixel centre to the nearest pixel
// centre where `mask` is 0 (Felzenszwalb-Huttenlocher, separable, exact). Pixels beyond
// the grid do not count as blocked, so the grid should have a blocked border.
std::vector<float> squaredDistanceToBlocked(const Mask& mask, int cols, int rows);

// Binary dilation by a (2 * radius + 1)-pixel square, separable, O(pixels).
Mask dilateSquare(const Mask& mask, int cols, int rows, int radius);

// Pixels of `region` 4-connected to any seed pixel (indices into the grid).
Mask floodFill(const Mask& region, int cols, int rows, const std::vector<size_t>& seeds);

} // namespace fc
