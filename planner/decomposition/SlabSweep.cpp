#include "decomposition/SlabSweep.h"

#include "model/Plan.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace fc::detail {
namespace {

struct SweepEdge {
    double xl, yl, xr, yr;
    int room; // -1 for walls

    double yAt(double x) const {
        if (x == xl)
            return yl;
        if (x == xr)
            return yr;
        return yl + (yr - yl) * (x - xl) / (xr - xl);
    }
};

void collectEdges(const Ring& ring, int room, std::vector<SweepEdge>& out) {
    for (size_t i = 0; i < ring.size(); ++i) {
        Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        if (a.x == b.x)
            continue; // vertical edges lie on event lines and bound no slab interval
        if (a.x > b.x)
            std::swap(a, b);
        out.push_back({a.x, a.y, b.x, b.y, room});
    }
}

struct ActiveEdge {
    const SweepEdge* edge;
    double yMid;
};

} // namespace

void computeLinks(SlabSweep& out, double epsY) {
    out.links.clear();
    out.linksOfTrapezoid.assign(out.trapezoids.size(), {});
    const int slabCount = static_cast<int>(out.slabMembers.size());
    for (int k = 0; k + 1 < slabCount; ++k) {
        const auto& L = out.slabMembers[k];
        const auto& R = out.slabMembers[k + 1];
        size_t i = 0, j = 0;
        while (i < L.size() && j < R.size()) {
            const Trapezoid& a = out.trapezoids[L[i]];
            const Trapezoid& b = out.trapezoids[R[j]];
            const double y0 = std::max(a.fb, b.fa), y1 = std::min(a.cb, b.ca);
            if (y1 - y0 > epsY) {
                const int id = static_cast<int>(out.links.size());
                out.links.push_back({L[i], R[j], out.xs[k + 1], y0, y1});
                out.linksOfTrapezoid[L[i]].push_back(id);
                out.linksOfTrapezoid[R[j]].push_back(id);
            }
            if (a.cb < b.ca)
                ++i;
            else
                ++j;
        }
    }
}

void fuseSameRoomStacks(SlabSweep& sweep, double epsY) {
    // Trapezoids separated only by a room border that now has the same room on both
    // sides (a door strip given to its room) become one trapezoid.
    std::vector<int> upperOf(sweep.trapezoids.size(), -1);
    for (const TrapezoidStack& s : sweep.stacks)
        upperOf[s.lower] = s.upper;
    std::vector<Trapezoid> fused;
    std::vector<std::vector<int>> members(sweep.slabMembers.size());
    std::vector<TrapezoidStack> stacks;
    std::vector<int> newId(sweep.trapezoids.size(), -1);
    for (size_t k = 0; k < sweep.slabMembers.size(); ++k) {
        for (int t : sweep.slabMembers[k]) {
            if (newId[t] >= 0)
                continue;
            Trapezoid z = sweep.trapezoids[t];
            newId[t] = static_cast<int>(fused.size());
            int u = upperOf[t];
            while (u >= 0 && sweep.trapezoids[u].room == z.room) {
                z.ca = sweep.trapezoids[u].ca, z.cb = sweep.trapezoids[u].cb;
                newId[u] = newId[t];
                u = upperOf[u];
            }
            members[k].push_back(newId[t]);
            fused.push_back(z);
        }
    }
    for (const TrapezoidStack& s : sweep.stacks)
        if (newId[s.lower] != newId[s.upper])
            stacks.push_back({newId[s.lower], newId[s.upper]});
    sweep.trapezoids = std::move(fused);
    sweep.slabMembers = std::move(members);
    sweep.stacks = std::move(stacks);
    computeLinks(sweep, epsY);
}

SlabSweep sweepSlabs(const std::vector<Ring>& freeRings, const std::vector<Ring>& rooms,
                     double epsY) {
    SlabSweep out;
    std::vector<SweepEdge> edges;
    for (const Ring& r : freeRings) {
        collectEdges(r, -1, edges);
        for (const Vec2& p : r)
            out.xs.push_back(p.x);
    }
    for (size_t i = 0; i < rooms.size(); ++i) {
        collectEdges(rooms[i], static_cast<int>(i), edges);
        for (const Vec2& p : rooms[i])
            out.xs.push_back(p.x);
    }
    std::sort(out.xs.begin(), out.xs.end());
    out.xs.erase(std::unique(out.xs.begin(), out.xs.end()), out.xs.end());
    std::sort(edges.begin(), edges.end(),
              [](const SweepEdge& a, const SweepEdge& b) { return a.xl < b.xl; });

    const int slabCount = static_cast<int>(out.xs.size()) - 1;
    out.slabMembers.resize(std::max(0, slabCount));
    std::vector<const SweepEdge*> active;
    size_t next = 0;
    std::vector<ActiveEdge> walls, borders;
    std::vector<int> roomParity(rooms.size(), 0);
    std::set<int> openRooms;

    for (int k = 0; k < slabCount; ++k) {
        const double xa = out.xs[k], xb = out.xs[k + 1], xm = 0.5 * (xa + xb);
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [xa](const SweepEdge* e) { return e->xr <= xa; }),
                     active.end());
        while (next < edges.size() && edges[next].xl <= xa)
            active.push_back(&edges[next++]);

        walls.clear();
        borders.clear();
        for (const SweepEdge* e : active) {
            if (e->xr < xb)
                continue; // cannot happen with exact event x's; defensive
            (e->room < 0 ? walls : borders).push_back({e, e->yAt(xm)});
        }
        auto byY = [](const ActiveEdge& a, const ActiveEdge& b) { return a.yMid < b.yMid; };
        std::sort(walls.begin(), walls.end(), byY);
        std::sort(borders.begin(), borders.end(), byY);
        if (walls.size() % 2 != 0) {
            std::ostringstream msg;
            msg << "walls do not enclose the free space consistently near x = " << xm
                << " (sweep frame); is a ring self-intersecting?";
            throw InputError(msg.str());
        }

        std::fill(roomParity.begin(), roomParity.end(), 0);
        openRooms.clear();
        size_t nextBorder = 0;
        for (size_t w = 0; w + 1 < walls.size(); w += 2) {
            // Split the free interval at room borders strictly inside it.
            std::vector<const SweepEdge*> cuts{walls[w].edge};
            for (const ActiveEdge& b : borders)
                if (b.yMid > walls[w].yMid + epsY && b.yMid < walls[w + 1].yMid - epsY)
                    cuts.push_back(b.edge);
            cuts.push_back(walls[w + 1].edge);

            int previousInInterval = -1;
            for (size_t c = 0; c + 1 < cuts.size(); ++c) {
                Trapezoid t;
                t.slab = k;
                t.xa = xa, t.xb = xb;
                t.fa = cuts[c]->yAt(xa), t.fb = cuts[c]->yAt(xb);
                t.ca = cuts[c + 1]->yAt(xa), t.cb = cuts[c + 1]->yAt(xb);
                const double yLow = cuts[c]->yAt(xm), yHigh = cuts[c + 1]->yAt(xm);
                if (yHigh - yLow <= epsY)
                    continue;
                // Rooms containing the middle: parity of the borders below it.
                const double yMid = 0.5 * (yLow + yHigh);
                while (nextBorder < borders.size() && borders[nextBorder].yMid < yMid) {
                    const int room = borders[nextBorder].edge->room;
                    roomParity[room] ^= 1;
                    if (roomParity[room])
                        openRooms.insert(room);
                    else
                        openRooms.erase(room);
                    ++nextBorder;
                }
                t.room = openRooms.empty() ? -1 : *openRooms.begin();
                const int id = static_cast<int>(out.trapezoids.size());
                out.trapezoids.push_back(t);
                out.slabMembers[k].push_back(id);
                if (previousInInterval >= 0)
                    out.stacks.push_back({previousInInterval, id});
                previousInInterval = id;
            }
        }
    }

    computeLinks(out, epsY);
    return out;
}

namespace {

// Where a slab narrower than W meets its neighbour: the walls' heights on either side.
struct Joint {
    bool left = false; // the narrow trapezoid lies left of the other
    double aFloor = 0, bFloor = 0, aCeiling = 0, bCeiling = 0;
};

// Calls visit(narrow, other, joint) for every link's trapezoid narrower than w, both ways,
// until no call returns true: a run of narrow slabs passes a band along.
template <typename Visit> void untilSettled(const SlabSweep& sweep, double w, Visit visit) {
    for (bool changed = true; changed;) {
        changed = false;
        for (const TrapezoidLink& link : sweep.links)
            for (const auto& [narrow, wide] :
                 {std::pair{link.left, link.right}, std::pair{link.right, link.left}}) {
                const Trapezoid& a = sweep.trapezoids[narrow];
                const Trapezoid& b = sweep.trapezoids[wide];
                if (a.xb - a.xa >= w)
                    continue;
                Joint at;
                at.left = narrow == link.left;
                at.aFloor = at.left ? a.fb : a.fa, at.bFloor = at.left ? b.fa : b.fb;
                at.aCeiling = at.left ? a.cb : a.ca, at.bCeiling = at.left ? b.ca : b.cb;
                changed = visit(narrow, wide, at) || changed;
            }
    }
}

} // namespace

int splitHeadlands(SlabSweep& sweep, int roomCount, double w, bool floors, bool ceilings,
                   double maxSlope, double epsY) {
    int bands = 0;
    const size_t n = sweep.trapezoids.size();
    std::vector<char> floorIsWall(n, 1), ceilingIsWall(n, 1);
    for (const TrapezoidStack& s : sweep.stacks) {
        ceilingIsWall[s.lower] = 0;
        floorIsWall[s.upper] = 0;
    }
    // Walls gentle enough to run a band along; a trapezoid narrower than W whose wall rises
    // less than W/2 (a chamfered corner, a traced wall's jog) continues the band of a
    // neighbour whose wall it continues, else the band would stop a cell short of the end.
    std::vector<char> gentleFloor(n, 0), gentleCeiling(n, 0);
    auto slope = [&](const Trapezoid& z, double ya, double yb) {
        return z.xb > z.xa && std::abs(yb - ya) <= maxSlope * (z.xb - z.xa);
    };
    for (size_t t = 0; t < n; ++t) {
        const Trapezoid& z = sweep.trapezoids[t];
        gentleFloor[t] = slope(z, z.fa, z.fb);
        gentleCeiling[t] = slope(z, z.ca, z.cb);
    }
    const double joint = std::max(epsY, 1e-6 * w);
    untilSettled(sweep, w, [&](int narrow, int wide, const Joint& at) {
        const Trapezoid& a = sweep.trapezoids[narrow];
        bool changed = false;
        if (!gentleFloor[narrow] && gentleFloor[wide] && std::abs(at.aFloor - at.bFloor) <= joint &&
            std::abs(a.fb - a.fa) <= 0.5 * w)
            gentleFloor[narrow] = 1, changed = true;
        if (!gentleCeiling[narrow] && gentleCeiling[wide] &&
            std::abs(at.aCeiling - at.bCeiling) <= joint && std::abs(a.cb - a.ca) <= 0.5 * w)
            gentleCeiling[narrow] = 1, changed = true;
        return changed;
    });
    // A band's inner edge, per trapezoid at xa and xb: w off its wall, except that a slab
    // narrower than W whose wall jogs by at most W/4 from a neighbour's (a traced wall's
    // tooth or notch) takes that neighbour's edge, so that the band's pieces line up and
    // form one cell instead of three offset by the jog.
    std::vector<double> lowA(n), lowB(n), highA(n), highB(n);
    std::vector<char> aligned(n, 0);
    for (size_t t = 0; t < n; ++t) {
        const Trapezoid& z = sweep.trapezoids[t];
        lowA[t] = z.fa + w, lowB[t] = z.fb + w;
        highA[t] = z.ca - w, highB[t] = z.cb - w;
    }
    const double jog = 0.25 * w;
    untilSettled(sweep, w, [&](int narrow, int wide, const Joint& at) {
        const Trapezoid& a = sweep.trapezoids[narrow];
        const Trapezoid& b = sweep.trapezoids[wide];
        if (aligned[narrow] || (b.xb - b.xa < w && !aligned[wide]))
            return false;
        const double bLow = at.left ? lowA[wide] : lowB[wide];
        const double bHigh = at.left ? highA[wide] : highB[wide];
        if (gentleFloor[narrow] && gentleFloor[wide] && std::abs(at.aFloor - at.bFloor) <= jog &&
            std::min(bLow - a.fa, bLow - a.fb) >= 0.5 * w)
            lowA[narrow] = lowB[narrow] = bLow, aligned[narrow] = 1;
        if (gentleCeiling[narrow] && gentleCeiling[wide] &&
            std::abs(at.aCeiling - at.bCeiling) <= jog &&
            std::min(a.ca - bHigh, a.cb - bHigh) >= 0.5 * w)
            highA[narrow] = highB[narrow] = bHigh, aligned[narrow] = 1;
        return aligned[narrow] != 0;
    });
    std::vector<Trapezoid> split;
    std::vector<std::vector<int>> members(sweep.slabMembers.size());
    std::vector<TrapezoidStack> stacks;
    std::vector<int> lowest(n, -1), highest(n, -1);
    for (size_t k = 0; k < sweep.slabMembers.size(); ++k) {
        for (int t : sweep.slabMembers[k]) {
            const Trapezoid& z = sweep.trapezoids[t];
            const bool band = z.room >= 0 && z.room < roomCount;
            const bool low = band && floors && floorIsWall[t] && gentleFloor[t];
            const bool high = band && ceilings && ceilingIsWall[t] && gentleCeiling[t];
            // The middle piece left between the bands must stay at least W tall.
            const double bottomA = low ? lowA[t] : z.fa, bottomB = low ? lowB[t] : z.fb;
            const double topA = high ? highA[t] : z.ca, topB = high ? highB[t] : z.cb;
            std::vector<Trapezoid> pieces;
            if ((low || high) && std::min(topA - bottomA, topB - bottomB) > w) {
                Trapezoid middle = z;
                if (low) {
                    Trapezoid b = z;
                    b.room = roomCount + z.room;
                    b.ca = lowA[t], b.cb = lowB[t];
                    middle.fa = b.ca, middle.fb = b.cb;
                    pieces.push_back(b);
                }
                pieces.push_back(middle);
                if (high) {
                    Trapezoid b = z;
                    b.room = roomCount + z.room;
                    b.fa = highA[t], b.fb = highB[t];
                    pieces.back().ca = b.fa, pieces.back().cb = b.fb;
                    pieces.push_back(b);
                }
                bands += (low ? 1 : 0) + (high ? 1 : 0);
            } else {
                pieces.push_back(z);
            }
            for (size_t i = 0; i < pieces.size(); ++i) {
                const int id = static_cast<int>(split.size());
                if (i == 0)
                    lowest[t] = id;
                else
                    stacks.push_back({id - 1, id});
                highest[t] = id;
                members[k].push_back(id);
                split.push_back(pieces[i]);
            }
        }
    }
    for (const TrapezoidStack& s : sweep.stacks)
        stacks.push_back({highest[s.lower], lowest[s.upper]});
    sweep.trapezoids = std::move(split);
    sweep.slabMembers = std::move(members);
    sweep.stacks = std::move(stacks);
    computeLinks(sweep, epsY);
    return bands;
}

int assignLeftovers(SlabSweep& sweep, int roomCount) {
    auto& traps = sweep.trapezoids;
    const int n = static_cast<int>(traps.size());
    // Union-find over leftover trapezoids connected by links or stacks.
    std::vector<int> parent(n);
    for (int i = 0; i < n; ++i)
        parent[i] = i;
    auto find = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    auto unite = [&](int a, int b) {
        if (traps[a].room < 0 && traps[b].room < 0)
            parent[find(a)] = find(b);
    };
    for (const TrapezoidLink& l : sweep.links)
        unite(l.left, l.right);
    for (const TrapezoidStack& s : sweep.stacks)
        unite(s.lower, s.upper);

    // Shared border length between each leftover component and each room.
    std::map<int, std::map<int, double>> border; // component -> room -> length
    auto addBorder = [&](int a, int b, double length) {
        if (traps[a].room < 0 && traps[b].room >= 0)
            border[find(a)][traps[b].room] += length;
        else if (traps[b].room < 0 && traps[a].room >= 0)
            border[find(b)][traps[a].room] += length;
    };
    for (const TrapezoidLink& l : sweep.links)
        addBorder(l.left, l.right, l.y1 - l.y0);
    for (const TrapezoidStack& s : sweep.stacks) {
        const Trapezoid& t = traps[s.lower];
        addBorder(s.lower, s.upper, std::hypot(t.xb - t.xa, t.cb - t.ca));
    }

    std::map<int, int> componentRoom;
    int rooms = roomCount;
    for (int i = 0; i < n; ++i) {
        if (traps[i].room >= 0)
            continue;
        const int c = find(i);
        auto it = componentRoom.find(c);
        if (it == componentRoom.end()) {
            int best = -1;
            double bestLength = 0.0;
            for (const auto& [room, length] : border[c]) // ascending room: ties go low
                if (length > bestLength * (1 + 1e-9) + 1e-12) {
                    best = room;
                    bestLength = length;
                }
            if (best < 0)
                best = rooms++;
            it = componentRoom.emplace(c, best).first;
        }
        traps[i].room = it->second;
    }
    return rooms;
}

} // namespace fc::detail
