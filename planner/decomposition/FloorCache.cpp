#include "decomposition/FloorCache.h"

namespace fc {

FloorCache::Parts FloorCache::partsFor(const std::vector<Ring>& rings, double radius,
                                       double inset) {
    std::shared_ptr<Slot> slot;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (auto it = slots_.begin(); it != slots_.end(); ++it) {
            if ((*it)->radius == radius && (*it)->inset == inset && (*it)->rings == rings) {
                slot = *it;
                slots_.erase(it);
                break;
            }
        }
        if (!slot) {
            slot = std::make_shared<Slot>();
            slot->rings = rings;
            slot->radius = radius;
            slot->inset = inset;
        }
        slots_.push_front(slot);
        if (slots_.size() > kCapacity)
            slots_.pop_back();
    }
    // Made outside the lock: another floor's parts may be made at the same time, and a
    // second caller of this floor waits for the first.
    std::call_once(slot->once, [&] {
        slot->parts.clearance = std::make_shared<const ClearanceField>(rings, radius, inset);
        slot->parts.derived = std::make_shared<DerivedCache>();
    });
    return slot->parts;
}

} // namespace fc
