#include "tiling/Tiling.h"

#include <algorithm>
#include <numeric>

namespace fc::tiling {
namespace {

struct Placement {
    int orientation = 0;
    std::array<int, kBlockCount> cells{};
};

// Lists of placement ids per cell, stored contiguously (compressed rows).
struct CellLists {
    std::vector<int> start, items;
    template <class Range> void build(int cellCount, const Range& pairs) {
        start.assign(cellCount + 1, 0);
        for (const auto& [cell, id] : pairs)
            ++start[cell + 1];
        std::partial_sum(start.begin(), start.end(), start.begin());
        items.resize(pairs.size());
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (const auto& [cell, id] : pairs)
            items[fill[cell]++] = id;
    }
    const int* begin(int cell) const { return items.data() + start[cell]; }
    const int* end(int cell) const { return items.data() + start[cell + 1]; }
    bool empty(int cell) const { return start[cell] == start[cell + 1]; }
};

struct Search {
    const TriangleGrid& grid;
    std::vector<ShapeOrientation> orientations = allOrientations();
    std::vector<Placement> placements;
    CellLists anchored; // placements whose lowest cell id is this cell
    CellLists covering; // placements that cover this cell
    std::vector<char> covered;
    std::vector<std::array<int, 3>> neighbours; // free cells across each edge, -1 if none

    explicit Search(const TriangleGrid& g) : grid(g), covered(g.cellCount(), 0) {
        for (int cell = 0; cell < grid.cellCount(); ++cell)
            neighbours.push_back(edgeNeighbours(cell));
        std::vector<std::pair<int, int>> anchors, covers;
        for (int o = 0; o < static_cast<int>(orientations.size()); ++o) {
            const ShapeOrientation& shape = orientations[o];
            for (int ty = 0; ty < grid.ny(); ++ty)
                for (int tx = (ty + shape.translationParity) & 1; tx < grid.nx(); tx += 2)
                    addPlacement(o, tx, ty, anchors, covers);
        }
        anchored.build(grid.cellCount(), anchors);
        covering.build(grid.cellCount(), covers);
        // Try first the placements that reach least far in scan order: filling the current
        // row before poking into the next keeps the frontier flat, so the search rarely has
        // to undo a choice made rows earlier.
        auto reach = [this](int id) {
            const auto& cells = placements[id].cells;
            return std::make_pair(*std::max_element(cells.begin(), cells.end()), id);
        };
        for (int cell = 0; cell < grid.cellCount(); ++cell)
            std::sort(anchored.items.begin() + anchored.start[cell],
                      anchored.items.begin() + anchored.start[cell + 1],
                      [&reach](int a, int b) { return reach(a) < reach(b); });
    }

    void addPlacement(int o, int tx, int ty, std::vector<std::pair<int, int>>& anchors,
                      std::vector<std::pair<int, int>>& covers) {
        Placement p{o, {}};
        for (int b = 0; b < kBlockCount; ++b) {
            const LatticeTriangle t = translated(orientations[o].blocks[b], tx, ty);
            if (!grid.contains(t) || !grid.isFree(grid.cellId(t)))
                return;
            p.cells[b] = grid.cellId(t);
        }
        const int id = static_cast<int>(placements.size());
        placements.push_back(p);
        anchors.emplace_back(*std::min_element(p.cells.begin(), p.cells.end()), id);
        for (int cell : p.cells)
            covers.emplace_back(cell, id);
    }

    std::array<int, 3> edgeNeighbours(int cell) const {
        const LatticeTriangle t = grid.triangle(cell);
        const int i = t.squareI(), j = t.squareJ();
        auto freeCell = [this](int si, int sj, int half) {
            if (si < 0 || sj < 0 || si >= grid.nx() || sj >= grid.ny())
                return -1;
            const int id = grid.cellId(si, sj, half);
            return grid.isFree(id) ? id : -1;
        };
        // Across the horizontal leg: the half of the square below that holds its top edge
        // (half 1), or of the square above that holds its bottom edge (half 0).
        const int vertical = t.sy > 0 ? freeCell(i, j - 1, 1) : freeCell(i, j + 1, 0);
        // Across the vertical leg: in a "\" square the right edge is in half 1 and the left
        // edge in half 0; in a "/" square the other way round.
        const int left = i - 1, right = i + 1;
        const bool leftEven = ((left + j) & 1) == 0, rightEven = ((right + j) & 1) == 0;
        const int horizontal =
            t.sx > 0 ? freeCell(left, j, leftEven ? 1 : 0) : freeCell(right, j, rightEven ? 0 : 1);
        return {freeCell(i, j, 1 - t.half()), vertical, horizontal};
    }

    // A placement that leaves a neighbouring free cell without any fitting placement can
    // never be part of a complete tiling: prune it at once instead of rows later.
    bool strandsANeighbour(int id) const {
        for (int cell : placements[id].cells)
            for (int neighbour : neighbours[cell])
                if (neighbour >= 0 && !covered[neighbour] && !coverable(neighbour))
                    return true;
        return false;
    }

    bool fits(int id) const {
        for (int cell : placements[id].cells)
            if (covered[cell])
                return false;
        return true;
    }
    void mark(int id, char value) {
        for (int cell : placements[id].cells)
            covered[cell] = value;
    }
    bool coverable(int cell) const {
        for (const int* p = covering.begin(cell); p != covering.end(cell); ++p)
            if (fits(*p))
                return true;
        return false;
    }

    // Connected pieces: cells joined by a common placement (union-find), ascending ids.
    std::vector<std::vector<int>> pieces() const {
        std::vector<int> parent(grid.cellCount());
        std::iota(parent.begin(), parent.end(), 0);
        auto find = [&parent](int x) {
            while (parent[x] != x)
                x = parent[x] = parent[parent[x]];
            return x;
        };
        for (const Placement& p : placements)
            for (int b = 1; b < kBlockCount; ++b)
                parent[find(p.cells[b])] = find(p.cells[0]);
        std::vector<int> pieceOfRoot(grid.cellCount(), -1);
        std::vector<std::vector<int>> result;
        for (int cell = 0; cell < grid.cellCount(); ++cell) {
            if (covering.empty(cell))
                continue;
            int& piece = pieceOfRoot[find(cell)];
            if (piece < 0) {
                piece = static_cast<int>(result.size());
                result.emplace_back();
            }
            result[piece].push_back(cell);
        }
        return result;
    }

    // Cover of the piece by backtracking: the lowest uncovered cell must be covered by a
    // placement anchored there, or, while `skips` allows, left untiled (a piece whose size
    // is not a multiple of four must leave size % 4 cells). False when the budget runs out.
    bool backtrack(const std::vector<int>& cells, int skips, long long budget, long long& nodes,
                   std::vector<int>& chosen, std::vector<int>& skipped) {
        struct Frame {
            std::size_t position;
            const int* next; // next anchored placement to try
            int placed;
            bool skipping;
        };
        std::vector<Frame> stack;
        std::size_t position = 0;
        bool descend = true;
        while (true) {
            if (descend) {
                while (position < cells.size() && covered[cells[position]])
                    ++position;
                if (position == cells.size())
                    break;
                stack.push_back({position, anchored.begin(cells[position]), -1, false});
            }
            Frame& top = stack.back();
            const int cell = cells[top.position];
            if (top.placed >= 0)
                mark(top.placed, 0);
            top.placed = -1;
            while (top.next != anchored.end(cell) && !fits(*top.next))
                ++top.next;
            if (top.next != anchored.end(cell) && nodes < budget) {
                ++nodes;
                top.placed = *top.next++;
                mark(top.placed, 1);
                descend = !strandsANeighbour(top.placed); // else the frame's next placement
                position = top.position;
                continue;
            }
            if (!top.skipping && skips > 0 && nodes < budget) {
                ++nodes;
                top.skipping = true;
                covered[cell] = 2; // left untiled
                --skips;
                position = top.position;
                descend = true;
                continue;
            }
            if (top.skipping) {
                covered[cell] = 0;
                ++skips;
            }
            stack.pop_back();
            if (stack.empty() || nodes >= budget) {
                for (const Frame& f : stack) {
                    if (f.placed >= 0)
                        mark(f.placed, 0);
                    if (f.skipping)
                        covered[cells[f.position]] = 0;
                }
                return false;
            }
            descend = false;
        }
        for (const Frame& f : stack) {
            if (f.skipping)
                skipped.push_back(cells[f.position]);
            else
                chosen.push_back(f.placed);
        }
        return true;
    }

    // Cells near a placement that it would leave without any fitting placement.
    int deadCellsAfter(int id, std::vector<int>& stamp, int round) {
        mark(id, 1);
        int dead = 0;
        for (int cell : placements[id].cells)
            for (const int* p = covering.begin(cell); p != covering.end(cell); ++p)
                for (int neighbour : placements[*p].cells) {
                    if (covered[neighbour] || stamp[neighbour] == round)
                        continue;
                    stamp[neighbour] = round;
                    dead += coverable(neighbour) ? 0 : 1;
                }
        mark(id, 0);
        return dead;
    }

    // Scan-order fill choosing, at each lowest uncovered cell, the anchored placement that
    // strands the fewest neighbouring cells; a cell nothing fits is left untiled.
    void greedy(const std::vector<int>& cells, std::vector<int>& chosen,
                std::vector<int>& untiled) {
        std::vector<int> stamp(grid.cellCount(), 0);
        int round = 0;
        for (int cell : cells) {
            if (covered[cell])
                continue;
            int best = -1, bestDead = 0;
            for (const int* p = anchored.begin(cell); p != anchored.end(cell); ++p) {
                if (!fits(*p))
                    continue;
                const int dead = deadCellsAfter(*p, stamp, ++round);
                if (best < 0 || dead < bestDead) {
                    best = *p;
                    bestDead = dead;
                }
                if (dead == 0)
                    break;
            }
            if (best < 0) {
                untiled.push_back(cell);
                continue;
            }
            mark(best, 1);
            chosen.push_back(best);
        }
    }

    // Local repair of a greedy fill: around each cell left untiled, lift the tiles within
    // `radius` squares and re-tile that patch exactly, allowing fewer cells to stay untiled
    // than before; keep the patch only if it improves. Each patch search has its own budget.
    void repair(std::vector<int>& chosen, std::vector<int>& untiled, int radius, long long budget,
                long long& nodes) {
        std::vector<int> owner(grid.cellCount(), -1); // index into chosen
        for (int t = 0; t < static_cast<int>(chosen.size()); ++t)
            for (int cell : placements[chosen[t]].cells)
                owner[cell] = t;
        std::vector<char> isUntiled(grid.cellCount(), 0);
        for (int cell : untiled)
            isUntiled[cell] = 1;
        for (std::size_t k = 0; k < untiled.size(); ++k) {
            const int centre = untiled[k];
            if (!isUntiled[centre])
                continue; // tiled by an earlier patch
            const LatticeTriangle c = grid.triangle(centre);
            std::vector<int> patch, lifted;
            for (int j = std::max(0, c.squareJ() - radius);
                 j <= std::min(grid.ny() - 1, c.squareJ() + radius); ++j)
                for (int i = std::max(0, c.squareI() - radius);
                     i <= std::min(grid.nx() - 1, c.squareI() + radius); ++i)
                    for (int half = 0; half < 2; ++half) {
                        const int cell = grid.cellId(i, j, half);
                        if (owner[cell] >= 0 && chosen[owner[cell]] >= 0) {
                            lifted.push_back(owner[cell]);
                            for (int tileCell : placements[chosen[owner[cell]]].cells)
                                patch.push_back(tileCell);
                            chosen[owner[cell]] = -chosen[owner[cell]] - 1; // lifted
                        } else if (isUntiled[cell]) {
                            patch.push_back(cell);
                        }
                    }
            std::sort(patch.begin(), patch.end());
            patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
            int before = 0;
            for (int cell : patch)
                before += isUntiled[cell];
            // Untiled cells outside the patch must stay as they are.
            for (int cell : untiled)
                if (isUntiled[cell] && !std::binary_search(patch.begin(), patch.end(), cell))
                    covered[cell] = 2;
            for (int id : lifted)
                mark(-chosen[id] - 1, 0);
            std::vector<int> placed, skipped;
            bool improved = false;
            for (int skips = before % kBlockCount; !improved && skips < before;
                 skips += kBlockCount) {
                placed.clear();
                skipped.clear();
                long long used = 0;
                improved = backtrack(patch, skips, budget, used, placed, skipped);
                nodes += used;
            }
            for (int cell : untiled)
                if (covered[cell] == 2)
                    covered[cell] = 0;
            for (int cell : skipped) // backtrack marks the cells it leaves with 2
                covered[cell] = 0;
            if (!improved) {
                for (int id : lifted) {
                    chosen[id] = -chosen[id] - 1;
                    mark(chosen[id], 1);
                }
                continue;
            }
            // backtrack left the new tiles marked; the skipped cells are not covered.
            for (int cell : patch)
                isUntiled[cell] = 0;
            for (int cell : skipped)
                isUntiled[cell] = 1;
            std::size_t slot = 0;
            for (int id : placed) {
                int index;
                if (slot < lifted.size()) {
                    index = lifted[slot++];
                    chosen[index] = id;
                } else {
                    index = static_cast<int>(chosen.size());
                    chosen.push_back(id);
                }
                for (int cell : placements[id].cells)
                    owner[cell] = index;
            }
            for (; slot < lifted.size(); ++slot)
                chosen[lifted[slot]] = -1; // an emptied slot, dropped below
            for (int cell : skipped)
                owner[cell] = -1;
        }
        chosen.erase(std::remove_if(chosen.begin(), chosen.end(), [](int id) { return id < 0; }),
                     chosen.end());
        std::vector<int> left;
        for (int cell = 0; cell < grid.cellCount(); ++cell)
            if (isUntiled[cell])
                left.push_back(cell);
        untiled = std::move(left);
    }
};

} // namespace

TilingResult tileFreeSpace(const TriangleGrid& grid, const TilingOptions& options) {
    Search search(grid);
    TilingResult result;
    result.freeCells = grid.freeCount();
    for (int cell = 0; cell < grid.cellCount(); ++cell)
        if (grid.isFree(cell) && search.covering.empty(cell))
            result.unreachable.push_back(cell);
    std::vector<int> chosen;
    const auto pieces = search.pieces();
    result.pieces = static_cast<int>(pieces.size());
    for (const std::vector<int>& cells : pieces) {
        long long nodes = 0;
        // Four cells a tile: a piece of another size leaves size % 4 cells at the least.
        const int skips = static_cast<int>(cells.size() % kBlockCount);
        std::vector<int> skipped;
        if (search.backtrack(cells, skips, options.nodeBudget, nodes, chosen, skipped)) {
            ++result.piecesTiledExactly;
            result.untiled.insert(result.untiled.end(), skipped.begin(), skipped.end());
        } else {
            std::vector<int> untiled;
            search.greedy(cells, chosen, untiled);
            search.repair(chosen, untiled, options.repairRadius, options.repairBudget, nodes);
            result.untiled.insert(result.untiled.end(), untiled.begin(), untiled.end());
        }
        result.nodes += nodes;
    }
    for (int id : chosen) {
        const ShapeOrientation& o = search.orientations[search.placements[id].orientation];
        result.tiles.push_back({o.shape, o.quarterTurns, o.mirrored, search.placements[id].cells});
    }
    std::sort(result.untiled.begin(), result.untiled.end());
    return result;
}

Pose poseOf(const TriangleGrid& grid, const Tile& tile) {
    Pose pose;
    pose.shape = tile.shape;
    pose.heading = tile.quarterTurns * 1.57079632679489661923;
    for (int b = 0; b < kBlockCount; ++b)
        pose.blocks[b] = grid.centroid(tile.cells[b]);
    return pose;
}

} // namespace fc::tiling
