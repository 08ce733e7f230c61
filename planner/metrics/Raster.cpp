#include "metrics/Raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fc {

Grid Grid::covering(const BoundingBox& bounds, double margin, double resolution) {
    Grid grid;
    grid.resolution = resolution;
    if (bounds.empty())
        return grid;
    grid.originX = bounds.minX - margin;
    grid.originY = bounds.minY - margin;
    grid.cols = static_cast<int>(std::ceil((bounds.width() + 2.0 * margin) / resolution));
    grid.rows = static_cast<int>(std::ceil((bounds.height() + 2.0 * margin) / resolution));
    return grid;
}

const std::vector<Span>& ScanlineFill::spans(const Ring* rings, size_t ringCount) {
    edges_.clear();
    spans_.clear();
    const double res = grid_.resolution;
    // First pixel index whose centre is >= v along one axis. Every edge uses this one
    // monotone function of its end points, so each row meets a closed ring an even
    // number of times even where vertices sit exactly on pixel centres.
    auto firstCentreAtOrAbove = [res](double v, double origin) {
        return std::ceil((v - origin) / res - 0.5);
    };
    int minRow = grid_.rows, endRow = 0;
    for (size_t r = 0; r < ringCount; ++r) {
        const Ring& ring = rings[r];
        const size_t n = ring.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 a = ring[i], b = ring[(i + 1) % n];
            if (a.y == b.y)
                continue; // horizontal edges never cross a row centre line
            const double rowA = firstCentreAtOrAbove(a.y, grid_.originY);
            const double rowB = firstCentreAtOrAbove(b.y, grid_.originY);
            const int lo = static_cast<int>(std::max(std::min(rowA, rowB), 0.0));
            const int hi =
                static_cast<int>(std::min(std::max(rowA, rowB), static_cast<double>(grid_.rows)));
            if (lo >= hi)
                continue;
            edges_.push_back({lo, hi, a, (b.x - a.x) / (b.y - a.y)});
            minRow = std::min(minRow, lo);
            endRow = std::max(endRow, hi);
        }
    }
    if (edges_.empty())
        return spans_;

    // Bucket the crossings by row (counting sort), then sort each row's few x values.
    if (rowEnd_.size() != static_cast<size_t>(grid_.rows))
        rowEnd_.assign(static_cast<size_t>(grid_.rows), 0);
    for (const EdgeRows& edge : edges_)
        for (int row = edge.lo; row < edge.hi; ++row)
            ++rowEnd_[static_cast<size_t>(row)];
    size_t total = 0;
    for (int row = minRow; row < endRow; ++row) {
        total += rowEnd_[static_cast<size_t>(row)];
        rowEnd_[static_cast<size_t>(row)] = total;
    }
    xs_.resize(total);
    for (const EdgeRows& edge : edges_) {
        for (int row = edge.lo; row < edge.hi; ++row) {
            const double y = grid_.originY + (row + 0.5) * res;
            xs_[--rowEnd_[static_cast<size_t>(row)]] = edge.a.x + (y - edge.a.y) * edge.slope;
        }
    }
    // rowEnd_[row] now holds the start of the row; the next row's start is its end.
    const double maxCol = grid_.cols;
    for (int row = minRow; row < endRow; ++row) {
        const size_t begin = rowEnd_[static_cast<size_t>(row)];
        const size_t end = row + 1 < endRow ? rowEnd_[static_cast<size_t>(row) + 1] : total;
        std::sort(xs_.begin() + static_cast<std::ptrdiff_t>(begin),
                  xs_.begin() + static_cast<std::ptrdiff_t>(end));
        for (size_t i = begin; i + 1 < end; i += 2) {
            const double c0 = std::clamp(firstCentreAtOrAbove(xs_[i], grid_.originX), 0.0, maxCol);
            const double c1 =
                std::clamp(firstCentreAtOrAbove(xs_[i + 1], grid_.originX), 0.0, maxCol);
            if (c1 > c0)
                spans_.push_back({row, static_cast<int>(c0), static_cast<int>(c1)});
        }
    }
    // Leave the bucket array zeroed for the next call, touching only the rows used.
    std::fill(rowEnd_.begin() + minRow, rowEnd_.begin() + endRow, size_t{0});
    return spans_;
}

void ScanlineFill::paint(const Ring* rings, size_t ringCount, Mask& mask) {
    for (const Span& span : spans(rings, ringCount)) {
        const size_t rowStart = grid_.index(0, span.row);
        std::fill(mask.begin() + static_cast<std::ptrdiff_t>(rowStart + span.col0),
                  mask.begin() + static_cast<std::ptrdiff_t>(rowStart + span.col1), uint8_t{1});
    }
}

namespace {

// One-dimensional squared distance transform of sampled function f (lower envelope of
// parabolas, Felzenszwalb & Huttenlocher 2012). v, z are scratch of size n and n + 1.
void distanceTransform1d(const double* f, int n, double* out, int* v, double* z) {
    const double inf = std::numeric_limits<double>::infinity();
    int k = 0;
    v[0] = 0;
    z[0] = -inf;
    z[1] = inf;
    auto intersection = [f](int q, int p) {
        return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
    };
    for (int q = 1; q < n; ++q) {
        // z[0] is -inf and every f is finite, so k never drops below 0.
        double s = intersection(q, v[k]);
        while (s <= z[k])
            s = intersection(q, v[--k]);
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = inf;
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[k + 1] < q)
            ++k;
        const double d = q - v[k];
        out[q] = d * d + f[v[k]];
    }
}

} // namespace

std::vector<float> squaredDistanceToBlocked(const Mask& mask, int cols, int rows) {
    // A large finite value keeps the parabola intersections free of inf - inf.
    const double far = 1e20;
    const int longest = std::max(cols, rows);
    std::vector<double> f(static_cast<size_t>(longest)), d(static_cast<size_t>(longest));
    std::vector<double> z(static_cast<size_t>(longest) + 1);
    std::vector<int> v(static_cast<size_t>(longest));
    std::vector<double> columnPass(mask.size());
    for (int col = 0; col < cols; ++col) {
        for (int row = 0; row < rows; ++row)
            f[row] = mask[static_cast<size_t>(row) * cols + col] ? far : 0.0;
        distanceTransform1d(f.data(), rows, d.data(), v.data(), z.data());
        for (int row = 0; row < rows; ++row)
            columnPass[static_cast<size_t>(row) * cols + col] = d[row];
    }
    std::vector<float> result(mask.size());
    for (int row = 0; row < rows; ++row) {
        const size_t start = static_cast<size_t>(row) * cols;
        distanceTransform1d(columnPass.data() + start, cols, d.data(), v.data(), z.data());
        for (int col = 0; col < cols; ++col)
            result[start + col] = static_cast<float>(std::min(d[col], far));
    }
    return result;
}

Mask dilateSquare(const Mask& mask, int cols, int rows, int radius) {
    if (radius <= 0)
        return mask;
    // Horizontal pass: a sliding count of set pixels in [col - radius, col + radius].
    Mask horizontal(mask.size(), 0);
    for (int row = 0; row < rows; ++row) {
        const uint8_t* in = mask.data() + static_cast<size_t>(row) * cols;
        uint8_t* out = horizontal.data() + static_cast<size_t>(row) * cols;
        int count = 0;
        for (int c = 0; c <= radius && c < cols; ++c)
            count += in[c];
        for (int col = 0; col < cols; ++col) {
            out[col] = count > 0;
            if (col + radius + 1 < cols)
                count += in[col + radius + 1];
            if (col - radius >= 0)
                count -= in[col - radius];
        }
    }
    // Vertical pass, row by row with one count per column to stay cache friendly.
    Mask result(mask.size(), 0);
    std::vector<int> counts(static_cast<size_t>(cols), 0);
    auto addRow = [&](int row, int sign) {
        const uint8_t* in = horizontal.data() + static_cast<size_t>(row) * cols;
        for (int col = 0; col < cols; ++col)
            counts[col] += sign * in[col];
    };
    for (int r = 0; r <= radius && r < rows; ++r)
        addRow(r, +1);
    for (int row = 0; row < rows; ++row) {
        uint8_t* out = result.data() + static_cast<size_t>(row) * cols;
        for (int col = 0; col < cols; ++col)
            out[col] = counts[col] > 0;
        if (row + radius + 1 < rows)
            addRow(row + radius + 1, +1);
        if (row - radius >= 0)
            addRow(row - radius, -1);
    }
    return result;
}

Mask floodFill(const Mask& region, int cols, int rows, const std::vector<size_t>& seeds) {
    Mask reached(region.size(), 0);
    std::vector<size_t> stack;
    for (size_t seed : seeds) {
        if (seed < region.size() && region[seed] && !reached[seed]) {
            reached[seed] = 1;
            stack.push_back(seed);
        }
    }
    const size_t width = static_cast<size_t>(cols);
    while (!stack.empty()) {
        const size_t i = stack.back();
        stack.pop_back();
        const size_t col = i % width, row = i / width;
        auto visit = [&](size_t j) {
            if (region[j] && !reached[j]) {
                reached[j] = 1;
                stack.push_back(j);
            }
        };
        if (col > 0)
            visit(i - 1);
        if (col + 1 < width)
            visit(i + 1);
        if (row > 0)
            visit(i - width);
        if (row + 1 < static_cast<size_t>(rows))
            visit(i + width);
    }
    return reached;
}

} // namespace fc
