// The robot's five shapes as four lattice triangles each (blocks B1..B4 in hinge order),
// in every orientation the lattice allows.
#pragma once

#include "tiling/TilingRobot.h"
#include "tiling/TriangleGrid.h"

#include <array>
#include <vector>

namespace fc::tiling {

using Blocks = std::array<LatticeTriangle, kBlockCount>;

// One orientation of a shape: blocks translated so their squares start at (0, 0), and the
// parity of (tx + ty) that translations must have to keep the blocks on the lattice.
struct ShapeOrientation {
    Shape shape = Shape::Rectangle;
    int quarterTurns = 0; // heading = quarterTurns * pi/2
    bool mirrored = false;
    Blocks blocks{};
    int translationParity = 0;
    double heading() const;
};

// The shape's blocks in its reference orientation (heading 0). The paper's figures are
// missing, so the shapes are our reading of its text: rectangle a x 2a, triangle with legs
// 2a, parallelogram 2a x a with 45-degree sides, curve (a square with an ear on two
// adjacent sides, a chevron), square (side a*sqrt(2), four blocks around its centre).
Blocks referenceBlocks(Shape shape);

// Distinct orientations (4 turns x mirror, duplicates of symmetric shapes removed).
std::vector<ShapeOrientation> shapeOrientations(Shape shape);
std::vector<ShapeOrientation> allOrientations();

LatticeTriangle translated(const LatticeTriangle& t, int dx, int dy);

} // namespace fc::tiling
