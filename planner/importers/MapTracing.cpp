// Tracing occupancy grids with GDAL's polygonizer (cell edges, 4-connected) and smoothing
// the traced staircase with GEOS (through OGR).
#include "importers/MapTracing.h"

#include <algorithm>
#include <cmath>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <geos_c.h>
#include <memory>
#include <ogrsf_frmts.h>

namespace fc::importing {

namespace {

constexpr long long kMaxTracedPolygons = 200000;
constexpr double kOpening = 0.05; // pixels
// Smaller differences between the floor and its opening are rounding (square pixels).
constexpr double kMinPassageArea = 0.01;
// A closed passage's outline is simplified within this (pixels): the opening's arcs would
// otherwise add dozens of vertices, and as many slice events, per passage.
constexpr double kPassageTolerance = 0.25;
// And the outline with the passages closed (below the tracing's own tolerance, 0.45 cells).
constexpr double kSimplifyTolerance = 0.4;

int cancelWhenHuge(double, const char*, void* layer) {
    return static_cast<OGRLayer*>(layer)->GetFeatureCount(FALSE) < kMaxTracedPolygons;
}

// Rings and parts of a free space: what a passage's closing changes.
std::pair<int, int> topologyOf(const OGRGeometry& g) {
    std::vector<Polygon2> polygons;
    collectPolygons(&g, polygons);
    int holes = 0;
    for (const Polygon2& p : polygons)
        holes += static_cast<int>(p.holes.size());
    return {static_cast<int>(polygons.size()), holes};
}

OGRPolygon rectangle(double x0, double y0, double x1, double y1) {
    OGRLinearRing ring;
    ring.addPoint(x0, y0);
    ring.addPoint(x1, y0);
    ring.addPoint(x1, y1);
    ring.addPoint(x0, y1);
    ring.closeRings();
    OGRPolygon box;
    box.addRing(&ring);
    return box;
}

// The floor cut to a small box, from nested clips made on demand (a quadtree whose nodes
// overlap by a margin): cutting it from the whole floor for each of a big map's thousands of
// pieces cost a linear pass each, half a minute on a 4,700 m^2 map.
class LocalFloor {
public:
    explicit LocalFloor(const OGRGeometry& free) {
        free.getEnvelope(&root_.core);
        root_.region = root_.core;
        root_.clip.reset(free.clone());
    }

    // The floor inside `box` (null where GEOS failed).
    GeometryPtr within(const OGREnvelope& box) {
        Node* node = &root_;
        for (int depth = 0; depth < kMaxDepth; ++depth) {
            const double w = node->core.MaxX - node->core.MinX;
            const double h = node->core.MaxY - node->core.MinY;
            if (std::max(w, h) < kSmallestCore || !node->clip)
                break;
            const int q = quadrantHolding(*node, box);
            if (q < 0)
                break;
            if (!node->children[q])
                node->children[q] = child(*node, q);
            node = node->children[q].get();
        }
        if (!node->clip)
            return nullptr;
        const OGRPolygon rect = rectangle(box.MinX, box.MinY, box.MaxX, box.MaxY);
        return GeometryPtr(node->clip->Intersection(&rect));
    }

private:
    static constexpr int kMaxDepth = 12;
    static constexpr double kSmallestCore = 128; // pixels
    static constexpr double kOverlap = 16;       // pixels: pieces across a core's edge

    struct Node {
        OGREnvelope core, region; // region: the core grown by the overlap
        GeometryPtr clip;         // the floor within region
        std::unique_ptr<Node> children[4];
    };

    static OGREnvelope quadrant(const Node& n, int q) {
        const double mx = 0.5 * (n.core.MinX + n.core.MaxX);
        const double my = 0.5 * (n.core.MinY + n.core.MaxY);
        OGREnvelope e;
        e.MinX = q & 1 ? mx : n.core.MinX;
        e.MaxX = q & 1 ? n.core.MaxX : mx;
        e.MinY = q & 2 ? my : n.core.MinY;
        e.MaxY = q & 2 ? n.core.MaxY : my;
        return e;
    }

    static OGREnvelope grown(OGREnvelope e) {
        e.MinX -= kOverlap, e.MinY -= kOverlap, e.MaxX += kOverlap, e.MaxY += kOverlap;
        return e;
    }

    static int quadrantHolding(const Node& n, const OGREnvelope& box) {
        for (int q = 0; q < 4; ++q)
            if (grown(quadrant(n, q)).Contains(box))
                return q;
        return -1;
    }

    static std::unique_ptr<Node> child(const Node& parent, int q) {
        auto node = std::make_unique<Node>();
        node->core = quadrant(parent, q);
        node->region = grown(node->core);
        const OGRPolygon rect =
            rectangle(node->region.MinX, node->region.MinY, node->region.MaxX, node->region.MaxY);
        node->clip.reset(parent.clip->Intersection(&rect));
        return node;
    }

    Node root_;
};

// Whether taking `piece` from the floor changes its parts or holes. That depends only on
// how the piece meets the floor's outline, so it is decided on the floor round the piece.
bool changesTopology(LocalFloor& floor, const OGRGeometry& piece) {
    OGREnvelope box;
    piece.getEnvelope(&box);
    constexpr double kMargin = 1.0; // pixels: the box's edges stay clear of the piece
    box.MinX -= kMargin, box.MinY -= kMargin, box.MaxX += kMargin, box.MaxY += kMargin;
    const GeometryPtr local = floor.within(box);
    const GeometryPtr without(local ? local->Difference(&piece) : nullptr);
    return without && topologyOf(*without) != topologyOf(*local);
}

// The rings that a closed passage changed (a joined obstacle's outline zigzags along its
// former gaps) simplified as the tracing was; the others are simplified already and stay.
// Passages left are at least the robot wide, so a ring cannot cross another.
GeometryPtr simplifiedWhereClosed(const OGRGeometry& free, const OGRGeometry& closed) {
    std::vector<Polygon2> polygons;
    collectPolygons(&free, polygons);
    auto simplified = [&](const Ring& ring) {
        OGRPolygon single;
        single.addRingDirectly(ogrRing(ring));
        if (!single.Intersects(&closed))
            return ring;
        const GeometryPtr simple(single.SimplifyPreserveTopology(kSimplifyTolerance));
        std::vector<Polygon2> pieces;
        if (simple)
            collectPolygons(simple.get(), pieces);
        return pieces.size() == 1 ? pieces[0].shell : ring;
    };
    auto out = std::make_unique<OGRMultiPolygon>();
    for (const Polygon2& polygon : polygons) {
        auto* p = new OGRPolygon;
        p->addRingDirectly(ogrRing(simplified(polygon.shell)));
        for (const Ring& hole : polygon.holes)
            p->addRingDirectly(ogrRing(simplified(hole)));
        out->addGeometryDirectly(p);
    }
    return out;
}

} // namespace

// The cells of each value of `values` where `mask` is set, traced by GDAL's polygonizer along
// the cell edges (4-connected), in pixel units (x right, y down): one geometry per value.
std::map<std::int32_t, GeometryPtr> traceCells(const std::vector<std::int32_t>& values,
                                               const std::vector<unsigned char>& mask, int width,
                                               int height) {
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("Memory");
    if (!mem || !memory)
        throw InputError("GDAL lacks its in-memory drivers");
    DatasetPtr raster(mem->Create("", width, height, 2, GDT_Int32, nullptr));
    GDALRasterBand* band = raster->GetRasterBand(1);
    GDALRasterBand* maskBand = raster->GetRasterBand(2);
    std::vector<std::int32_t> mask32(mask.begin(), mask.end());
    if (band->RasterIO(GF_Write, 0, 0, width, height, const_cast<std::int32_t*>(values.data()),
                       width, height, GDT_Int32, 0, 0, nullptr) != CE_None ||
        maskBand->RasterIO(GF_Write, 0, 0, width, height, mask32.data(), width, height, GDT_Int32,
                           0, 0, nullptr) != CE_None)
        throw InputError("cannot hold the map image in memory");
    DatasetPtr vector(memory->Create("", 0, 0, 0, GDT_Unknown, nullptr));
    OGRLayer* layer = vector->CreateLayer("cells", nullptr, wkbPolygon, nullptr);
    OGRFieldDefn field("value", OFTInteger);
    layer->CreateField(&field);
    if (GDALPolygonize(band, maskBand, layer, 0, nullptr, cancelWhenHuge, layer) != CE_None)
        throw InputError(layer->GetFeatureCount(FALSE) >= kMaxTracedPolygons
                             ? "the free space is split into more than 200000 pieces"
                             : std::string("tracing the free space failed: ") +
                                   CPLGetLastErrorMsg());
    std::map<std::int32_t, GeometryPtr> traced;
    layer->ResetReading();
    while (std::unique_ptr<OGRFeature> feature{layer->GetNextFeature()}) {
        GeometryPtr& all = traced[feature->GetFieldAsInteger(0)];
        if (!all)
            all = std::make_unique<OGRMultiPolygon>();
        if (OGRGeometry* g = feature->StealGeometry())
            static_cast<OGRMultiPolygon*>(all.get())->addGeometryDirectly(g);
    }
    return traced;
}

void toMapFrame(std::vector<Polygon2>& polygons, int imageHeight, const RosMapInfo& info) {
    const double c = std::cos(info.yaw), s = std::sin(info.yaw);
    auto place = [&](Vec2& p) {
        const double x = p.x * info.resolution, y = (imageHeight - p.y) * info.resolution;
        p = {info.origin.x + c * x - s * y, info.origin.y + s * x + c * y};
    };
    for (Polygon2& polygon : polygons) {
        for (Vec2& p : polygon.shell)
            place(p);
        for (Ring& hole : polygon.holes)
            for (Vec2& p : hole)
                place(p);
    }
}

int vertexCount(const OGRGeometry* g) {
    std::vector<Polygon2> polygons;
    collectPolygons(g, polygons);
    size_t n = 0;
    for (const Polygon2& p : polygons) {
        n += p.shell.size();
        for (const Ring& h : p.holes)
            n += h.size();
    }
    return static_cast<int>(n);
}

namespace {

// The staircase through the midpoints of its unit cell edges (sub-cell tracing): a wall
// along the grid stays straight where it is, a slanted one lies within half a cell of its
// true line, and Douglas-Peucker then keeps no staircase corner for a wall; a corner between
// two longer runs (a room's corner) stays exact.
OGRLinearRing* throughMidpoints(const OGRLinearRing& ring) {
    auto* out = new OGRLinearRing;
    const int n = ring.getNumPoints(); // closed: the last point repeats the first
    auto edgeLength = [&](int i) {     // of the edge from point i
        return std::hypot(ring.getX(i + 1) - ring.getX(i), ring.getY(i + 1) - ring.getY(i));
    };
    for (int i = 0; i + 1 < n; ++i) {
        const double ax = ring.getX(i), ay = ring.getY(i);
        const double dx = ring.getX(i + 1) - ax, dy = ring.getY(i + 1) - ay;
        // A corner between two runs longer than a step is the shape's own corner: kept.
        if (edgeLength(i) > 1.5 && edgeLength(i > 0 ? i - 1 : n - 2) > 1.5)
            out->addPoint(ax, ay);
        const int steps = std::max(1, static_cast<int>(std::lround(std::hypot(dx, dy))));
        for (int k = 0; k < steps; ++k) {
            const double t = (k + 0.5) / steps;
            out->addPoint(ax + t * dx, ay + t * dy);
        }
    }
    out->closeRings();
    return out;
}

GeometryPtr midpointTrace(const OGRGeometry& traced) {
    auto out = std::make_unique<OGRMultiPolygon>();
    auto add = [&](const OGRPolygon& polygon) {
        auto* p = new OGRPolygon;
        p->addRingDirectly(throughMidpoints(*polygon.getExteriorRing()));
        for (int h = 0; h < polygon.getNumInteriorRings(); ++h)
            p->addRingDirectly(throughMidpoints(*polygon.getInteriorRing(h)));
        out->addGeometryDirectly(p);
    };
    if (auto* collection = dynamic_cast<const OGRGeometryCollection*>(&traced)) {
        for (int i = 0; i < collection->getNumGeometries(); ++i)
            if (auto* polygon = dynamic_cast<const OGRPolygon*>(collection->getGeometryRef(i)))
                add(*polygon);
    } else if (auto* polygon = dynamic_cast<const OGRPolygon*>(&traced)) {
        add(*polygon);
    }
    return out;
}

} // namespace

// Douglas-Peucker on the traced outline through the cell edges' midpoints, keeping the
// topology, then opened by a twentieth of a pixel: a hole touching the outline joins it
// (the plan validation refuses rings that touch); convex corners are cut by 0.05 pixel.
GeometryPtr simplifiedCells(const OGRGeometry& staircase, double tolerance) {
    const GeometryPtr traced = midpointTrace(staircase);
    // A tolerance of 0 still drops the collinear midpoints along each wall.
    GeometryPtr g(traced->SimplifyPreserveTopology(std::max(tolerance, 1e-6)));
    if (!g)
        throw InputError("simplifying the free space failed");
    return openedPolygons(*g, kOpening);
}

GeometryPtr openedMitred(const OGRGeometry& g, double radius, int quadSegments, bool roundErosion,
                         double mitreLimit) {
    GEOSContextHandle_t context = OGRGeometry::createGEOSContext();
    GEOSGeom geometry = g.exportToGEOS(context);
    GEOSGeom eroded = geometry
                          ? GEOSBufferWithStyle_r(
                                context, geometry, -radius, quadSegments, GEOSBUF_CAP_ROUND,
                                roundErosion ? GEOSBUF_JOIN_ROUND : GEOSBUF_JOIN_MITRE, mitreLimit)
                          : nullptr;
    GEOSGeom opened = eroded
                          ? GEOSBufferWithStyle_r(context, eroded, radius, quadSegments,
                                                  GEOSBUF_CAP_FLAT, GEOSBUF_JOIN_MITRE, mitreLimit)
                          : nullptr;
    GeometryPtr out(opened ? OGRGeometryFactory::createFromGEOS(context, opened) : nullptr);
    for (GEOSGeom part : {geometry, eroded, opened})
        if (part)
            GEOSGeom_destroy_r(context, part);
    OGRGeometry::freeGEOSContext(context);
    return out;
}

PassageClosing withoutNarrowPassages(const OGRGeometry& free, double radius) {
    PassageClosing out;
    if (!(radius > kOpening)) {
        out.free.reset(free.clone());
        return out;
    }
    // Round joins around the obstacles' corners: the body's footprint, so that two pillars
    // diagonally apart keep the passage between them when the robot fits. Mitred back, so
    // that right-angled corners come back sharp.
    const GeometryPtr kept = openedMitred(free, radius, 8, true, 1.5);
    const GeometryPtr lost(kept ? free.Difference(kept.get()) : nullptr);
    if (!lost)
        throw InputError("closing the passages narrower than the robot failed");
    // Only the passages are taken from the floor, each simplified and grown by a hair so
    // that it overlaps the obstacles it joins instead of touching them at a point; elsewhere
    // the outline stays as traced (the buffers' round trip moves every corner a little, and
    // a sweep direction a hundredth of a degree off cuts cells at every wall's end).
    std::vector<Polygon2> parts;
    collectPolygons(lost.get(), parts);
    GeometryPtr closed = std::make_unique<OGRMultiPolygon>();
    LocalFloor localFloor(free);
    for (const Polygon2& part : parts) {
        OGRPolygon polygon; // the shell: a passage all round a speck closes over it too
        polygon.addRingDirectly(ogrRing(part.shell));
        if (polygon.get_Area() < kMinPassageArea)
            continue;
        const GeometryPtr simple(polygon.SimplifyPreserveTopology(kPassageTolerance));
        const GeometryPtr grown(simple ? simple->Buffer(kOpening, 1) : nullptr);
        // A passage joins two walls (or parts the floor); a wedge or a notch of one wall,
        // which the opening cuts off as well, changes neither and stays.
        if (!grown || !changesTopology(localFloor, *grown))
            continue;
        GeometryPtr joined(closed->Union(grown.get()));
        if (!joined)
            throw InputError("closing the passages narrower than the robot failed");
        closed = std::move(joined);
    }
    if (closed->IsEmpty()) {
        out.free.reset(free.clone());
        return out;
    }
    const GeometryPtr joined(free.Difference(closed.get()));
    if (joined)
        out.free = simplifiedWhereClosed(*joined, *closed);
    const GeometryPtr taken(out.free ? free.Difference(out.free.get()) : nullptr);
    if (!out.free || !taken)
        throw InputError("closing the passages narrower than the robot failed");
    out.obstaclesJoined = std::max(0, topologyOf(free).second - topologyOf(*out.free).second);
    if (auto* surfaces = dynamic_cast<const OGRGeometryCollection*>(taken.get()))
        out.area = surfaces->get_Area();
    else if (auto* surface = dynamic_cast<const OGRSurface*>(taken.get()))
        out.area = surface->get_Area();
    return out;
}

} // namespace fc::importing
