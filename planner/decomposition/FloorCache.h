// What a decomposition derives from its free space alone, kept across decompositions of one
// floor: the clearance field (wall index, corner waypoints, open regions) and the derived
// values (DerivedCache: the metrics' floor raster). An edit of the rooms, of the query or of
// the sweep angle back to an earlier one leaves the free space in the sweep frame as it was,
// and the editor's live replanning then builds none of them again.
#pragma once

#include "decomposition/DerivedCache.h"
#include "geometry/Clearance.h"

#include <list>
#include <memory>
#include <mutex>
#include <vector>

namespace fc {

class FloorCache {
public:
    struct Parts {
        std::shared_ptr<const ClearanceField> clearance;
        std::shared_ptr<DerivedCache> derived;
    };

    // The parts of the free space `rings` (sweep frame) for a robot of clearance `radius`
    // and stripe `inset` (ClearanceField's arguments), made on first use; equal rings and
    // radii, the same parts. Keeps the most recently used kCapacity floors.
    Parts partsFor(const std::vector<Ring>& rings, double radius, double inset);

    static constexpr size_t kCapacity = 8;

private:
    struct Slot {
        std::vector<Ring> rings;
        double radius = 0.0, inset = 0.0;
        std::once_flag once;
        Parts parts;
    };
    std::mutex mutex_;
    std::list<std::shared_ptr<Slot>> slots_; // most recently used first
};

} // namespace fc
