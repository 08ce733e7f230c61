// The reconfigurable tiling robot of seeds/001 (hTetran): four isosceles right-triangle
// blocks B1..B4 joined by hinges, five shapes, and the energy of moving between two
// waypoints (the paper's Equations 1-4).
#pragma once

#include "geometry/Geometry.h"

#include <array>
#include <optional>
#include <string>

namespace fc::tiling {

enum class Shape { Rectangle, Triangle, Parallelogram, Curve, Square };
constexpr int kShapeCount = 5;
constexpr int kBlockCount = 4;

const char* shapeName(Shape shape);
std::optional<Shape> shapeFromName(const std::string& name);

// What one block does during a shape change (the paper's Tables 1 and 2): up to two hinge
// rotations in radians, the first with lever l1, the second with lever l2.
struct BlockRotation {
    double first = 0.0;
    double second = 0.0;
};
BlockRotation blockRotation(Shape from, Shape to, int block);

struct TilingRobotProfile {
    double blockLeg = 0.21; // m, the legs of each block (hypotenuse 0.297 m)
    // kg. The paper gives no masses; B2 carries the controller and the battery, so it is
    // the heaviest by default. Override with measured values.
    std::array<double, kBlockCount> blockMass{0.9, 1.4, 0.9, 0.9};

    // Lever arms of a block rotating about a hinge (the paper's l1 and l2): from a hinge at
    // an acute corner to the block's centre of mass (a*sqrt(5)/3), and from a hinge at the
    // right-angle corner (a*sqrt(2)/3).
    double firstLever() const;
    double secondLever() const;
    double totalMass() const;
    // Throws InputError unless the leg and every mass are positive and finite.
    void validate() const;
};

// The robot at a waypoint: its shape, heading and the centres of its four blocks.
struct Pose {
    Shape shape = Shape::Rectangle;
    double heading = 0.0; // rad
    std::array<Vec2, kBlockCount> blocks{};
    // The paper's waypoint: the centre of gravity of block 2.
    Vec2 waypoint() const { return blocks[1]; }
};

struct EnergyTerms {
    double translation = 0.0;                                                   // Eq. 1
    double transformation = 0.0;                                                // Eq. 2
    double orientation = 0.0;                                                   // Eq. 3
    double total() const { return translation + transformation + orientation; } // Eq. 4
    EnergyTerms& operator+=(const EnergyTerms& o);
};

// Smallest absolute difference between two headings, in [0, pi].
double headingDifference(double a, double b);

EnergyTerms transitionEnergy(const TilingRobotProfile& robot, const Pose& from, const Pose& to);

} // namespace fc::tiling
