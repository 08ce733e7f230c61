// Where a raw cell's stripes go. By default evenly, the first and last W/2 inside the cell's
// ends. Where wide cells of one room meet at an obstacle's corner (a slice of zero wall
// height), their stripes instead continue one lattice W apart across the slice: restarting
// W/2 from every cell's edge would add a stripe per cell, 12 m on a 12 x 8 m hall with a
// rotated box in it.
#pragma once

#include <vector>

namespace fc {

// How a decomposition places its cells' stripes (DecompositionOptions::stripeLattice).
enum class LatticeMode {
    Own,       // every cell spaced on its own
    AtCorners, // wide cells meeting at an obstacle's corner share the room's lattice
    // Every cell on the room's lattice, with a stripe W/2 inside a side only where a long
    // wall lies on it; a cell no lattice line crosses gets no stripe of its own. For traced
    // maps, whose ragged outlines start cells a few centimetres wide across the whole floor.
    Dense,
    // Dense where it saves at least a quarter of the estimated stripe length (a traced
    // map's ragged floor), Own elsewhere.
    Auto,
};

} // namespace fc

namespace fc::detail {

// Evenly spaced stripes in [x0, x1], the first and last W/2 inside (one in the middle when
// the cell is at most W wide).
std::vector<double> evenStripePositions(double x0, double x1, double w);

// A wall face across the sweep inside a cell: a step of its floor or ceiling.
struct LatticeStep {
    double x = 0;
    double length = 0;
    bool facesRight = false; // free space on its +x side
};

struct LatticeCell {
    int room = 0;
    double x0 = 0, x1 = 0;
    double leftHeight = 0, rightHeight = 0; // ceiling - floor at x0 and x1
    bool keepsStripe = false;               // borders another room along the sweep (a doorway)
    std::vector<LatticeStep> steps = {};    // read by Dense only
};

// Two raw cells sharing a piece of a slice: `left` ends at x, `right` starts there.
struct LatticeLink {
    int left = -1, right = -1;
    double x = 0;
    double length = 0; // of the shared piece
};

struct StripeLayout {
    std::vector<std::vector<double>> stripes; // per raw cell; empty: swept by its neighbours
    std::vector<char> onLattice;              // stripes on the room's lattice
    std::vector<char> sweepsSliver;           // receives a neighbour's sliver (hand-off)
};

// The largest sliver handed off: 0.15 W, and no more than keeps the receiving stripe L/2
// clear of a wall on the shared slice (W/2 - sliver >= L/2).
double maxHandOff(double w, double robotDiameter);

// Slivers up to handOff wide are handed off (0: none; not in Dense). Dense keeps its stripes
// robotDiameter / 2 clear of long wall faces.
StripeLayout layOutStripes(const std::vector<LatticeCell>& cells,
                           const std::vector<LatticeLink>& links, double w,
                           LatticeMode mode = LatticeMode::AtCorners, double handOff = 0.0,
                           double robotDiameter = 0.0);

} // namespace fc::detail
