#include "decomposition/FunctionClip.h"

namespace fc::detail {

double rightLimit(const Polyline& f, double x) {
    // Last point at or before x; if it sits exactly on x it is the value after any jump.
    size_t i = 0;
    while (i + 1 < f.size() && f[i + 1].x <= x)
        ++i;
    if (f[i].x == x || i + 1 == f.size())
        return f[i].y;
    const Vec2 a = f[i], b = f[i + 1];
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

double leftLimit(const Polyline& f, double x) {
    size_t i = 0;
    while (i < f.size() && f[i].x < x)
        ++i;
    if (i == f.size())
        return f.back().y;
    if (f[i].x == x || i == 0)
        return f[i].y;
    const Vec2 a = f[i - 1], b = f[i];
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

Polyline clipFunction(const Polyline& f, double xa, double xb) {
    Polyline out{{xa, rightLimit(f, xa)}};
    for (const Vec2& p : f)
        if (p.x > xa && p.x < xb && p != out.back())
            out.push_back(p);
    const Vec2 end{xb, leftLimit(f, xb)};
    if (end != out.back() || out.size() == 1)
        out.push_back(end);
    return out;
}

void appendPiece(Polyline& f, double xa, double ya, double xb, double yb) {
    if (f.empty() || f.back() != Vec2{xa, ya})
        f.push_back({xa, ya});
    // Drop the middle point of three collinear ones to keep outlines small.
    if (f.size() >= 2) {
        const Vec2 p = f[f.size() - 2], q = f.back(), r{xb, yb};
        if (p.x < q.x &&
            std::abs(cross(q - p, r - q)) <= 1e-12 * (1 + norm(r - p)) * (1 + norm(q - p)))
            f.pop_back();
    }
    f.push_back({xb, yb});
}

} // namespace fc::detail
