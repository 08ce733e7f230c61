// Seeded random floor plans for property tests and the property bench (issue 13, item 6):
// hard cases the sample plans do not contain. Every plan returned has passed
// fc::validatePlan for the robot it was made for; a draw that fails validation is redrawn
// (from a seed derived from the case seed and the attempt), never handed out.
//
// Families (W = 1 m, L = 0.6 m unless the robot says otherwise):
//   rotated-office  fc::generateOfficeFloor (2-6 rooms, 1.2 m doors, furniture) rotated by
//                   any angle;
//   door-rooms      2-4 rectilinear rooms in a row joined by doors of random width in
//                   [1.05 L, 2 W] (SPEC: a passage at least L wide "plus a small margin" is
//                   passable; 5 % of L is that margin here), random wall thickness and
//                   door position (flush with a corner too), some desks (none within 1.05 L
//                   of a door: it would shut the room behind it); rotated;
//   slanted-rooms   a random convex polygon (no two walls parallel, in general) split by a
//                   slanted wall with a door of random width in [1.05 L, 2 W], a convex
//                   obstacle in some draws;
//   star-room       a star-shaped room with convex obstacles and round pillars (24-48-gons),
//                   gaps to walls and to each other from 0.2 m (narrower than L: pockets the
//                   robot cannot enter) to 1.5 m;
//   pillar-hall     a rectangular hall rotated by any angle, with round pillars, convex
//                   obstacles and slanted boxes;
//   round-walls     curved walls as CAD exports write them (arcs of 5 cm to 1 m segments): a
//                   rotunda with an annex behind a door, a curved corridor with rooms off
//                   it, a hall with rounded corners and an apse, or a hall with a concave
//                   round corner; round stair wells and pillars.
// Every family: any rotation, and in half of the draws a UTM-sized offset (x + 5e5..6e5,
// y + 5.4e6..5.5e6); the rest sit within 50 m of the origin.
#pragma once

#include "PathChecker.h"
#include "model/Plan.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fcgen {

enum class Family { RotatedOffice, DoorRooms, SlantedRooms, StarRoom, PillarHall, RoundWalls };

std::vector<Family> allFamilies();
const char* familyName(Family family); // "rotated-office", ...

struct GeneratedPlan {
    fc::Plan plan;
    Family family = Family::RotatedOffice;
    std::uint64_t seed = 0;
    double rotationDeg = 0.0;
    fc::Vec2 offset;
    int attempts = 1;        // draws made until one validated
    std::string description; // one line: family, seed, rotation, offset, sizes
};

// Throws std::runtime_error when 100 draws in a row fail validation (a generator bug).
GeneratedPlan generatePlan(Family family, std::uint64_t seed, const fc::RobotProfile& robot = {});

// Every coordinate of the plan (boundary, obstacles, rooms) rotated by angleDeg about the
// origin, then shifted by offset.
fc::Plan transformPlan(const fc::Plan& plan, double angleDeg, fc::Vec2 offset);

// `count` odd angles in degrees from a seed: uniform in [0, 360), to 0.1 degree, none
// within 1 degree of a multiple of 45 (so no wall of a rectilinear plan lands on an axis).
std::vector<double> oddAngles(std::uint64_t seed, int count);

// The plan and path as the checker takes them (the checker does not include planner
// headers).
fccheck::FreeSpace freeSpaceOf(const fc::Plan& plan);
fccheck::PolylineXY polylineOf(const fc::Polyline& path);

} // namespace fcgen
