// The open-region grid (geometry/OpenRegions) decides blocks of grid nodes far from the
// walls with one distance query each; on generated floors of every family (any rotation,
// UTM offsets, 0.9 m doors, slanted and star rooms, pillars) it must label the grid exactly
// as testing every node does.
#include "PlanGenerator.h"
#include "geometry/OpenRegions.h"

#include <gtest/gtest.h>

namespace fcgen {
namespace {

TEST(OpenRegions, PrunedGridEqualsTestingEveryNode) {
    for (Family family : allFamilies()) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const GeneratedPlan generated = generatePlan(family, seed);
            std::vector<fc::Ring> rings{generated.plan.boundary};
            rings.insert(rings.end(), generated.plan.obstacles.begin(),
                         generated.plan.obstacles.end());
            const fc::SegmentIndex walls(rings);
            const fc::BoundingBox extent = fc::boundsOf(generated.plan.boundary);
            for (double r : {0.3, 0.45}) {
                const fc::OpenRegions pruned(walls, extent, r);
                const fc::OpenRegions reference(walls, extent, r,
                                                fc::OpenRegions::Classification::EveryNode);
                EXPECT_EQ(pruned.labels(), reference.labels())
                    << generated.description << ", r = " << r;
            }
        }
    }
}

} // namespace
} // namespace fcgen
