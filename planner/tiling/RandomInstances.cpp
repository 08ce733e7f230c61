#include "tiling/RandomInstances.h"

#include "tiling/Polyabolo.h"
#include "tiling/RandomSource.h"
#include "tiling/Tiling.h"

namespace fc::tiling {

OrderingProblem randomOrderingProblem(int waypoints, std::uint64_t seed,
                                      const TilingRobotProfile& robot) {
    RandomSource random(seed);
    const std::vector<ShapeOrientation> orientations = allOrientations();
    const int squares = static_cast<int>(6.0 / robot.blockLeg);
    const TriangleGrid grid({0, 0}, robot.blockLeg, squares + 4, squares + 4);
    OrderingProblem problem;
    problem.robot = robot;
    for (int k = 0; k < waypoints; ++k) {
        const ShapeOrientation& o =
            orientations[random.below(static_cast<int>(orientations.size()))];
        const int ty = random.below(squares);
        // Translations keep the parity that puts the blocks on the lattice.
        const int tx = 2 * random.below(squares / 2) + ((ty + o.translationParity) & 1);
        Tile tile{o.shape, o.quarterTurns, o.mirrored, {}};
        for (int b = 0; b < kBlockCount; ++b)
            tile.cells[b] = grid.cellId(translated(o.blocks[b], tx, ty));
        problem.poses.push_back(poseOf(grid, tile));
    }
    return problem;
}

} // namespace fc::tiling
