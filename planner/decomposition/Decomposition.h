// Boustrophedon decomposition with transition cells (SPEC sect. 2).
// All coordinates here are in the sweep frame (see Frame): stripes run along +y and the
// slice sweeps along +x, so a cell is an x-interval with a floor and a ceiling.
#pragma once

#include "decomposition/DerivedCache.h"
#include "decomposition/StripeLattice.h"
#include "geometry/Clearance.h"
#include "geometry/Geometry.h"
#include "model/Plan.h"

#include <memory>
#include <string>
#include <vector>

namespace fc {

enum class CellKind { Primary, Transition };

struct Cell {
    int id = -1;
    CellKind kind = CellKind::Primary;
    int room = 0; // index into Decomposition::roomNames
    double x0 = 0.0, x1 = 0.0;
    // Piecewise-linear floor and ceiling over [x0, x1], x non-decreasing; a vertical
    // step (floor or ceiling jump) appears as two points with the same x.
    Polyline floor, ceiling;
    // x of each stripe (evenly spaced, first and last W/2 inside [x0, x1]).
    std::vector<double> stripes;
    // Where the robot centre runs on each stripe: inside the cell, L/2 clear of walls and
    // W/2 from the cell's floor and ceiling where the room allows (a single point down the
    // middle of a gap narrower than W); an empty interval marks a stripe the robot cannot
    // reach.
    std::vector<Interval> stripeSpans;
    // Its stripe also sweeps a sliver of the cell across (StripeLattice's hand-off): a cell
    // narrower than W keeps it where planned if the robot fits there, not in its middle.
    bool stripesPlaced = false;
    // No stripe of its own: the lattice lines of the cells on either side sweep it (a
    // sliver between two slices of a traced map; LatticeMode::Dense). Not required, and
    // its neighbours are joined across it.
    bool sweptByNeighbours = false;
    // Part of a headland band (DecompositionOptions::headland): the step to the next piece
    // of its band sweeps the band, as a step between stripes does.
    bool headland = false;

    double width() const { return x1 - x0; }
    bool reachable() const;           // at least one stripe with a clear span
    double floorAt(double x) const;   // lower value at a jump
    double ceilingAt(double x) const; // upper value at a jump
    double area() const;
    Ring outline() const; // counter-clockwise polygon of the cell
};

// Two cells that share part of their border. AcrossSweep: a vertical segment at x
// (a critical slice, a room border across the sweep, or a cut-off transition strip).
// AlongSweep: a floor/ceiling segment shared by a lower and an upper cell (only at
// room borders, since walls separate cells otherwise).
struct Adjacency {
    enum class Kind { AcrossSweep, AlongSweep };
    Kind kind = Kind::AcrossSweep;
    int first = -1;  // left cell (AcrossSweep) or lower cell (AlongSweep)
    int second = -1; // right cell or upper cell
    Segment shared;  // the shared border piece
};

struct CriticalSlice {
    double x = 0.0;
    double y0 = 0.0, y1 = 0.0;
};

// A part of the free space the robot cannot sweep (narrower than the robot, or cut off).
struct UnreachableArea {
    double area = 0.0;  // m^2
    Vec2 location;      // a representative point, world frame
    std::string reason; // "narrower than the coverage width", ...
};

struct Decomposition {
    Frame frame;
    // The robot it was made for: W = robot.coverageWidth, L = robot.robotDiameter.
    RobotProfile robot = RobotProfile{1.0, 1.0, 1.0};
    std::vector<std::string> roomNames; // "Floor" when the plan has no rooms
    std::vector<Cell> cells;
    std::vector<Adjacency> adjacencies;
    std::vector<CriticalSlice> criticalSlices;
    std::vector<UnreachableArea> unreachable;
    std::vector<Ring> freeSpace;           // sweep frame: [0] boundary (ccw), then holes (cw)
    bool stripeLattice = false;            // some cells' stripes lie on a shared lattice
    LatticeMode layout = LatticeMode::Own; // how the stripes were laid out (never Auto)
    // Whether DecompositionOptions::stripeLattice AtCorners (Dense) would move some cells'
    // stripes.
    bool stripeLatticeAvailable = false;
    bool denseLatticeAvailable = false;
    // The share of the stripes' estimated length the dense lattice saves over every cell's
    // own spacing (LatticeMode::Auto takes it from kDenseAutoSaving, 25%, on).
    double denseSaving = 0.0;
    bool headland = false; // some walls have a headland band (DecompositionOptions::headland)

    int primaryCount() const;
    int transitionCount() const;
    double coverageWidth() const { return robot.coverageWidth; }
    double clearanceRadius() const { return 0.5 * robot.robotDiameter; } // L/2, from walls

    // Where the robot centre may go in this decomposition (sweep frame): L/2 from walls,
    // stripes inset W/2 where the walls allow. Built once by decompose and shared by copies;
    // throws std::logic_error for a decomposition decompose did not make.
    const ClearanceField& clearance() const;
    // The field of freeSpace for robot (see clearance()); decompose sets it.
    std::shared_ptr<const ClearanceField> clearanceField;
    // Values derived from the free space (DerivedCache.h), shared by its copies and by other
    // decompositions of the same free space; decompose sets it. Whoever changes a
    // decomposition's free space must reset it.
    std::shared_ptr<DerivedCache> derived;
};

class FloorCache;

// Which walls the stripes end at get a headland band (DecompositionOptions::headland): in
// the sweep frame, floors (below the stripes), ceilings (above them), or both. One side
// lets a tour with an even number of stripes come back along it; both make a spiral.
enum class Headland { None, Floors, Ceilings, Both };

// LatticeMode::Auto lays out the dense lattice at once where it saves this share of the
// stripes' estimated length: on the faculty map 39% (at 7 degrees), the lab 31% (0 degrees),
// drawn plans nothing.
inline constexpr double kDenseAutoSaving = 0.25;

struct DecompositionOptions {
    // W and L <= W (the robot centre keeps L/2 from walls; L = 0 is read as L = W); only
    // these two are used. The default is a robot that sweeps its own diameter, L = W = 1.
    RobotProfile robot = RobotProfile{1.0, 1.0, 1.0};
    double stripeAngleDeg = 90.0;
    bool transitionCells = true; // the paper's modification; off = classic BCD
    // Wide cells meeting at an obstacle's corner share one stripe lattice, or every cell
    // does (StripeLattice.h), instead of each restarting W/2 inside its edges.
    LatticeMode stripeLattice = LatticeMode::Own;
    // A band one coverage width deep along the walls the stripes end at is swept along the
    // wall by one pass (a headland), and the stripes end where it begins: a tour can return
    // along it instead of over swept floor.
    Headland headland = Headland::None;
    // Where the clearance field and derived values of a free space decomposed before are
    // taken from (FloorCache.h); null: made afresh.
    std::shared_ptr<FloorCache> floorCache;
};

// Decomposes a validated plan. Throws InputError for geometry it cannot handle.
Decomposition decompose(const Plan& plan, const DecompositionOptions& options);

} // namespace fc
