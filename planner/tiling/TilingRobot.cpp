#include "tiling/TilingRobot.h"

#include "model/Plan.h"

#include <cmath>

namespace fc::tiling {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kQuarter = kPi / 2;   // pi/2
constexpr double kSeven = 7 * kPi / 4; // 7pi/4
constexpr BlockRotation kStill{0, 0};  // block does not turn
constexpr BlockRotation kHalf{kPi, 0}; // pi about its first hinge
constexpr BlockRotation kQuart{kQuarter, 0};
constexpr BlockRotation kSev{kSeven, 0};
constexpr BlockRotation kTwice{kPi, kSeven}; // pi, then 7pi/4 about its second hinge

using BlockRow = std::array<BlockRotation, kBlockCount>;

// The paper's Table 1 (rows: source shape, columns: target shape), as printed; signs are
// dropped because energy counts the magnitude of a rotation. Table 2 (which lever each
// rotation uses) is read off Table 1: a single rotation uses l1, a double one l1 then l2.
// Where the printed Table 2 disagrees with Table 1 (rectangle to curve, triangle rows),
// Table 1 and the paper's text (Section 5.1: rectangle to curve turns B1-B3 with l1) win.
const std::array<std::array<BlockRow, kShapeCount>, kShapeCount> kTable1{{
    // from Rectangle
    {{{kStill, kStill, kStill, kStill},
      {kStill, kStill, kStill, kHalf},
      {kHalf, kStill, kStill, kHalf},
      {kQuart, kSev, kSev, kStill},
      {kStill, kStill, kSev, kTwice}}},
    // from Triangle
    {{{kStill, kStill, kStill, kHalf},
      {kStill, kStill, kStill, kStill},
      {kStill, kStill, kStill, kHalf},
      {kSev, kSev, kStill, kStill},
      {kSev, kSev, kStill, kSev}}},
    // from Parallelogram
    {{{kHalf, kStill, kStill, kHalf},
      {kStill, kStill, kStill, kHalf},
      {kStill, kStill, kStill, kStill},
      {kTwice, kSev, kStill, kSev},
      {kTwice, kSev, kStill, kStill}}},
    // from Curve
    {{{kQuart, kSev, kSev, kStill},
      {kSev, kSev, kStill, kStill},
      {kTwice, kSev, kStill, kSev},
      {kStill, kStill, kStill, kStill},
      {kStill, kStill, kStill, kSev}}},
    // from Square
    {{{kStill, kStill, kSev, kTwice},
      {kSev, kSev, kStill, kSev},
      {kTwice, kSev, kStill, kStill},
      {kStill, kStill, kStill, kSev},
      {kStill, kStill, kStill, kStill}}},
}};

const std::array<const char*, kShapeCount> kShapeNames{"rectangle", "triangle", "parallelogram",
                                                       "curve", "square"};

} // namespace

const char* shapeName(Shape shape) {
    return kShapeNames[static_cast<int>(shape)];
}

std::optional<Shape> shapeFromName(const std::string& name) {
    for (int s = 0; s < kShapeCount; ++s)
        if (name == kShapeNames[s])
            return static_cast<Shape>(s);
    return std::nullopt;
}

BlockRotation blockRotation(Shape from, Shape to, int block) {
    return kTable1[static_cast<int>(from)][static_cast<int>(to)][block];
}

double TilingRobotProfile::firstLever() const {
    return blockLeg * std::sqrt(5.0) / 3.0;
}

double TilingRobotProfile::secondLever() const {
    return blockLeg * std::sqrt(2.0) / 3.0;
}

double TilingRobotProfile::totalMass() const {
    double sum = 0.0;
    for (double m : blockMass)
        sum += m;
    return sum;
}

void TilingRobotProfile::validate() const {
    if (!(blockLeg > 0.0) || !std::isfinite(blockLeg))
        throw InputError("block leg must be a positive length in metres");
    for (double m : blockMass)
        if (!(m > 0.0) || !(m <= 1e6))
            throw InputError("block masses must be positive and at most 1,000,000 kg");
}

EnergyTerms& EnergyTerms::operator+=(const EnergyTerms& o) {
    translation += o.translation;
    transformation += o.transformation;
    orientation += o.orientation;
    return *this;
}

double headingDifference(double a, double b) {
    double d = std::fmod(std::fabs(a - b), 2 * kPi);
    return d > kPi ? 2 * kPi - d : d;
}

EnergyTerms transitionEnergy(const TilingRobotProfile& robot, const Pose& from, const Pose& to) {
    EnergyTerms e;
    const double l1 = robot.firstLever();
    const double l2 = robot.secondLever();
    const double turn = headingDifference(from.heading, to.heading);
    for (int b = 0; b < kBlockCount; ++b) {
        const double m = robot.blockMass[b];
        e.translation += m * distance(from.blocks[b], to.blocks[b]);
        const BlockRotation r = blockRotation(from.shape, to.shape, b);
        e.transformation += m * (r.first * l1 + r.second * l2);
        e.orientation += m * turn * (l1 + l2);
    }
    return e;
}

} // namespace fc::tiling
