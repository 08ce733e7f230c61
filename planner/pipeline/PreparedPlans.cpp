#include "pipeline/PreparedPlans.h"

#include "decomposition/FloorCache.h"
#include "pipeline/Planner.h"

#include <cmath>

namespace fc {

PreparedPlans::PreparedPlans(const Plan& plan, const RobotProfile& robot, bool transitionCells,
                             std::shared_ptr<FloorCache> floorCache, LatticeMode stripeLattice,
                             Headland headland)
    : plan_(plan), robot_(robot), transitionCells_(transitionCells), stripeLattice_(stripeLattice),
      headland_(headland),
      floorCache_(floorCache ? std::move(floorCache) : std::make_shared<FloorCache>()) {}

double PreparedPlans::roundedAngle(double angleDeg) {
    return std::isfinite(angleDeg) ? std::round(angleDeg * 1e9) / 1e9 : angleDeg;
}

bool PreparedPlans::asked(double angleDeg, bool classicStages) const {
    if (!std::isfinite(angleDeg))
        return false;
    std::lock_guard<std::mutex> lock(mutex_);
    return built_.count(
               std::make_tuple(std::llround(roundedAngle(angleDeg) * 1e9), classicStages)) > 0;
}

PreparedPlan PreparedPlans::at(double angleDeg, bool classicStages) const {
    return *shared(angleDeg, classicStages);
}

std::shared_ptr<const PreparedPlan> PreparedPlans::shared(double angleDeg,
                                                          bool classicStages) const {
    if (!std::isfinite(angleDeg)) // preparePlan's own error
        return std::make_shared<const PreparedPlan>(
            preparePlan(plan_, robot_, angleDeg, transitionCells_, classicStages));
    const double angle = roundedAngle(angleDeg);
    const auto key = std::make_tuple(std::llround(angle * 1e9), classicStages);
    std::promise<std::shared_ptr<const PreparedPlan>> promise;
    Built built;
    bool builder = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = built_.find(key);
        if (it == built_.end()) {
            built = promise.get_future().share();
            built_.emplace(key, built);
            builder = true;
        } else {
            built = it->second;
        }
    }
    if (builder) {
        try {
            promise.set_value(std::make_shared<const PreparedPlan>(
                preparePlan(plan_, robot_, angle, transitionCells_, classicStages, floorCache_,
                            stripeLattice_, headland_)));
        } catch (...) {
            promise.set_exception(std::current_exception());
        }
    }
    return built.get();
}

} // namespace fc
