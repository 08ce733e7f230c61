// Straightening traced map outlines: the traced points are covered by runs that fit between two
// lines along a wall direction, each run becomes one line, collinear runs separated by a
// shallow notch or a tooth within the band become one, and neighbouring lines meet at their
// intersection. Points no run covers (round walls, rounded corners) are kept as traced.
#include "importers/MapWalls.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <vector>

namespace fc::importing {

namespace {

constexpr double kMinShare = 1.0 / 3.0;
constexpr int kMaxExcursion = 16;       // elements between two runs joined as one wall
constexpr size_t kMaxChamferPoints = 4; // traced points of a corner squared (squaredCorners)

double signedAreaOf(const Ring& r) {
    double a = 0.0;
    for (size_t i = 0; i < r.size(); ++i)
        a += cross(r[i], r[(i + 1) % r.size()]);
    return 0.5 * a;
}

// A run of points fitted as one wall, or a point kept as traced.
struct Element {
    bool line = false;
    int family = 0;          // 0: a line v = c (along u); 1: a line u = c (along v)
    int first = 0, last = 0; // offsets from the ring's start point, first <= last
    double c = 0.0;
    int dir = 1; // +1 when the run heads towards larger along-coordinates
};

class Straightener {
public:
    Straightener(const Ring& ring, bool freeInside, const StraightenOptions& o,
                 StraightenStats& stats)
        : options_(o), stats_(stats) {
        const double a = options_.angleDeg * M_PI / 180.0;
        cos_ = std::cos(a), sin_ = std::sin(a);
        for (const Vec2& p : ring)
            local_.push_back({p.x * cos_ + p.y * sin_, -p.x * sin_ + p.y * cos_});
        interiorLeft_ = signedAreaOf(local_) > 0;
        freeInside_ = freeInside;
    }

    Ring run() {
        const int n = static_cast<int>(local_.size());
        if (n < 4)
            return toWorld(local_);
        std::vector<Element> elements = runs();
        reseamAtCorner(elements, n);
        mergeAcrossExcursions(elements);
        stats_.walls += static_cast<int>(
            std::count_if(elements.begin(), elements.end(), [](auto& e) { return e.line; }));
        return toWorld(rebuild(elements));
    }

    // How well the two directions fit: the sum of the squared lengths of the runs along
    // them (a long wall that fits counts more than many short pieces that happen to).
    double lengthAlongWalls() {
        if (local_.size() < 4)
            return 0.0;
        double sum = 0.0;
        for (const Element& e : runs())
            if (e.line)
                sum += std::pow(spanLength(e.first, e.last, e.family), 2);
        return sum;
    }

private:
    // The outline covered greedily by runs (from the longest) and single points.
    std::vector<Element> runs() {
        const int n = static_cast<int>(local_.size());
        const std::vector<int> ext[2] = {extents(0), extents(1)};
        // Start at the longest run, so that the seam never cuts a wall in two.
        int start = 0;
        double longest = -1;
        for (int i = 0; i < n; ++i)
            for (int f : {0, 1})
                if (double len = spanLength(i, ext[f][i], f); len > longest)
                    longest = len, start = i;
        rotateStart(start);
        std::vector<Element> elements;
        for (int k = 0; k < n;) {
            const int i = (start + k) % n;
            int bestFamily = 0, bestEnd = k;
            double bestLength = -1;
            for (int f : {0, 1}) {
                const int end = std::min(k + (ext[f][i] - i), n - 1);
                if (double len = spanLength(k, end, f); len > bestLength)
                    bestLength = len, bestFamily = f, bestEnd = end;
            }
            if (bestLength >= options_.minRun && bestEnd > k) {
                elements.push_back(fitted(bestFamily, k, bestEnd));
                k = bestEnd + 1;
            } else {
                elements.push_back({false, 0, k, k, 0.0, 1});
                ++k;
            }
        }
        return elements;
    }

    double perp(const Vec2& p, int f) const { return f == 0 ? p.y : p.x; }
    double along(const Vec2& p, int f) const { return f == 0 ? p.x : p.y; }
    const Vec2& at(int k) const { return local_[k % local_.size()]; }
    double spanLength(int a, int b, int f) const {
        return std::abs(along(at(b), f) - along(at(a), f));
    }

    void rotateStart(int start) {
        std::rotate(local_.begin(), local_.begin() + start, local_.end());
    }

    // For each point i, the last point j (i <= j < i + n, cyclically) such that points i..j
    // lie within 2 * band across family f.
    std::vector<int> extents(int f) const {
        const int n = static_cast<int>(local_.size());
        std::vector<int> ext(n);
        std::deque<int> hi, lo; // indices of decreasing maxima / increasing minima
        int j = -1;
        for (int i = 0; i < n; ++i) {
            while (j + 1 < i + n) {
                const double v = perp(at(j + 1), f);
                const double top = hi.empty() ? v : std::max(v, perp(at(hi.front()), f));
                const double bottom = lo.empty() ? v : std::min(v, perp(at(lo.front()), f));
                if (top - bottom > 2.0 * options_.band && j >= i)
                    break;
                ++j;
                while (!hi.empty() && perp(at(hi.back()), f) <= v)
                    hi.pop_back();
                hi.push_back(j);
                while (!lo.empty() && perp(at(lo.back()), f) >= v)
                    lo.pop_back();
                lo.push_back(j);
            }
            ext[i] = j;
            if (!hi.empty() && hi.front() == i)
                hi.pop_front();
            if (!lo.empty() && lo.front() == i)
                lo.pop_front();
        }
        return ext;
    }

    // The line through points first..last: the length-weighted median of their segments
    // across the run (a clean wall keeps its exact line; the start of a chamfered corner or
    // a lone bump does not pull it), so within two bands of every point of the run.
    Element fitted(int f, int first, int last) const {
        Element e{true, f, first, last, 0.0, along(at(last), f) >= along(at(first), f) ? 1 : -1};
        std::vector<std::pair<double, double>> pieces; // across, length
        double weight = 0, top = -INFINITY, bottom = INFINITY;
        for (int k = first; k <= last; ++k) {
            top = std::max(top, perp(at(k), f)), bottom = std::min(bottom, perp(at(k), f));
            if (k < last) {
                const double len = distance(at(k), at(k + 1));
                pieces.push_back({0.5 * (perp(at(k), f) + perp(at(k + 1), f)), len});
                weight += len;
            }
        }
        std::sort(pieces.begin(), pieces.end());
        double median = 0.5 * (top + bottom), below = 0;
        for (const auto& [across, len] : pieces) {
            below += len;
            if (below >= 0.5 * weight) {
                median = across;
                break;
            }
        }
        e.c = std::clamp(median, bottom, top);
        return e;
    }

    // Which side of a wall of family f heading dir is floor, as a sign across the wall.
    double freeSign(int f, int dir) const {
        const double left = f == 0 ? dir : -dir; // the left normal, across the wall
        const double interior = interiorLeft_ ? left : -left;
        return freeInside_ ? interior : -interior;
    }

    // Joins line a with a later line b of the same wall when every point between them
    // stays within the band on the floor side (a tooth) and within notchDepth on the wall
    // side (a notch, then filled).
    bool tryJoin(std::vector<Element>& el, size_t a, size_t b) {
        const Element& A = el[a];
        const Element& B = el[b];
        const double la = spanLength(A.first, A.last, A.family);
        const double lb = spanLength(B.first, B.last, B.family);
        const double c = (A.c * la + B.c * lb) / std::max(la + lb, 1e-12);
        const int f = A.family;
        const double sign = freeSign(f, A.dir);
        bool notch = false;
        for (int k = A.first; k <= B.last; ++k) {
            const double d = (perp(at(k), f) - c) * sign; // > 0: towards the floor
            // Two pieces of one wall fitted apart may differ by up to the band; joined, the
            // wall runs between them (within two bands of their points).
            const bool inRun = k <= A.last || k >= B.first;
            const double limit = (inRun ? 2.0 : 1.0) * options_.band + 1e-9;
            if (d > limit || (inRun && d < -limit))
                return false;
            if (!inRun && d < -options_.band - 1e-9) {
                if (d < -options_.notchDepth - 1e-9)
                    return false;
                notch = true;
            }
        }
        stats_.notchesFilled += notch;
        el[a].last = B.last;
        el[a].c = c;
        el.erase(el.begin() + a + 1, el.begin() + b + 1);
        return true;
    }

    // The longest run may begin partway along a wall: start the list at a corner instead,
    // so that no wall is cut at the seam (offsets past the seam grow beyond n).
    static void reseamAtCorner(std::vector<Element>& el, int n) {
        for (size_t r = 1; r < el.size(); ++r) {
            if (el[r].line && el[r - 1].line && el[r].family != el[r - 1].family) {
                for (size_t k = 0; k < r; ++k)
                    el[k].first += n, el[k].last += n;
                std::rotate(el.begin(), el.begin() + r, el.end());
                return;
            }
        }
    }

    void mergeAcrossExcursions(std::vector<Element>& el) {
        for (bool changed = true; changed;) {
            changed = false;
            for (size_t a = 0; a < el.size() && !changed; ++a) {
                if (!el[a].line)
                    continue;
                for (size_t b = a + 1; b < el.size() && b <= a + kMaxExcursion; ++b) {
                    const Element& B = el[b];
                    if (!B.line || B.family != el[a].family || B.dir != el[a].dir ||
                        std::abs(B.c - el[a].c) > options_.band)
                        continue;
                    changed = tryJoin(el, a, b);
                    break;
                }
            }
        }
    }

    Vec2 onLine(const Element& l, double a) const {
        return l.family == 0 ? Vec2{a, l.c} : Vec2{l.c, a};
    }

    // Where line l begins after element p (or ends before element p, with `atEnd`).
    Vec2 joint(const Element& l, const Element& p, bool atEnd) const {
        const Vec2& own = at(atEnd ? l.last : l.first);
        const Vec2& other = at(atEnd ? p.first : p.last);
        if (p.line && p.family != l.family) {
            const Vec2 x = l.family == 0 ? Vec2{p.c, l.c} : Vec2{l.c, p.c};
            const double shift = cornerShiftBetween(l, p);
            if (distance(x, own) <= shift && distance(x, other) <= shift)
                return x;
        } else if (p.line) { // a step between two parallel walls, halfway between their ends
            return onLine(l, 0.5 * (along(own, l.family) + along(other, l.family)));
        }
        return onLine(l, along(own, l.family));
    }

    // Whether both walls are long enough for a cut corner between them to be squared.
    bool longWalls(const Element& a, const Element& b) const {
        return spanLength(a.first, a.last, a.family) >= options_.chamferMinWall &&
               spanLength(b.first, b.last, b.family) >= options_.chamferMinWall;
    }
    double cornerShiftBetween(const Element& a, const Element& b) const {
        return longWalls(a, b) ? std::max(options_.cornerShift, options_.chamferShift)
                               : options_.cornerShift;
    }

    // Corners the tracing cut or rounded: a few points between long walls of the two
    // families, put back at the walls' intersection where that lies within chamferShift of
    // both walls' ends, as joint() allows (the skipped points, and the corner, per element).
    struct Corners {
        std::vector<char> skipped;
        std::vector<std::optional<Vec2>> start, end;
    };
    Corners squaredCorners(const std::vector<Element>& el) const {
        const size_t m = el.size();
        Corners corners{std::vector<char>(m, 0), std::vector<std::optional<Vec2>>(m),
                        std::vector<std::optional<Vec2>>(m)};
        for (size_t i = 0; i < m; ++i) {
            const Element& e = el[i];
            if (!e.line || corners.skipped[i])
                continue;
            size_t k = 1;
            while (k <= kMaxChamferPoints && k < m && !el[(i + k) % m].line)
                ++k;
            if (k == 1 || k > kMaxChamferPoints || k >= m)
                continue;
            const size_t q = (i + k) % m;
            const Element& next = el[q];
            if (next.family == e.family)
                continue;
            const Vec2 x = e.family == 0 ? Vec2{next.c, e.c} : Vec2{e.c, next.c};
            const double shift = cornerShiftBetween(e, next);
            if (!longWalls(e, next) || distance(x, at(e.last)) > shift ||
                distance(x, at(next.first)) > shift)
                continue;
            corners.end[i] = x;
            corners.start[q] = x;
            for (size_t j = 1; j < k; ++j)
                corners.skipped[(i + j) % m] = 1;
        }
        return corners;
    }

    Ring rebuild(const std::vector<Element>& el) const {
        Ring out;
        auto emit = [&](Vec2 p) {
            if (out.empty() || distance(out.back(), p) > 1e-9)
                out.push_back(p);
        };
        const size_t m = el.size();
        const Corners corners = squaredCorners(el);
        for (size_t i = 0; i < m; ++i) {
            const Element& e = el[i];
            if (corners.skipped[i])
                continue;
            if (!e.line) {
                emit(at(e.first));
                continue;
            }
            emit(corners.start[i] ? *corners.start[i] : joint(e, el[(i + m - 1) % m], false));
            emit(corners.end[i] ? *corners.end[i] : joint(e, el[(i + 1) % m], true));
        }
        if (out.size() > 1 && distance(out.front(), out.back()) <= 1e-9)
            out.pop_back();
        return out;
    }

    Ring toWorld(const Ring& local) const {
        Ring out;
        for (const Vec2& p : local)
            out.push_back({p.x * cos_ - p.y * sin_, p.x * sin_ + p.y * cos_});
        return out;
    }

    StraightenOptions options_;
    StraightenStats& stats_;
    double cos_ = 1, sin_ = 0;
    Ring local_;
    bool interiorLeft_ = true, freeInside_ = true;
};

double areaOf(const OGRGeometry* g) {
    if (!g)
        return 0.0;
    if (auto* s = dynamic_cast<const OGRSurface*>(g))
        return s->get_Area();
    if (auto* c = dynamic_cast<const OGRGeometryCollection*>(g))
        return c->get_Area();
    return 0.0;
}

} // namespace

std::optional<double> dominantWallDirection(const OGRGeometry& traced, const OGRGeometry* fine,
                                            double band) {
    // Directions of a coarse simplification: a slanted wall's staircase becomes one segment,
    // whose direction is the more exact the longer it is (weights: length squared).
    const GeometryPtr coarse(traced.Simplify(2.0));
    if (!coarse)
        return std::nullopt;
    std::vector<Polygon2> polygons;
    collectPolygons(coarse.get(), polygons);
    constexpr int kBins = 180; // half a degree each, over [0, 90)
    std::vector<double> bins(kBins, 0.0);
    std::vector<std::pair<double, double>> walls; // degrees mod 90, length
    double total = 0.0;
    auto vote = [&](const Ring& r) {
        for (size_t i = 0; i < r.size(); ++i) {
            const Vec2 d = r[(i + 1) % r.size()] - r[i];
            const double len = norm(d);
            total += len * len;
            if (len < 8.0)
                continue;
            const double deg = std::fmod(std::atan2(d.y, d.x) * 180.0 / M_PI + 360.0, 90.0);
            bins[static_cast<int>(deg * 2.0) % kBins] += len * len;
            walls.push_back({deg, len * len});
        }
    };
    for (const Polygon2& p : polygons) {
        vote(p.shell);
        for (const Ring& h : p.holes)
            vote(h);
    }
    int best = 0;
    double bestScore = -1;
    for (int b = 0; b < kBins; ++b) {
        double score = 0;
        for (int k = -4; k <= 4; ++k)
            score += bins[(b + k + kBins) % kBins];
        if (score > bestScore)
            bestScore = score, best = b;
    }
    const double centre = (best + 0.5) / 2.0;
    double sum = 0, weight = 0;
    for (const auto& [deg, len] : walls) {
        double delta = std::fmod(deg - centre + 135.0, 90.0) - 45.0;
        if (delta < -45.0)
            delta += 90.0;
        if (std::abs(delta) <= 2.0)
            sum += delta * len, weight += len;
    }
    if (total <= 0.0 || weight < kMinShare * total)
        return std::nullopt;
    const double coarseAngle = centre + sum / weight;
    if (!fine)
        return std::fmod(coarseAngle + 90.0, 90.0);
    // A coarse segment may end a pixel or two into a rounded corner, which tilts a long wall
    // by a degree, and a wall that misses its direction by a third of a degree over 20 m
    // leaves the band. So the direction is the one, on a 0.05 degree grid within 2 degrees,
    // along which the fine outline runs in the longest walls (ties: the nearer).
    std::vector<Polygon2> finePolygons;
    collectPolygons(fine, finePolygons);
    StraightenOptions probe;
    probe.band = band;
    probe.minRun = std::max(4.0, 2.0 * band + 2.0);
    double chosen = coarseAngle, bestLength = -1;
    const double first = std::round((coarseAngle - 2.0) / 0.05) * 0.05;
    for (int k = 0; k <= 80; ++k) {
        probe.angleDeg = first + 0.05 * k;
        double length = 0;
        StraightenStats unused;
        for (const Polygon2& p : finePolygons) {
            length += Straightener(p.shell, true, probe, unused).lengthAlongWalls();
            for (const Ring& h : p.holes)
                length += Straightener(h, false, probe, unused).lengthAlongWalls();
        }
        if (length > bestLength + 1e-9 ||
            (length > bestLength - 1e-9 &&
             std::abs(probe.angleDeg - coarseAngle) < std::abs(chosen - coarseAngle))) {
            bestLength = length;
            chosen = probe.angleDeg;
        }
    }
    return std::fmod(std::fmod(chosen, 90.0) + 90.0, 90.0);
}

Ring straightenRing(const Ring& ring, bool freeInside, const StraightenOptions& options,
                    StraightenStats& stats) {
    return Straightener(ring, freeInside, options, stats).run();
}

StraightenResult straightenOutlines(const OGRGeometry& outlines, const StraightenOptions& options,
                                    bool freeInside) {
    std::vector<Polygon2> polygons;
    collectPolygons(&outlines, polygons);
    StraightenResult result;
    auto all = std::make_unique<OGRMultiPolygon>();
    for (const Polygon2& p : polygons) {
        StraightenStats stats;
        // A ring whose straightened form crosses itself (two walls a band apart on either
        // side of a thin spot) stays as traced; the others are still straightened.
        auto straightened = [&](const Ring& ring, bool inside) {
            StraightenStats own;
            Ring out = straightenRing(ring, inside, options, own);
            const std::unique_ptr<OGRPolygon> alone(out.size() >= 3 ? ogrPolygon(out, {})
                                                                    : nullptr);
            if (!alone || !alone->IsValid())
                return ring;
            stats.walls += own.walls;
            stats.notchesFilled += own.notchesFilled;
            return out;
        };
        Ring shell = straightened(p.shell, freeInside);
        std::vector<Ring> holes;
        for (const Ring& h : p.holes)
            holes.push_back(straightened(h, !freeInside));
        const bool degenerate =
            shell.size() < 3 ||
            std::any_of(holes.begin(), holes.end(), [](const Ring& h) { return h.size() < 3; });
        std::unique_ptr<OGRPolygon> straight(degenerate ? nullptr : ogrPolygon(shell, holes));
        if (straight && straight->IsValid()) {
            all->addGeometryDirectly(straight.release());
            result.stats.walls += stats.walls;
            result.stats.notchesFilled += stats.notchesFilled;
        } else {
            all->addGeometryDirectly(ogrPolygon(p.shell, p.holes));
        }
    }
    const GeometryPtr added(all->Difference(&outlines));
    const GeometryPtr removed(outlines.Difference(all.get()));
    result.floorAdded = areaOf(added.get());
    result.floorRemoved = areaOf(removed.get());
    result.geometry = std::move(all);
    return result;
}

} // namespace fc::importing
