// The floor as a lattice of right-triangle cells: squares of side `leg` (the robot's
// block leg), each split along one diagonal. The diagonal alternates like a checkerboard
// ("\" where i + j is even, "/" where it is odd) so that the lattice is the tetrakis
// (polyabolo) lattice turned by 45 degrees: every four-block shape of the robot fits it.
#pragma once

#include "geometry/Geometry.h"
#include "model/Plan.h"

#include <array>
#include <cstdint>
#include <vector>

namespace fc::tiling {

// A lattice triangle by its right-angle vertex (lattice point) and the directions of its
// two legs (each +1 or -1). Cell (i, j, half): square (i, j); half 0 has its right angle
// on the square's bottom edge, half 1 on its top edge.
struct LatticeTriangle {
    int rx = 0, ry = 0;
    int sx = 1, sy = 1;
    int squareI() const { return rx + (sx < 0 ? -1 : 0); }
    int squareJ() const { return ry + (sy < 0 ? -1 : 0); }
    int half() const { return sy < 0 ? 1 : 0; }
    // True where the lattice's diagonal in this square is this triangle's hypotenuse.
    bool fitsLattice() const { return (((squareI() + squareJ()) & 1) == 0) == (sx * sy == 1); }
    bool operator<(const LatticeTriangle& o) const;
    bool operator==(const LatticeTriangle& o) const;
};

class TriangleGrid {
public:
    TriangleGrid() = default;
    TriangleGrid(Vec2 origin, double leg, int nx, int ny);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    double leg() const { return leg_; }
    Vec2 origin() const { return origin_; }
    int cellCount() const { return 2 * nx_ * ny_; }
    // Ids run row by row (j, then i, then half): the backtracking's scan order.
    int cellId(int i, int j, int half) const { return (j * nx_ + i) * 2 + half; }
    int cellId(const LatticeTriangle& t) const {
        return cellId(t.squareI(), t.squareJ(), t.half());
    }
    bool contains(const LatticeTriangle& t) const;
    LatticeTriangle triangle(int cell) const;
    std::array<Vec2, 3> vertices(int cell) const; // right-angle vertex first
    Vec2 centroid(int cell) const;
    double cellArea() const { return 0.5 * leg_ * leg_; }

    bool isFree(int cell) const { return free_[cell] != 0; }
    void setFree(int cell, bool value) { free_[cell] = value ? 1 : 0; }
    int freeCount() const;

private:
    Vec2 origin_;
    double leg_ = 1.0;
    int nx_ = 0, ny_ = 0;
    std::vector<std::uint8_t> free_;
};

// The lattice over the plan's bounding box with a cell free when the whole triangle lies
// in the free space (inside the boundary, outside every obstacle; touching a wall is fine).
TriangleGrid buildTriangleGrid(const Plan& plan, double leg);

} // namespace fc::tiling
