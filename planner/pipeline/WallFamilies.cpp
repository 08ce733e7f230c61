#include "pipeline/WallFamilies.h"

#include "geometry/Geometry.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace fc {

std::vector<WallFamily> wallFamilies(const Plan& plan, int families) {
    // Wall length per direction (mod 90, in tenths of a degree, so that a wall and its
    // normal vote together), boundary, obstacles and rooms alike; each direction's score
    // is the wall length within half a degree of it.
    std::map<int, double> byDirection;
    std::vector<std::pair<double, double>> walls; // direction mod 90, length
    auto vote = [&](const Ring& ring) {
        for (size_t i = 0; i < ring.size(); ++i) {
            const Vec2 d = ring[(i + 1) % ring.size()] - ring[i];
            if (!(norm(d) > 0.0))
                continue;
            double deg = std::fmod(std::atan2(d.y, d.x) * 180.0 / M_PI + 360.0, 90.0);
            byDirection[static_cast<int>(std::lround(deg * 10.0)) % 900] += norm(d);
            walls.push_back({deg, norm(d)});
        }
    };
    // The exact direction of a family: the length-weighted median of the walls within half a
    // degree of its bin (a plan drawn at 219.6843 degrees sweeps at that angle, not 219.7).
    // A median, not a mean: short edges a little off (a traced doorway, a chamfered corner)
    // must not turn the sweep off the walls by a ten-thousandth of a degree, which splits
    // every wall's cells at its ends.
    auto refined = [&](double bin) {
        std::vector<std::pair<double, double>> near; // deviation, length
        double weight = 0.0;
        for (const auto& [deg, length] : walls) {
            double delta = std::fmod(deg - bin + 135.0, 90.0) - 45.0; // in [-45, 45)
            if (delta < -45.0)
                delta += 90.0;
            if (std::abs(delta) <= 0.55)
                near.push_back({delta, length}), weight += length;
        }
        std::sort(near.begin(), near.end());
        double a = bin, below = 0.0;
        for (const auto& [delta, length] : near) {
            below += length;
            if (below >= weight / 2) {
                a = bin + delta;
                break;
            }
        }
        return std::fmod(a + 90.0, 90.0);
    };
    vote(plan.boundary);
    for (const Ring& hole : plan.obstacles)
        vote(hole);
    for (const Room& room : plan.rooms)
        vote(room.outline);
    std::vector<std::pair<double, int>> ranked;
    for (const auto& [tenth, len] : byDirection) {
        double score = 0.0;
        for (int k = -5; k <= 5; ++k) {
            auto it = byDirection.find((tenth + k + 900) % 900);
            if (it != byDirection.end())
                score += it->second;
        }
        ranked.push_back({-score, tenth});
    }
    std::sort(ranked.begin(), ranked.end());
    std::vector<WallFamily> out;
    for (const auto& [score, tenth] : ranked) {
        if (static_cast<int>(out.size()) >= families)
            break;
        const double a = refined(tenth / 10.0);
        const bool near = std::any_of(out.begin(), out.end(), [a](const WallFamily& o) {
            const double d = std::fmod(std::abs(o.angleDeg - a), 90.0);
            return std::min(d, 90.0 - d) < 2.0;
        });
        if (!near)
            out.push_back({a, -score});
    }
    return out;
}

std::vector<double> dominantWallAngles(const Plan& plan, int families) {
    std::vector<double> out;
    for (const WallFamily& family : wallFamilies(plan, families))
        out.push_back(family.angleDeg);
    return out;
}

std::vector<double> candidateAngles(const Plan& plan) {
    // Stripes along and across the two dominant wall families, then 90 and 0 degrees.
    std::vector<double> out;
    auto add = [&](double a) {
        a = std::fmod(std::fmod(a, 180.0) + 180.0, 180.0);
        if (std::none_of(out.begin(), out.end(), [a](double o) {
                const double d = std::abs(o - a);
                return std::min(d, 180.0 - d) < 1.0;
            }))
            out.push_back(a);
    };
    for (double a : dominantWallAngles(plan, 2)) {
        add(a + 90.0);
        add(a);
    }
    add(90.0);
    add(0.0);
    return out;
}

} // namespace fc
