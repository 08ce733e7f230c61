// Doorway borders of a segmented map's rooms laid along the walls. Two rooms' territories
// meet inside a doorway wherever their growth fronts met: on a map turned by 30 degrees,
// along the pixel rows, diagonally across the wall's thickness. Each door then left the
// corridor a triangle of the passage and a jog into its floor (0.3 m deep), each a cell with
// a stripe of its own where the corridor is swept along its length. The border is moved onto
// the wall line of the room with fewer doorways, so that room keeps a straight wall and the
// other (a corridor) owns the whole passage, as a drawn plan's rooms end on their walls.
#include "importers/MapTracing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <ogr_api.h>
#include <ogr_geometry.h>

namespace fc::importing {

namespace {

struct Frame2 {
    Vec2 along, across;
    double a(Vec2 p) const { return dot(p, along); }
    double n(Vec2 p) const { return dot(p, across); }
    Vec2 at(double a, double n) const { return along * a + across * n; }
};

double areaOf(const OGRGeometry* g) {
    return g ? OGR_G_Area(OGRGeometry::ToHandle(const_cast<OGRGeometry*>(g))) : 0.0;
}

void collectSegments(const OGRGeometry* g, std::vector<Segment>& out) {
    if (!g)
        return;
    if (auto* c = dynamic_cast<const OGRGeometryCollection*>(g)) {
        for (int i = 0; i < c->getNumGeometries(); ++i)
            collectSegments(c->getGeometryRef(i), out);
        return;
    }
    if (auto* line = dynamic_cast<const OGRSimpleCurve*>(g))
        for (int i = 0; i + 1 < line->getNumPoints(); ++i)
            out.push_back({{line->getX(i), line->getY(i)}, {line->getX(i + 1), line->getY(i + 1)}});
}

// Connected pieces of a set of segments (joined at shared end points).
std::vector<std::vector<Segment>> components(const std::vector<Segment>& segments) {
    std::map<std::pair<long long, long long>, int> pointId;
    auto id = [&](Vec2 p) {
        const auto key = std::make_pair(std::llround(p.x * 1e6), std::llround(p.y * 1e6));
        return pointId.emplace(key, static_cast<int>(pointId.size())).first->second;
    };
    std::vector<std::pair<int, int>> ends;
    for (const Segment& s : segments)
        ends.emplace_back(id(s.a), id(s.b));
    std::vector<int> parent(pointId.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    for (const auto& [a, b] : ends)
        parent[find(a)] = find(b);
    std::map<int, std::vector<Segment>> byRoot;
    for (size_t k = 0; k < segments.size(); ++k)
        byRoot[find(ends[k].first)].push_back(segments[k]);
    std::vector<std::vector<Segment>> out;
    for (auto& [root, list] : byRoot)
        out.push_back(std::move(list));
    return out;
}

// The rectangle [a0, a1] x [n0, n1] in the frame's coordinates.
std::unique_ptr<OGRPolygon> rectangle(const Frame2& f, double a0, double a1, double n0, double n1) {
    auto ring = new OGRLinearRing;
    for (const auto& [a, n] : {std::pair{a0, n0}, {a1, n0}, {a1, n1}, {a0, n1}, {a0, n0}}) {
        const Vec2 p = f.at(a, n);
        ring->addPoint(p.x, p.y);
    }
    auto polygon = std::make_unique<OGRPolygon>();
    polygon->addRingDirectly(ring);
    return polygon;
}

GeometryPtr owned(OGRGeometry* g) {
    return GeometryPtr(g);
}

Vec2 centroid(const OGRGeometry* g) {
    OGRPoint c;
    if (!g || g->IsEmpty() || g->Centroid(&c) != OGRERR_NONE)
        return {NAN, NAN};
    return {c.getX(), c.getY()};
}

// Pieces up to this many cells that a move cuts off a room (slivers between two rooms
// simplified apart) are dropped; they stay floor outside every room.
constexpr double kCrumbCells = 2.0;
// Border ends this close (cells) to a corner of the floor are moved onto it.
constexpr double kCornerSnap = 0.25;

// Whether g is one polygon, or one beside crumbs (then g becomes that polygon).
bool singlePolygon(GeometryPtr& g) {
    if (!g)
        return false;
    if (wkbFlatten(g->getGeometryType()) == wkbPolygon)
        return true;
    auto* parts = dynamic_cast<OGRGeometryCollection*>(g.get());
    if (!parts)
        return false;
    const OGRGeometry* largest = nullptr;
    double rest = 0;
    for (int i = 0; i < parts->getNumGeometries(); ++i) {
        const OGRGeometry* part = parts->getGeometryRef(i);
        const double area = areaOf(part);
        if (wkbFlatten(part->getGeometryType()) == wkbPolygon &&
            (!largest || area > areaOf(largest))) {
            rest += largest ? areaOf(largest) : 0.0;
            largest = part;
        } else {
            rest += area;
        }
    }
    if (!largest || rest > kCrumbCells)
        return false;
    g.reset(largest->clone());
    return true;
}

struct Door {
    size_t first, second;
    std::vector<Segment> border;
};

} // namespace

FloorCorners::FloorCorners(const OGRGeometry& floor, double tolerance) : tolerance_(tolerance) {
    const GeometryPtr walls = owned(floor.Boundary());
    std::vector<Segment> edges;
    collectSegments(walls.get(), edges);
    for (const Segment& e : edges)
        cells_[{std::llround(e.a.x / tolerance_), std::llround(e.a.y / tolerance_)}].push_back(e.a);
}

const Vec2* FloorCorners::nearest(Vec2 p) const {
    const long long cx = std::llround(p.x / tolerance_), cy = std::llround(p.y / tolerance_);
    const Vec2* best = nullptr;
    for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy) {
            const auto it = cells_.find({cx + dx, cy + dy});
            if (it != cells_.end())
                for (const Vec2& c : it->second)
                    if (distance(c, p) <= tolerance_ &&
                        (!best || distance(c, p) < distance(*best, p)))
                        best = &c;
        }
    return best;
}

void FloorCorners::snap(Ring& ring) const {
    for (Vec2& p : ring)
        if (const Vec2* c = nearest(p))
            p = *c;
}

void FloorCorners::snap(OGRPolygon& polygon) const {
    for (int k = 0; k <= polygon.getNumInteriorRings(); ++k) {
        OGRLinearRing* ring = k == 0 ? polygon.getExteriorRing() : polygon.getInteriorRing(k - 1);
        const int n = ring ? ring->getNumPoints() : 0;
        for (int i = 0; i + 1 < n; ++i) { // the closing point follows the first
            const Vec2 p{ring->getX(i), ring->getY(i)};
            const Vec2* c = nearest(p);
            if (!c || distance(*c, p) == 0)
                continue;
            auto place = [&](Vec2 q) {
                ring->setPoint(i, q.x, q.y);
                if (i == 0)
                    ring->setPoint(n - 1, q.x, q.y);
            };
            place(*c);
            if (!polygon.IsValid())
                place(p);
        }
    }
}

int straightenDoorwayBorders(std::vector<GeometryPtr>& rooms, const OGRGeometry& floor,
                             double wallAngleDeg, double maxWidth, double maxDepth) {
    const double angle = wallAngleDeg * M_PI / 180.0;
    const Vec2 u{std::cos(angle), std::sin(angle)}, v{-std::sin(angle), std::cos(angle)};
    // The rooms were simplified one by one, so two rooms' borders in a doorway need not
    // coincide: a door is a piece of a room's outline off the floor's walls, shared with
    // the room that overlaps most a rectangle around it.
    const GeometryPtr walls = owned(floor.Boundary());
    const FloorCorners corners(floor, kCornerSnap);
    std::vector<OGREnvelope> boxes(rooms.size());
    for (size_t i = 0; i < rooms.size(); ++i)
        rooms[i]->getEnvelope(&boxes[i]);
    std::vector<Door> doors;
    std::vector<int> doorCount(rooms.size(), 0);
    for (size_t i = 0; i < rooms.size(); ++i) {
        const GeometryPtr outline = owned(rooms[i]->Boundary());
        const GeometryPtr offWalls =
            owned(outline && walls ? outline->Difference(walls.get()) : nullptr);
        std::vector<Segment> segments;
        collectSegments(offWalls.get(), segments);
        for (std::vector<Segment>& piece : components(segments)) {
            double length = 0;
            OGREnvelope box;
            for (const Segment& s : piece) {
                length += distance(s.a, s.b);
                box.Merge(s.a.x, s.a.y), box.Merge(s.b.x, s.b.y);
            }
            if (length < 1.0)
                continue; // a rounding crumb of the wall
            ++doorCount[i];
            box.MinX -= 1, box.MinY -= 1, box.MaxX += 1, box.MaxY += 1;
            const auto around = rectangle({{1, 0}, {0, 1}}, box.MinX, box.MaxX, box.MinY, box.MaxY);
            size_t partner = i;
            double best = 0;
            for (size_t j = 0; j < rooms.size(); ++j) {
                if (j == i || !boxes[j].Intersects(box))
                    continue;
                const GeometryPtr common = owned(rooms[j]->Intersection(around.get()));
                if (areaOf(common.get()) > best)
                    best = areaOf(common.get()), partner = j;
            }
            if (partner != i)
                doors.push_back({i, partner, std::move(piece)});
        }
    }
    int moved = 0;
    std::vector<std::pair<std::pair<size_t, size_t>, Vec2>> movedDoors;
    for (const Door& door : doors) {
        // The border's extent along the wall directions; the longer one is the wall's.
        Frame2 f{u, v};
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (const Segment& s : door.border)
            for (const Vec2 p : {s.a, s.b}) {
                lo[0] = std::min(lo[0], f.a(p)), hi[0] = std::max(hi[0], f.a(p));
                lo[1] = std::min(lo[1], f.n(p)), hi[1] = std::max(hi[1], f.n(p));
            }
        if (hi[1] - lo[1] > hi[0] - lo[0]) {
            f = {v, u};
            std::swap(lo[0], lo[1]), std::swap(hi[0], hi[1]);
        }
        const double width = hi[0] - lo[0], depth = hi[1] - lo[1];
        if (width > maxWidth || depth < 0.5 || depth > maxDepth)
            continue; // not a doorway, or already along the wall
        // The room with fewer doorways keeps its wall straight and the one with more (a
        // corridor) owns the passage; ties: the larger owns it. Measured on noisy maps of the
        // ward and office drawn at ten angles: +2.3% and +7.4% by time against their
        // drawings (+4.1%, +7.9% with the diagonal borders); owned by the rooms instead,
        // +4.6% and +8.4% against +3.0% and +7.0% in the same first version (each room's
        // notch costs its sweep, a corridor swept across takes the passages at its stripes'
        // ends).
        size_t keep = door.first, other = door.second;
        if (doorCount[keep] > doorCount[other] ||
            (doorCount[keep] == doorCount[other] &&
             areaOf(rooms[keep].get()) > areaOf(rooms[other].get())))
            std::swap(keep, other);
        // Which side of the border each room lies on, from their parts near the door.
        const auto near = rectangle(f, lo[0] - width, hi[0] + width, lo[1] - width, hi[1] + width);
        const GeometryPtr keepNear = owned(rooms[keep]->Intersection(near.get()));
        const GeometryPtr otherNear = owned(rooms[other]->Intersection(near.get()));
        const double side = f.n(centroid(keepNear.get())) - f.n(centroid(otherNear.get()));
        if (!(std::abs(side) > 0.5))
            continue;
        const double s = side > 0 ? 1.0 : -1.0; // the kept room lies towards s * across
        // The kept room's wall line: its faces along the wall beside the door (not on the
        // border), the one nearest the other room, so that none of its floor changes hands.
        const auto band =
            rectangle(f, lo[0] - std::max(width, 2 * maxDepth),
                      hi[0] + std::max(width, 2 * maxDepth), lo[1] - depth, hi[1] + depth);
        // Both clipped to the band first: the floor's walls are the whole map's.
        const GeometryPtr keepEdge = owned(rooms[keep]->Boundary());
        const GeometryPtr edgeNear = owned(keepEdge ? keepEdge->Intersection(band.get()) : nullptr);
        const GeometryPtr wallsNear = owned(walls ? walls->Intersection(band.get()) : nullptr);
        const GeometryPtr ownNear =
            owned(edgeNear && wallsNear ? edgeNear->Intersection(wallsNear.get()) : nullptr);
        std::vector<Segment> faces;
        collectSegments(ownNear.get(), faces);
        double line = INFINITY; // in s * across units: smallest is nearest the other room
        for (const Segment& face : faces) {
            const Vec2 d = face.b - face.a;
            if (norm(d) >= 2.0 && std::abs(f.n(d)) <= 0.05 * norm(d))
                line = std::min(line, s * 0.5 * (f.n(face.a) + f.n(face.b)));
        }
        // The wall line may lie a little beyond the border's ends (a border that stops a
        // pixel short of the jamb's corner).
        const double t = s * line, reach = std::max(2.0, 0.5 * depth);
        if (!std::isfinite(line) || t < lo[1] - reach || t > hi[1] + reach)
            continue; // no wall beside the door, or one far from the border
        const double n0 = std::min(lo[1], t) - 1.0, n1 = std::max(hi[1], t) + 1.0;
        const auto keepHalf = s > 0 ? rectangle(f, lo[0] - 1, hi[0] + 1, t, n1)
                                    : rectangle(f, lo[0] - 1, hi[0] + 1, n0, t);
        const auto otherHalf = s > 0 ? rectangle(f, lo[0] - 1, hi[0] + 1, n0, t)
                                     : rectangle(f, lo[0] - 1, hi[0] + 1, t, n1);
        const GeometryPtr gives = owned(rooms[keep]->Intersection(otherHalf.get()));
        const GeometryPtr takes = owned(rooms[other]->Intersection(keepHalf.get()));
        if (areaOf(gives.get()) + areaOf(takes.get()) < 0.25)
            continue;
        const GeometryPtr keepLeft = owned(rooms[keep]->Difference(otherHalf.get()));
        const GeometryPtr otherLeft = owned(rooms[other]->Difference(keepHalf.get()));
        GeometryPtr newKeep = owned(keepLeft && takes ? keepLeft->Union(takes.get()) : nullptr);
        GeometryPtr newOther = owned(otherLeft && gives ? otherLeft->Union(gives.get()) : nullptr);
        const double before = areaOf(rooms[keep].get()) + areaOf(rooms[other].get());
        if (!singlePolygon(newKeep) || !singlePolygon(newOther) ||
            std::abs(areaOf(newKeep.get()) + areaOf(newOther.get()) - before) >
                1e-6 * before + 2 * kCrumbCells + 1)
            continue; // a piece would come loose: leave this door as it is
        corners.snap(static_cast<OGRPolygon&>(*newKeep));
        corners.snap(static_cast<OGRPolygon&>(*newOther));
        rooms[keep] = std::move(newKeep);
        rooms[other] = std::move(newOther);
        // A door is met from both rooms' outlines; counted once.
        const Vec2 centre = f.at(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
        const std::pair<size_t, size_t> pair{std::min(door.first, door.second),
                                             std::max(door.first, door.second)};
        if (std::none_of(movedDoors.begin(), movedDoors.end(), [&](const auto& m) {
                return m.first == pair && distance(m.second, centre) <= maxWidth;
            })) {
            movedDoors.emplace_back(pair, centre);
            ++moved;
        }
    }
    return moved;
}

} // namespace fc::importing
