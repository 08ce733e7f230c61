// Plan validation. The only translation unit that includes CGAL: exact orientation and
// segment-intersection predicates, and box_intersection_d to find candidate pairs of
// edges and rings in O(n log n + k) instead of testing every pair.
#include "model/Validation.h"

#include "model/OverlapArea.h"
#include "model/ValidationSupport.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

namespace fc {

using validation::checkRingShape;
using validation::formatArea;
using validation::formatNumber;
using validation::formatPoint;

namespace {

// m: the widest a plan may be (Earth is 12,742 km across).
constexpr double kMaxPlanSpan = 2e7;
// The most stripe length (free area / W) a plan may need, km: a 10 km^2 site at W = 1 m.
constexpr double kMaxStripeKm = 10000.0;
// The most coverage squares (free area / W^2), the same 10 km^2 at W = 1 m: the stripes'
// index, the path's and the coverage raster grow with them, not with the stripes' length
// (office at W = 5 mm, 114 km of stripes: 23 million squares, 6 GB).
constexpr double kMaxCoverageSquares = 1e7;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;

Kernel::Point_2 toPoint(Vec2 p) {
    return {p.x, p.y};
}

// All rings of the plan with their names: 0 = boundary, then obstacles, then rooms.
struct RingTable {
    const Plan& plan;
    std::vector<const Ring*> rings;
    int firstRoom = 0;

    explicit RingTable(const Plan& p) : plan(p) {
        rings.push_back(&plan.boundary);
        for (const Ring& obstacle : plan.obstacles)
            rings.push_back(&obstacle);
        firstRoom = static_cast<int>(rings.size());
        for (const Room& room : plan.rooms)
            rings.push_back(&room.outline);
    }
    bool isFreeSpace(int ring) const { return ring < firstRoom; }
    std::string name(int ring) const {
        if (ring == 0)
            return "boundary";
        if (ring < firstRoom)
            return "obstacle " + std::to_string(ring);
        return "room \"" + plan.rooms[ring - firstRoom].name + "\"";
    }
};

struct EdgeRef {
    int ring, index;
};

// A defect found among candidate edge pairs; the smallest key is reported so that the
// message does not depend on the order in which pairs are found.
struct Defect {
    std::tuple<int, int, int, int, int> key; // (ring a, ring b, kind, edge a, edge b)
    std::string message;
    Vec2 where;
    bool operator<(const Defect& other) const { return key < other.key; }
};

struct EdgeChecks {
    std::vector<Defect> selfIntersections; // per ring, rooms included
    std::vector<Defect> contacts;          // between boundary and obstacles
};

Vec2 contactPoint(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const double denominator = cross(b - a, d - c);
    if (denominator != 0.0) {
        const double t = cross(c - a, d - c) / denominator;
        if (t > 0.0 && t < 1.0)
            return a + (b - a) * t;
    }
    // Touching or overlapping: the endpoint nearest to the other segment.
    std::pair<double, Vec2> best{pointSegmentDistance(a, c, d), a};
    best = std::min(best, {pointSegmentDistance(b, c, d), b},
                    [](auto& x, auto& y) { return x.first < y.first; });
    best = std::min(best, {pointSegmentDistance(c, a, b), c},
                    [](auto& x, auto& y) { return x.first < y.first; });
    best = std::min(best, {pointSegmentDistance(d, a, b), d},
                    [](auto& x, auto& y) { return x.first < y.first; });
    return best.second;
}

bool properlyCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    using CGAL::orientation;
    const auto pa = toPoint(a), pb = toPoint(b), pc = toPoint(c), pd = toPoint(d);
    const auto o1 = orientation(pa, pb, pc), o2 = orientation(pa, pb, pd);
    const auto o3 = orientation(pc, pd, pa), o4 = orientation(pc, pd, pb);
    return o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR &&
           o4 != CGAL::COLLINEAR && o3 != o4;
}

EdgeChecks checkEdges(const RingTable& table, double tolerance) {
    std::vector<EdgeRef> edges;
    std::vector<Box> boxes;
    for (int r = 0; r < static_cast<int>(table.rings.size()); ++r) {
        const Ring& ring = *table.rings[r];
        for (int i = 0; i < static_cast<int>(ring.size()); ++i) {
            const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
            const CGAL::Bbox_2 box(std::min(a.x, b.x) - tolerance, std::min(a.y, b.y) - tolerance,
                                   std::max(a.x, b.x) + tolerance, std::max(a.y, b.y) + tolerance);
            boxes.emplace_back(box, static_cast<int>(edges.size()));
            edges.push_back({r, i});
        }
    }
    EdgeChecks result;
    auto onPair = [&](const Box& first, const Box& second) {
        EdgeRef e = edges[first.info()], f = edges[second.info()];
        if (std::tie(e.ring, e.index) > std::tie(f.ring, f.index))
            std::swap(e, f);
        const Ring& ringE = *table.rings[e.ring];
        const Ring& ringF = *table.rings[f.ring];
        const int n = static_cast<int>(ringE.size());
        const Vec2 a = ringE[e.index], b = ringE[(e.index + 1) % n];
        const Vec2 c = ringF[f.index], d = ringF[(f.index + 1) % ringF.size()];
        // Spikes (kind 0) explain a ring better than the crossings they cause (kind 1).
        const auto spikeKey = std::make_tuple(e.ring, f.ring, 0, e.index, f.index);
        const auto key = std::make_tuple(e.ring, f.ring, 1, e.index, f.index);
        if (e.ring == f.ring) {
            const bool eThenF = (e.index + 1) % n == f.index, fThenE = (f.index + 1) % n == e.index;
            if (eThenF || fThenE) {
                // Neighbouring edges meet at their shared vertex; they must not fold back.
                const Vec2 shared = eThenF ? b : a;
                const Vec2 before = eThenF ? a : c, after = eThenF ? d : b;
                const bool foldsBack = dot(before - shared, after - shared) > 0.0 &&
                                       (pointSegmentDistance(after, shared, before) <= tolerance ||
                                        pointSegmentDistance(before, shared, after) <= tolerance);
                if (foldsBack)
                    result.selfIntersections.push_back({spikeKey,
                                                        table.name(e.ring) +
                                                            " folds back on itself (a spike) at " +
                                                            formatPoint(shared),
                                                        shared});
                return;
            }
        } else if (!table.isFreeSpace(e.ring) || !table.isFreeSpace(f.ring)) {
            return; // rooms may share borders with anything; their overlaps are areas
        }
        const bool meet = CGAL::do_intersect(Kernel::Segment_2(toPoint(a), toPoint(b)),
                                             Kernel::Segment_2(toPoint(c), toPoint(d))) ||
                          segmentSegmentDistance(a, b, c, d) <= tolerance;
        if (!meet)
            return;
        const Vec2 where = contactPoint(a, b, c, d);
        const bool crossing = properlyCross(a, b, c, d);
        if (e.ring == f.ring) {
            result.selfIntersections.push_back(
                {key,
                 table.name(e.ring) +
                     (crossing ? " intersects itself near " : " touches itself at ") +
                     formatPoint(where),
                 where});
        } else if (e.ring == 0) {
            result.contacts.push_back(
                {key,
                 table.name(f.ring) + (crossing ? " crosses the boundary near " + formatPoint(where)
                                                : " touches the boundary at " + formatPoint(where) +
                                                      "; obstacles must lie strictly inside it"),
                 where});
        } else {
            result.contacts.push_back(
                {key,
                 "obstacles " + std::to_string(e.ring) + " and " + std::to_string(f.ring) +
                     (crossing
                          ? " overlap near " + formatPoint(where)
                          : " touch at " + formatPoint(where) + "; merge them into one obstacle"),
                 where});
        }
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), onPair);
    return result;
}

void throwFirst(std::vector<Defect>& defects, int fromRing, int toRing) {
    std::sort(defects.begin(), defects.end());
    for (const Defect& defect : defects) {
        if (std::get<0>(defect.key) >= fromRing && std::get<0>(defect.key) < toRing)
            throw RepairablePlanError(defect.message);
    }
}

void checkDuplicateObstacles(const Plan& plan) {
    std::map<std::vector<std::pair<double, double>>, size_t> seen;
    for (size_t k = 0; k < plan.obstacles.size(); ++k) {
        std::vector<std::pair<double, double>> vertices;
        for (const Vec2& p : plan.obstacles[k])
            vertices.emplace_back(p.x, p.y);
        std::sort(vertices.begin(), vertices.end());
        const auto [it, inserted] = seen.emplace(std::move(vertices), k + 1);
        if (!inserted)
            throw RepairablePlanError("obstacles " + std::to_string(it->second) + " and " +
                                      std::to_string(k + 1) +
                                      " are identical (duplicate obstacle)");
    }
}

CGAL::Bbox_2 ringBox(const Ring& ring, double margin = 0.0) {
    const BoundingBox b = boundsOf(ring);
    return {b.minX - margin, b.minY - margin, b.maxX + margin, b.maxY + margin};
}

bool boxContains(const CGAL::Bbox_2& outer, const CGAL::Bbox_2& inner) {
    return outer.xmin() <= inner.xmin() && outer.ymin() <= inner.ymin() &&
           outer.xmax() >= inner.xmax() && outer.ymax() >= inner.ymax();
}

// Obstacles touch nothing at this point, so one vertex decides inside or outside.
void checkObstaclePlacement(const Plan& plan) {
    const overlap::EvenOddIndex boundary(overlap::edgesOf(plan.boundary));
    for (size_t k = 0; k < plan.obstacles.size(); ++k) {
        if (!boundary.contains(plan.obstacles[k][0]))
            throw RepairablePlanError("obstacle " + std::to_string(k + 1) +
                                      " lies outside the boundary, near " +
                                      formatPoint(plan.obstacles[k][0]));
    }
    std::vector<Box> boxes;
    for (size_t k = 0; k < plan.obstacles.size(); ++k)
        boxes.emplace_back(ringBox(plan.obstacles[k]), static_cast<int>(k));
    std::vector<std::pair<int, int>> nested; // (outer, inner)
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        for (auto [outer, inner] : {std::pair(x, y), std::pair(y, x)}) {
            const Ring& outerRing = plan.obstacles[outer.info()];
            const Ring& innerRing = plan.obstacles[inner.info()];
            if (boxContains(outer.bbox(), inner.bbox()) && pointInRing(outerRing, innerRing[0]))
                nested.emplace_back(outer.info(), inner.info());
        }
    });
    if (!nested.empty()) {
        const auto [outer, inner] = *std::min_element(nested.begin(), nested.end());
        throw RepairablePlanError("obstacle " + std::to_string(inner + 1) +
                                  " lies inside obstacle " + std::to_string(outer + 1));
    }
}

void checkFreeArea(const Plan& plan, const RobotProfile& robot) {
    double freeArea = ringArea(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        freeArea -= ringArea(obstacle);
    const double footprint = M_PI * robot.robotDiameter * robot.robotDiameter / 4.0;
    const double square = robot.coverageWidth * robot.coverageWidth;
    if (freeArea < footprint)
        throw InputError("free area " + formatArea(freeArea) +
                         " (boundary minus obstacles) is smaller than the robot footprint " +
                         formatArea(footprint) + " (L = " + formatNumber(robot.robotDiameter) +
                         " m)");
    if (freeArea < square)
        throw InputError("free area " + formatArea(freeArea) +
                         " (boundary minus obstacles) is smaller than one coverage square W^2 = " +
                         formatArea(square));
    // A drawing in millimetres read as metres is a million times the area: its planning
    // would run for hours and take tens of GB (office x 100: 5,700 km of stripes, 30 s,
    // 1.7 GB; x 1,000 did not finish), so it is refused with the likely cause.
    const double stripeKm = freeArea / robot.coverageWidth / 1000.0;
    if (stripeKm > kMaxStripeKm) {
        char km[64];
        std::snprintf(km, sizeof km, "%.0f km of stripes", stripeKm);
        throw InputError("free area " + formatArea(freeArea) + " needs about " + km +
                         " at W = " + formatNumber(robot.coverageWidth) +
                         " m, more than the planner's limit of 10000 km: is the plan in "
                         "metres? (a drawing in millimetres is 1,000 times too large)");
    }
    if (freeArea / square > kMaxCoverageSquares) {
        char squares[64];
        std::snprintf(squares, sizeof squares, "%.1f million", freeArea / square / 1e6);
        throw InputError("free area " + formatArea(freeArea) + " is " + squares +
                         " coverage squares W^2 at W = " + formatNumber(robot.coverageWidth) +
                         " m, more than the planner's limit of 10 million: is W in metres? "
                         "(W = 0.005 is 5 mm)");
    }
}

void checkRoomNames(const Plan& plan) {
    std::map<std::string, size_t> seen;
    for (size_t i = 0; i < plan.rooms.size(); ++i) {
        const std::string& name = plan.rooms[i].name;
        if (name.find_first_not_of(" \t") == std::string::npos)
            throw InputError("room " + std::to_string(i + 1) + " has no name");
        if (!seen.emplace(name, i).second)
            throw InputError("duplicate room name \"" + name + "\"");
    }
}

bool nearRing(const Ring& ring, Vec2 p, double tolerance) {
    for (size_t i = 0; i < ring.size(); ++i) {
        if (pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]) <= tolerance)
            return true;
    }
    return false;
}

// Why a room shares no area with the free space, as precisely as cheaply possible.
std::string roomOutsideMessage(const Plan& plan, const Room& room, double tolerance) {
    const std::string name = "room \"" + room.name + "\"";
    auto within = [&](const Ring& ring) {
        return std::all_of(room.outline.begin(), room.outline.end(), [&](Vec2 p) {
            return pointInRing(ring, p) || nearRing(ring, p, tolerance);
        });
    };
    for (size_t k = 0; k < plan.obstacles.size(); ++k) {
        if (within(plan.obstacles[k]))
            return name + " lies inside obstacle " + std::to_string(k + 1);
    }
    const bool anyVertexInside = std::any_of(room.outline.begin(), room.outline.end(), [&](Vec2 p) {
        return pointInRing(plan.boundary, p) && !nearRing(plan.boundary, p, tolerance);
    });
    if (!anyVertexInside)
        return name + " lies outside the boundary";
    return name + " does not overlap the free space (it covers only obstacles)";
}

void checkRooms(const Plan& plan, const RobotProfile& robot, double tolerance) {
    if (plan.rooms.empty())
        return;
    checkRoomNames(plan);
    // The free space: boundary and obstacle edges with the free side on their left.
    std::vector<overlap::DirectedEdge> freeEdges = overlap::edgesOf(plan.boundary, true);
    for (const Ring& obstacle : plan.obstacles) {
        const auto edges = overlap::edgesOf(obstacle, false);
        freeEdges.insert(freeEdges.end(), edges.begin(), edges.end());
    }
    const overlap::EvenOddIndex freeIndex(freeEdges);
    auto insideFree = [&](Vec2 p) { return freeIndex.contains(p); };
    const Vec2 origin = plan.boundary.front();

    const size_t roomCount = plan.rooms.size();
    std::vector<Box> roomBoxes, edgeBoxes;
    // Room boxes are widened by the tolerance: a wall that close to a room's edge is shared.
    for (size_t r = 0; r < roomCount; ++r)
        roomBoxes.emplace_back(ringBox(plan.rooms[r].outline, tolerance), static_cast<int>(r));
    for (size_t i = 0; i < freeEdges.size(); ++i) {
        const overlap::DirectedEdge& e = freeEdges[i];
        const CGAL::Bbox_2 box(std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y),
                               std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y));
        edgeBoxes.emplace_back(box, static_cast<int>(i));
    }
    std::vector<std::vector<int>> nearbyEdges(roomCount);
    CGAL::box_intersection_d(
        roomBoxes.begin(), roomBoxes.end(), edgeBoxes.begin(), edgeBoxes.end(),
        [&](const Box& room, const Box& edge) { nearbyEdges[room.info()].push_back(edge.info()); });

    std::vector<std::vector<overlap::DirectedEdge>> roomEdges(roomCount);
    for (size_t r = 0; r < roomCount; ++r) {
        const Room& room = plan.rooms[r];
        roomEdges[r] = overlap::edgesOf(room.outline, true);
        std::sort(nearbyEdges[r].begin(), nearbyEdges[r].end()); // order-independent sums
        std::vector<overlap::DirectedEdge> nearby;
        for (int i : nearbyEdges[r])
            nearby.push_back(freeEdges[i]);
        const overlap::EvenOddIndex roomIndex(roomEdges[r]); // traced rooms: many vertices
        const auto insideRoom = [&](Vec2 p) { return roomIndex.contains(p); };
        const auto shared =
            overlap::overlapArea(roomEdges[r], insideRoom, nearby, insideFree, origin, tolerance);
        const BoundingBox box = boundsOf(room.outline);
        const double noise = 100.0 * tolerance * (box.width() + box.height());
        if (shared.area <= noise)
            throw InputError(roomOutsideMessage(plan, room, tolerance));
    }

    // Rooms may share walls, and sloppy drawing leaves slivers of overlap; more than a
    // quarter of a coverage square W^2 or 1% of the smaller room gives floor to two rooms.
    std::vector<std::pair<int, int>> candidates;
    CGAL::box_self_intersection_d(
        roomBoxes.begin(), roomBoxes.end(), [&](const Box& x, const Box& y) {
            candidates.emplace_back(std::min(x.info(), y.info()), std::max(x.info(), y.info()));
        });
    std::sort(candidates.begin(), candidates.end());
    const double coverageSquare = robot.coverageWidth * robot.coverageWidth;
    for (const auto& [i, j] : candidates) {
        const Room& first = plan.rooms[i];
        const Room& second = plan.rooms[j];
        const double allowed =
            std::max(0.25 * coverageSquare,
                     0.01 * std::min(ringArea(first.outline), ringArea(second.outline)));
        // The shared area is at most that of the bounding boxes' intersection.
        const BoundingBox a = boundsOf(first.outline), b = boundsOf(second.outline);
        const double boxOverlap =
            std::max(0.0, std::min(a.maxX, b.maxX) - std::max(a.minX, b.minX)) *
            std::max(0.0, std::min(a.maxY, b.maxY) - std::max(a.minY, b.minY));
        if (boxOverlap <= allowed)
            continue;
        const auto shared = overlap::overlapArea(
            roomEdges[i], [&](Vec2 p) { return pointInRing(first.outline, p); }, roomEdges[j],
            [&](Vec2 p) { return pointInRing(second.outline, p); }, origin, tolerance);
        if (shared.area > allowed)
            throw RepairablePlanError(
                "rooms \"" + first.name + "\" and \"" + second.name + "\" overlap by " +
                formatArea(shared.area) +
                (shared.hasSample ? " near " + formatPoint(shared.sample) : ""));
    }
}

} // namespace

std::vector<PlanProblem> planProblems(const Plan& plan, const RobotProfile& robot, size_t limit) {
    std::vector<PlanProblem> problems;
    const auto add = [&](const std::string& message, const Vec2* where) {
        if (problems.size() >= limit)
            return;
        PlanProblem problem;
        problem.message = message;
        if (where && std::isfinite(where->x) && std::isfinite(where->y)) {
            problem.hasLocation = true;
            problem.location = *where;
        }
        problems.push_back(std::move(problem));
    };
    const RingTable table(plan);
    const int ringCount = static_cast<int>(table.rings.size());
    const double tolerance = validation::planTolerance(plan);
    bool shapesOk = true;
    for (int r = 0; r < ringCount; ++r) {
        try {
            checkRingShape(*table.rings[r], table.name(r), tolerance);
        } catch (const InputError& e) {
            shapesOk = false;
            const Ring& ring = *table.rings[r];
            add(e.what(), ring.empty() ? nullptr : &ring.front());
        }
    }
    if (shapesOk) {
        EdgeChecks checks = checkEdges(table, tolerance);
        for (auto* defects : {&checks.selfIntersections, &checks.contacts}) {
            std::sort(defects->begin(), defects->end());
            for (const Defect& defect : *defects)
                add(defect.message, &defect.where);
        }
    }
    if (problems.empty()) {
        try {
            validatePlan(plan, robot);
        } catch (const InputError& e) {
            add(e.what(), nullptr);
        }
    }
    return problems;
}

void validatePlan(const Plan& plan, const RobotProfile& robot) {
    robot.validate();
    // Before the ring checks, whose tolerances grow with the plan: a 1e10 m long rectangle
    // was refused for "repeating" its 8 m short side's vertices.
    if (!plan.boundary.empty()) {
        const BoundingBox box = plan.bounds();
        const double span = std::max(box.maxX - box.minX, box.maxY - box.minY);
        if (std::isfinite(span) && span > kMaxPlanSpan) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "the boundary spans %.3g km, more than the %.0f km of any site on "
                          "Earth: is the plan in metres?",
                          span / 1000.0, kMaxPlanSpan / 1000.0);
            throw InputError(text);
        }
    }
    const RingTable table(plan);
    const int ringCount = static_cast<int>(table.rings.size());
    const double tolerance = validation::planTolerance(plan);
    for (int r = 0; r < ringCount; ++r)
        checkRingShape(*table.rings[r], table.name(r), tolerance);

    // The free space first: the room checks measure areas against it.
    EdgeChecks edgeChecks = checkEdges(table, tolerance);
    throwFirst(edgeChecks.selfIntersections, 0, table.firstRoom);
    checkDuplicateObstacles(plan);
    throwFirst(edgeChecks.contacts, 0, table.firstRoom);
    checkObstaclePlacement(plan);
    checkFreeArea(plan, robot);

    throwFirst(edgeChecks.selfIntersections, table.firstRoom, ringCount);
    checkRooms(plan, robot, tolerance);
}

} // namespace fc
