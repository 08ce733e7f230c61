#include "path/ExcursionPruning.h"

#include "geometry/GridCells.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace fc::detail {
namespace {

// Segments bucketed on a W-sized grid for local coverage queries.
class SegmentGrid {
public:
    // Each segment in the cells it passes through (forEachCellNear).
    SegmentGrid(const Polyline& pts, double cell) : pts_(pts), cell_(cell) {
        for (int i = 0; i + 1 < static_cast<int>(pts.size()); ++i)
            forEachCellNear(pts[i], pts[i + 1], cell, 0.0, [&](long long gx, long long gy) {
                std::vector<int>& bucket =
                    buckets_[hash(static_cast<long>(gx), static_cast<long>(gy))];
                if (bucket.empty() || bucket.back() != i) // a segment's pieces share cells
                    bucket.push_back(i);
            });
    }
    // Segment indices whose grid cells meet the box grown by one cell.
    void near(const BoundingBox& box, std::vector<int>& out) const {
        out.clear();
        for (long gx = key(box.minX) - 1; gx <= key(box.maxX) + 1; ++gx)
            for (long gy = key(box.minY) - 1; gy <= key(box.maxY) + 1; ++gy) {
                auto it = buckets_.find(hash(gx, gy));
                if (it != buckets_.end())
                    out.insert(out.end(), it->second.begin(), it->second.end());
            }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

private:
    long key(double v) const { return static_cast<long>(std::floor(v / cell_)); }
    static long long hash(long gx, long gy) { return (static_cast<long long>(gx) << 32) ^ gy; }
    const Polyline& pts_;
    double cell_;
    std::unordered_map<long long, std::vector<int>> buckets_;
};

// Whether the path turns from direction u to v by at most a right angle, give or take
// kRightAngleSlack: a traced wall a millimetre off makes a stripe end's turn 90.6 degrees,
// whose mitre still sweeps the corner (the metric bevels only beyond a 2 W mitre, turns
// past 150 degrees), and the seal kept for it cost two turns.
constexpr double kRightAngleSlack = 0.1736; // sin 10 degrees
bool turnsAtMostSquare(Vec2 u, Vec2 v) {
    return dot(u, v) >= -kRightAngleSlack * std::sqrt(dot(u, u) * dot(v, v));
}

// Is q inside the strip of half-width h around segment ab, between its ends extended by
// `before` and `after`?
bool inStrip(Vec2 q, Vec2 a, Vec2 b, double h, double before, double after) {
    const Vec2 d = b - a;
    const double len = std::sqrt(dot(d, d));
    if (len < 1e-12)
        return false;
    const Vec2 u = d * (1 / len);
    const double t = dot(q - a, u), s = std::abs(cross(u, q - a));
    return s <= h && t >= -before && t <= len + after;
}

// A margin swept all but a sliver this thin (a share of W) along the wall needs no seal.
// A traced wall is ragged by a map cell or two, so a flat stripe end's mitre misses a sliver
// a few centimetres deep; its seal cost two turns and a metre for a hundredth of a square
// metre. appendStripeEndSeal accepts wedges up to 0.2 W deep unsealed.
constexpr double kSliverDepth = 0.1;

} // namespace

std::vector<char> prunableExcursions(const Polyline& pts,
                                     const std::vector<PathExcursion>& excursions, double width) {
    std::vector<char> keep(pts.size(), 1);
    std::vector<char> segmentActive(pts.size(), 1); // segment i = pts[i] -> pts[i + 1]
    const SegmentGrid grid(pts, width);
    const double h = 0.5 * width * (1 - 1e-6);
    std::vector<int> nearby;
    // The join the path would make at an excursion's base if the excursion were dropped:
    // between the nearest active segments before and after it.
    auto virtualJoin = [&](Vec2 q, int begin, int end) {
        int before = begin - 1, after = end;
        while (before >= 0 && !segmentActive[before])
            --before;
        while (after + 1 < static_cast<int>(pts.size()) && !segmentActive[after])
            ++after;
        if (before < 0 || after + 1 >= static_cast<int>(pts.size()))
            return false;
        const Vec2 v = pts[begin];
        if (distance(pts[before + 1], v) > 1e-9 || distance(pts[after], v) > 1e-9)
            return false;
        const Vec2 a = pts[before], c = pts[after + 1];
        return turnsAtMostSquare(v - a, c - v) && distance(q, v) <= h * std::sqrt(2.0) &&
               inStrip(q, a, v, h, 0, h) && inStrip(q, v, c, h, h, 0);
    };
    auto covered = [&](Vec2 q, int skipBegin, int skipEnd) { // nearby: filled per excursion
        if (virtualJoin(q, skipBegin, skipEnd))
            return true;
        for (int i : nearby) {
            if (!segmentActive[i] || (i >= skipBegin && i < skipEnd))
                continue;
            if (inStrip(q, pts[i], pts[i + 1], h, 0, 0))
                return true;
            // Mitred join at the segment's end: inside both strips extended by W/2, and no
            // further from the corner than a right-angle mitre reaches (sharper turns are
            // bevelled, so their wide wedge is not swept).
            const int j = i + 1;
            if (j + 1 < static_cast<int>(pts.size()) && segmentActive[j] &&
                turnsAtMostSquare(pts[j] - pts[i], pts[j + 1] - pts[j]) &&
                !(j >= skipBegin && j < skipEnd) && distance(q, pts[j]) <= h * std::sqrt(2.0) &&
                inStrip(q, pts[i], pts[j], h, 0, h) && inStrip(q, pts[j], pts[j + 1], h, h, 0))
                return true;
        }
        return false;
    };
    // Whether the rest of the path, as it stands, sweeps the margin this excursion seals.
    auto prunable = [&](const PathExcursion& ex) {
        // The margin: between the excursion's turning point and the wall side.
        int tip = ex.begin;
        for (int k = ex.begin; k <= ex.end; ++k)
            if (distance(pts[k], pts[ex.begin]) > distance(pts[tip], pts[ex.begin]))
                tip = k;
        const Vec2 a = pts[ex.begin], b = pts[tip];
        const double side = ex.towardsCeiling ? 1.0 : -1.0;
        BoundingBox region;
        region.add(a);
        region.add(b);
        region.add(a + Vec2{0, side * 0.5 * width});
        region.add(b + Vec2{0, side * 0.5 * width});
        grid.near(region, nearby);
        for (int i = 0; i <= 8; ++i) {
            const Vec2 along = a + (b - a) * (0.02 + 0.96 * i / 8.0);
            for (int k = 1; k <= 4; ++k) {
                const Vec2 q{along.x, along.y + side * (0.49 - kSliverDepth) * width * k / 4.0};
                if (!covered(q, ex.begin, ex.end))
                    return false;
            }
        }
        return true;
    };
    auto setActive = [&](const PathExcursion& ex, char value) {
        for (int k = ex.begin; k < ex.end; ++k)
            segmentActive[k] = value;
    };
    // Dropping one excursion can make another droppable (two seals at one stripe end: once
    // the second is gone, the first's base becomes a plain right-angle turn whose mitre
    // sweeps its margin), so repeat until nothing changes.
    const int count = static_cast<int>(excursions.size());
    std::vector<char> pruned(count, 0);
    for (bool changed = true; changed;) {
        changed = false;
        for (int i = 0; i < count; ++i)
            if (!pruned[i] && prunable(excursions[i])) {
                setActive(excursions[i], 0);
                pruned[i] = changed = true;
            }
    }
    // A decision may have leant on an excursion dropped later: check each against the final
    // path and restore the ones it no longer justifies (restoring only adds swept area).
    for (bool changed = true; changed;) {
        changed = false;
        for (int i = 0; i < count; ++i)
            if (pruned[i] && !prunable(excursions[i])) {
                setActive(excursions[i], 1);
                pruned[i] = 0;
                changed = true;
            }
    }
    for (int i = 0; i < count; ++i)
        if (pruned[i])
            for (int k = excursions[i].begin + 1; k <= excursions[i].end; ++k)
                keep[k] = 0;
    return keep;
}

namespace {

// Estimated time of a polyline: length / speed + turns x turn time.
double timeOf(const Polyline& line, const RobotProfile& robot) {
    return (robot.speed > 0.0 ? polylineLength(line) / robot.speed : 0.0) +
           countTurns(line) * robot.turnTime;
}

} // namespace

void foldExcursionsIntoTransits(const Polyline& pts, const std::vector<PathExcursion>& excursions,
                                const ClearanceField& field, const RobotProfile& robot,
                                std::vector<char>& keep, std::vector<SegmentKind>& arriving) {
    const int n = static_cast<int>(pts.size());
    // Points another excursion starts or ends at stay: two seals can share a stripe end.
    std::vector<int> bases(n, 0);
    for (const PathExcursion& ex : excursions)
        ++bases[ex.begin], ++bases[ex.end];
    auto keptBefore = [&](int i) {
        for (--i; i >= 0 && !keep[i];)
            --i;
        return i;
    };
    auto keptAfter = [&](int i) {
        for (++i; i < n && !keep[i];)
            ++i;
        return i < n ? i : -1;
    };
    for (const PathExcursion& ex : excursions) {
        if (ex.end - ex.begin < 2 || distance(pts[ex.begin], pts[ex.end]) > 1e-9 ||
            bases[ex.begin] > 1 || bases[ex.end] > 1 || !keep[ex.begin])
            continue;
        bool whole = true;
        for (int k = ex.begin + 1; k <= ex.end; ++k)
            whole = whole && keep[k];
        if (!whole)
            continue; // pruned by prunableExcursions
        int tip = ex.begin;
        for (int k = ex.begin; k <= ex.end; ++k)
            if (distance(pts[k], pts[ex.begin]) > distance(pts[tip], pts[ex.begin]))
                tip = k;
        const int prev = keptBefore(ex.begin), next = keptAfter(ex.end);
        if (tip == ex.begin || prev < 0 || next < 0)
            continue;
        // The neighbourhood as it is and with each fold, one kept point wider on each side
        // so that the turns at prev and next count.
        const int outerPrev = std::max(keptBefore(prev), 0), outerNext = keptAfter(next);
        auto window = [&](int skipFrom, int skipTo) { // points skipFrom..skipTo left out
            Polyline line{pts[outerPrev]};
            for (int k = prev; k <= ex.end; ++k)
                if (k < skipFrom || k > skipTo)
                    line.push_back(pts[k]);
            line.push_back(pts[next]);
            if (outerNext >= 0)
                line.push_back(pts[outerNext]);
            return line;
        };
        const double now = timeOf(window(1, 0), robot);
        const bool entry =
            arriving[ex.begin] == SegmentKind::Transit && field.segmentIsClear(pts[prev], pts[tip]);
        const bool exit =
            arriving[next] == SegmentKind::Transit && field.segmentIsClear(pts[tip], pts[next]);
        const double entryTime = entry ? timeOf(window(ex.begin, tip - 1), robot) : INFINITY;
        const double exitTime = exit ? timeOf(window(tip + 1, ex.end), robot) : INFINITY;
        if (!(std::min(entryTime, exitTime) < now - 1e-9))
            continue;
        if (entryTime <= exitTime) {
            std::fill(keep.begin() + ex.begin, keep.begin() + tip, 0);
            arriving[tip] = SegmentKind::Transit;
        } else {
            std::fill(keep.begin() + tip + 1, keep.begin() + ex.end + 1, 0);
            arriving[next] = SegmentKind::Transit;
        }
    }
}

} // namespace fc::detail
