// Prepared plans (decomposition and corner graph) of one plan and robot, built once per
// sweep angle and shared by every candidate planned at that angle. The per-room search
// plans the building's family, the rooms' own angles and their turned variants: on a
// building of two wall families that is the same two angles many times over (the faculty
// map built its two graphs eight times, 0.3-1.4 s each).
#pragma once

#include "graph/PreparedPlan.h"

#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace fc {

class PreparedPlans {
public:
    // Keeps its own copy of the plan: the editor keeps one across requests (live
    // replanning) while the document moves on. floorCache: what plans of the same floor
    // prepared before built from its free space (the editor passes one cache to the plans
    // of every edit); null: a cache of its own, shared by its angles.
    // stripeLattice, headland: DecompositionOptions' for every angle.
    PreparedPlans(const Plan& plan, const RobotProfile& robot, bool transitionCells,
                  std::shared_ptr<FloorCache> floorCache = nullptr,
                  LatticeMode stripeLattice = LatticeMode::Auto,
                  Headland headland = Headland::None);

    const Plan& plan() const { return plan_; }
    const RobotProfile& robot() const { return robot_; }
    bool transitionCells() const { return transitionCells_; }
    LatticeMode stripeLattice() const { return stripeLattice_; }
    Headland headland() const { return headland_; }
    const std::shared_ptr<FloorCache>& floorCache() const { return floorCache_; }

    // A copy of the plan prepared at the angle rounded to 1e-9 degrees (so that 7.15 + 90
    // and 97.15 share one build, and a plan does not depend on which caller built it
    // first). Built on first use; concurrent callers of one angle wait for that build.
    // Throws what preparePlan throws, to every caller of that angle.
    PreparedPlan at(double angleDeg, bool classicStages) const;
    // The same without the copy.
    std::shared_ptr<const PreparedPlan> shared(double angleDeg, bool classicStages) const;

    // Whether at(angleDeg, classicStages) was asked for before (built or being built).
    bool asked(double angleDeg, bool classicStages) const;

    // The angle at() prepares for angleDeg.
    static double roundedAngle(double angleDeg);

private:
    using Built = std::shared_future<std::shared_ptr<const PreparedPlan>>;
    Plan plan_;
    RobotProfile robot_;
    bool transitionCells_;
    LatticeMode stripeLattice_;
    Headland headland_;
    std::shared_ptr<FloorCache> floorCache_;
    mutable std::mutex mutex_;
    mutable std::map<std::tuple<long long, bool>, Built> built_;
};

} // namespace fc
