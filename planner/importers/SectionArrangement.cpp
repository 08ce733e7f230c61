// The exact section of the 3D importer: one CGAL arrangement, per-solid parity by a
// breadth-first walk from the unbounded face, regions traced along face-set borders.
#include "importers/SectionArrangement.h"

#include "model/Plan.h"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Snap_rounding_2.h>
#include <CGAL/Snap_rounding_traits_2.h>
#include <algorithm>
#include <cmath>
#include <deque>
#include <list>
#include <map>
#include <numeric>
#include <set>

namespace fc::building {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using SolidIds = std::vector<int>; // with multiplicity: overlapping segments keep every id

struct ConcatenateIds {
    SolidIds operator()(const SolidIds& a, const SolidIds& b) const {
        SolidIds merged = a;
        merged.insert(merged.end(), b.begin(), b.end());
        return merged;
    }
};

using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, SolidIds, ConcatenateIds>;
using Dcel = CGAL::Arr_face_extended_dcel<Traits, int>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;

// The arrangement with every face numbered and its set of solids (ids of odd parity).
struct Section {
    Arrangement arrangement;
    std::vector<Face> faces;
    std::vector<std::vector<int>> inside; // sorted solid ids per face
    std::vector<double> area;             // per face, m^2 (unbounded: 0)
    int unbounded = -1;
};

int indexOf(Face face) {
    return face->data();
}

template <class Visit> void forEachBorderHalfedge(Face face, Visit visit) {
    if (!face->is_unbounded()) {
        auto circ = face->outer_ccb(), start = circ;
        do
            visit(Halfedge(circ));
        while (++circ != start);
    }
    for (auto hole = face->inner_ccbs_begin(); hole != face->inner_ccbs_end(); ++hole) {
        auto circ = *hole, start = circ;
        do
            visit(Halfedge(circ));
        while (++circ != start);
    }
}

Vec2 toVec2(const Kernel::Point_2& p) { // grid units to metres
    return {CGAL::to_double(p.x()) / kGridPerMetre, CGAL::to_double(p.y()) / kGridPerMetre};
}

double ccbArea(Arrangement::Ccb_halfedge_const_circulator circ) {
    Ring ring;
    auto start = circ;
    do
        ring.push_back(toVec2(circ->source()->point()));
    while (++circ != start);
    return ringArea(ring);
}

// Iterated snap rounding (Hobby, Halperin-Packer) on a 0.1 mm grid: assimp hands over
// single-precision coordinates, so the cuts of one edge by two triangles, T-junctions and
// walls meant to touch differ in the last bits; an exact arrangement of the raw segments
// would keep micrometre gaps and slivers. After snapping, nearly coincident pieces coincide
// exactly. Coordinates are kept on the integer grid (kGridPerMetre units a metre) until output.
void buildSection(Section& section, const std::vector<SectionSegment>& segments) {
    using SnapTraits = CGAL::Snap_rounding_traits_2<Kernel>;
    std::list<Kernel::Segment_2> input;
    std::vector<int> solidOf;
    for (const SectionSegment& s : segments) {
        const Kernel::Point_2 a(s.segment.a.x * kGridPerMetre, s.segment.a.y * kGridPerMetre);
        const Kernel::Point_2 b(s.segment.b.x * kGridPerMetre, s.segment.b.y * kGridPerMetre);
        if (a != b) {
            input.emplace_back(a, b);
            solidOf.push_back(s.solid);
        }
    }
    std::list<std::list<Kernel::Point_2>> snapped;
    CGAL::snap_rounding_2<SnapTraits>(input.begin(), input.end(), snapped, Kernel::FT(1), true,
                                      true, 1);
    std::vector<Traits::Curve_2> curves;
    size_t index = 0;
    for (const auto& polyline : snapped) {
        const int solid = solidOf[std::min(index++, solidOf.size() - 1)];
        for (auto p = polyline.begin(), q = std::next(p);
             p != polyline.end() && q != polyline.end(); ++p, ++q)
            if (*p != *q)
                curves.emplace_back(SegmentTraits::Curve_2(*p, *q), SolidIds{solid});
    }
    Arrangement& arr = section.arrangement;
    CGAL::insert(arr, curves.begin(), curves.end());
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
        f->set_data(static_cast<int>(section.faces.size()));
        section.faces.push_back(f);
        double area = 0;
        if (!f->is_unbounded()) {
            area = ccbArea(f->outer_ccb());
            for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole)
                area -= ccbArea(*hole);
        } else {
            section.unbounded = static_cast<int>(section.area.size());
        }
        section.area.push_back(area);
    }
    // Parity walk: crossing an edge toggles every solid whose segments run along it.
    const size_t n = section.faces.size();
    section.inside.assign(n, {});
    std::vector<bool> seen(n, false);
    std::deque<int> queue{section.unbounded};
    seen[section.unbounded] = true;
    while (!queue.empty()) {
        const int current = queue.front();
        queue.pop_front();
        forEachBorderHalfedge(section.faces[current], [&](Halfedge h) {
            const int next = indexOf(h->twin()->face());
            if (seen[next])
                return;
            std::set<int> odd(section.inside[current].begin(), section.inside[current].end());
            for (int id : h->curve().data())
                if (!odd.erase(id))
                    odd.insert(id);
            section.inside[next].assign(odd.begin(), odd.end());
            seen[next] = true;
            queue.push_back(next);
        });
    }
}

// Splits a closed walk that passes a vertex more than once into simple loops (a region
// touching itself at a corner gives such walks).
void splitAtRepeatedVertices(const std::vector<const void*>& ids, const Ring& walk,
                             std::vector<Ring>& rings) {
    std::vector<size_t> stack;
    std::map<const void*, size_t> position; // vertex -> index in stack
    for (size_t i = 0; i < walk.size(); ++i) {
        const auto seen = position.find(ids[i]);
        if (seen == position.end()) {
            position[ids[i]] = stack.size();
            stack.push_back(i);
            continue;
        }
        Ring loop;
        for (size_t k = seen->second; k < stack.size(); ++k) {
            loop.push_back(walk[stack[k]]);
            if (k > seen->second)
                position.erase(ids[stack[k]]);
        }
        stack.resize(seen->second + 1);
        if (loop.size() >= 3)
            rings.push_back(std::move(loop));
    }
    Ring rest;
    for (size_t k : stack)
        rest.push_back(walk[k]);
    if (rest.size() >= 3)
        rings.push_back(std::move(rest));
}

// Closed rings along the border of a set of faces (the set on the left of each ring).
std::vector<Ring> traceBorder(const Section& section, const std::vector<bool>& member) {
    std::vector<Ring> rings;
    std::set<const void*> used;
    auto isBorder = [&](Halfedge h) {
        return member[indexOf(h->face())] && !member[indexOf(h->twin()->face())];
    };
    for (auto e = section.arrangement.halfedges_begin(); e != section.arrangement.halfedges_end();
         ++e) {
        Halfedge first = e;
        if (!isBorder(first) || used.count(&*first))
            continue;
        Ring walk;
        std::vector<const void*> vertices;
        Halfedge h = first;
        do {
            used.insert(&*h);
            walk.push_back(toVec2(h->source()->point()));
            vertices.push_back(&*h->source());
            Halfedge next = h->next();
            while (!isBorder(next)) // rotate around the target vertex past inner edges
                next = next->twin()->next();
            h = next;
        } while (h != first && walk.size() <= section.arrangement.number_of_halfedges());
        splitAtRepeatedVertices(vertices, walk, rings);
    }
    return rings;
}

// Rings of a region may touch at a vertex (a table leg against a wall corner): the plan model
// wants separate rings, so every ring whose solid side has a convex corner at a shared vertex
// gets that corner cut off by kChamfer (an area change of kChamfer^2 / 2 at most).
void separateTouchingRings(Region& region) {
    std::map<std::pair<double, double>, int> uses;
    std::vector<Ring*> rings{&region.outer};
    for (Ring& hole : region.holes)
        rings.push_back(&hole);
    for (Ring* ring : rings)
        for (Vec2 p : *ring)
            ++uses[{p.x, p.y}];
    for (Ring* ring : rings) {
        Ring cut;
        const size_t n = ring->size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 prev = (*ring)[(i + n - 1) % n], p = (*ring)[i], next = (*ring)[(i + 1) % n];
            const Vec2 in = p - prev, out = next - p;
            if (uses[{p.x, p.y}] < 2 || cross(in, out) >= 0) { // free side on the left
                cut.push_back(p);
                continue;
            }
            const double step = std::min({kChamfer, norm(in) / 4, norm(out) / 4});
            cut.push_back(p - in * (step / norm(in)));
            cut.push_back(p + out * (step / norm(out)));
        }
        *ring = std::move(cut);
    }
}

// One component's border: its outer ring (the largest counter-clockwise one) and its holes.
Region regionOf(const Section& section, const std::vector<bool>& member) {
    Region region;
    for (Ring& ring : traceBorder(section, member)) {
        if (signedArea(ring) < 0)
            region.holes.push_back(std::move(ring));
        else if (ringArea(ring) > ringArea(region.outer))
            region.outer = std::move(ring);
    }
    for (size_t f = 0; f < section.faces.size(); ++f)
        if (member[f])
            region.area += section.area[f];
    separateTouchingRings(region);
    return region;
}

// Connected components of the faces accepted by `joinable`, joined across shared edges.
std::vector<int> components(const Section& section, const std::vector<bool>& joinable) {
    std::vector<int> label(section.faces.size(), -1);
    int next = 0;
    for (size_t start = 0; start < section.faces.size(); ++start) {
        if (!joinable[start] || label[start] >= 0)
            continue;
        std::deque<int> queue{static_cast<int>(start)};
        label[start] = next;
        while (!queue.empty()) {
            const int f = queue.front();
            queue.pop_front();
            forEachBorderHalfedge(section.faces[f], [&](Halfedge h) {
                const int g = indexOf(h->twin()->face());
                if (joinable[g] && label[g] < 0) {
                    label[g] = next;
                    queue.push_back(g);
                }
            });
        }
        ++next;
    }
    return label;
}

} // namespace

FreeSpace enclosedFreeSpace(const std::vector<SectionSegment>& segments,
                            const std::vector<bool>& isDoor, bool doorsAreFloor) {
    Section section;
    buildSection(section, segments);
    const size_t n = section.faces.size();
    std::vector<bool> free(n), doorOnly(n);
    for (size_t f = 0; f < n; ++f) {
        const auto& ids = section.inside[f];
        free[f] = ids.empty();
        doorOnly[f] = !ids.empty() && std::all_of(ids.begin(), ids.end(), [&](int id) {
            return id >= 0 && static_cast<size_t>(id) < isDoor.size() && isDoor[id];
        });
    }
    // Outside: free faces reachable from the unbounded face, door leaves closing openings.
    const std::vector<int> outsideLabel = components(section, free);
    const int outside = outsideLabel[section.unbounded];
    std::vector<bool> floor(n);
    for (size_t f = 0; f < n; ++f)
        floor[f] = (free[f] && outsideLabel[f] != outside) || (doorsAreFloor && doorOnly[f]);
    const std::vector<int> label = components(section, floor);
    std::vector<double> componentArea;
    std::vector<bool> touchesEnclosed; // door-leaf-only components are not floor by themselves
    for (size_t f = 0; f < n; ++f) {
        if (label[f] < 0)
            continue;
        if (static_cast<size_t>(label[f]) >= componentArea.size()) {
            componentArea.resize(label[f] + 1, 0.0);
            touchesEnclosed.resize(label[f] + 1, false);
        }
        componentArea[label[f]] += section.area[f];
        if (free[f])
            touchesEnclosed[label[f]] = true;
    }
    int best = -1;
    FreeSpace result;
    for (size_t c = 0; c < componentArea.size(); ++c) {
        if (!touchesEnclosed[c])
            continue;
        if (best < 0 || componentArea[c] > componentArea[best]) {
            if (best >= 0) {
                ++result.otherRegions;
                result.otherRegionsArea += componentArea[best];
            }
            best = static_cast<int>(c);
        } else {
            ++result.otherRegions;
            result.otherRegionsArea += componentArea[c];
        }
    }
    if (best < 0)
        throw InputError("the section encloses no free space (the outer walls are open at "
                         "that height, or the model is not closed)");
    std::vector<bool> member(n);
    for (size_t f = 0; f < n; ++f)
        member[f] = label[f] == best;
    result.region = regionOf(section, member);
    return result;
}

std::vector<Ring> solidOutlines(const std::vector<SectionSegment>& segments) {
    Section section;
    buildSection(section, segments);
    std::vector<bool> member(section.faces.size());
    for (size_t f = 0; f < member.size(); ++f)
        member[f] = !section.inside[f].empty();
    std::vector<Ring> outer;
    for (Ring& ring : traceBorder(section, member))
        if (signedArea(ring) > 0)
            outer.push_back(std::move(ring));
    std::sort(outer.begin(), outer.end(),
              [](const Ring& a, const Ring& b) { return ringArea(a) > ringArea(b); });
    return outer;
}

} // namespace fc::building
