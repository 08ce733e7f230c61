#include "geometry/Geometry.h"

#include <algorithm>

namespace fc {

double signedArea(const Ring& ring) {
    double a = 0.0;
    const size_t n = ring.size();
    if (n < 3)
        return 0.0;
    // Shoelace relative to the first vertex keeps precision for large coordinates.
    const Vec2 o = ring[0];
    for (size_t i = 1; i + 1 < n; ++i)
        a += cross(ring[i] - o, ring[i + 1] - o);
    return 0.5 * a;
}

double ringArea(const Ring& ring) {
    return std::abs(signedArea(ring));
}

int countTurns(const Polyline& points) {
    const double threshold = std::cos(45.0 * M_PI / 180.0);
    int turns = 0;
    bool haveHeading = false;
    Vec2 heading;
    for (size_t i = 1; i < points.size(); ++i) {
        const Vec2 delta = points[i] - points[i - 1];
        const double length = norm(delta);
        if (length <= 1e-9)
            continue;
        const Vec2 direction = delta * (1.0 / length);
        // cos(change) <= cos(45 deg), with slack so that an exact 45 degrees counts.
        if (haveHeading && dot(heading, direction) <= threshold + 1e-12)
            ++turns;
        heading = direction;
        haveHeading = true;
    }
    return turns;
}

double polylineLength(const Polyline& line) {
    double len = 0.0;
    for (size_t i = 1; i < line.size(); ++i)
        len += distance(line[i - 1], line[i]);
    return len;
}

BoundingBox boundsOf(const Ring& ring) {
    BoundingBox b;
    for (const Vec2& p : ring)
        b.add(p);
    return b;
}

bool pointInRing(const Ring& ring, Vec2 p) {
    bool inside = false;
    const size_t n = ring.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec2 a = ring[i], b = ring[j];
        if ((a.y > p.y) != (b.y > p.y)) {
            const double xCross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (p.x < xCross)
                inside = !inside;
        }
    }
    return inside;
}

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double len2 = dot(ab, ab);
    double t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return distance(p, a + ab * t);
}

static bool segmentsCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
           d4 != 0;
}

double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    if (segmentsCross(a, b, c, d))
        return 0.0;
    return std::min(std::min(pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d)),
                    std::min(pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)));
}

Frame::Frame(Vec2 origin, double stripeAngleDeg) : origin_(origin), angleDeg_(stripeAngleDeg) {
    // Rotate the world so that the stripe direction maps onto +y. Multiples of 90 degrees
    // are set exactly so that axis-parallel walls stay exactly axis-parallel.
    const double rot = 90.0 - stripeAngleDeg; // degrees, counter-clockwise
    double r = std::fmod(rot, 360.0);
    if (r < 0)
        r += 360.0;
    if (r == 0.0) {
        c_ = 1.0, s_ = 0.0;
    } else if (r == 90.0) {
        c_ = 0.0, s_ = 1.0;
    } else if (r == 180.0) {
        c_ = -1.0, s_ = 0.0;
    } else if (r == 270.0) {
        c_ = 0.0, s_ = -1.0;
    } else {
        const double rad = r * M_PI / 180.0;
        c_ = std::cos(rad), s_ = std::sin(rad);
    }
}

Vec2 Frame::toLocal(Vec2 w) const {
    const Vec2 d = w - origin_;
    return {c_ * d.x - s_ * d.y, s_ * d.x + c_ * d.y};
}

Vec2 Frame::toWorld(Vec2 l) const {
    return Vec2{c_ * l.x + s_ * l.y, -s_ * l.x + c_ * l.y} + origin_;
}

Ring Frame::toLocal(const Ring& ring) const {
    Ring out;
    out.reserve(ring.size());
    for (const Vec2& p : ring)
        out.push_back(toLocal(p));
    return out;
}

Polyline Frame::toWorld(const Polyline& line) const {
    Polyline out;
    out.reserve(line.size());
    for (const Vec2& p : line)
        out.push_back(toWorld(p));
    return out;
}

} // namespace fc

namespace fc {

namespace {

// Distance from p to the nearest edge of the outline or a hole; -1 outside the outline or
// inside a hole.
double insideDistance(Vec2 p, const Ring& outline, const std::vector<const Ring*>& holes) {
    if (!pointInRing(outline, p))
        return -1.0;
    for (const Ring* hole : holes)
        if (pointInRing(*hole, p))
            return -1.0;
    double nearest = INFINITY;
    auto edges = [&](const Ring& ring) {
        for (size_t i = 0; i < ring.size(); ++i)
            nearest =
                std::min(nearest, pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]));
    };
    edges(outline);
    for (const Ring* hole : holes)
        edges(*hole);
    return nearest;
}

} // namespace

Vec2 interiorLabelPoint(const Ring& outline, const std::vector<Ring>& holes) {
    if (outline.size() < 3)
        return outline.empty() ? Vec2{} : outline.front();
    const BoundingBox box = boundsOf(outline);
    std::vector<const Ring*> near;
    for (const Ring& hole : holes) {
        const BoundingBox b = boundsOf(hole);
        if (b.maxX >= box.minX && b.minX <= box.maxX && b.maxY >= box.minY && b.minY <= box.maxY)
            near.push_back(&hole);
    }
    // The area centroid, about the first vertex (UTM-sized coordinates keep their precision).
    const Vec2 o = outline.front();
    double a = 0.0, cx = 0.0, cy = 0.0;
    for (size_t i = 0; i < outline.size(); ++i) {
        const Vec2 p = outline[i] - o, q = outline[(i + 1) % outline.size()] - o;
        const double c = cross(p, q);
        a += c;
        cx += (p.x + q.x) * c;
        cy += (p.y + q.y) * c;
    }
    const Vec2 centroid = std::abs(a) > 1e-12
                              ? o + Vec2{cx / (3 * a), cy / (3 * a)}
                              : Vec2{0.5 * (box.minX + box.maxX), 0.5 * (box.minY + box.maxY)};
    const double side = std::min(box.width(), box.height());
    const double atCentroid = insideDistance(centroid, outline, near);
    if (atCentroid >= 0.2 * side) // a convex or nearly convex room: where it always was
        return centroid;
    // Far from every edge: a grid over the box, the sample nearest the centroid among those
    // at least 80% as far from the edges as the farthest (a corridor's whole centre line is
    // as far: its name goes to the middle, not to one end).
    const int n = 24;
    const Vec2 step{box.width() / n, box.height() / n};
    std::vector<std::pair<Vec2, double>> samples;
    double farthest = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec2 p{box.minX + (i + 0.5) * step.x, box.minY + (j + 0.5) * step.y};
            const double d = insideDistance(p, outline, near);
            if (d > 0.0)
                samples.push_back({p, d});
            farthest = std::max(farthest, d);
        }
    Vec2 best = centroid;
    double bestDistance = atCentroid;
    for (const auto& [p, d] : samples)
        if (d >= 0.8 * farthest &&
            (bestDistance < 0.8 * farthest || distance(p, centroid) < distance(best, centroid))) {
            best = p;
            bestDistance = d;
        }
    if (bestDistance > 0.0)
        return best;
    return centroid; // a sliver the grid missed
}

} // namespace fc
