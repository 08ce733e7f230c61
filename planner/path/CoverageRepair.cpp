#include "path/CoverageRepair.h"

#include "geometry/Clearance.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace fc {
namespace {

// Groups of missed points handled at most (each costs a few clearance queries).
constexpr size_t kMaxGaps = 4000;
// Segment tests per route to a touch-up stroke: the route is a few widths long at most, and a
// search that fails among a ragged map's thousands of corners would otherwise test them all.
constexpr size_t kMaxRouteChecks = 20'000;

using CellKey = std::pair<long long, long long>;

CellKey keyOf(Vec2 p, double size) {
    return {static_cast<long long>(std::floor(p.x / size)),
            static_cast<long long>(std::floor(p.y / size))};
}

// A stroke of the head: centre c, along u, half length h; it sweeps |along| <= h, |across|
// <= W/2 around c.
struct Stroke {
    Vec2 c, u;
    double h = 0.0;
};

bool sweeps(const Stroke& s, Vec2 p, double halfWidth) {
    const Vec2 d = p - s.c;
    return std::abs(dot(d, s.u)) <= s.h + 1e-9 && std::abs(cross(s.u, d)) <= halfWidth;
}

// The clear centre nearest to t from which a head of width W reaches t (t itself when the
// robot fits there); nullopt when there is none within W/2.
std::optional<Vec2> centreFor(const ClearanceField& field, Vec2 t, double w) {
    if (field.isClear(t))
        return t;
    for (int ring = 1; ring <= 9; ++ring) {
        const double rho = 0.05 * w * ring;
        for (int k = 0; k < 32; ++k) {
            const double a = 2.0 * M_PI * k / 32.0;
            const Vec2 c = t + Vec2{std::cos(a), std::sin(a)} * rho;
            if (field.isClear(c))
                return c;
        }
    }
    return std::nullopt;
}

// A stroke to add and how the robot gets there from the path vertex `from` (route[0] is
// that vertex, route.back() == a).
struct TouchUp {
    int from = -1;
    Polyline route;
    Vec2 a, b;
};

// The detour driving t alone: from its vertex to the stroke, along it and back, and back to
// the vertex (route[0] at both ends).
Polyline outAndBack(const TouchUp& t) {
    Polyline detour = t.route;
    detour.push_back(t.b);
    detour.push_back(t.a);
    detour.insert(detour.end(), t.route.rbegin() + 1, t.route.rend());
    return detour;
}

// A run of short strokes along one stretch of wall: the touch-ups of `left` whose strokes
// lie on t's line (within a millionth of W) and overlap t's stroke or one another, t
// included, and the ends of the stretch they sweep together.
struct CollinearRun {
    std::vector<const TouchUp*> touchUps;
    Vec2 first, second;
};

CollinearRun collinearRun(const std::vector<const TouchUp*>& left, const TouchUp& t, double w) {
    const double length = distance(t.a, t.b);
    std::vector<const TouchUp*> run{&t};
    if (length < 1e-12)
        return {run, t.a, t.b};
    const Vec2 u = (t.b - t.a) * (1.0 / length);
    const double tolerance = 1e-6 * w;
    auto along = [&](Vec2 p) { return dot(p - t.a, u); };
    double lo = 0.0, hi = length;
    for (bool grown = true; grown;) {
        grown = false;
        for (const TouchUp* s : left) {
            if (std::find(run.begin(), run.end(), s) != run.end() ||
                std::abs(cross(u, s->a - t.a)) > tolerance ||
                std::abs(cross(u, s->b - t.a)) > tolerance)
                continue;
            const double sLo = std::min(along(s->a), along(s->b));
            const double sHi = std::max(along(s->a), along(s->b));
            if (sLo > hi + tolerance || sHi < lo - tolerance)
                continue;
            run.push_back(s);
            lo = std::min(lo, sLo), hi = std::max(hi, sHi);
            grown = true;
        }
    }
    return {run, t.a + u * lo, t.a + u * hi};
}

// Touch-ups that leave from path vertices close together (within W, along at most 2 W of
// path: the many vertices of one traced stripe end under a slanted wall) are driven as one
// chain from the first vertex: stroke to nearest stroke, each swept once from its nearer
// end, then back, where that is shorter than driving each alone (on a ragged map, alone
// they make a fan of there-and-back strokes from one corner). A stroke whose leg is not
// clear leaves on its own route from its own vertex, as before. Returns, per vertex, the
// detours that leave from it and return to it (the vertex itself not included at either
// end).
std::map<int, std::vector<Polyline>> chainedDetours(const ClearanceField& field,
                                                    const std::vector<Vec2>& local,
                                                    std::vector<TouchUp> touchUps, double w,
                                                    double maxDetour, bool chainNearby,
                                                    int& chains) {
    std::sort(touchUps.begin(), touchUps.end(),
              [](const TouchUp& x, const TouchUp& y) { return x.from < y.from; });
    std::map<int, std::vector<Polyline>> detours;
    auto alone = [&](const TouchUp& t) {
        const Polyline detour = outAndBack(t);
        detours[t.from].push_back(Polyline(detour.begin() + 1, detour.end())); // not the vertex
    };
    auto clearLeg = [&](Vec2 p, Vec2 q) -> Polyline {
        if (field.segmentIsClear(p, q))
            return {p, q};
        Polyline route = field.findPath(p, q, {}, maxDetour, kMaxRouteChecks);
        return !route.empty() && polylineLength(route) <= maxDetour ? route : Polyline{};
    };
    for (size_t first = 0; first < touchUps.size();) {
        // The group: touch-ups from vertices near the first one's, along a short stretch.
        const int anchor = touchUps[first].from;
        size_t end = first + 1;
        double along = 0.0;
        int last = anchor;
        while (end < touchUps.size()) {
            const int v = touchUps[end].from;
            for (int i = last; i < v; ++i)
                along += distance(local[i], local[i + 1]);
            last = v;
            if (along > 2.0 * w || distance(local[v], local[anchor]) > w)
                break;
            ++end;
        }
        std::vector<const TouchUp*> left;
        for (size_t k = first; k < end; ++k)
            left.push_back(&touchUps[k]);
        first = end;
        if (left.size() == 1 || !chainNearby) {
            for (const TouchUp* t : left)
                alone(*t);
            continue;
        }
        if (left.size() == 1) {
            alone(*left.front());
            continue;
        }
        const Vec2 home = local[anchor];
        Polyline chain{home};
        std::vector<const TouchUp*> chained;
        while (!left.empty()) {
            const Vec2 at = chain.back();
            auto nearest = std::min_element(left.begin(), left.end(), [&](auto* x, auto* y) {
                return std::min(distance(at, x->a), distance(at, x->b)) <
                       std::min(distance(at, y->a), distance(at, y->b));
            });
            const TouchUp& t = **nearest;
            // Strokes on t's line that overlap it are swept as one stroke: one after another
            // they went up, back a little, up again along a ragged wall.
            const CollinearRun line = collinearRun(left, t, w);
            const bool merged =
                line.touchUps.size() > 1 && field.segmentIsClear(line.first, line.second);
            const Vec2 first = merged ? line.first : t.a, second = merged ? line.second : t.b;
            const bool fromFirst = distance(at, first) <= distance(at, second);
            const Vec2 enter = fromFirst ? first : second, leave = fromFirst ? second : first;
            Polyline leg = clearLeg(at, enter);
            if (leg.empty()) {
                alone(t); // on its own route from its own vertex
                left.erase(nearest);
                continue;
            }
            chain.insert(chain.end(), leg.begin() + 1, leg.end());
            chain.push_back(leave);
            const std::vector<const TouchUp*> done =
                merged ? line.touchUps : std::vector<const TouchUp*>{&t};
            for (const TouchUp* s : done) {
                chained.push_back(s);
                left.erase(std::find(left.begin(), left.end(), s));
            }
        }
        if (chain.size() < 2)
            continue;
        Polyline back = clearLeg(chain.back(), home);
        if (back.empty()) // retrace the chain: clear by construction
            back.assign(chain.rbegin(), chain.rend());
        chain.insert(chain.end(), back.begin() + 1, back.end());
        // Kept only where it is shorter than its strokes driven each on its own.
        double separately = 0.0;
        for (const TouchUp* t : chained)
            separately += 2.0 * (polylineLength(t->route) + distance(t->a, t->b));
        if (polylineLength(chain) < separately) {
            detours[anchor].push_back(Polyline(chain.begin() + 1, chain.end()));
            ++chains;
        } else {
            for (const TouchUp* t : chained)
                alone(*t);
        }
    }
    return detours;
}

// The missed points (local frame) that the detour to t and its stroke sweep, as indices.
std::vector<int> sweptBy(const TouchUp& t, const std::vector<Vec2>& points,
                         const std::map<CellKey, std::vector<int>>& grid, double w) {
    Polyline line = t.route;
    line.push_back(t.b);
    BoundingBox box;
    for (const Vec2& p : line)
        box.add(p);
    const double cell = w / 3.0, reach = 0.5 * w;
    const CellKey lo = keyOf({box.minX - reach, box.minY - reach}, cell);
    const CellKey hi = keyOf({box.maxX + reach, box.maxY + reach}, cell);
    std::vector<int> swept;
    for (long long x = lo.first; x <= hi.first; ++x)
        for (long long y = lo.second; y <= hi.second; ++y) {
            const auto it = grid.find({x, y});
            if (it == grid.end())
                continue;
            for (const int i : it->second)
                for (size_t k = 1; k < line.size(); ++k)
                    if (pointSegmentDistance(points[i], line[k - 1], line[k]) <= reach) {
                        swept.push_back(i);
                        break;
                    }
        }
    return swept;
}

// The touch-ups the budget keeps (CoverageRepair.h: best rate first, then only while floor
// beyond budget.keepMissed is missed or the rate reaches budget.minRate).
std::vector<TouchUp> withinBudget(std::vector<TouchUp> touchUps, const std::vector<Vec2>& points,
                                  double w, const TouchUpBudget& budget, int& skipped) {
    std::map<CellKey, std::vector<int>> grid;
    for (size_t i = 0; i < points.size(); ++i)
        grid[keyOf(points[i], w / 3.0)].push_back(static_cast<int>(i));
    struct Priced {
        size_t index;
        std::vector<int> swept;
        double seconds, rate;
    };
    std::vector<Priced> priced;
    for (size_t k = 0; k < touchUps.size(); ++k) {
        const TouchUp& t = touchUps[k];
        const Polyline detour = outAndBack(t);
        // One more turn where it leaves the path: the path rarely heads its way.
        const double seconds =
            polylineLength(detour) / budget.speed + (countTurns(detour) + 1) * budget.turnTime;
        std::vector<int> swept = sweptBy(t, points, grid, w);
        const double rate = swept.size() * budget.pointArea / std::max(seconds, 1e-9);
        priced.push_back({k, std::move(swept), seconds, rate});
    }
    std::stable_sort(priced.begin(), priced.end(),
                     [](const Priced& x, const Priced& y) { return x.rate > y.rate; });
    std::vector<char> claimed(points.size(), 0);
    std::vector<char> keep(touchUps.size(), 0);
    double missed = budget.missedArea;
    for (const Priced& p : priced) {
        std::size_t fresh = 0;
        for (const int i : p.swept)
            fresh += claimed[i] ? 0 : 1;
        const double area = fresh * budget.pointArea;
        // A stroke whose floor the better-paying ones sweep already adds only time.
        if (fresh == 0 || (!(missed > budget.keepMissed) && area < budget.minRate * p.seconds))
            continue;
        keep[p.index] = 1;
        missed -= area;
        for (const int i : p.swept)
            claimed[i] = 1;
    }
    std::vector<TouchUp> kept;
    for (size_t k = 0; k < touchUps.size(); ++k) {
        if (keep[k])
            kept.push_back(std::move(touchUps[k]));
        else
            ++skipped;
    }
    return kept;
}

} // namespace

CoverageRepairStats repairCoverage(const Decomposition& dec, CoveragePath& path,
                                   const std::vector<Vec2>& missed, double maxDetour,
                                   bool chainNearby, const TouchUpBudget* budget) {
    CoverageRepairStats stats;
    if (missed.empty() || path.points.size() < 2)
        return stats;
    const ClearanceField& field = dec.clearance();
    const double w = dec.coverageWidth();
    std::vector<Vec2> local;
    local.reserve(path.points.size());
    for (const Vec2& p : path.points)
        local.push_back(dec.frame.toLocal(p));

    // Missed points grouped on a W/3 grid; each group's point nearest its mean is the target.
    std::map<CellKey, std::vector<Vec2>> groups;
    for (const Vec2& p : missed) {
        const Vec2 q = dec.frame.toLocal(p);
        groups[keyOf(q, w / 3.0)].push_back(q);
    }
    // Path vertices on a grid, to find where to leave the path.
    const double bucket = std::max(w, maxDetour / 2.0);
    std::map<CellKey, std::vector<int>> vertices;
    for (size_t i = 0; i < local.size(); ++i)
        vertices[keyOf(local[i], bucket)].push_back(static_cast<int>(i));

    std::vector<Stroke> strokes;
    std::vector<TouchUp> touchUps;
    for (const auto& [key, points] : groups) {
        if (static_cast<size_t>(stats.gaps) >= kMaxGaps)
            break;
        ++stats.gaps;
        Vec2 mean;
        for (const Vec2& p : points)
            mean = mean + p * (1.0 / points.size());
        Vec2 target = points.front();
        for (const Vec2& p : points)
            if (distance(p, mean) < distance(target, mean))
                target = p;
        if (std::any_of(strokes.begin(), strokes.end(),
                        [&](const Stroke& s) { return sweeps(s, target, 0.5 * w); }))
            continue;
        const std::optional<Vec2> centre = centreFor(field, target, w);
        if (!centre)
            continue;
        // A stroke through the centre along the wall (across the line to the target) when
        // it is clear; pinned in a corner, a one-sided stroke from the centre in any
        // direction whose sweep still holds the target (any direction does: the target lies
        // within W/2 of the centre, so it only has to fall within the stroke's length).
        const Vec2 toTarget = target - *centre;
        const double reach = norm(toTarget);
        const Vec2 u = reach > 1e-9 ? Vec2{-toTarget.y / reach, toTarget.x / reach} : Vec2{1, 0};
        std::optional<std::pair<Vec2, Vec2>> ends;
        for (double h : {0.25 * w, 0.125 * w, 0.05 * w})
            if (!ends && field.segmentIsClear(*centre - u * h, *centre + u * h))
                ends = std::pair{*centre - u * h, *centre + u * h};
        for (int k = 0; k < 16 && !ends; ++k) {
            const double angle = 2.0 * M_PI * k / 16.0;
            const Vec2 v{std::cos(angle), std::sin(angle)};
            const double along = dot(toTarget, v);
            if (along < -1e-9)
                continue;
            const double h = std::max(0.05 * w, along + 0.02 * w);
            if (field.segmentIsClear(*centre, *centre + v * h))
                ends = std::pair{*centre, *centre + v * h};
        }
        if (!ends)
            continue;
        const Vec2 a = ends->first, b = ends->second;
        const double strokeLength = distance(a, b);
        const Stroke stroke{(a + b) * 0.5, (b - a) * (1.0 / strokeLength), 0.5 * strokeLength};
        if (!sweeps(stroke, target, 0.5 * w))
            continue;

        // Leave from the nearest path vertex that a short clear route joins to the stroke.
        std::vector<std::pair<double, int>> near;
        const CellKey home = keyOf(a, bucket);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy) {
                auto it = vertices.find({home.first + dx, home.second + dy});
                if (it == vertices.end())
                    continue;
                for (int i : it->second)
                    if (distance(local[i], a) <= maxDetour)
                        near.push_back({distance(local[i], a), i});
            }
        std::sort(near.begin(), near.end());
        Polyline route;
        int from = -1;
        for (size_t k = 0; k < near.size() && k < 6 && route.empty(); ++k) {
            const Vec2 v = local[near[k].second];
            if (field.segmentIsClear(v, a))
                route = {v, a};
            else
                route = field.findPath(v, a, {}, maxDetour, kMaxRouteChecks);
            if (!route.empty() && polylineLength(route) > maxDetour)
                route.clear();
            if (!route.empty())
                from = near[k].second;
        }
        if (route.empty())
            continue;
        ++stats.touchUps;
        strokes.push_back(stroke);
        touchUps.push_back({from, std::move(route), a, b});
    }
    if (budget && !touchUps.empty()) {
        std::vector<Vec2> points;
        points.reserve(missed.size());
        for (const Vec2& p : missed)
            points.push_back(dec.frame.toLocal(p));
        touchUps = withinBudget(std::move(touchUps), points, w, *budget, stats.skipped);
        stats.touchUps = static_cast<int>(touchUps.size());
    }
    if (touchUps.empty())
        return stats;
    const std::map<int, std::vector<Polyline>> detours =
        chainedDetours(field, local, std::move(touchUps), w, maxDetour, chainNearby, stats.chains);
    for (const auto& [vertex, list] : detours)
        for (const Polyline& detour : list)
            stats.added += distance(local[vertex], detour.front()) + polylineLength(detour);

    CoveragePath out;
    auto add = [&out](Vec2 p, SegmentKind kind) {
        if (!out.points.empty()) {
            if (distance(out.points.back(), p) < 1e-9)
                return;
            out.kinds.push_back(kind);
        }
        out.points.push_back(p);
    };
    for (size_t i = 0; i < local.size(); ++i) {
        add(path.points[i], i == 0 ? SegmentKind::Transit : path.kinds[i - 1]);
        if (auto it = detours.find(static_cast<int>(i)); it != detours.end())
            for (const Polyline& detour : it->second) {
                for (size_t j = 0; j + 1 < detour.size(); ++j)
                    add(dec.frame.toWorld(detour[j]), SegmentKind::Contour);
                add(path.points[i], SegmentKind::Contour); // back on the path, exactly
            }
    }
    path = std::move(out);
    return stats;
}

} // namespace fc
