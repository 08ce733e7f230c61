#include "geometry/Clearance.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>

namespace fc {
namespace {

constexpr std::size_t kMaxRememberedSearches = 200'000; // tens of MB at most
// Wall-corner points in a search window above which the grid's route is tried first: most
// of a cleaned map's windows hold a few hundred (faculty map: 93% under 1,000; its path
// 0.3 m longer of 1,747 with the grid in the others), an uncleaned one's thousands.
constexpr std::size_t kCrowdedWindow = 1'000;
constexpr std::size_t kCrowdedWindowChecks = 50'000; // per crowded window but the last
// Gaps across a wall corner up to this many radii wide get a waypoint in their middle; the
// corner points keep 1.01 r from walls at 1.02 r from their corner, so none fits below ~2.03 r.
constexpr double kGapMiddleMaxWidth = 2.05;
// Gaps up to this many radii wide are portals of the open regions' grid: its surely clear
// nodes keep r + h sqrt(2)/2 (h = r/6) from walls, so a gap narrower than about 2.47 r may
// hold none of them; the grid's route then went through the portal's middle where it
// otherwise failed, and a visibility search among thousands of corners ran for minutes.
constexpr double kPortalMaxWidth = 2.6;
// Walls within this cosine of the corner's free-side bisector (78 degrees) count as across.
constexpr double kGapMiddleCosine = 0.2;

// The y-interval where the vertical line x meets the capsule of radius r around ab.
bool capsuleSpan(Vec2 a, Vec2 b, double x, double r, double& lo, double& hi) {
    lo = INFINITY, hi = -INFINITY;
    auto disk = [&](Vec2 c) {
        const double dx = x - c.x;
        if (std::abs(dx) >= r)
            return;
        const double h = std::sqrt(r * r - dx * dx);
        lo = std::min(lo, c.y - h);
        hi = std::max(hi, c.y + h);
    };
    disk(a);
    disk(b);
    // The band: points projecting inside ab within distance r. Both conditions are linear
    // in y, so the band meets the line in an interval.
    const Vec2 d = b - a;
    const double len = norm(d);
    if (len > 0) {
        const Vec2 u = d * (1.0 / len);
        // p = (x, y): t(y) = (p - a).u = (x - a.x) u.x + (y - a.y) u.y, in [0, len]
        //             s(y) = cross(u, p - a) = u.x (y - a.y) - u.y (x - a.x), |s| < r
        double ylo = -INFINITY, yhi = INFINITY;
        auto clampLinear = [&](double coef, double constant, double low, double high) {
            // low <= coef * y + constant <= high
            if (std::abs(coef) < 1e-15) {
                if (constant < low || constant > high)
                    ylo = INFINITY, yhi = -INFINITY;
                return;
            }
            double y1 = (low - constant) / coef, y2 = (high - constant) / coef;
            if (y1 > y2)
                std::swap(y1, y2);
            ylo = std::max(ylo, y1);
            yhi = std::min(yhi, y2);
        };
        clampLinear(u.y, (x - a.x) * u.x - a.y * u.y, 0.0, len);
        clampLinear(u.x, -a.y * u.x - u.y * (x - a.x), -r, r);
        if (ylo < yhi) {
            lo = std::min(lo, ylo);
            hi = std::max(hi, yhi);
        }
    }
    return lo < hi;
}

} // namespace

ClearanceField::ClearanceField(const std::vector<Ring>& rings, double radius, double inset)
    : walls_(rings), radius_(radius), inset_(std::max(radius, inset)),
      tolerance_(1e-7 * std::max(1.0, radius)), acceptance_(1.5e-3 * radius), rings_(rings) {
    for (const Ring& ring : rings)
        for (const Vec2& p : ring)
            extent_.add(p);
}

const std::vector<Vec2>& ClearanceField::cornerPoints() const {
    std::call_once(cornersBuilt_, [this] { buildCornerPoints(); });
    return cornerPoints_;
}

void ClearanceField::buildCornerPoints() const {
    const std::vector<Ring>& rings = rings_;
    // Reflex corners of the free space: the interior angle seen from free space exceeds
    // 180 degrees. Orientation-free test: probe a point just off the corner along the
    // outward bisector and keep it if it is clear.
    for (const Ring& ring : rings) {
        const size_t n = ring.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 prev = ring[(i + n - 1) % n], p = ring[i], next = ring[(i + 1) % n];
            const Vec2 e1 = p - prev, e2 = next - p;
            const double l1 = norm(e1), l2 = norm(e2);
            if (l1 == 0 || l2 == 0)
                continue;
            const Vec2 u1 = e1 * (1 / l1), u2 = e2 * (1 / l2);
            Vec2 bis = u1 - u2; // points away from the corner's inside wedge
            double bl = norm(bis);
            if (bl < 1e-12)
                continue; // straight continuation
            bis = bis * (1 / bl);
            const double sinHalf = std::sqrt(std::max(0.0, 0.5 * (1 - dot(u1 * -1, u2))));
            const double offset = radius_ * 1.02 / std::max(sinHalf, 0.2);
            for (int side = -1; side <= 1; side += 2) {
                const Vec2 q = p + bis * (side * offset);
                if (walls_.pointKeepsDistance(q, radius_ * 1.01)) // strictly clear
                    cornerPoints_.push_back(q);
            }
            // Points on the clearance arc around the corner, so that paths can hug it where
            // the bisector point is blocked by another wall nearby (a bed near a wall).
            const double angle0 = std::atan2(bis.y, bis.x);
            for (int k = -3; k <= 3; ++k) {
                if (k == 0)
                    continue;
                const double a = angle0 + k * M_PI / 6;
                const Vec2 q = p + Vec2{std::cos(a), std::sin(a)} * (radius_ * 1.02);
                if (walls_.pointKeepsDistance(q, radius_ * 1.01))
                    cornerPoints_.push_back(q);
            }
            addGapMiddle(p, bis);
        }
    }
    bucketCornerPoints();
}

// A gap across from corner p barely wider than the robot (a traced doorway of 2r to 2.05r):
// the points above keep 1.01 r from every wall and none fits in it, nor a node of the open
// regions' grid, so no search found a way through that the robot may drive. Its middle is
// a waypoint of its own, kept where it is clear. Gaps up to kPortalMaxWidth r are also kept
// as portals, the open regions' grid's ways through gaps too tight for its nodes.
void ClearanceField::addGapMiddle(Vec2 p, Vec2 away) const {
    const double reach = kPortalMaxWidth * radius_;
    BoundingBox box;
    box.add({p.x - reach, p.y - reach});
    box.add({p.x + reach, p.y + reach});
    std::vector<int> hits;
    walls_.query(box, hits);
    double nearest = INFINITY;
    Vec2 across{};
    for (int id : hits) {
        const Segment& s = walls_.segments()[static_cast<size_t>(id)];
        if (s.a == p || s.b == p)
            continue;
        const Vec2 d = s.b - s.a;
        const double l2 = dot(d, d);
        const double t = l2 > 0 ? std::clamp(dot(p - s.a, d) / l2, 0.0, 1.0) : 0.0;
        const Vec2 w = s.a + d * t;
        const double gap = distance(p, w);
        // Only walls across the free side: the corner's own ragged wall lies behind it.
        if (gap < nearest && dot(w - p, away) > kGapMiddleCosine * gap) {
            nearest = gap;
            across = w;
        }
    }
    if (nearest < 2 * (radius_ - acceptance_) || nearest > reach)
        return;
    const Vec2 middle = (p + across) * 0.5;
    if (!walls_.pointKeepsDistance(middle, radius_ - 0.5 * acceptance_))
        return;
    const Vec2 across1 = (across - p) * (1 / nearest);
    const Vec2 along{-across1.y, across1.x};
    portals_.push_back({middle, along});
    if (nearest > kGapMiddleMaxWidth * radius_)
        return;
    cornerPoints_.push_back(middle);
    // And on the way in and out, along the gap: a gap in a channel (traced walls a robot
    // width apart for a metre) is seen from neither end's corners.
    for (double step : {-2.0, -1.0, 1.0, 2.0}) {
        const Vec2 q = middle + along * (step * radius_);
        if (walls_.pointKeepsDistance(q, radius_ - 0.5 * acceptance_))
            cornerPoints_.push_back(q);
    }
}

std::vector<Interval> ClearanceField::clearPieces(double x, double yLow, double yHigh,
                                                  double margin) const {
    std::vector<Interval> forbidden;
    BoundingBox box;
    const double r = radius_ + margin - tolerance_;
    box.add({x - r, yLow - r});
    box.add({x + r, yHigh + r});
    std::vector<int> hits;
    walls_.query(box, hits);
    for (int id : hits) {
        const Segment& s = walls_.segments()[id];
        double lo, hi;
        if (capsuleSpan(s.a, s.b, x, r, lo, hi))
            forbidden.push_back({lo, hi});
    }
    std::sort(forbidden.begin(), forbidden.end(),
              [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    std::vector<Interval> pieces;
    double cursor = yLow;
    for (const Interval& f : forbidden) {
        if (f.lo > cursor && f.lo > yLow)
            pieces.push_back({cursor, std::min(f.lo, yHigh)});
        cursor = std::max(cursor, f.hi);
        if (cursor > yHigh)
            break;
    }
    // A gap exactly as wide as the robot leaves a clear piece of zero length: keep it.
    if (cursor <= yHigh)
        pieces.push_back({cursor, yHigh});
    pieces.erase(
        std::remove_if(pieces.begin(), pieces.end(), [](const Interval& i) { return i.hi < i.lo; }),
        pieces.end());
    return pieces;
}

bool ClearanceField::isClear(Vec2 p) const {
    return walls_.pointKeepsDistance(p, radius_ - acceptance_);
}

bool ClearanceField::segmentIsClear(Vec2 a, Vec2 b) const {
    return walls_.segmentKeepsDistance(a, b, radius_ - acceptance_);
}

bool ClearanceField::polylineIsClear(const Polyline& line) const {
    for (size_t i = 1; i < line.size(); ++i)
        if (!segmentIsClear(line[i - 1], line[i]))
            return false;
    return line.size() != 1 || isClear(line[0]);
}

bool ClearanceField::SearchKey::operator==(const SearchKey& o) const {
    return ax == o.ax && ay == o.ay && bx == o.bx && by == o.by && maxMargin == o.maxMargin &&
           maxChecks == o.maxChecks && hints == o.hints;
}

std::size_t ClearanceField::SearchKeyHash::operator()(const SearchKey& k) const {
    std::size_t h = k.maxChecks * 0x9e3779b97f4a7c15ull ^ k.hints;
    for (const double v : {k.ax, k.ay, k.bx, k.by, k.maxMargin})
        h = (h ^ std::hash<double>()(v)) * 0x100000001b3ull;
    return h;
}

Polyline ClearanceField::findPath(Vec2 a, Vec2 b, const std::vector<Vec2>& hints, double maxMargin,
                                  std::size_t maxChecks) const {
    if (segmentIsClear(a, b))
        return {a, b};
    std::size_t hintsHash = hints.size();
    for (const Vec2& h : hints)
        hintsHash = (hintsHash ^ std::hash<double>()(h.x) ^ (std::hash<double>()(h.y) << 1)) *
                    0x100000001b3ull;
    const SearchKey key{a.x, a.y, b.x, b.y, maxMargin, maxChecks, hintsHash};
    {
        std::lock_guard<std::mutex> lock(searchesMutex_);
        const auto it = searches_.find(key);
        if (it != searches_.end())
            return it->second;
    }
    Polyline path = searchPath(a, b, hints, maxMargin, maxChecks);
    std::lock_guard<std::mutex> lock(searchesMutex_);
    if (searches_.size() < kMaxRememberedSearches)
        searches_.emplace(key, path);
    return path;
}

Polyline ClearanceField::searchPath(Vec2 a, Vec2 b, const std::vector<Vec2>& hints,
                                    double maxMargin, std::size_t maxChecks) const {
    std::size_t checksLeft = maxChecks > 0 ? maxChecks : std::numeric_limits<std::size_t>::max();
    // Provably apart: no search (a failed one tests every pair of corners in its window;
    // wall touch-ups aimed into pockets made thousands of them on a traced map). The grid
    // costs more than most searches (0.6 s on a 100-room office whose every search
    // succeeds), so it is built at the first search that fails and asked from then on.
    auto provablyApart = [&] {
        const int ra = openRegionOf(a), rb = openRegionOf(b);
        return ra >= 0 && rb >= 0 && ra != rb;
    };
    if (regionsReady_.load(std::memory_order_acquire) && provablyApart())
        return {};
    double margin = std::min(std::max(4 * radius_, 0.5 * distance(a, b)), maxMargin);
    for (int round = 0; round < 8; ++round) {
        BoundingBox window;
        window.add(a);
        window.add(b);
        window.minX -= margin, window.minY -= margin;
        window.maxX += margin, window.maxY += margin;
        const bool coversAll = window.minX <= extent_.minX && window.minY <= extent_.minY &&
                               window.maxX >= extent_.maxX && window.maxY >= extent_.maxY;
        const bool lastWindow = coversAll || margin >= maxMargin || round == 7;
        // Among thousands of wall corners (an uncleaned map's speckle) the visibility search
        // is slow and often spends its whole budget; the grid's route is found in a fraction
        // of the time and is about 1% longer. There the grid is asked first, and the
        // visibility search then looks for a way through a gap too tight for the grid.
        // Elsewhere the grid's route stands in only when the search gave up (a search that
        // fails on budget is not proof that no path exists).
        const bool crowded = cornersIn(window) > kCrowdedWindow;
        if (crowded)
            openRegionOf(a);
        // A window the grid proves holds no path is not searched (once the grid exists).
        const bool mayHoldPath =
            !regionsReady_.load(std::memory_order_acquire) || regions_->mayJoinWithin(a, b, window);
        if (mayHoldPath) {
            Polyline path = crowded ? gridRoute(a, b, window) : Polyline{};
            if (path.empty() && (!crowded || lastWindow)) {
                path = searchWindow(a, b, window, hints, checksLeft);
            } else if (path.empty()) {
                // A crowded window that may hold a path only through a tight gap: a bounded
                // look, then the larger windows (an unbounded search here ran for minutes).
                std::size_t look = std::min(checksLeft, kCrowdedWindowChecks);
                const std::size_t before = look;
                path = searchWindow(a, b, window, hints, look);
                checksLeft -= before - look;
            }
            if (!path.empty())
                return path;
            if (checksLeft == 0 && !crowded) {
                openRegionOf(a);
                return gridRoute(a, b, window);
            }
        }
        if (checksLeft == 0 || (round == 0 && provablyApart()) || lastWindow)
            return {};
        margin = std::min(3 * margin, maxMargin);
    }
    return {};
}

Polyline ClearanceField::gridRoute(Vec2 a, Vec2 b, const BoundingBox& window) const {
    return regions_->clearRoute(a, b, window,
                                [this](Vec2 p, Vec2 q) { return segmentIsClear(p, q); });
}

int ClearanceField::openRegionOf(Vec2 p) const {
    std::call_once(regionsBuilt_, [this] {
        regions_ = std::make_unique<OpenRegions>(walls_, extent_, radius_ - acceptance_);
        cornerPoints(); // the portals come with them
        regions_->addPortals(portals_, [this](Vec2 a, Vec2 b) { return segmentIsClear(a, b); });
        regionsReady_.store(true, std::memory_order_release);
    });
    return regions_->regionOf(p);
}

} // namespace fc
