#include "pipeline/LayoutOffers.h"

#include "pipeline/PerRoomSweep.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <map>
#include <memory>
#include <set>

namespace fc::detail {
namespace {

// Planning a second time is what the per-room search affords on floors it searches; a
// 1,000-room floor would take half as long again (8 s to 13 s).
constexpr size_t kLatticeMaxRooms = 60;
// Headlands are planned on floors of at most this many cells at every angle of the
// variant: they pay where one tour's way back is a large share of it (a hall), and would
// triple the planning time of an office floor (0.66 -> 2.0 s), where they did not shorten
// the path.
constexpr int kHeadlandMaxCells = 40;
// The own-cells offer is not made on floors of more obstacles than this (a laser map imported
// without cleaning: thousands of cells, each plan seconds), as the per-room search is not.
constexpr size_t kOwnOfferMaxObstacles = 500;
// Nor where the dense lattice saved this share of the stripes or more: the real laser maps,
// whose ragged walls start slivers all along them (faculty 39%, lab 47%), where the offer
// never won and cost 1.2-1.5 s of the faculty's 2.5 s. The noisy ward drawn at 17°, 30° and
// 45° saves 35%, 28% and 28%; at 17° the offer won until the touch-ups were priced
// (TouchUpBudget), and now plans the same path as the dense layout. It still wins on 5 of
// the property bench's 250 floors (star and slanted rooms, a pillar hall: up to 27%).
constexpr double kOwnOfferMaxDenseSaving = 0.375;

// Whether the floor's corners start a slab narrower than W/10 in `frame` (stripes along its
// y): a traced outline's jogs and bulges, which drawn floors seldom have.
bool startsSlivers(const Plan& plan, const Frame& frame, double w) {
    std::vector<double> xs;
    auto add = [&](const Ring& ring) {
        for (const Vec2& p : ring)
            xs.push_back(frame.toLocal(p).x);
    };
    add(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        add(obstacle);
    for (const Room& room : plan.rooms)
        add(room.outline);
    std::sort(xs.begin(), xs.end());
    const double same = 1e-9 * std::max(1.0, w);
    for (size_t i = 0; i + 1 < xs.size(); ++i)
        if (xs[i + 1] - xs[i] > same && xs[i + 1] - xs[i] < 0.1 * w)
            return true;
    return false;
}

struct Layout {
    LatticeMode mode;
    Headland headland;
};

struct Variant {
    const PreparedPlans* layout;
    std::map<std::string, double> angles;
};

PlanResult planVariant(const PlanRequest& request, const Variant& variant,
                       const SolveControl& control, bool touchUps) {
    PlanResult again;
    const auto& angles = variant.angles;
    const bool single = std::all_of(angles.begin(), angles.end(), [&](const auto& entry) {
        return entry.second == angles.begin()->second;
    });
    if (single && !request.sweep.perRoom) {
        again = planOneAngle(request, angles.begin()->second, control, variant.layout);
    } else {
        std::map<std::string, double> all = familyAngles(request.plan, request.sweep);
        for (const auto& [room, angle] : angles)
            all[room] = angle;
        again = planWithRoomAngles(request, all, control, *variant.layout);
    }
    if (touchUps)
        applyTouchUps(request, again);
    return again;
}

// Waits for every one of `pending`; keeps what planned, drops offers that cannot be
// planned, rethrows anything else (cancellation) after all have finished.
template <typename T> std::vector<T> collect(std::vector<std::future<T>>& pending) {
    std::vector<T> done;
    std::exception_ptr failure;
    for (std::future<PlanResult>& plan : pending) {
        try {
            done.push_back(plan.get());
        } catch (const InputError&) {
            // An offer: a variant that cannot be planned is not one.
        } catch (const SolverError&) {
            // Nor one beyond the solver's limits (exact: a headland's cells over its limit).
        } catch (...) {
            if (!failure)
                failure = std::current_exception(); // cancelled
        }
    }
    if (failure)
        std::rethrow_exception(failure);
    return done;
}

} // namespace

// Where wide cells meet at an obstacle's corner, stripes on one lattice save a stripe per
// cell (12 m on simple-diamond), or cost turns where lattice lines graze the corner: only
// the path tells. Plans again on the lattice at the angles of `first`, and (where the sweep
// is the planner's choice) with the free rooms turned by 90 degrees, as the per-room search
// did; returns the best of those, if any. Only where some cell would move its stripes, only
// at angles `prepared` built already and on floors of at most 60 rooms; not for solvers bound
// to their own graph.
std::vector<PlanResult> planLayoutOffers(const PlanRequest& request, const PlanResult& first,
                                         const SolveControl& control,
                                         const PreparedPlans& prepared) {
    if (!request.stripeLattice || request.plan.rooms.size() > kLatticeMaxRooms ||
        !plansAnyGraph(request.solver))
        return {};
    const std::map<std::string, double> chosen = roomAnglesOf(first, request.plan);
    std::vector<std::map<std::string, double>> variants{chosen};
    if (request.sweep.perRoom || request.sweep.automatic) {
        std::map<std::string, double> turned = chosen;
        for (auto& [room, angle] : turned)
            if (request.sweep.automatic || request.sweep.roomAngles.count(room) == 0)
                angle = std::fmod(angle + 90.0, 180.0);
        variants.push_back(turned);
    }
    // The building's family swept as one stays on offer where the first plan turned some
    // rooms off it (a room along its second wall family): the layouts below can make it
    // the better plan after all (a generated pair of slanted rooms: 372 s chosen with one
    // room along its second family, where the family on a headland plans 325 s).
    if (request.sweep.perRoom && !request.sweep.automatic) {
        const std::map<std::string, double> family = familyAngles(request.plan, request.sweep);
        const bool offered = std::any_of(variants.begin(), variants.end(), [&](const auto& v) {
            return std::all_of(v.begin(), v.end(), [&](const auto& entry) {
                const auto it = family.find(entry.first);
                return it == family.end() || angleDistance(it->second, entry.second) < 0.5;
            });
        });
        if (!offered)
            variants.push_back(family);
    }
    // Each layout's preparations are shared by its variants, which are planned at once.
    std::vector<std::unique_ptr<PreparedPlans>> layouts;
    std::vector<std::future<PlanResult>> pending;
    SolveControl quiet;
    quiet.cancelled = control.cancelled;
    // Headlands (DecompositionOptions::headland) on the first plan's layout and on the
    // lattice, at the chosen angles: where a tour must come back (its end beside its start),
    // returning along a wall sweeps that wall's band instead of crossing swept floor.
    std::vector<Layout> offers{{LatticeMode::AtCorners, Headland::None},
                               {LatticeMode::Dense, Headland::None}};
    // They are offered on the dense lattice too, at every variant's angles, where the
    // floor's corners start slivers (a traced map's outline: a wall's 2.5 cm bulge): a
    // sliver's own stripes, or the corner lattice's, break the band and cost the tour its
    // way back (noisy room-obstacle: 651.8 s plain, 663.4 s with headlands at the corners,
    // 644.7 s with them on the dense lattice; its drawing plans 642.9 s). Not elsewhere:
    // on the drawn halls it changed nothing and cost 0.8 s of planning.
    bool cornerLattice = false; // whether the corner lattice moves stripes at some angle
    bool slivers = false;       // whether some angle's slabs include slivers
    bool dense = false;         // whether the first plan chose the dense lattice somewhere
    std::set<double> looked;    // each angle's frame once (rooms share angles)
    for (const auto& angles : variants)
        for (const auto& entry : angles) {
            if (!prepared.asked(entry.second, false) || !looked.insert(entry.second).second)
                continue;
            const Decomposition& plain = prepared.shared(entry.second, false)->decomposition;
            cornerLattice = cornerLattice || plain.stripeLatticeAvailable;
            dense = dense || (plain.layout == LatticeMode::Dense &&
                              plain.denseSaving < kOwnOfferMaxDenseSaving);
            slivers =
                slivers || startsSlivers(request.plan, plain.frame, request.robot.coverageWidth);
        }
    // Where the first plan chose the dense lattice by a small margin, every cell spaced on
    // its own is offered in turn: the dense lattice's line beside a bed's or a pillar's
    // side may run closer than L/2 to it, and the strip along that side is left to the
    // touch-ups. A noisy ward map drawn at 30 degrees (the dense lattice saves 28% there,
    // 18% upright, where every cell keeps its own): 5,311 s with it, 4,490 s with every
    // cell on its own; the upright map 4,383 s.
    if (dense && request.plan.obstacles.size() <= kOwnOfferMaxObstacles)
        offers.push_back({LatticeMode::Own, Headland::None});
    const LatticeMode firstLayout =
        cornerLattice ? LatticeMode::AtCorners : prepared.stripeLattice();
    for (const Headland sides : {Headland::Both, Headland::Floors, Headland::Ceilings}) {
        offers.push_back({firstLayout, sides});
        if (slivers && firstLayout != LatticeMode::Dense)
            offers.push_back({LatticeMode::Dense, sides});
    }
    for (const Layout layout : offers) {
        const bool headland = layout.headland != Headland::None;
        const LatticeMode mode = layout.mode;
        layouts.push_back(
            std::make_unique<PreparedPlans>(request.plan, request.robot, request.transitionCells,
                                            prepared.floorCache(), mode, layout.headland));
        const PreparedPlans& lattice = *layouts.back();
        // The dense lattice follows the chosen sweep: turned, it never won on the maps it
        // is for (faculty 8,127 s against 7,912 s; lab 1,299 s against 1,167 s).
        const size_t tried = mode == LatticeMode::Dense && !headland ? 1 : variants.size();
        for (size_t v = 0; v < tried; ++v) {
            const std::map<std::string, double>& angles = variants[v];
            std::set<double> distinct;
            for (const auto& entry : angles)
                distinct.insert(PreparedPlans::roundedAngle(entry.second));
            bool known = true, moves = false, small = true;
            for (double angle : distinct) {
                known = known && prepared.asked(angle, false);
                if (!known)
                    break;
                const Decomposition& plain = prepared.shared(angle, false)->decomposition;
                small = small && static_cast<int>(plain.cells.size()) <= kHeadlandMaxCells;
                if (headland)
                    moves = true;
                else if (mode == LatticeMode::Own)
                    moves = moves || plain.layout == LatticeMode::Dense;
                else
                    moves = moves ||
                            (mode == LatticeMode::Dense
                                 ? plain.denseLatticeAvailable && plain.layout != LatticeMode::Dense
                                 : plain.stripeLatticeAvailable);
            }
            // exact proves the optimum of its own graph within 60 s; a headland graph
            // (36-61 cells on room-obstacle and room-notches) ran it into that limit.
            if (!known || !moves || (headland && (!small || request.solver == "exact")))
                continue;
            pending.push_back(
                std::async(std::launch::async, [&request, quiet, v = Variant{&lattice, angles}]() {
                    return planVariant(request, v, quiet, true);
                }));
        }
    }
    return collect(pending);
}
} // namespace fc::detail
