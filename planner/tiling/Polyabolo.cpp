#include "tiling/Polyabolo.h"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace fc::tiling {
namespace {

LatticeTriangle quarterTurn(const LatticeTriangle& t) { // (x, y) -> (-y, x)
    return {-t.ry, t.rx, -t.sy, t.sx};
}

LatticeTriangle mirror(const LatticeTriangle& t) { // (x, y) -> (-x, y)
    return {-t.rx, t.ry, -t.sx, t.sy};
}

Blocks normalized(Blocks blocks) {
    int minI = INT_MAX, minJ = INT_MAX;
    for (const LatticeTriangle& t : blocks) {
        minI = std::min(minI, t.squareI());
        minJ = std::min(minJ, t.squareJ());
    }
    for (LatticeTriangle& t : blocks)
        t = translated(t, -minI, -minJ);
    return blocks;
}

bool allFit(const Blocks& blocks, int dx) {
    return std::all_of(blocks.begin(), blocks.end(), [dx](const LatticeTriangle& t) {
        return translated(t, dx, 0).fitsLattice();
    });
}

Blocks sortedCopy(Blocks blocks) {
    std::sort(blocks.begin(), blocks.end());
    return blocks;
}

} // namespace

LatticeTriangle translated(const LatticeTriangle& t, int dx, int dy) {
    return {t.rx + dx, t.ry + dy, t.sx, t.sy};
}

double ShapeOrientation::heading() const {
    return quarterTurns * 1.57079632679489661923;
}

// Blocks are listed in hinge order: consecutive blocks share an edge or a hinge corner.
Blocks referenceBlocks(Shape shape) {
    switch (shape) {
    case Shape::Rectangle: // squares (0,0) and (1,0), both halves
        return {{{0, 0, 1, 1}, {1, 1, -1, -1}, {1, 1, 1, -1}, {2, 0, -1, 1}}};
    case Shape::Triangle: // right angle at (0,0), legs 2a along +x and +y
        return {{{1, 0, 1, 1}, {1, 0, -1, 1}, {0, 1, 1, -1}, {0, 1, 1, 1}}};
    case Shape::Parallelogram: // (0,0) (2,0) (3,1) (1,1)
        return {{{1, 0, -1, 1}, {1, 0, 1, 1}, {2, 1, -1, -1}, {2, 1, 1, -1}}};
    case Shape::Curve: // square (0,0) with ears on its right and top sides
        return {{{1, 1, 1, -1}, {1, 1, -1, -1}, {1, 1, -1, 1}, {0, 0, 1, 1}}};
    case Shape::Square: // four right angles at the centre (1,1)
        return {{{1, 1, 1, 1}, {1, 1, -1, 1}, {1, 1, -1, -1}, {1, 1, 1, -1}}};
    }
    throw std::logic_error("unknown shape");
}

std::vector<ShapeOrientation> shapeOrientations(Shape shape) {
    std::vector<ShapeOrientation> result;
    std::vector<std::pair<Blocks, int>> seen; // sorted blocks and parity
    for (int mirrored = 0; mirrored < 2; ++mirrored) {
        Blocks blocks = referenceBlocks(shape);
        if (mirrored)
            for (LatticeTriangle& t : blocks)
                t = mirror(t);
        for (int turns = 0; turns < 4; ++turns) {
            if (turns > 0)
                for (LatticeTriangle& t : blocks)
                    t = quarterTurn(t);
            ShapeOrientation o;
            o.shape = shape;
            o.quarterTurns = turns;
            o.mirrored = mirrored != 0;
            o.blocks = normalized(blocks);
            if (allFit(o.blocks, 0))
                o.translationParity = 0;
            else if (allFit(o.blocks, 1))
                o.translationParity = 1;
            else
                throw std::logic_error("shape does not fit the triangle lattice");
            const std::pair<Blocks, int> key{sortedCopy(o.blocks), o.translationParity};
            if (std::find(seen.begin(), seen.end(), key) != seen.end())
                continue;
            seen.push_back(key);
            result.push_back(o);
        }
    }
    return result;
}

std::vector<ShapeOrientation> allOrientations() {
    std::vector<ShapeOrientation> all;
    for (int s = 0; s < kShapeCount; ++s) {
        const auto some = shapeOrientations(static_cast<Shape>(s));
        all.insert(all.end(), some.begin(), some.end());
    }
    return all;
}

} // namespace fc::tiling
