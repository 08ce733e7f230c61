// From outlines to a plan with GEOS (through GDAL's OGR geometry): boundary minus the union
// of the obstacles, so overlapping, duplicated (outline + hatch) or wall-touching obstacles
// give one clean free-space polygon. Also the WKT importer.
#include "importers/OgrSupport.h"
#include "model/Validation.h"

#include <algorithm>
#include <memory>
#include <set>
#include <sstream>

namespace fc::importing {

namespace {

Ring fromOgrRing(const OGRLinearRing& ring) {
    Ring out;
    for (int i = 0; i < ring.getNumPoints(); ++i)
        out.push_back({ring.getX(i), ring.getY(i)});
    // The closing point repeats the first; a ring written without it (WKT that GDAL reads as
    // it stands) keeps its last vertex (it had lost it: half of a rectangle's floor).
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

GeometryPtr shellPolygon(const Ring& shell) {
    auto polygon = std::make_unique<OGRPolygon>();
    polygon->addRingDirectly(ogrRing(shell));
    return polygon;
}

// A valid polygonal geometry for a ring (self-intersecting rings repaired by MakeValid).
GeometryPtr polygonOf(const Ring& ring) {
    auto polygon = std::make_unique<OGRPolygon>();
    polygon->addRingDirectly(ogrRing(ring));
    if (polygon->IsValid())
        return polygon;
    GeometryPtr valid(polygon->MakeValid());
    return valid ? std::move(valid) : GeometryPtr(polygon->Buffer(0));
}

double areaOf(const Polygon2& p) {
    double a = ringArea(p.shell);
    for (const Ring& h : p.holes)
        a -= ringArea(h);
    return a;
}

std::string roomName(const Ring& outline, const std::vector<Label>& labels,
                     std::set<std::string>& taken) {
    std::string name;
    for (const Label& label : labels)
        if (pointInRing(outline, label.at)) {
            name = label.text;
            break;
        }
    if (name.empty())
        name = "Room " + std::to_string(taken.size() + 1);
    std::string unique = name;
    for (int n = 2; taken.count(unique); ++n)
        unique = name + " " + std::to_string(n);
    taken.insert(unique);
    return unique;
}

} // namespace

OGRLinearRing* ogrRing(const Ring& ring) {
    auto* out = new OGRLinearRing;
    for (const Vec2& p : ring)
        out->addPoint(p.x, p.y);
    out->closeRings();
    return out;
}

OGRPolygon* ogrPolygon(const Ring& shell, const std::vector<Ring>& holes) {
    auto* p = new OGRPolygon;
    p->addRingDirectly(ogrRing(shell));
    for (const Ring& h : holes)
        p->addRingDirectly(ogrRing(h));
    return p;
}

void collectPolygons(const OGRGeometry* g, std::vector<Polygon2>& out) {
    if (!g || g->IsEmpty())
        return;
    const OGRwkbGeometryType type = wkbFlatten(g->getGeometryType());
    if (type == wkbPolygon) {
        const OGRPolygon* polygon = g->toPolygon();
        Polygon2 p;
        p.shell = fromOgrRing(*polygon->getExteriorRing());
        for (int i = 0; i < polygon->getNumInteriorRings(); ++i)
            p.holes.push_back(fromOgrRing(*polygon->getInteriorRing(i)));
        out.push_back(std::move(p));
    } else if (type == wkbMultiPolygon || type == wkbGeometryCollection) {
        const OGRGeometryCollection* c = g->toGeometryCollection();
        for (int i = 0; i < c->getNumGeometries(); ++i)
            collectPolygons(c->getGeometryRef(i), out);
    }
}

Plan planFromPolygons(std::vector<Polygon2> polygons, const std::string& what,
                      std::vector<std::string>& warnings) {
    if (polygons.empty())
        throw InputError("no " + what + " left to import");
    std::sort(polygons.begin(), polygons.end(),
              [](const Polygon2& a, const Polygon2& b) { return areaOf(a) > areaOf(b); });
    if (polygons.size() > 1) {
        double dropped = 0;
        for (size_t i = 1; i < polygons.size(); ++i)
            dropped += areaOf(polygons[i]);
        std::ostringstream text;
        text.precision(3);
        text << polygons.size() - 1 << " separate " << what << " part"
             << (polygons.size() == 2 ? "" : "s") << " (" << dropped
             << " m2) not connected to the largest; dropped";
        warnings.push_back(text.str());
    }
    Plan plan;
    plan.boundary = std::move(polygons.front().shell);
    plan.obstacles = std::move(polygons.front().holes);
    return plan;
}

// The plan of `free` minus the union of `obstacles`: its largest part (the others dropped
// with a warning), shell as boundary and holes as obstacles.
Plan freeSpacePlan(GeometryPtr free, const OGRMultiPolygon& obstacles,
                   std::vector<std::string>& warnings) {
    if (!obstacles.IsEmpty()) {
        GeometryPtr merged(obstacles.UnionCascaded());
        if (!merged)
            throw InputError("the obstacles could not be merged (invalid geometry)");
        free.reset(free->Difference(merged.get()));
        if (!free)
            throw InputError("the obstacles could not be cut out of the boundary");
    }
    std::vector<Polygon2> parts;
    collectPolygons(free.get(), parts);
    return planFromPolygons(std::move(parts), "free area", warnings);
}

Plan assemblePlan(const std::vector<Outline>& outlines, const std::vector<Label>& labels,
                  const LayerMapping& mapping, std::vector<std::string>& warnings) {
    std::vector<const Outline*> boundaryCandidates, rest, rooms;
    for (const Outline& o : outlines) {
        const Role role = roleOfLayer(o.layer, mapping);
        if (role == Role::Room)
            rooms.push_back(&o);
        else if (role == Role::Boundary)
            boundaryCandidates.push_back(&o);
        else if (role != Role::Ignored)
            rest.push_back(&o);
    }
    if (boundaryCandidates.empty()) // no boundary layer: the largest outline of all
        for (const Outline* o : rest)
            if (roleOfLayer(o->layer, mapping) == Role::Unassigned)
                boundaryCandidates.push_back(o);
    if (boundaryCandidates.empty()) {
        std::string open;
        for (const std::string& w : warnings)
            if (w.find("not closed") != std::string::npos)
                open += (open.empty() ? "; " : ", ") + w.substr(0, w.find(" not closed"));
        throw InputError("no closed outline for the boundary" + open +
                         (open.empty() ? "" : " (a larger gap tolerance may close them)"));
    }
    const Outline* boundary = *std::max_element(
        boundaryCandidates.begin(), boundaryCandidates.end(),
        [](const Outline* a, const Outline* b) { return ringArea(a->ring) < ringArea(b->ring); });
    for (const Outline* o : boundaryCandidates)
        if (o != boundary && std::find(rest.begin(), rest.end(), o) == rest.end())
            rest.push_back(o);

    GeometryPtr free = polygonOf(boundary->ring);
    auto obstacles = std::make_unique<OGRMultiPolygon>();
    size_t outside = 0;
    for (const Outline* o : rest) {
        if (o == boundary)
            continue;
        GeometryPtr p = polygonOf(o->ring);
        if (!p || !p->Intersects(free.get())) {
            ++outside;
            continue;
        }
        std::vector<Polygon2> parts;
        collectPolygons(p.get(), parts);
        for (const Polygon2& part : parts)
            obstacles->addGeometryDirectly(shellPolygon(part.shell).release());
    }
    if (outside > 0)
        warnings.push_back(std::to_string(outside) +
                           " closed outlines outside the boundary ignored");
    Plan plan = freeSpacePlan(std::move(free), *obstacles, warnings);

    std::set<std::string> taken;
    size_t roomsOutside = 0;
    GeometryPtr freeArea = polygonOf(plan.boundary);
    for (const Outline* o : rooms) {
        GeometryPtr p = polygonOf(o->ring);
        if (!p || !p->Intersects(freeArea.get())) {
            ++roomsOutside;
            continue;
        }
        plan.rooms.push_back({roomName(o->ring, labels, taken), o->ring});
    }
    if (roomsOutside > 0)
        warnings.push_back(std::to_string(roomsOutside) + " room outlines outside the boundary "
                                                          "ignored");
    return plan;
}

namespace {

std::string squareMetres(double area) {
    std::ostringstream text;
    text.precision(area < 10 ? 2 : 3);
    text << area << " m2";
    return text.str();
}

// The largest polygon of a geometry, or an empty one.
Polygon2 largestPart(const OGRGeometry* g, size_t* partCount = nullptr) {
    std::vector<Polygon2> parts;
    collectPolygons(g, parts);
    if (partCount)
        *partCount = parts.size();
    if (parts.empty())
        return {};
    return *std::max_element(parts.begin(), parts.end(), [](const Polygon2& a, const Polygon2& b) {
        return areaOf(a) < areaOf(b);
    });
}

} // namespace

namespace {

constexpr double kTouchShrink = 1e-3; // m

// Whether the plan's checks stop at rings that touch (validatePlan's words).
bool hasPointTouches(const Plan& plan) {
    for (const PlanProblem& problem : planProblems(plan, RobotProfile{}, 20))
        if (problem.message.find(" touch") != std::string::npos)
            return true;
    return false;
}

} // namespace

Plan repairBrokenPlan(const Plan& broken, std::vector<std::string>& notes) {
    ensureGdal();
    if (broken.boundary.size() < 3)
        throw InputError("the plan has no boundary to repair");
    GeometryPtr free = polygonOf(broken.boundary);
    if (!free || free->IsEmpty())
        throw InputError("the boundary encloses no area");
    if (!shellPolygon(broken.boundary)->IsValid())
        notes.push_back("the boundary crossed or touched itself: split where it does");
    auto obstacles = std::make_unique<OGRMultiPolygon>();
    size_t dropped = 0, selfCrossing = 0;
    for (const Ring& ring : broken.obstacles) {
        if (ring.size() < 3) {
            ++dropped;
            continue;
        }
        std::vector<Polygon2> parts;
        GeometryPtr p = polygonOf(ring);
        collectPolygons(p.get(), parts);
        if (parts.empty())
            ++dropped;
        else if (!shellPolygon(ring)->IsValid())
            ++selfCrossing;
        for (const Polygon2& part : parts)
            obstacles->addGeometryDirectly(shellPolygon(part.shell).release());
    }
    if (dropped > 0)
        notes.push_back(std::to_string(dropped) + " obstacle(s) without area removed");
    if (selfCrossing > 0)
        notes.push_back(std::to_string(selfCrossing) +
                        " obstacle(s) crossed themselves: split where they cross");
    std::vector<std::string> warnings;
    Plan plan = freeSpacePlan(std::move(free), *obstacles, warnings);
    // Obstacles that touch the wall or each other at a single point (a diamond's corner on
    // the wall) leave a pinch the cut-out cannot remove: shrunk by a millimetre they stand
    // apart, and the gap is far narrower than any robot.
    if (!plan.obstacles.empty() && hasPointTouches(plan)) {
        // The plan's own holes: a boundary that touched itself made some of them.
        auto shrunk = std::make_unique<OGRMultiPolygon>();
        for (const Ring& hole : plan.obstacles) {
            GeometryPtr part(shellPolygon(hole)->Buffer(-kTouchShrink, 1));
            std::vector<Polygon2> pieces;
            collectPolygons(part.get(), pieces);
            for (const Polygon2& piece : pieces)
                shrunk->addGeometryDirectly(shellPolygon(piece.shell).release());
        }
        std::vector<std::string> again;
        Plan apart = freeSpacePlan(shellPolygon(plan.boundary), *shrunk, again);
        if (!hasPointTouches(apart)) {
            plan = std::move(apart);
            warnings = std::move(again);
            notes.push_back("obstacles that touched the wall or each other at a point shrunk "
                            "by 1 mm");
        }
    }
    for (const std::string& w : warnings)
        notes.push_back(w);
    if (plan.obstacles.size() != broken.obstacles.size())
        notes.push_back("obstacles merged, clipped to the boundary or joined to the wall: " +
                        std::to_string(broken.obstacles.size()) + " before, " +
                        std::to_string(plan.obstacles.size()) + " after");
    plan.name = broken.name;
    plan.epsg = broken.epsg;

    // Rooms: valid, inside the free space, not over the rooms before them.
    GeometryPtr freeArea = polygonOf(plan.boundary);
    std::unique_ptr<OGRGeometry> claimed;
    std::set<std::string> taken;
    for (const Room& room : broken.rooms) {
        const std::string label = room.name.find_first_not_of(" \t") == std::string::npos
                                      ? "an unnamed room"
                                      : "room \"" + room.name + "\"";
        GeometryPtr p = room.outline.size() >= 3 ? polygonOf(room.outline) : nullptr;
        if (p && !p->IsEmpty())
            p.reset(p->Intersection(freeArea.get()));
        if (p && claimed && !p->IsEmpty())
            p.reset(p->Difference(claimed.get()));
        size_t count = 0;
        const Polygon2 part = p ? largestPart(p.get(), &count) : Polygon2{};
        if (part.shell.size() < 3 || ringArea(part.shell) < 1e-6) {
            notes.push_back(label + " lies outside the floor or under other rooms: removed");
            continue;
        }
        const double before = ringArea(room.outline), after = ringArea(part.shell);
        if (count > 1 || std::abs(after - before) > 1e-6 * std::max(1.0, before))
            notes.push_back(label + " reshaped to fit the floor (" + squareMetres(before) +
                            " before, " + squareMetres(after) + " after)");
        std::string name = room.name.find_first_not_of(" \t") == std::string::npos
                               ? "Room " + std::to_string(plan.rooms.size() + 1)
                               : room.name;
        const std::string base = name;
        for (int n = 2; taken.count(name); ++n)
            name = base + " " + std::to_string(n);
        if (name != room.name)
            notes.push_back(label + " renamed \"" + name + "\"");
        taken.insert(name);
        plan.rooms.push_back({name, part.shell});
        GeometryPtr shell = shellPolygon(part.shell);
        claimed.reset(claimed ? claimed->Union(shell.get()) : shell.release());
    }
    return plan;
}

// WKT: POLYGON or MULTIPOLYGON (an "SRID=n;" prefix sets the EPSG code). The first
// polygon's shell is the boundary and its holes the obstacles; further polygons are rooms
// ("Room 2", "Room 3", ...). Coordinates are metres unless options.metresPerUnit says.
ImportResult importWkt(const std::string& text, const ImportOptions& options) {
    ensureGdal();
    std::string wkt = text;
    ImportResult result;
    if (wkt.size() > 5 && (wkt.compare(0, 5, "SRID=") == 0 || wkt.compare(0, 5, "srid=") == 0)) {
        const size_t semicolon = wkt.find(';');
        if (semicolon == std::string::npos)
            throw InputError("\"SRID=\" without \";\"");
        try {
            result.project.plan.epsg = std::stoi(wkt.substr(5, semicolon - 5));
        } catch (const std::exception&) {
            throw InputError("SRID is not a number");
        }
        wkt = wkt.substr(semicolon + 1);
    }
    OGRGeometry* raw = nullptr;
    const char* cursor = wkt.c_str();
    if (OGRGeometryFactory::createFromWkt(&cursor, nullptr, &raw) != OGRERR_NONE || !raw)
        throw InputError("not valid WKT");
    GeometryPtr geometry(raw);
    if (std::string(cursor).find_first_not_of(" \t\r\n") != std::string::npos)
        throw InputError("text after the WKT geometry");
    if (geometry->hasCurveGeometry())
        geometry.reset(geometry->getLinearGeometry());
    const OGRwkbGeometryType type = wkbFlatten(geometry->getGeometryType());
    if (type != wkbPolygon && type != wkbMultiPolygon)
        throw InputError(std::string("WKT ") + geometry->getGeometryName() +
                         " is not a POLYGON or MULTIPOLYGON");
    std::vector<Polygon2> polygons;
    collectPolygons(geometry.get(), polygons);
    if (polygons.empty())
        throw InputError("the WKT polygon is empty");
    if (options.metresPerUnit) {
        const double k = *options.metresPerUnit;
        for (Polygon2& p : polygons) {
            for (Vec2& v : p.shell)
                v = {v.x * k, v.y * k};
            for (Ring& h : p.holes)
                for (Vec2& v : h)
                    v = {v.x * k, v.y * k};
        }
    }
    Plan& plan = result.project.plan;
    plan.boundary = polygons.front().shell;
    plan.obstacles = polygons.front().holes;
    for (size_t i = 1; i < polygons.size(); ++i) {
        if (!polygons[i].holes.empty())
            result.warnings.push_back("holes of polygon " + std::to_string(i + 1) +
                                      " (a room) ignored");
        plan.rooms.push_back({"Room " + std::to_string(i + 1), polygons[i].shell});
    }
    return result;
}

} // namespace fc::importing

namespace fc {

Plan repairPlan(const Plan& plan, std::vector<std::string>& notes) {
    return importing::repairBrokenPlan(plan, notes);
}

} // namespace fc
