#include "decomposition/IslandDetours.h"

#include "geometry/BoostGeometry.h"

#include <algorithm>
#include <cmath>

namespace fc {
namespace {

using namespace bgeo;

// Added to the clearance of a zone's ring: its round corners' chords cut 1.4 mm inwards
// (see roundBuffer), and a free start point keeps a centimetre (clearPointNear).
constexpr double kZoneMargin = 0.005;

BPolygon polygonOf(const Ring& outline, const std::vector<const Ring*>& holes, Vec2 origin) {
    BPolygon polygon;
    appendRing(outline, origin, polygon.outer());
    for (const Ring* hole : holes) {
        polygon.inners().emplace_back();
        appendRing(*hole, origin, polygon.inners().back());
    }
    bg::correct(polygon);
    return polygon;
}

// roundBuffer of many disjoint polygons by a positive distance: each buffered on its own,
// and only those whose grown pieces meet buffered together. Boost's buffer of the whole
// multi-polygon joins every piece with every other: 1,173 pillars 10 cm square (a
// speckled map's furniture) took 10 s there, each wall-loop draft again.
BMulti bufferedApart(const BMulti& polygons, double distance) {
    using BBox = bg::model::box<BPoint>;
    const size_t n = polygons.size();
    std::vector<BMulti> grown(n);
    std::vector<BBox> boxes(n);
    for (size_t i = 0; i < n; ++i) {
        grown[i] = roundBuffer(polygons[i], distance);
        boxes[i] = bg::return_envelope<BBox>(grown[i]);
    }
    std::vector<size_t> order(n), parent(n);
    for (size_t i = 0; i < n; ++i)
        order[i] = parent[i] = i;
    const auto find = [&](size_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return boxes[a].min_corner().x() < boxes[b].min_corner().x();
    });
    for (size_t k = 0; k < n; ++k) {
        const size_t a = order[k];
        for (size_t m = k + 1;
             m < n && boxes[order[m]].min_corner().x() <= boxes[a].max_corner().x(); ++m) {
            const size_t b = order[m];
            if (find(a) != find(b) && bg::intersects(boxes[a], boxes[b]) &&
                bg::intersects(grown[a], grown[b]))
                parent[find(a)] = find(b);
        }
    }
    std::vector<std::vector<size_t>> groups(n);
    for (size_t i = 0; i < n; ++i)
        groups[find(i)].push_back(i);
    BMulti out;
    for (const std::vector<size_t>& group : groups) {
        if (group.empty())
            continue;
        BMulti joined;
        if (group.size() == 1) {
            joined = std::move(grown[group.front()]);
        } else {
            BMulti members;
            for (size_t i : group)
                members.push_back(polygons[i]);
            joined = roundBuffer(members, distance);
        }
        for (BPolygon& part : joined)
            out.push_back(std::move(part));
    }
    return out;
}

// roundBuffer by a negative distance of disjoint pieces, each on its own.
BMulti shrunkApart(const BMulti& pieces, double distance) {
    BMulti out;
    for (const BPolygon& piece : pieces)
        for (BPolygon& part : roundBuffer(piece, distance))
            out.push_back(std::move(part));
    return out;
}

struct Zone {
    std::vector<Vec2> ring; // local frame, not closed
    Vec2 low, high;         // bounding box
};

bool inside(const Zone& zone, Vec2 p) {
    return p.x >= zone.low.x && p.x <= zone.high.x && p.y >= zone.low.y && p.y <= zone.high.y &&
           pointInRing(zone.ring, p);
}

// A point of the path: a vertex, or where a segment crosses a zone's ring.
struct Station {
    size_t segment = 0;
    double t = 0.0; // along the segment
    Vec2 at;
    int zone = -1; // crossing: the zone, its edge and where along it
    size_t edge = 0;
    double u = 0.0;
};

void addCrossings(const std::vector<Zone>& zones, size_t segment, Vec2 p, Vec2 q,
                  std::vector<Station>& out) {
    const Vec2 d = q - p;
    for (size_t z = 0; z < zones.size(); ++z) {
        const Zone& zone = zones[z];
        if (std::max(p.x, q.x) < zone.low.x || std::min(p.x, q.x) > zone.high.x ||
            std::max(p.y, q.y) < zone.low.y || std::min(p.y, q.y) > zone.high.y)
            continue;
        const size_t n = zone.ring.size();
        for (size_t e = 0; e < n; ++e) {
            const Vec2 a = zone.ring[e], b = zone.ring[(e + 1) % n], f = b - a;
            const double denom = cross(d, f);
            if (std::abs(denom) < 1e-12)
                continue;
            const double t = cross(a - p, f) / denom, u = cross(a - p, d) / denom;
            if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0)
                out.push_back({segment, t, p + d * t, static_cast<int>(z), e, u});
        }
    }
}

// The shorter way along the zone's ring from crossing a to crossing b.
Polyline roundTheZone(const Zone& zone, const Station& a, const Station& b) {
    const size_t n = zone.ring.size();
    Polyline forward{a.at}, backward{a.at};
    if (!(a.edge == b.edge && b.u >= a.u))
        for (size_t i = (a.edge + 1) % n;; i = (i + 1) % n) {
            forward.push_back(zone.ring[i]);
            if (i == b.edge)
                break;
        }
    if (!(a.edge == b.edge && b.u <= a.u))
        for (size_t i = a.edge;; i = (i + n - 1) % n) {
            backward.push_back(zone.ring[i]);
            if (i == (b.edge + 1) % n)
                break;
        }
    forward.push_back(b.at);
    backward.push_back(b.at);
    return polylineLength(forward) <= polylineLength(backward) ? forward : backward;
}

// The crossing of `zone`'s ring at station k or at a station in the same place (a path
// vertex on the ring is both).
const Station* crossingAt(const std::vector<Station>& stations, size_t k, int zone) {
    for (size_t m = k + 1; m-- > 0 && norm(stations[m].at - stations[k].at) < 1e-7;)
        if (stations[m].zone == zone)
            return &stations[m];
    for (size_t m = k + 1; m < stations.size() && norm(stations[m].at - stations[k].at) < 1e-7; ++m)
        if (stations[m].zone == zone)
            return &stations[m];
    return nullptr;
}

// The outer ring of the merged group joined with its members: the buffers' round corners
// are chords, so closing (out, then in) leaves a member's convex corners up to a few
// millimetres outside the group, and a path planned round the group came 1.3 mm too near
// such a corner (a pillar hall, clearance 0.2987 m for L/2 = 0.3 m).
BRing coveringOuter(const BPolygon& group, const BMulti& polygons,
                    const std::vector<size_t>& members) {
    BMulti joined{group};
    for (size_t i : members) {
        BMulti next;
        bg::union_(joined, polygons[i], next);
        joined = std::move(next);
    }
    const BPolygon* largest = &group;
    double largestArea = -1.0;
    for (const BPolygon& part : joined)
        if (bg::area(part) > largestArea) {
            largestArea = bg::area(part);
            largest = &part;
        }
    return largest->outer();
}

// Holes the robot cannot pass between are one obstacle to it: merged (closed by the
// clearance, which fills the gaps between them). A hole with no neighbour that near stays as
// it was.
std::vector<Ring> mergedHoles(const std::vector<Ring>& holes, double clearance, Vec2 origin) {
    BMulti polygons;
    std::vector<const Ring*> given;
    for (const Ring& hole : holes)
        if (hole.size() >= 3) {
            polygons.push_back(polygonOf(hole, {}, origin));
            given.push_back(&hole);
        }
    const double reach = clearance + kZoneMargin;
    const BMulti closed = shrunkApart(bufferedApart(polygons, reach), -reach);
    std::vector<Ring> out;
    std::vector<char> used(polygons.size(), 0);
    for (const BPolygon& group : closed) {
        std::vector<size_t> members;
        for (size_t i = 0; i < polygons.size(); ++i)
            if (!used[i] && bg::intersects(group, polygons[i]))
                members.push_back(i);
        for (size_t i : members)
            used[i] = 1;
        if (members.size() == 1)
            out.push_back(*given[members.front()]);
        else if (members.size() > 1) // floor they enclose is behind gaps the robot cannot pass
            out.push_back(toRing(coveringOuter(group, polygons, members), origin));
    }
    for (size_t i = 0; i < polygons.size(); ++i)
        if (!used[i]) // lost by the buffers (a sliver): kept as it was
            out.push_back(*given[i]);
    return out;
}

} // namespace

IslandDetours islandDetours(const Ring& outline, const std::vector<Ring>& givenHoles,
                            double clearance, double maxIslandArea) {
    IslandDetours out;
    if (outline.size() < 3 || givenHoles.empty()) {
        out.keptHoles = givenHoles;
        return out;
    }
    const Vec2 origin = outline.front();
    const std::vector<Ring> holes = mergedHoles(givenHoles, clearance, origin);
    std::vector<char> kept(holes.size());
    for (size_t i = 0; i < holes.size(); ++i)
        kept[i] = std::abs(signedArea(holes[i])) > maxIslandArea || holes[i].size() < 3;
    // A zone that comes too near a kept wall keeps its islands, which narrows the floor the
    // other zones must fit in: repeated until nothing changes (each round keeps one more
    // island or ends).
    BMulti zones;
    while (true) {
        std::vector<const Ring*> keptRings;
        BMulti islands;
        std::vector<size_t> islandHole;
        for (size_t i = 0; i < holes.size(); ++i)
            if (kept[i]) {
                keptRings.push_back(&holes[i]);
            } else {
                islands.push_back(polygonOf(holes[i], {}, origin));
                islandHole.push_back(i);
            }
        zones.clear();
        if (islands.empty())
            break;
        const BMulti centres = roundBuffer(polygonOf(outline, keptRings, origin), -clearance);
        zones = bufferedApart(islands, clearance + kZoneMargin);
        bool changed = false;
        for (const BPolygon& zone : zones) {
            if (zone.inners().empty() && bg::within(zone, centres))
                continue;
            bool found = false;
            for (size_t k = 0; k < islands.size(); ++k)
                if (bg::intersects(zone, islands[k])) {
                    kept[islandHole[k]] = 1;
                    found = true;
                }
            if (!found) // cannot be told apart: no island is driven round
                for (size_t k : islandHole)
                    kept[k] = 1;
            changed = true;
        }
        if (!changed)
            break;
    }
    for (size_t i = 0; i < holes.size(); ++i)
        if (kept[i])
            out.keptHoles.push_back(holes[i]);
    for (const BPolygon& zone : zones)
        out.zones.push_back(toRing(zone.outer(), origin));
    return out;
}

std::optional<CoveragePath> detouredPath(const CoveragePath& path, const std::vector<Ring>& zones) {
    if (zones.empty() || path.empty())
        return path;
    const Vec2 origin = path.points.front();
    std::vector<Zone> local;
    for (const Ring& ring : zones) {
        Zone zone{{}, {INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
        for (const Vec2& p : ring) {
            zone.ring.push_back(p - origin);
            zone.low = {std::min(zone.low.x, p.x - origin.x), std::min(zone.low.y, p.y - origin.y)};
            zone.high = {std::max(zone.high.x, p.x - origin.x),
                         std::max(zone.high.y, p.y - origin.y)};
        }
        if (zone.ring.size() >= 3)
            local.push_back(std::move(zone));
    }
    std::vector<Station> stations;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) {
        const Vec2 p = path.points[i] - origin, q = path.points[i + 1] - origin;
        const size_t first = stations.size();
        stations.push_back({i, 0.0, p});
        addCrossings(local, i, p, q, stations);
        std::sort(stations.begin() + static_cast<std::ptrdiff_t>(first), stations.end(),
                  [](const Station& a, const Station& b) { return a.t < b.t; });
    }
    stations.push_back({path.points.size() - 2, 1.0, path.points.back() - origin});
    // Which zone each piece between two stations lies in (-1: none); a piece too short to
    // tell (a ring touched at a point) goes with the one before.
    std::vector<int> in(stations.size() - 1, -1);
    for (size_t k = 0; k + 1 < stations.size(); ++k) {
        const Vec2 a = stations[k].at, b = stations[k + 1].at;
        if (norm(b - a) < 1e-7) {
            in[k] = k ? in[k - 1] : -1;
            continue;
        }
        const Vec2 middle = (a + b) * 0.5;
        for (size_t z = 0; z < local.size() && in[k] < 0; ++z)
            if (inside(local[z], middle))
                in[k] = static_cast<int>(z);
    }
    CoveragePath out;
    out.points.push_back(path.points.front());
    auto add = [&](Vec2 p, SegmentKind kind) {
        if (norm(p + origin - out.points.back()) < 1e-9)
            return;
        out.points.push_back(p + origin);
        out.kinds.push_back(kind);
    };
    for (size_t k = 0; k + 1 < stations.size();) {
        const int zone = in[k];
        if (zone < 0) {
            add(stations[k + 1].at, path.kinds[stations[k].segment]);
            ++k;
            continue;
        }
        size_t j = k;
        while (j + 1 < stations.size() && in[j] == zone)
            ++j;
        const Station* entry = crossingAt(stations, k, zone);
        const Station* exit = crossingAt(stations, j, zone);
        if (!entry || !exit)
            return std::nullopt; // starts or ends inside the zone
        const Polyline round = roundTheZone(local[static_cast<size_t>(zone)], *entry, *exit);
        for (size_t i = 1; i < round.size(); ++i)
            add(round[i], SegmentKind::Contour);
        k = j;
    }
    if (out.points.size() < 2)
        return std::nullopt;
    return out;
}

} // namespace fc
