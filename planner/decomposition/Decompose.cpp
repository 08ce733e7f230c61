#include "decomposition/ClearRanges.h"
#include "decomposition/Decomposition.h"
#include "decomposition/FloorCache.h"
#include "decomposition/FunctionClip.h"
#include "decomposition/SlabSweep.h"
#include "decomposition/Snapping.h"
#include "decomposition/StripeLattice.h"
#include "decomposition/StripePlanner.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace fc {
namespace {

// Edges leaning by at most this share of W across the sweep are made exactly vertical.
constexpr double kStraightenTolerance = 0.002;
// Coordinates closer than this share of W are one (mergeCloseCoordinates): the jitter of drawing
// tools and reprojections (tens of micrometres: a plan read from longitude/latitude) made
// walls lean at the sweep angle and cut slivers, 12 cells for 8 and a plan 9% slower.
constexpr double kSnapTolerance = 2e-4;
// Floors of at most this many raw cells may hand slivers across (see layOutStripes' use).
constexpr std::size_t kHandOffMaxCells = 60;
// The share of the stripes' length the dense lattice must save to be offered.
constexpr double kDenseMinSaving = 0.1;
// Headland bands follow walls at most this steep across the sweep (tan 10 degrees): along a
// steeper wall the band's single pass would run closer than L/2 to it.
constexpr double kHeadlandMaxSlope = 0.176;

using detail::SlabSweep;
using detail::Trapezoid;

// Area times centroid of a ring, whatever its orientation (its first moment of area).
Vec2 centroidMoment(const Ring& ring) {
    Vec2 sum;
    double twiceArea = 0.0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        const double c = cross(a, b);
        twiceArea += c;
        sum = sum + (a + b) * c;
    }
    // sum / 6 is area * centroid with the ring's signed area; make it the absolute one.
    return sum * ((twiceArea < 0 ? -1.0 : 1.0) / 6.0);
}

void orient(Ring& ring, bool counterClockwise) {
    if ((signedArea(ring) > 0) != counterClockwise)
        std::reverse(ring.begin(), ring.end());
}

struct RawCell {
    int room = 0;
    double x0 = 0, x1 = 0;
    Polyline floor, ceiling;
};

// The wall faces across the sweep inside a raw cell: steps of its floor and ceiling. A
// ceiling that rises, or a floor that falls, has the free space on the step's +x side.
std::vector<detail::LatticeStep> wallSteps(const RawCell& c) {
    std::vector<detail::LatticeStep> steps;
    for (const bool top : {false, true}) {
        const Polyline& f = top ? c.ceiling : c.floor;
        for (size_t k = 0; k + 1 < f.size(); ++k) {
            const double rise = f[k + 1].y - f[k].y;
            if (f[k].x == f[k + 1].x && rise != 0.0)
                steps.push_back({f[k].x, std::abs(rise), (rise > 0) == top});
        }
    }
    return steps;
}

// One raw cell's share of the final cells: consecutive x-pieces.
struct Piece {
    int cell = -1; // final cell id
    double x0 = 0, x1 = 0;
    int layer = 0, layers = 1; // stacked sub-cells where the clear region splits in y
};

struct RawAdjacency {
    Adjacency::Kind kind;
    int first, second;
    double x0, x1; // along: shared x-range; across: x0 == x1 == x
    double y0, y1; // across: shared y-range; along: border y at x0 and x1
};

std::vector<RawAdjacency> rawAdjacencies(const SlabSweep& sweep, const std::vector<int>& cellOf) {
    std::vector<RawAdjacency> out;
    for (const detail::TrapezoidLink& l : sweep.links) {
        const int a = cellOf[l.left], b = cellOf[l.right];
        if (a != b)
            out.push_back({Adjacency::Kind::AcrossSweep, a, b, l.x, l.x, l.y0, l.y1});
    }
    // Along-sweep borders: merge contiguous pieces between the same pair of cells.
    std::map<std::pair<int, int>, std::vector<RawAdjacency>> along;
    for (const detail::TrapezoidStack& s : sweep.stacks) {
        const int a = cellOf[s.lower], b = cellOf[s.upper];
        if (a == b)
            continue;
        const Trapezoid& t = sweep.trapezoids[s.lower];
        auto& list = along[{a, b}];
        if (!list.empty() && list.back().x1 == t.xa) {
            list.back().x1 = t.xb;
            list.back().y1 = t.cb;
        } else {
            list.push_back({Adjacency::Kind::AlongSweep, a, b, t.xa, t.xb, t.ca, t.cb});
        }
    }
    for (auto& [key, list] : along)
        out.insert(out.end(), list.begin(), list.end());
    return out;
}

std::vector<double> stripePositions(double x0, double x1, double w) {
    return detail::evenStripePositions(x0, x1, w);
}

// The x-pieces one raw cell becomes (SPEC sect. 2.3, our rule for narrow cells). The
// cell's stripes are placed once, evenly, the first and last W/2 inside its ends; at each
// critical side the outermost stripe becomes a transition cell (a strip of width
// W/2 + spacing/2 <= W, exactly W when the stripes are W apart) and the primary keeps the
// stripes between. A cell with no more stripes than critical sides becomes transition
// cells only: one per stripe.
struct PieceSpec {
    double x0, x1;
    CellKind kind;
    std::vector<double> stripes;
};

std::vector<PieceSpec> pieceSpecs(double x0, double x1, bool left, bool right,
                                  const std::vector<double>& stripes) {
    const size_t m = stripes.size();
    const size_t k = size_t(left) + size_t(right);
    if (k == 0)
        return {{x0, x1, CellKind::Primary, stripes}};
    if (m >= k + 1) {
        std::vector<PieceSpec> out;
        double a = x0, b = x1;
        if (left) {
            a = 0.5 * (stripes[0] + stripes[1]);
            out.push_back({x0, a, CellKind::Transition, {stripes[0]}});
        }
        if (right)
            b = 0.5 * (stripes[m - 2] + stripes[m - 1]);
        out.push_back({a, b, CellKind::Primary,
                       std::vector<double>(stripes.begin() + (left ? 1 : 0),
                                           stripes.end() - (right ? 1 : 0))});
        if (right)
            out.push_back({b, x1, CellKind::Transition, {stripes[m - 1]}});
        return out;
    }
    if (m == 2) {
        const double mid = 0.5 * (stripes[0] + stripes[1]);
        return {{x0, mid, CellKind::Transition, {stripes[0]}},
                {mid, x1, CellKind::Transition, {stripes[1]}}};
    }
    return {{x0, x1, CellKind::Transition, stripes}};
}

// The pieces of a raw cell on either side of x whose slice overlaps [y0, y1].
std::vector<const Piece*> piecesAt(const std::vector<Piece>& pieces, const std::vector<Cell>& cells,
                                   double x, bool leftOfX, double y0, double y1) {
    std::vector<const Piece*> out;
    for (const Piece& p : pieces) {
        const bool inside = leftOfX ? (p.x0 < x && x <= p.x1) : (p.x0 <= x && x < p.x1);
        if (!inside)
            continue;
        const Cell& c = cells[p.cell];
        if (std::min(c.ceilingAt(x), y1) - std::max(c.floorAt(x), y0) > 0)
            out.push_back(&p);
    }
    return out;
}

Cell makeCell(int id, CellKind kind, int room, double x0, double x1, Polyline floor,
              Polyline ceiling, std::vector<double> stripes) {
    Cell c;
    c.id = id;
    c.kind = kind;
    c.room = room;
    c.x0 = x0, c.x1 = x1;
    c.floor = std::move(floor);
    c.ceiling = std::move(ceiling);
    c.stripes = std::move(stripes);
    return c;
}

// Cells swept by their neighbours' stripes are not visited: the cells on their left are
// joined to the first cells with stripes on their right, through the border where they
// leave (the graph connects the corners of that side to all of the far cell's corners).
void joinAcrossSweptCells(Decomposition& out) {
    const size_t n = out.cells.size();
    std::vector<std::vector<size_t>> rightOf(n);
    for (size_t k = 0; k < out.adjacencies.size(); ++k)
        if (out.adjacencies[k].kind == Adjacency::Kind::AcrossSweep)
            rightOf[out.adjacencies[k].first].push_back(k);
    std::vector<Adjacency> added;
    for (size_t p = 0; p < n; ++p) {
        if (out.cells[p].sweptByNeighbours)
            continue;
        for (size_t k : rightOf[p]) {
            const Adjacency leaving = out.adjacencies[k];
            if (!out.cells[leaving.second].sweptByNeighbours)
                continue;
            std::vector<int> todo{leaving.second};
            std::vector<char> seen(n, 0), joined(n, 0);
            seen[leaving.second] = 1;
            while (!todo.empty()) {
                const int z = todo.back();
                todo.pop_back();
                for (size_t m : rightOf[z]) {
                    const int q = out.adjacencies[m].second;
                    if (out.cells[q].sweptByNeighbours) {
                        if (!seen[q])
                            seen[q] = 1, todo.push_back(q);
                    } else if (!joined[q]) {
                        joined[q] = 1;
                        added.push_back(
                            {Adjacency::Kind::AcrossSweep, static_cast<int>(p), q, leaving.shared});
                    }
                }
            }
        }
    }
    out.adjacencies.insert(out.adjacencies.end(), added.begin(), added.end());
}

// A band piece lower than W (beside a traced wall's tooth, splitHeadlands) has its single
// pass run down its middle, off its neighbours' line by half the tooth: the band's pass then
// zigzags, and the seals at its stripe ends, which the next piece's pass no longer sweeps,
// stay as half turns. Its pass keeps W/2 from the band's inner edge (the border to the
// stripes it heads), as its neighbours' do, where the robot fits there.
void keepBandPassesInLine(Decomposition& out) {
    const ClearanceField& field = out.clearance();
    const double half = out.coverageWidth() / 2;
    std::vector<int> innerFloor(out.cells.size(), 0), innerCeiling(out.cells.size(), 0);
    for (const Adjacency& a : out.adjacencies)
        if (a.kind == Adjacency::Kind::AlongSweep) {
            innerCeiling[a.first] |= out.cells[a.first].headland && !out.cells[a.second].headland;
            innerFloor[a.second] |= out.cells[a.second].headland && !out.cells[a.first].headland;
        }
    for (Cell& cell : out.cells) {
        if (!cell.headland || innerFloor[cell.id] == innerCeiling[cell.id])
            continue;
        for (size_t i = 0; i < cell.stripes.size() && i < cell.stripeSpans.size(); ++i) {
            Interval& span = cell.stripeSpans[i];
            const double x = cell.stripes[i];
            if (span.empty() || span.hi - span.lo > 1e-9)
                continue; // a pass of its own length: the piece is W or more tall
            const double y =
                innerFloor[cell.id] ? cell.floorAt(x) + half : cell.ceilingAt(x) - half;
            if (y > cell.floorAt(x) && y < cell.ceilingAt(x) && field.isClear({x, y}))
                span.lo = span.hi = y;
        }
    }
}

} // namespace

Decomposition decompose(const Plan& plan, const DecompositionOptions& options) {
    const double w = options.robot.coverageWidth;
    Decomposition out;
    out.robot = options.robot;
    if (out.robot.robotDiameter == 0.0)
        out.robot.robotDiameter = w;
    const double robot = out.robot.robotDiameter;
    if (!(robot > 0.0) || robot > w * (1 + 1e-12))
        throw InputError("the robot diameter must be positive and at most the coverage width");
    const BoundingBox bounds = plan.bounds();
    out.frame = Frame({bounds.minX, bounds.minY}, options.stripeAngleDeg);
    // The local origin at the corner of the plan's box in the sweep frame, so that the same
    // plan at another rotation or position gets the same local coordinates.
    // Stripes at a and a + 180 degrees are one family; the slice sweeps from the side the
    // free space's centroid is nearer to, so that a plan turned by 180 degrees (or drawn
    // at any rotation) gets the same cells in the same order.
    double angle = options.stripeAngleDeg;
    {
        const Ring local = out.frame.toLocal(plan.boundary);
        const BoundingBox box = boundsOf(local);
        Vec2 moment = centroidMoment(local);
        double area = std::abs(signedArea(local));
        for (const Ring& hole : plan.obstacles) {
            const Ring h = out.frame.toLocal(hole);
            moment = moment - centroidMoment(h);
            area -= std::abs(signedArea(h));
        }
        if (area > 0.0) {
            const Vec2 c = moment * (1.0 / area);
            // Near-symmetric floors tie: a vertex jittered by micrometres (a reprojection)
            // must not turn the sweep round, as the lattice's phase then changes.
            const double tol =
                std::max(1e-6 * std::max({1.0, box.width(), box.height()}), kSnapTolerance * w);
            const double dx = (c.x - box.minX) - (box.maxX - c.x);
            const double dy = (c.y - box.minY) - (box.maxY - c.y);
            if (dx > tol || (std::abs(dx) <= tol && dy > tol))
                angle += 180.0;
        }
    }
    out.frame = Frame({bounds.minX, bounds.minY}, angle);
    const BoundingBox local = boundsOf(out.frame.toLocal(plan.boundary));
    out.frame = Frame(out.frame.toWorld({local.minX, local.minY}), angle);
    const double extent = std::max({1.0, bounds.width(), bounds.height()});

    Ring boundary = out.frame.toLocal(plan.boundary);
    orient(boundary, true);
    std::vector<Ring> holes, rooms;
    for (const Ring& h : plan.obstacles) {
        holes.push_back(out.frame.toLocal(h));
        orient(holes.back(), false);
    }
    for (const Room& r : plan.rooms)
        rooms.push_back(out.frame.toLocal(r.outline));
    // The walls as drawn, for the clearance field and the metrics: straightening below moves
    // vertices by up to 2 mm, and paths checked against the straightened walls came that
    // much closer to the real ones (a noisy ward map: 1.1 mm inside L/2 at a corner).
    out.freeSpace.push_back(boundary);
    out.freeSpace.insert(out.freeSpace.end(), holes.begin(), holes.end());
    std::vector<Ring*> all{&boundary};
    for (Ring& h : holes)
        all.push_back(&h);
    for (Ring& r : rooms)
        all.push_back(&r);
    detail::straightenNearVertical(all, 1 + holes.size(), kStraightenTolerance * w);
    detail::snapCoordinates(all, 1e-9 * extent, false);
    detail::snapCoordinates(all, 1e-9 * extent, true);
    detail::mergeCloseCoordinates(all, kSnapTolerance * w, false);
    detail::mergeCloseCoordinates(all, kSnapTolerance * w, true);

    std::vector<Ring> straightened{boundary};
    straightened.insert(straightened.end(), holes.begin(), holes.end());
    SlabSweep sweep = detail::sweepSlabs(straightened, rooms, 1e-9 * extent);

    for (const Room& r : plan.rooms)
        out.roomNames.push_back(r.name);
    if (plan.rooms.empty()) {
        out.roomNames.push_back("Floor");
        for (Trapezoid& t : sweep.trapezoids)
            t.room = 0;
    } else {
        const int rooms = detail::assignLeftovers(sweep, static_cast<int>(plan.rooms.size()));
        for (int i = static_cast<int>(plan.rooms.size()); i < rooms; ++i)
            out.roomNames.push_back("Unassigned " + std::to_string(i - plan.rooms.size() + 1));
        detail::fuseSameRoomStacks(sweep, 1e-9 * extent);
    }
    const int roomCount = static_cast<int>(out.roomNames.size());
    if (options.headland != Headland::None)
        out.headland =
            detail::splitHeadlands(sweep, roomCount, w, options.headland != Headland::Ceilings,
                                   options.headland != Headland::Floors, kHeadlandMaxSlope,
                                   1e-9 * extent) > 0;

    // Merge trapezoids while the slice connectivity inside their room does not change.
    const int nt = static_cast<int>(sweep.trapezoids.size());
    std::vector<std::vector<int>> sameRight(nt), sameLeft(nt);
    for (const detail::TrapezoidLink& l : sweep.links) {
        if (sweep.trapezoids[l.left].room == sweep.trapezoids[l.right].room) {
            sameRight[l.left].push_back(l.right);
            sameLeft[l.right].push_back(l.left);
        }
    }
    std::vector<int> cellOf(nt, -1);
    std::vector<RawCell> raw;
    for (const auto& members : sweep.slabMembers) {
        for (int t : members) {
            const Trapezoid& z = sweep.trapezoids[t];
            const bool continues = sameLeft[t].size() == 1 && sameRight[sameLeft[t][0]].size() == 1;
            if (continues) {
                cellOf[t] = cellOf[sameLeft[t][0]];
            } else {
                cellOf[t] = static_cast<int>(raw.size());
                raw.push_back({z.room, z.xa, z.xb, {}, {}});
            }
            RawCell& c = raw[cellOf[t]];
            c.x1 = z.xb;
            detail::appendPiece(c.floor, z.xa, z.fa, z.xb, z.fb);
            detail::appendPiece(c.ceiling, z.xa, z.ca, z.xb, z.cb);
        }
    }

    const std::vector<RawAdjacency> adj = rawAdjacencies(sweep, cellOf);
    std::vector<char> leftCritical(raw.size(), 0), rightCritical(raw.size(), 0);
    for (const RawAdjacency& a : adj) {
        if (a.kind != Adjacency::Kind::AcrossSweep)
            continue;
        if (raw[a.first].x1 == a.x0)
            rightCritical[a.first] = 1;
        if (raw[a.second].x0 == a.x0)
            leftCritical[a.second] = 1;
    }
    std::vector<detail::LatticeCell> latticeCells;
    for (const RawCell& c : raw)
        latticeCells.push_back(
            {c.room, c.x0, c.x1, c.ceiling.empty() ? 0.0 : c.ceiling.front().y - c.floor.front().y,
             c.ceiling.empty() ? 0.0 : c.ceiling.back().y - c.floor.back().y, false, wallSteps(c)});
    for (const RawAdjacency& a : adj)
        if (a.kind == Adjacency::Kind::AlongSweep)
            latticeCells[a.first].keepsStripe = latticeCells[a.second].keepsStripe = true;
    std::vector<detail::LatticeLink> latticeLinks;
    for (const RawAdjacency& a : adj)
        if (a.kind == Adjacency::Kind::AcrossSweep && raw[a.first].x1 == a.x0 &&
            raw[a.second].x0 == a.x0)
            latticeLinks.push_back({a.first, a.second, a.x0, a.y1 - a.y0});
    // Slivers are handed off only in the alternative layout (with the lattice), which the
    // planner plans beside the plain one and keeps when it is faster: on traced maps a
    // hand-off saves a stripe (noisy simple: 270 -> 230 s), yet on generated offices, whose
    // cells are a hair over n W, its jogs cost more turns than the stripes saved (20 rooms:
    // 4,806 s against 4,748 s). Only on floors of few cells, so that big floors (ward,
    // real maps) are not planned twice.
    const double handOff =
        raw.size() <= kHandOffMaxCells ? detail::maxHandOff(w, options.robot.robotDiameter) : 0.0;
    detail::StripeLayout layout =
        detail::layOutStripes(latticeCells, latticeLinks, w, LatticeMode::AtCorners, handOff);
    detail::StripeLayout own =
        detail::layOutStripes(latticeCells, latticeLinks, w, LatticeMode::Own);
    detail::StripeLayout dense = detail::layOutStripes(
        latticeCells, latticeLinks, w, LatticeMode::Dense, 0.0, options.robot.robotDiameter);
    out.stripeLatticeAvailable = layout.stripes != own.stripes;
    // The dense lattice is offered where it saves a tenth of the stripes' length (traced
    // maps); on drawn plans it saves little and would double the planning time.
    auto stripeLength = [&](const detail::StripeLayout& l) {
        double sum = 0;
        for (size_t i = 0; i < raw.size(); ++i)
            sum += l.stripes[i].size() * 0.5 *
                   (latticeCells[i].leftHeight + latticeCells[i].rightHeight);
        return sum;
    };
    const double ownLength = stripeLength(own), denseLength = stripeLength(dense);
    out.denseLatticeAvailable = denseLength < (1 - kDenseMinSaving) * ownLength;
    out.denseSaving = ownLength > 0.0 ? 1.0 - denseLength / ownLength : 0.0;
    out.layout = options.stripeLattice;
    if (out.layout == LatticeMode::Auto)
        out.layout = denseLength < (1 - kDenseAutoSaving) * ownLength ? LatticeMode::Dense
                                                                      : LatticeMode::Own;
    if (out.layout == LatticeMode::AtCorners) {
        out.stripeLattice = out.stripeLatticeAvailable;
    } else if (out.layout == LatticeMode::Dense) {
        out.stripeLattice = out.denseLatticeAvailable;
        layout = std::move(dense);
    } else {
        layout = std::move(own); // every cell on its own
    }
    const bool mayBeEmpty = out.layout == LatticeMode::Dense;

    // Split where the clear region changes (narrow passages, spans stacked in y), cut
    // transition strips and create the final cells.
    if (options.floorCache) {
        FloorCache::Parts parts = options.floorCache->partsFor(out.freeSpace, out.clearanceRadius(),
                                                               0.5 * out.coverageWidth());
        out.clearanceField = std::move(parts.clearance);
        out.derived = std::move(parts.derived);
    } else {
        out.clearanceField = std::make_shared<const ClearanceField>(
            out.freeSpace, out.clearanceRadius(), 0.5 * out.coverageWidth());
        out.derived = std::make_shared<DerivedCache>();
    }
    const ClearanceField& field = out.clearance();
    std::vector<std::vector<Piece>> pieces(raw.size());
    // Where a cell meets another room along the sweep (a doorway), the slice connectivity
    // of the whole free space changes at the doorway's ends: split there, as a
    // decomposition of the whole floor would, so that corners sit next to the door.
    std::vector<std::vector<double>> splits(raw.size());
    for (const RawAdjacency& a : adj) {
        if (a.kind != Adjacency::Kind::AlongSweep)
            continue;
        for (int c : {a.first, a.second}) {
            // Snap to the nearest midpoint of the cell's own stripe grid so that the split
            // adds no stripe (a door column would otherwise get two stripes 0.2 m apart).
            const std::vector<double>& grid = layout.stripes[c];
            for (double x : {a.x0, a.x1}) {
                double best = x, bestGap = INFINITY;
                for (size_t k = 1; k < grid.size(); ++k) {
                    const double mid = 0.5 * (grid[k - 1] + grid[k]);
                    if (std::abs(mid - x) < bestGap)
                        bestGap = std::abs(mid - x), best = mid;
                }
                if (grid.size() >= 2 && best > raw[c].x0 + 1e-9 * extent &&
                    best < raw[c].x1 - 1e-9 * extent)
                    splits[c].push_back(best);
            }
        }
    }
    for (size_t i = 0; i < raw.size(); ++i) {
        const RawCell& whole = raw[i];
        std::vector<double> cuts = splits[i];
        cuts.push_back(whole.x0);
        cuts.push_back(whole.x1);
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        // The raw cell's stripes, once: its pieces share them.
        const std::vector<double>& grid = layout.stripes[i];
        const bool onLattice = layout.onLattice[i];
        auto linesIn = [&](double a, double b) {
            std::vector<double> xs;
            for (double x : grid)
                if (x >= a && (x < b || (b == whole.x1 && x <= b)))
                    xs.push_back(x);
            return xs.empty() && !(mayBeEmpty && !latticeCells[i].keepsStripe)
                       ? stripePositions(a, b, w)
                       : xs;
        };
        for (size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
            RawCell r = whole;
            r.x0 = cuts[seg], r.x1 = cuts[seg + 1];
            r.floor = detail::clipFunction(whole.floor, r.x0, r.x1);
            r.ceiling = detail::clipFunction(whole.ceiling, r.x0, r.x1);
            const bool leftSlice = seg > 0 || leftCritical[i];
            const bool rightSlice = seg + 2 < cuts.size() || rightCritical[i];
            Cell probe;
            probe.x0 = r.x0, probe.x1 = r.x1, probe.floor = r.floor, probe.ceiling = r.ceiling;
            double placed = NAN; // a narrow piece's lattice line
            if (mayBeEmpty && onLattice && r.x1 - r.x0 < w) {
                const std::vector<double> lines = linesIn(r.x0, r.x1);
                if (lines.size() == 1)
                    placed = lines[0];
            }
            for (const detail::ClearRange& part : detail::clearRanges(probe, field, placed)) {
                const Polyline floor = detail::clipFunction(r.floor, part.x0, part.x1);
                const Polyline ceiling = detail::clipFunction(r.ceiling, part.x0, part.x1);
                auto add = [&](Cell c, int layer, int layers) {
                    c.stripesPlaced = layout.sweepsSliver[i] != 0 || mayBeEmpty;
                    c.sweptByNeighbours = c.stripes.empty();
                    pieces[i].push_back({c.id, c.x0, c.x1, layer, layers});
                    out.cells.push_back(std::move(c));
                };
                const std::vector<double> stripes =
                    onLattice ? linesIn(part.x0, part.x1) : stripePositions(part.x0, part.x1, w);
                if (part.layers >= 2) {
                    for (int k = 0; k < part.layers; ++k) {
                        const int id = static_cast<int>(out.cells.size());
                        add(makeCell(id, CellKind::Primary, r.room, part.x0, part.x1,
                                     k == 0 ? floor : part.pinches[k - 1],
                                     k + 1 == part.layers ? ceiling : part.pinches[k], stripes),
                            k, part.layers);
                    }
                    continue;
                }
                const bool left = part.x0 == r.x0 && leftSlice;
                const bool right = part.x1 == r.x1 && rightSlice;
                const bool cut = options.transitionCells && part.layers == 1;
                for (PieceSpec& spec :
                     pieceSpecs(part.x0, part.x1, cut && left, cut && right, stripes))
                    add(makeCell(static_cast<int>(out.cells.size()), spec.kind, r.room, spec.x0,
                                 spec.x1, detail::clipFunction(r.floor, spec.x0, spec.x1),
                                 detail::clipFunction(r.ceiling, spec.x0, spec.x1),
                                 std::move(spec.stripes)),
                        0, 1);
            }
        }
        // Neighbouring pieces of one raw cell touch across the sweep where their slices
        // overlap.
        for (const Piece& l : pieces[i]) {
            for (const Piece& rt : pieces[i]) {
                if (l.x1 != rt.x0)
                    continue;
                const Cell& cl = out.cells[l.cell];
                const Cell& cr = out.cells[rt.cell];
                const double x = l.x1;
                const double y0 = std::max(cl.floorAt(x), cr.floorAt(x));
                const double y1 = std::min(cl.ceilingAt(x), cr.ceilingAt(x));
                if (y1 - y0 > 1e-9 * extent)
                    out.adjacencies.push_back(
                        {Adjacency::Kind::AcrossSweep, l.cell, rt.cell, {{x, y0}, {x, y1}}});
            }
        }
    }

    for (const RawAdjacency& a : adj) {
        if (a.kind == Adjacency::Kind::AcrossSweep) {
            out.criticalSlices.push_back({a.x0, a.y0, a.y1});
            for (const Piece* l : piecesAt(pieces[a.first], out.cells, a.x0, true, a.y0, a.y1)) {
                for (const Piece* r :
                     piecesAt(pieces[a.second], out.cells, a.x0, false, a.y0, a.y1)) {
                    const Cell& cl = out.cells[l->cell];
                    const Cell& cr = out.cells[r->cell];
                    const double y0 = std::max({a.y0, cl.floorAt(a.x0), cr.floorAt(a.x0)});
                    const double y1 = std::min({a.y1, cl.ceilingAt(a.x0), cr.ceilingAt(a.x0)});
                    if (y1 - y0 > 1e-9 * extent)
                        out.adjacencies.push_back(
                            {a.kind, l->cell, r->cell, {{a.x0, y0}, {a.x0, y1}}});
                }
            }
            continue;
        }
        for (const Piece& lo : pieces[a.first]) {
            if (lo.layer + 1 != lo.layers)
                continue; // only the top layer touches the cell above
            for (const Piece& up : pieces[a.second]) {
                if (up.layer != 0)
                    continue;
                const double x0 = std::max({a.x0, lo.x0, up.x0});
                const double x1 = std::min({a.x1, lo.x1, up.x1});
                if (x1 - x0 <= 1e-9 * extent)
                    continue;
                const Cell& c = out.cells[lo.cell];
                out.adjacencies.push_back(
                    {a.kind, lo.cell, up.cell, {{x0, c.ceilingAt(x0)}, {x1, c.ceilingAt(x1)}}});
            }
        }
    }

    joinAcrossSweptCells(out);
    detail::planStripeSpans(out);
    // A headland's cells belong to the room they border (splitHeadlands' labels).
    for (Cell& cell : out.cells)
        if (cell.room >= roomCount) {
            cell.room -= roomCount;
            cell.headland = true;
        }
    keepBandPassesInLine(out);
    return out;
}

const ClearanceField& Decomposition::clearance() const {
    if (!clearanceField)
        throw std::logic_error("this decomposition has no clearance field (not made by decompose)");
    return *clearanceField;
}

} // namespace fc
