#include "pipeline/Comparison.h"

#include <cmath>
#include <limits>

namespace fc {

bool isBaselineSolver(const std::string& name) {
    return name == "reeb-cpp" || name == "adjacency-ga" || name == "adjacency-ga-centres";
}

std::vector<BaselineRatio>
baselineRatios(const std::vector<std::pair<std::string, Metrics>>& results) {
    const std::pair<std::string, Metrics>* best = nullptr;
    for (const auto& r : results)
        if (!isBaselineSolver(r.first) &&
            (!best || r.second.extra < best->second.extra ||
             (r.second.extra == best->second.extra && r.second.turns < best->second.turns)))
            best = &r;
    std::vector<BaselineRatio> ratios;
    if (!best)
        return ratios;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& [name, m] : results) {
        if (!isBaselineSolver(name))
            continue;
        BaselineRatio r;
        r.baseline = name;
        r.ours = best->first;
        r.extraRatio = m.extra > 0 ? best->second.extra / m.extra : nan;
        r.turnsRatio = m.turns > 0 ? double(best->second.turns) / m.turns : nan;
        ratios.push_back(r);
    }
    return ratios;
}

std::string paperRatiosText(const std::string& baseline) {
    if (baseline == "reeb-cpp")
        return "extra 5% (simple) to 42% (complex), turns 45-65%";
    return "extra 3.6% (simple) to 43% (complex), turns similar";
}

} // namespace fc
