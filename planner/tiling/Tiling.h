// A tile set covering the free triangle cells with the robot's shapes (seeds/001 sect.
// 3.2): exact backtracking per connected piece of the floor within a node budget, and a
// greedy fill with one-step look-ahead where the budget runs out or no exact tiling exists.
#pragma once

#include "tiling/Polyabolo.h"
#include "tiling/TilingRobot.h"
#include "tiling/TriangleGrid.h"

#include <array>
#include <vector>

namespace fc::tiling {

struct Tile {
    Shape shape = Shape::Rectangle;
    int quarterTurns = 0;
    bool mirrored = false;
    std::array<int, kBlockCount> cells{}; // cell ids of blocks B1..B4
};

struct TilingOptions {
    long long nodeBudget = 2'000'000; // placements tried per piece before the greedy fill
    // After a greedy fill: the tiles within this many lattice squares of a cell left untiled
    // are lifted and the patch re-tiled exactly, within repairBudget placements per patch.
    int repairRadius = 6;
    long long repairBudget = 200'000;
};

struct TilingResult {
    std::vector<Tile> tiles;
    std::vector<int> unreachable; // free cells that no placement of any shape covers
    // Reachable cells left uncovered: size % 4 per piece at the least (four cells a tile),
    // more where the greedy fill had to take over.
    std::vector<int> untiled;
    int freeCells = 0;
    int pieces = 0;             // connected pieces of reachable cells
    int piecesTiledExactly = 0; // pieces the backtracking solved (leaving only size % 4)
    long long nodes = 0;        // placements tried by the backtracking
};

TilingResult tileFreeSpace(const TriangleGrid& grid, const TilingOptions& options = {});

// The robot's pose on a tile: block centres and heading.
Pose poseOf(const TriangleGrid& grid, const Tile& tile);

} // namespace fc::tiling
