#include "decomposition/StripeLattice.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace fc::detail {
namespace {

// Cells narrower than this many W keep their own stripes: beside pillars and in wedges
// their stripes move to where the robot fits, which would leave gaps in a lattice.
constexpr double kLatticeMinWidth = 2.0;
// A side counts as open when walls take at most this share of W of its height.
constexpr double kOpenWallTolerance = 0.05;
// A cell at most this share of W wider than (n - 1) W may hand that excess to the cells
// across a side it shares whole with them, when their own spare room absorbs it.
constexpr double kHandOffShare = 0.15;
// Receivers at least this many W wide: a narrower cell's one stripe goes wherever the robot
// fits in it (StripePlanner), not where the giver's sliver is.
constexpr double kReceiverMinWidth = 1.0;
constexpr double kStripeCountTolerance = 1e-3; // in W, as the lattice's own tolerance

// Lattice lines origin + W/2 + kW inside the cell; at a side that is not open, a stripe
// W/2 inside it unless a lattice line is there already.
std::vector<double> latticePositions(double x0, double x1, double w, bool leftOpen, bool rightOpen,
                                     double origin) {
    const double eps = 1e-9 * w, tol = 1e-3 * w;
    const double lo = leftOpen ? x0 - eps : x0 + 0.5 * w - tol;
    const double hi = rightOpen ? x1 - eps : x1 - 0.5 * w + tol;
    const double first = origin + 0.5 * w;
    std::vector<double> xs;
    for (double k = std::ceil((lo - first) / w); first + k * w <= hi; k += 1)
        if (first + k * w >= lo)
            xs.push_back(first + k * w);
    if (!leftOpen && (xs.empty() || xs.front() > x0 + 0.5 * w + tol))
        xs.insert(xs.begin(), x0 + 0.5 * w);
    if (!rightOpen && (xs.empty() || xs.back() < x1 - 0.5 * w - tol))
        xs.push_back(x1 - 0.5 * w);
    if (xs.empty())
        xs.push_back(0.5 * (x0 + x1));
    return xs;
}

// A cell up to a millimetre (per metre of W) wider than n W takes n stripes: drawing tools'
// and reprojections' jitter of tens of micrometres made a room's cells take one more, each
// a cell of its own (a plan read from longitude/latitude 9% slower than the same in metres).
int evenCount(double width, double w) {
    return std::max(1, static_cast<int>(std::ceil(width / w - kStripeCountTolerance)));
}

// Noisy outlines make cells a few centimetres wider than n W (an obstacle traced 2.05 m
// tall beside 2 m of stripes), and spacing such a cell evenly costs a whole stripe more.
// Where the cell shares one side whole with the cells across it (no wall on it), their
// first stripe can move that excess towards it and sweep the sliver, if their own spare
// room (n W - width) allows: the giver drops a stripe, the receivers keep their count.
// Cells on the lattice, and cells that give, receive nothing (no chains).
void handOffExcess(const std::vector<LatticeCell>& cells, const std::vector<LatticeLink>& links,
                   double w, double maxHandOff, const std::vector<double>& leftShared,
                   const std::vector<double>& rightShared, StripeLayout& out) {
    const size_t n = cells.size();
    std::vector<double> needLeft(n, 0.0), needRight(n, 0.0); // what receivers cover beyond
    std::vector<char> gives(n, 0);
    auto width = [&](size_t i) { return cells[i].x1 - cells[i].x0; };
    auto absorbs = [&](size_t j, double left, double right) {
        return !out.onLattice[j] && !gives[j] && width(j) >= kReceiverMinWidth * w &&
               std::max(left, needLeft[j]) + std::max(right, needRight[j]) + width(j) <=
                   evenCount(width(j), w) * w + 1e-9 * w;
    };
    for (size_t i = 0; i < n; ++i) {
        const int count = evenCount(width(i), w);
        const double excess = width(i) - (count - 1) * w;
        if (out.onLattice[i] || count < 2 || needLeft[i] > 0 || needRight[i] > 0 ||
            excess > maxHandOff)
            continue;
        for (const bool right : {true, false}) {
            const double height = right ? cells[i].rightHeight : cells[i].leftHeight;
            const double shared = right ? rightShared[i] : leftShared[i];
            if (shared <= 0 || height - shared > kOpenWallTolerance * w)
                continue; // a wall on that side: nobody can sweep the sliver
            std::vector<size_t> across;
            bool fits = true;
            for (const LatticeLink& l : links) {
                if (right ? l.left == static_cast<int>(i) : l.right == static_cast<int>(i)) {
                    const auto j = static_cast<size_t>(right ? l.right : l.left);
                    fits = fits && cells[j].room == cells[i].room &&
                           absorbs(j, right ? excess : 0.0, right ? 0.0 : excess);
                    across.push_back(j);
                }
            }
            if (!fits || across.empty())
                continue;
            for (size_t j : across)
                (right ? needLeft[j] : needRight[j]) =
                    std::max(right ? needLeft[j] : needRight[j], excess);
            gives[i] = 1;
            out.stripes[i] = right ? evenStripePositions(cells[i].x0, cells[i].x1 - excess, w)
                                   : evenStripePositions(cells[i].x0 + excess, cells[i].x1, w);
            out.onLattice[i] = 1; // its stripes are placed, not spaced per piece
            break;
        }
    }
    for (size_t j = 0; j < n; ++j) {
        if (needLeft[j] <= 0 && needRight[j] <= 0)
            continue;
        out.stripes[j] =
            evenStripePositions(cells[j].x0 - needLeft[j], cells[j].x1 + needRight[j], w);
        out.onLattice[j] = 1;
        out.sweepsSliver[j] = 1;
    }
}

// Dense: a side gets a stripe W/2 inside it when the wall on it is longer than this share
// of the cell's height or than kDenseWallWidths W; shorter wall faces (a pillar's side, a
// ragged wall's step) are left to the wall touch-ups, a stroke along the face instead of
// a stripe the cell's whole height.
constexpr double kDenseWallShare = 0.5;
constexpr double kDenseWallWidths = 2.0;
// A lattice line this share of W past the inset position still sweeps the side.
constexpr double kDenseInsetTolerance = 0.05;
// A wall face longer than this many W (and than half its cell's height) gets a stripe W/2
// off it where the lattice line nearest it runs closer than the robot's radius (plus this
// share of W), blocked there, or further than W/2 (plus the inset tolerance).
constexpr double kDenseBlockedWallWidths = 1.0;
constexpr double kDenseBlockedMargin = 0.02;

// Adds x to the sorted stripes xs unless one lies within tol of it.
void addStripe(std::vector<double>& xs, double x, double tol) {
    if (std::none_of(xs.begin(), xs.end(), [&](double s) { return std::abs(s - x) <= tol; }))
        xs.insert(std::lower_bound(xs.begin(), xs.end(), x), x);
}

std::map<int, double> roomStarts(const std::vector<LatticeCell>& cells) {
    std::map<int, double> start; // each room's lattice starts W/2 inside its first wall
    for (const LatticeCell& c : cells) {
        auto [it, inserted] = start.emplace(c.room, c.x0);
        if (!inserted)
            it->second = std::min(it->second, c.x0);
    }
    return start;
}

// The dense layout with each room's lattice starting at `start` (plus W/2).
StripeLayout denseLayoutFrom(const std::vector<LatticeCell>& cells,
                             const std::vector<LatticeLink>& links, double w,
                             const std::map<int, double>& start, double robotRadius,
                             std::map<int, double>* gapLength = nullptr) {
    const size_t n = cells.size();
    std::vector<double> leftShared(n, 0.0), rightShared(n, 0.0); // with the same room
    for (const LatticeLink& l : links) {
        if (cells[l.left].room != cells[l.right].room)
            continue;
        rightShared[l.left] += l.length;
        leftShared[l.right] += l.length;
    }
    StripeLayout out;
    out.stripes.resize(n);
    out.onLattice.assign(n, 1);
    out.sweepsSliver.assign(n, 0);
    const double eps = 1e-9 * w, tol = kDenseInsetTolerance * w;
    // Lines nearer a face than this are blocked along it (never nearer than the inset: a
    // robot as wide as its head has nowhere else to drive).
    const double blocked = std::min(robotRadius + kDenseBlockedMargin * w, 0.5 * w - tol);
    std::vector<std::pair<size_t, double>> handed; // (cell, inset stripe) for the cells across
    for (size_t i = 0; i < n; ++i) {
        const LatticeCell& c = cells[i];
        const double height = std::max(c.leftHeight, c.rightHeight);
        auto longWall = [&](double sideHeight, double shared) {
            const double wall = sideHeight - shared;
            return wall > kDenseWallShare * height || wall > kDenseWallWidths * w;
        };
        // A stripe the cell's whole height beside a face is shorter than a touch-up there
        // and back where the face is at least half that height (and a metre or more).
        auto faceWorthAStripe = [&](double face) {
            return face > kDenseBlockedWallWidths * w && face > kDenseWallShare * height;
        };
        // A wall face on part of a side, which a lattice line closer than L/2 cannot pass:
        // the line runs on beside it (fitStripes moves only a line blocked all along), and
        // the strip along the face would be left to the touch-ups. (A line blocked along a
        // whole side moves to where the robot fits, and sweeps the wall from there.)
        auto blockingWall = [&](double sideHeight, double shared) {
            return shared > 0.0 && faceWorthAStripe(sideHeight - shared);
        };
        const double first = start.at(c.room) + 0.5 * w;
        // The lattice lines nearest each side, inside the cell or not.
        const double lineRightOfX0 = first + std::ceil((c.x0 - eps - first) / w) * w;
        const double lineLeftOfX1 = first + std::floor((c.x1 + eps - first) / w) * w;
        bool leftNeeds =
            (longWall(c.leftHeight, leftShared[i]) && lineRightOfX0 > c.x0 + 0.5 * w + tol) ||
            (blockingWall(c.leftHeight, leftShared[i]) && lineRightOfX0 < c.x0 + blocked);
        bool rightNeeds =
            (longWall(c.rightHeight, rightShared[i]) && lineLeftOfX1 < c.x1 - 0.5 * w - tol) ||
            (blockingWall(c.rightHeight, rightShared[i]) && lineLeftOfX1 > c.x1 - blocked);
        std::vector<double>& xs = out.stripes[i];
        // A sliver beside a wall face, too narrow for the robot: the stripe W/2 off the face
        // runs in the cells across its other side. Its own lattice lines stay for the rest
        // of its height.
        if (leftNeeds != rightNeeds && !c.keepsStripe && c.x1 - c.x0 < 2.0 * robotRadius) {
            handed.push_back({i, leftNeeds ? c.x0 + 0.5 * w : c.x1 - 0.5 * w});
            leftNeeds = rightNeeds = false;
        }
        if ((leftNeeds || rightNeeds || c.keepsStripe) && c.x1 - c.x0 <= w + eps) {
            xs = evenStripePositions(c.x0, c.x1, w);
            out.onLattice[i] = 0;
            // The lattice line it replaces swept a strip of the cells across a shared side
            // that the middle stripe does not: a gap left to the touch-ups, which the
            // lattice's phase should avoid.
            const double middle = xs.front();
            const bool lineInside = lineRightOfX0 <= c.x1 + eps;
            if (gapLength && lineInside &&
                ((rightShared[i] > 0 && lineRightOfX0 - middle > tol) ||
                 (leftShared[i] > 0 && middle - lineRightOfX0 > tol)))
                (*gapLength)[c.room] += height;
            continue;
        }
        if (leftNeeds)
            xs.push_back(c.x0 + 0.5 * w);
        for (double x = lineRightOfX0; x <= lineLeftOfX1 + eps; x += w)
            if (x >= c.x0 - eps && x <= c.x1 + eps)
                xs.push_back(std::clamp(x, c.x0, c.x1));
        if (rightNeeds)
            xs.push_back(c.x1 - 0.5 * w);
        if (xs.empty() && c.keepsStripe)
            xs = evenStripePositions(c.x0, c.x1, w);
        // Wall faces inside the cell (a bed's side, where the cell runs on beside it) get the
        // same stripe W/2 off them, in this cell where it fits, else across its side.
        for (const LatticeStep& step : c.steps) {
            if (!faceWorthAStripe(step.length))
                continue;
            const double dir = step.facesRight ? 1.0 : -1.0;
            const double line = first + (step.facesRight ? std::ceil((step.x - eps - first) / w)
                                                         : std::floor((step.x + eps - first) / w)) *
                                            w;
            const double off = dir * (line - step.x);
            if (off >= blocked && off <= 0.5 * w + tol)
                continue;
            const double x = step.x + dir * 0.5 * w;
            if (x < c.x0 || x > c.x1)
                handed.push_back({i, x});
            else
                addStripe(xs, x, tol);
        }
    }
    // Each handed stripe goes to the cells of the room across the sliver's open side that
    // hold its position, through further slivers where it lies beyond them.
    std::vector<std::vector<size_t>> across(2 * n); // 2i: links on i's left, 2i + 1: right
    if (!handed.empty())
        for (size_t k = 0; k < links.size(); ++k) {
            across[2 * static_cast<size_t>(links[k].left) + 1].push_back(k);
            across[2 * static_cast<size_t>(links[k].right)].push_back(k);
        }
    std::vector<size_t> seenBy(n, handed.size()); // the handed stripe that reached a cell
    for (size_t h = 0; h < handed.size(); ++h) {
        const size_t giver = handed[h].first;
        const double x = handed[h].second;
        std::vector<size_t> todo{giver};
        seenBy[giver] = h;
        while (!todo.empty()) {
            const size_t i = todo.back();
            todo.pop_back();
            const bool rightwards = x > cells[i].x1;
            for (const size_t k : across[2 * i + (rightwards ? 1 : 0)]) {
                const LatticeLink& l = links[k];
                const auto j = static_cast<size_t>(rightwards ? l.right : l.left);
                if (seenBy[j] == h || cells[j].room != cells[giver].room)
                    continue;
                seenBy[j] = h;
                if (x < cells[j].x0 - eps || x > cells[j].x1 + eps) {
                    todo.push_back(j);
                    continue;
                }
                addStripe(out.stripes[j], x, tol);
            }
        }
    }
    // A cell without stripes relies on the lattice lines beyond its sides; where a
    // neighbour's stripe is off the lattice (a narrow cell's one stripe, in its middle), it
    // sweeps its own middle too, and so on across cells without stripes.
    for (bool changed = true; changed;) {
        changed = false;
        for (const LatticeLink& l : links) {
            for (const auto& [a, b] : {std::pair{l.left, l.right}, std::pair{l.right, l.left}}) {
                if (out.stripes[a].empty() && !out.onLattice[b] && cells[a].room == cells[b].room) {
                    out.stripes[a] = evenStripePositions(cells[a].x0, cells[a].x1, w);
                    out.onLattice[a] = 0;
                    changed = true;
                }
            }
        }
    }
    return out;
}

// Phases of a room's lattice tried by the dense layout (fractions of W).
constexpr int kDensePhases = 10;

// Each room's lattice phase is the one of kDensePhases with the least estimated stripe
// length (stripes times the cell's height): a traced room's first wall is often a blob the
// laser barely saw, and a lattice W/2 inside it may miss every long wall by a little, each
// then getting a stripe of its own.
StripeLayout denseLayout(const std::vector<LatticeCell>& cells,
                         const std::vector<LatticeLink>& links, double w, double robotRadius) {
    const std::map<int, double> first = roomStarts(cells);
    std::map<int, std::pair<double, double>> best; // room -> (length, phase)
    for (int k = 0; k < kDensePhases; ++k) {
        std::map<int, double> start = first;
        for (auto& [room, x] : start)
            x += w * k / kDensePhases;
        std::map<int, double> length; // with a stripe's length per gap
        const StripeLayout layout = denseLayoutFrom(cells, links, w, start, robotRadius, &length);
        for (size_t i = 0; i < cells.size(); ++i)
            length[cells[i].room] +=
                layout.stripes[i].size() * 0.5 * (cells[i].leftHeight + cells[i].rightHeight);
        for (const auto& [room, sum] : length) {
            auto it = best.find(room);
            if (it == best.end() || sum < it->second.first - 1e-9 * w)
                best[room] = {sum, w * k / kDensePhases};
        }
    }
    std::map<int, double> start = first;
    for (auto& [room, x] : start)
        x += best[room].second;
    return denseLayoutFrom(cells, links, w, start, robotRadius);
}

} // namespace

double maxHandOff(double w, double robotDiameter) {
    return std::max(0.0, std::min(kHandOffShare * w, 0.5 * (w - robotDiameter) - 0.01 * w));
}

std::vector<double> evenStripePositions(double x0, double x1, double w) {
    const double width = x1 - x0;
    const int n = evenCount(width, w);
    if (n == 1)
        return {0.5 * (x0 + x1)};
    std::vector<double> xs(n);
    for (int i = 0; i < n; ++i)
        xs[i] = x0 + 0.5 * w + i * (width - w) / (n - 1);
    return xs;
}

StripeLayout layOutStripes(const std::vector<LatticeCell>& cells,
                           const std::vector<LatticeLink>& links, double w, LatticeMode mode,
                           double handOff, double robotDiameter) {
    if (mode == LatticeMode::Dense)
        return denseLayout(cells, links, w, 0.5 * robotDiameter);
    const bool lattice = mode == LatticeMode::AtCorners;
    const size_t n = cells.size();
    // A side is open where neighbours share (almost) all of it, within one room, both
    // cells wide, and the neighbour's facing side is open too.
    std::vector<double> leftShared(n, 0.0), rightShared(n, 0.0);
    std::vector<char> leftLinked(n, 0), rightLinked(n, 0);
    for (const LatticeLink& l : links) {
        rightShared[l.left] += l.length, rightLinked[l.left] = 1;
        leftShared[l.right] += l.length, leftLinked[l.right] = 1;
    }
    std::vector<char> leftOpen(n, 0), rightOpen(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const bool wide = lattice && cells[i].x1 - cells[i].x0 >= kLatticeMinWidth * w;
        leftOpen[i] =
            wide && leftLinked[i] && cells[i].leftHeight - leftShared[i] <= kOpenWallTolerance * w;
        rightOpen[i] = wide && rightLinked[i] &&
                       cells[i].rightHeight - rightShared[i] <= kOpenWallTolerance * w;
    }
    // A side stays open only where every cell across it keeps its facing side open, until
    // nothing changes: a side closed by one neighbour (a traced tooth's sliver cell beside
    // it) closes the facing sides of its other neighbours too. Otherwise a cell would run
    // the lattice up to a neighbour that spaces its stripes evenly, and the two would leave
    // a sliver between them unswept (a noisy map: 9 cm along 4.6 m).
    for (bool changed = true; changed;) {
        changed = false;
        for (const LatticeLink& l : links) {
            if ((rightOpen[l.left] || leftOpen[l.right]) &&
                !(rightOpen[l.left] && leftOpen[l.right] &&
                  cells[l.left].room == cells[l.right].room)) {
                rightOpen[l.left] = 0, leftOpen[l.right] = 0;
                changed = true;
            }
        }
    }

    std::map<int, double> roomStart = roomStarts(cells);
    // Cells joined through open sides share the lattice; a group takes it only where it
    // saves stripes over spacing each cell evenly.
    std::vector<int> parent(n);
    for (size_t i = 0; i < n; ++i)
        parent[i] = static_cast<int>(i);
    std::function<int(int)> find = [&](int i) {
        return parent[i] == i ? i : parent[i] = find(parent[i]);
    };
    for (const LatticeLink& l : links)
        if (rightOpen[l.left] && leftOpen[l.right])
            parent[find(l.left)] = find(l.right);
    StripeLayout out;
    out.stripes.resize(n);
    out.onLattice.assign(n, 0);
    out.sweepsSliver.assign(n, 0);
    std::vector<std::vector<double>> even(n);
    std::map<int, std::pair<size_t, size_t>> counts; // group -> lattice, even stripes
    for (size_t i = 0; i < n; ++i) {
        const LatticeCell& c = cells[i];
        even[i] = evenStripePositions(c.x0, c.x1, w);
        if (leftOpen[i] || rightOpen[i])
            out.stripes[i] =
                latticePositions(c.x0, c.x1, w, leftOpen[i], rightOpen[i], roomStart[c.room]);
        else
            out.stripes[i] = even[i];
        auto& [latticeCount, evenCount] = counts[find(static_cast<int>(i))];
        latticeCount += out.stripes[i].size();
        evenCount += even[i].size();
    }
    for (size_t i = 0; i < n; ++i) {
        const auto& [latticeCount, evenCount] = counts[find(static_cast<int>(i))];
        if (latticeCount < evenCount && (leftOpen[i] || rightOpen[i]))
            out.onLattice[i] = 1;
        else
            out.stripes[i] = std::move(even[i]);
    }
    if (handOff > 0)
        handOffExcess(cells, links, w, handOff, leftShared, rightShared, out);
    return out;
}

} // namespace fc::detail
