// Opening traced polygons by a fraction of a pixel (GEOS buffers through OGR), fast on floors
// with thousands of holes.
#include "geometry/GridCells.h"
#include "importers/MapTracing.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace fc::importing {

namespace {

// Polygons with fewer holes are opened in one buffer, as they always were: the cost grows
// with holes times vertices, and below this it is a small part of the import (a cleaned map of
// four buildings, 79 obstacles). The parts' rings start at other vertices than the one
// buffer's, and the simplifications after it follow where a ring starts.
constexpr int kManyHoles = 200;
// A hole is opened on its own when no other ring comes within this many radii of it: the
// erosion grows each ring by one radius, so rings farther apart than two never meet.
constexpr double kApartRadii = 4.0;

std::vector<Vec2> pointsOf(const OGRLinearRing& ring) {
    std::vector<Vec2> points;
    points.reserve(static_cast<size_t>(ring.getNumPoints()));
    for (int i = 0; i < ring.getNumPoints(); ++i)
        points.push_back({ring.getX(i), ring.getY(i)});
    return points;
}

// The rings' segments bucketed by a square grid, to find which rings come near each other.
class RingProximity {
public:
    RingProximity(const std::vector<std::vector<Vec2>>& rings, double reach)
        : rings_(rings), reach_(reach), cell_(std::max(8.0 * reach, 1.0)) {
        for (size_t r = 0; r < rings.size(); ++r)
            for (size_t i = 0; i + 1 < rings[r].size(); ++i)
                forCells(rings[r][i], rings[r][i + 1], [&](long long key) {
                    buckets_[key].push_back({static_cast<int>(r), static_cast<int>(i)});
                });
    }

    // Whether a segment of another ring lies within `reach` of ring `r`.
    bool near(size_t r) const {
        const std::vector<Vec2>& ring = rings_[r];
        for (size_t i = 0; i + 1 < ring.size(); ++i) {
            bool found = false;
            forCells(ring[i], ring[i + 1], [&](long long key) {
                const auto it = buckets_.find(key);
                if (found || it == buckets_.end())
                    return;
                for (const auto& [other, k] : it->second) {
                    if (other == static_cast<int>(r))
                        continue;
                    const std::vector<Vec2>& o = rings_[static_cast<size_t>(other)];
                    if (segmentSegmentDistance(ring[i], ring[i + 1], o[k], o[k + 1]) < reach_) {
                        found = true;
                        return;
                    }
                }
            });
            if (found)
                return true;
        }
        return false;
    }

private:
    template <typename F> void forCells(Vec2 a, Vec2 b, F&& f) const {
        forEachCellNear(a, b, cell_, reach_,
                        [&](long long x, long long y) { f(x * 4000037LL + y); });
    }

    const std::vector<std::vector<Vec2>>& rings_;
    double reach_, cell_;
    std::unordered_map<long long, std::vector<std::pair<int, int>>> buckets_;
};

GeometryPtr bufferedTwice(const OGRGeometry& g, double first, double second) {
    GeometryPtr out(g.Buffer(first, 1));
    if (out)
        out.reset(out->Buffer(second, 1));
    if (!out)
        throw InputError("smoothing the free space failed");
    return out;
}

void appendPolygons(const OGRGeometry& g, std::vector<GeometryPtr>& out) {
    if (const auto* polygon = dynamic_cast<const OGRPolygon*>(&g)) {
        if (!polygon->IsEmpty())
            out.emplace_back(polygon->clone());
    } else if (const auto* parts = dynamic_cast<const OGRGeometryCollection*>(&g)) {
        for (int i = 0; i < parts->getNumGeometries(); ++i)
            appendPolygons(*parts->getGeometryRef(i), out);
    }
}

// One polygon of many holes: the shell with the holes near it or near each other in one
// buffer; every other hole closed on its own (all that opening the floor does to it) and put
// back into the part of the result around it.
void openPolygon(const OGRPolygon& polygon, double radius, std::vector<GeometryPtr>& out) {
    const int holes = polygon.getNumInteriorRings();
    if (holes < kManyHoles) {
        appendPolygons(*bufferedTwice(polygon, -radius, radius), out);
        return;
    }
    std::vector<std::vector<Vec2>> rings{pointsOf(*polygon.getExteriorRing())};
    for (int h = 0; h < holes; ++h)
        rings.push_back(pointsOf(*polygon.getInteriorRing(h)));
    const RingProximity proximity(rings, kApartRadii * radius);
    OGRPolygon core;
    core.addRingDirectly(polygon.getExteriorRing()->clone());
    std::vector<GeometryPtr> apart; // closed holes, as polygons
    for (int h = 0; h < holes; ++h) {
        const OGRLinearRing* hole = polygon.getInteriorRing(h);
        GeometryPtr closed;
        if (!proximity.near(static_cast<size_t>(h) + 1)) {
            OGRPolygon alone;
            alone.addRingDirectly(hole->clone());
            closed = bufferedTwice(alone, radius, -radius);
        }
        const auto* single = dynamic_cast<const OGRPolygon*>(closed.get());
        if (single && !single->IsEmpty() && single->getNumInteriorRings() == 0)
            apart.push_back(std::move(closed));
        else
            core.addRingDirectly(hole->clone());
    }
    std::vector<GeometryPtr> parts;
    appendPolygons(*bufferedTwice(core, -radius, radius), parts);
    std::vector<double> areas;
    for (const GeometryPtr& part : parts)
        areas.push_back(static_cast<const OGRPolygon*>(part.get())->get_Area());
    for (const GeometryPtr& closed : apart) {
        const OGRLinearRing* ring = static_cast<const OGRPolygon*>(closed.get())->getExteriorRing();
        OGRPoint inside;
        ring->getPoint(0, &inside);
        // The smallest part whose outline holds it: a part may lie inside another's hole.
        int owner = -1;
        for (size_t p = 0; p < parts.size(); ++p) {
            auto* part = static_cast<OGRPolygon*>(parts[p].get());
            if (part->getExteriorRing()->isPointInRing(&inside) &&
                (owner < 0 || areas[p] < areas[static_cast<size_t>(owner)]))
                owner = static_cast<int>(p);
        }
        if (owner >= 0) // else the hole lay in floor the opening took away
            static_cast<OGRPolygon*>(parts[static_cast<size_t>(owner)].get())
                ->addRingDirectly(ring->clone());
    }
    for (GeometryPtr& part : parts)
        out.push_back(std::move(part));
}

} // namespace

GeometryPtr openedPolygons(const OGRGeometry& g, double radius) {
    int holes = 0;
    std::vector<const OGRPolygon*> polygons;
    if (const auto* polygon = dynamic_cast<const OGRPolygon*>(&g))
        polygons.push_back(polygon);
    else if (const auto* parts = dynamic_cast<const OGRGeometryCollection*>(&g))
        for (int i = 0; i < parts->getNumGeometries(); ++i)
            if (const auto* p = dynamic_cast<const OGRPolygon*>(parts->getGeometryRef(i)))
                polygons.push_back(p);
    for (const OGRPolygon* polygon : polygons)
        holes = std::max(holes, polygon->getNumInteriorRings());
    if (holes < kManyHoles) // as it always was, one buffer over all
        return bufferedTwice(g, -radius, radius);
    std::vector<GeometryPtr> opened;
    for (const OGRPolygon* polygon : polygons)
        openPolygon(*polygon, radius, opened);
    auto out = std::make_unique<OGRMultiPolygon>();
    for (GeometryPtr& polygon : opened)
        out->addGeometryDirectly(polygon.release());
    return out;
}

} // namespace fc::importing
