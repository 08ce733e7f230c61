// The rooms of an occupancy map's segmentation as plan rooms: simple, disjoint outlines
// (GEOS through OGR), since a plan's room is one ring and rooms may not overlap.
#include "geometry/GridCells.h"
#include "importers/MapTracing.h"

#include <algorithm>
#include <cmath>
#include <ogr_api.h>
#include <ogr_geometry.h>
#include <unordered_map>

namespace fc::importing {

namespace {

constexpr double kMinCells = 4.0;      // overlaps smaller than this are tracing noise
constexpr double kMinPieceArea = 0.25; // m^2: a room piece smaller than this is a sliver
// A border between two rooms up to this wide (m) and this deep across the wall is a doorway.
constexpr double kMaxDoorWidth = 3.0;
constexpr double kMaxDoorDepth = 0.6;
constexpr double kFinalCornerSnap = 1e-3; // cells

double areaOf(const OGRGeometry* g) {
    return OGR_G_Area(OGRGeometry::ToHandle(const_cast<OGRGeometry*>(g)));
}

std::unique_ptr<OGRPolygon> polygonOfRing(const OGRLinearRing& ring) {
    auto polygon = std::make_unique<OGRPolygon>();
    polygon->addRingDirectly(ring.clone());
    return polygon;
}

const OGRPolygon* largestPolygon(const OGRGeometry* g) {
    const OGRPolygon* best = nullptr;
    auto consider = [&](const OGRGeometry* part) {
        if (wkbFlatten(part->getGeometryType()) != wkbPolygon)
            return;
        auto* p = static_cast<const OGRPolygon*>(part);
        if (!best || p->get_Area() > best->get_Area())
            best = p;
    };
    if (auto* collection = dynamic_cast<const OGRGeometryCollection*>(g)) {
        for (int i = 0; i < collection->getNumGeometries(); ++i)
            consider(collection->getGeometryRef(i));
    } else {
        consider(g);
    }
    return best;
}

// Cuts `polygon` along vertical lines through its holes until no piece has a hole.
void cutHoles(const OGRGeometry& g, double minArea, std::vector<GeometryPtr>& pieces) {
    std::vector<const OGRPolygon*> parts;
    if (auto* collection = dynamic_cast<const OGRGeometryCollection*>(&g)) {
        for (int i = 0; i < collection->getNumGeometries(); ++i)
            if (wkbFlatten(collection->getGeometryRef(i)->getGeometryType()) == wkbPolygon)
                parts.push_back(static_cast<const OGRPolygon*>(collection->getGeometryRef(i)));
    } else if (wkbFlatten(g.getGeometryType()) == wkbPolygon) {
        parts.push_back(static_cast<const OGRPolygon*>(&g));
    }
    for (const OGRPolygon* part : parts) {
        if (part->get_Area() < minArea)
            continue;
        // Holes of a few cells are where two rooms' borders nearly met (GEOS leaves holes of
        // no area there): filled, not cut around.
        auto whole = std::make_unique<OGRPolygon>();
        whole->addRingDirectly(part->getExteriorRing()->clone());
        for (int h = 0; h < part->getNumInteriorRings(); ++h)
            if (part->getInteriorRing(h)->get_Area() >= kMinCells)
                whole->addRingDirectly(part->getInteriorRing(h)->clone());
        part = whole.get();
        if (part->getNumInteriorRings() == 0) {
            pieces.emplace_back(part->clone());
            continue;
        }
        OGREnvelope box, hole;
        part->getEnvelope(&box);
        part->getInteriorRing(0)->getEnvelope(&hole);
        const double cut = (hole.MinX + hole.MaxX) / 2;
        for (const auto& [x0, x1] : {std::pair{box.MinX - 1, cut}, std::pair{cut, box.MaxX + 1}}) {
            OGRLinearRing ring;
            ring.addPoint(x0, box.MinY - 1);
            ring.addPoint(x1, box.MinY - 1);
            ring.addPoint(x1, box.MaxY + 1);
            ring.addPoint(x0, box.MaxY + 1);
            ring.closeRings();
            GeometryPtr half(part->Intersection(polygonOfRing(ring).get()));
            if (half)
                cutHoles(*half, minArea, pieces);
        }
    }
}

// Opened by a twentieth of a pixel: cutting rooms against each other and the floor may
// leave an outline pinched at a point or a spike of no width, which plans refuse. Mitred
// both ways, so that every other corner comes back where it was: a corner cut by a hair
// (a bevelled or round join) no longer meets the floor's corner, and the sliver between
// them starts cells of its own at every doorway's jamb.
void openSlightly(GeometryPtr& g) {
    if (g)
        g = openedMitred(*g, 0.05, 1, false, 5.0);
}

// Vertices where the outline turns back on itself within a degree: thin wedges left where
// rooms are cut against each other and the floor (plans refuse spikes).
void dropSpikes(Ring& ring) {
    for (bool changed = true; changed && ring.size() >= 3;) {
        changed = false;
        for (size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
            const Vec2 p = ring[i];
            const Vec2 a = ring[(i + ring.size() - 1) % ring.size()] - p;
            const Vec2 b = ring[(i + 1) % ring.size()] - p;
            const double la = norm(a), lb = norm(b);
            if (la < 1e-9 || lb < 1e-9 ||
                (dot(a, b) > 0 && std::abs(cross(a, b)) < 0.0175 * la * lb)) {
                ring.erase(ring.begin() + static_cast<long>(i));
                changed = true;
            }
        }
    }
}

// A ring's edges by grid cell, each in the cells it passes through (walked a cell at a
// time), to find the edges near a vertex without testing them all: a room traced from an
// uncleaned map has thousands of vertices, and every pair cost half a second.
class EdgeGrid {
public:
    EdgeGrid(const Ring& ring, double cell) : cell_(cell) {
        const size_t n = ring.size();
        for (size_t j = 0; j < n; ++j) {
            forEachCellNear(ring[j], ring[(j + 1) % n], cell, 0.0, [&](long long x, long long y) {
                std::vector<size_t>& edges = cells_[key(x, y)];
                if (edges.empty() || edges.back() != j) // a segment's pieces share cells
                    edges.push_back(j);
            });
        }
    }

    // The edges through the 3 x 3 cells around p, ascending: every edge within a cell of p.
    std::vector<size_t> near(Vec2 p) const {
        std::vector<size_t> out;
        for (long long x = cellOf(p.x) - 1; x <= cellOf(p.x) + 1; ++x)
            for (long long y = cellOf(p.y) - 1; y <= cellOf(p.y) + 1; ++y)
                if (const auto it = cells_.find(key(x, y)); it != cells_.end())
                    out.insert(out.end(), it->second.begin(), it->second.end());
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

private:
    long long cellOf(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
    static long long key(long long x, long long y) { return x * 4000037LL + y; }
    double cell_;
    std::unordered_map<long long, std::vector<size_t>> cells_;
};

// A ring that touches itself, as its loops: GEOS keeps a room pinched at a point (where a
// doorway's border meets a wall's corner) as one ring, which plans refuse.
std::vector<Ring> splitAtPinches(Ring ring, double tolerance) {
    std::vector<Ring> loops, todo{std::move(ring)};
    while (!todo.empty()) {
        Ring r = std::move(todo.back());
        todo.pop_back();
        const size_t n = r.size();
        double perimeter = 0.0;
        for (size_t i = 0; i < n; ++i)
            perimeter += distance(r[i], r[(i + 1) % n]);
        const EdgeGrid edges(r, std::max(16.0 * tolerance, perimeter / std::max<size_t>(n, 1)));
        bool split = false;
        for (size_t i = 0; i < n && !split; ++i)
            for (size_t j : edges.near(r[i])) {
                if (j == i || (j + 1) % n == i ||
                    pointSegmentDistance(r[i], r[j], r[(j + 1) % n]) > tolerance)
                    continue;
                // r[i] lies on the edge r[j] r[j+1]: one loop runs r[i] .. r[j], the other
                // r[j+1] .. r[i].
                Ring first, second;
                for (size_t k = i; k != (j + 1) % n; k = (k + 1) % n)
                    first.push_back(r[k]);
                for (size_t k = (j + 1) % n; k != i; k = (k + 1) % n)
                    second.push_back(r[k]);
                second.push_back(r[i]);
                for (Ring* loop : {&first, &second})
                    if (loop->size() >= 3 && ringArea(*loop) > tolerance * tolerance)
                        todo.push_back(std::move(*loop));
                split = true;
                break;
            }
        if (!split)
            loops.push_back(std::move(r));
    }
    return loops;
}

} // namespace

std::vector<Room> roomsFromLabels(const std::vector<std::int32_t>& labels,
                                  const std::vector<unsigned char>& free, int width, int height,
                                  const OGRGeometry& kept, double tolerance, const RosMapInfo& info,
                                  std::optional<double> wallAngleDeg, int* doorwaysAligned) {
    std::vector<GeometryPtr> regions; // each room's largest simplified part, with its holes
    if (wallAngleDeg) {
        // The floor's walls were straightened on their own: each room is its territory (the
        // map's cells nearest to it, walls included) cut by the floor, so it ends exactly on
        // the floor's walls and leaves no sliver outside every room (each
        // would be a cell border along the wall). Only doorways are the rooms' own borders.
        const std::vector<std::int32_t> territories = labelTerritories(labels, width, height);
        const std::vector<unsigned char> everywhere(territories.size(), 1);
        for (auto& [label, traced] : traceCells(territories, everywhere, width, height)) {
            if (label <= 0)
                continue;
            // The territory's borders meet the floor only in doorways (a wall cuts the
            // rest away): they are not straightened, as a doorway is not a wall.
            const GeometryPtr g = simplifiedCells(*traced, tolerance);
            GeometryPtr common(g->Intersection(&kept));
            openSlightly(common);
            if (const OGRPolygon* part = largestPolygon(common.get());
                part && areaOf(part) >= kMinCells)
                regions.emplace_back(part->clone());
        }
        const int aligned =
            straightenDoorwayBorders(regions, kept, *wallAngleDeg, kMaxDoorWidth / info.resolution,
                                     kMaxDoorDepth / info.resolution);
        if (doorwaysAligned)
            *doorwaysAligned = aligned;
    } else {
        // Asked once per segment: prepared (indexed) once, as an uncleaned map's floor has
        // thousands of holes and each plain test rebuilt its index.
        OGRGeometryH keptHandle = OGRGeometry::ToHandle(const_cast<OGRGeometry*>(&kept));
        OGRPreparedGeometryUniquePtr prepared(
            OGRHasPreparedGeometrySupport() ? OGRCreatePreparedGeometry(keptHandle) : nullptr);
        auto meetsFloor = [&](const OGRPolygon& polygon) {
            auto* handle = OGRGeometry::ToHandle(const_cast<OGRPolygon*>(&polygon));
            return prepared ? OGRPreparedGeometryIntersects(prepared.get(), handle) != 0
                            : polygon.Intersects(&kept);
        };
        for (auto& [label, traced] : traceCells(labels, free, width, height)) {
            if (label <= 0)
                continue;
            GeometryPtr g = simplifiedCells(*traced, tolerance);
            const OGRPolygon* largest = largestPolygon(g.get());
            if (!largest || !meetsFloor(*largest))
                continue;
            GeometryPtr common(largest->Intersection(&kept));
            if (common && areaOf(common.get()) >= kMinCells)
                regions.emplace_back(largest->clone());
        }
    }
    // A hole of a room that holds no other room is an obstacle: the outline covers it.
    // Cheap tests first: an uncleaned map's room has thousands of speckle holes, and GEOS
    // intersected each with every other room (most of a 25 s import).
    std::vector<OGREnvelope> boxes(regions.size());
    for (size_t i = 0; i < regions.size(); ++i)
        regions[i]->getEnvelope(&boxes[i]);
    std::vector<GeometryPtr> filled;
    for (size_t i = 0; i < regions.size(); ++i) {
        auto* polygon = static_cast<OGRPolygon*>(regions[i].get());
        auto outline = polygonOfRing(*polygon->getExteriorRing());
        for (int h = 0; h < polygon->getNumInteriorRings(); ++h) {
            const OGRLinearRing* ring = polygon->getInteriorRing(h);
            OGREnvelope holeBox;
            ring->getEnvelope(&holeBox);
            bool mayHoldRoom = false; // the shared area is at most the hole's
            if (ring->get_Area() >= kMinCells)
                for (size_t k = 0; k < regions.size() && !mayHoldRoom; ++k)
                    mayHoldRoom = k != i && boxes[k].Intersects(holeBox);
            if (!mayHoldRoom)
                continue;
            auto hole = polygonOfRing(*ring);
            const bool holdsRoom = std::any_of(regions.begin(), regions.end(), [&](auto& other) {
                if (other.get() == regions[i].get() || !hole->Intersects(other.get()))
                    return false;
                GeometryPtr common(hole->Intersection(other.get()));
                return common && areaOf(common.get()) >= kMinCells;
            });
            if (holdsRoom)
                outline->addRingDirectly(polygon->getInteriorRing(h)->clone());
        }
        filled.push_back(std::move(outline));
    }
    // Overlays round a border through a floor's corner by micrometres: put back on it.
    const FloorCorners corners(kept, kFinalCornerSnap);
    // Disjoint (the staircases were simplified one room at a time), then without holes.
    GeometryPtr taken = std::make_unique<OGRMultiPolygon>();
    std::vector<std::pair<Vec2, Ring>> outlines;
    for (GeometryPtr& region : filled) {
        GeometryPtr own(region->Difference(taken.get()));
        taken.reset(taken->Union(region.get()));
        openSlightly(own);
        if (!own || !taken)
            throw InputError("separating the rooms failed");
        std::vector<GeometryPtr> pieces;
        // Slivers left between rooms (below a quarter square metre) join a neighbour as free
        // space outside every room does.
        cutHoles(*own, std::max(kMinCells, kMinPieceArea / (info.resolution * info.resolution)),
                 pieces);
        for (GeometryPtr& piece : pieces) {
            std::vector<Polygon2> room;
            collectPolygons(piece.get(), room);
            if (room.empty() || room[0].shell.size() < 3)
                continue;
            dropSpikes(room[0].shell);
            const double minArea = kMinPieceArea / (info.resolution * info.resolution);
            for (Ring& loop : splitAtPinches(std::move(room[0].shell), 0.01)) {
                if (ringArea(loop) < minArea)
                    continue; // a sliver pinched off: free space outside every room
                if (wallAngleDeg)
                    corners.snap(loop);
                std::vector<Polygon2> part{{std::move(loop), {}}};
                toMapFrame(part, height, info);
                Ring& shell = part[0].shell;
                Vec2 centre;
                for (const Vec2& p : shell)
                    centre = centre + p * (1.0 / shell.size());
                outlines.emplace_back(centre, std::move(shell));
            }
        }
    }
    std::sort(outlines.begin(), outlines.end(), [](const auto& a, const auto& b) {
        return std::make_pair(-a.first.y, a.first.x) < std::make_pair(-b.first.y, b.first.x);
    });
    std::vector<Room> rooms;
    for (auto& [centre, outline] : outlines)
        rooms.push_back({"Room " + std::to_string(rooms.size() + 1), std::move(outline)});
    return rooms;
}

} // namespace fc::importing
