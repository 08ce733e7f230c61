// Stripes that drive round small islands (issue 15). A traced map's interior is dotted with
// furniture legs, bins and pillars; as holes of the floor each one parts the stripes into
// cells of their own, entered one by one and joined by transits (the faculty map's interior:
// 943 m^2 swept with about 1,560 m of path, 390 m of it transits). Planned without those
// islands, the stripes run on, and where one meets an island it goes round it along the
// island's clearance ring instead.
#pragma once

#include "geometry/Geometry.h"
#include "model/CoveragePath.h"

#include <optional>
#include <vector>

namespace fc {

struct IslandDetours {
    std::vector<Ring> keptHoles; // holes the stripes must still part at
    std::vector<Ring> zones;     // rings the robot centre drives round instead of the others
};

// Splits the floor `outline` minus `holes` into holes kept and islands driven round. Holes
// closer together than the robot are merged first (the gaps between them filled); a hole
// of at most `maxIslandArea` is then driven round when the ring at `clearance` (and a few
// millimetres) around it, merged with its neighbours' where they overlap, keeps `clearance`
// from everything else; the rest are kept.
IslandDetours islandDetours(const Ring& outline, const std::vector<Ring>& holes, double clearance,
                            double maxIslandArea);

// `path` with each run inside a zone replaced by the shorter way round that zone's ring
// (contour segments). Empty where the path starts or ends inside a zone.
std::optional<CoveragePath> detouredPath(const CoveragePath& path, const std::vector<Ring>& zones);

} // namespace fc
