// The paper's comparison (its Table 2): the extra travelled distance and the turns of our
// best solver divided by those of each baseline. Shared by `floorcover-cli compare` and
// the comparison report.
#pragma once

#include "metrics/Metrics.h"

#include <string>
#include <utility>
#include <vector>

namespace fc {

// The earlier methods the paper compares against (reeb-cpp, adjacency-ga).
bool isBaselineSolver(const std::string& name);

struct BaselineRatio {
    std::string baseline;
    std::string ours;        // our solver with the least extra distance
    double extraRatio = 0.0; // ours.extra / baseline.extra; NaN when baseline.extra <= 0
    double turnsRatio = 0.0; // ours.turns / baseline.turns; NaN when baseline.turns == 0
};

// results: (solver, metrics) of the solvers that answered. One entry per baseline present,
// empty when no corner-graph solver answered.
std::vector<BaselineRatio>
baselineRatios(const std::vector<std::pair<std::string, Metrics>>& results);

// What the paper reports (Table 2 and its conclusion): extra-distance ratios from 3.6% to
// 43% (simple environment: 5% vs Xu et al. 2014, 3.6% vs Tung & Liu 2019; complex one: 42%
// and 43%), turn ratios from 45% to 65% against Xu et al. (65% simple, 45% complex) and
// "similar" against Tung & Liu.
struct PaperRange {
    double low = 0.0, high = 0.0;
};
constexpr PaperRange kPaperExtraRatio{0.036, 0.43};
constexpr PaperRange kPaperTurnsRatioReeb{0.45, 0.65};
// The paper's text for one baseline, e.g. "extra 3.6-43%, turns similar".
std::string paperRatiosText(const std::string& baseline);

} // namespace fc
