// Values derived from a decomposition's free space alone (the metrics' floor raster),
// computed on first use and shared by every decomposition of that free space (FloorCache):
// the editor's live replanning measures many paths of one floor, and each would otherwise
// rasterise the floor again.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace fc {

class DerivedCache {
public:
    // The value under `key`, made by `make` on first use (callers of one key made
    // concurrently wait for the first). `make` must depend only on the free space and what the
    // key names.
    template <class T>
    std::shared_ptr<const T> get(const std::string& key,
                                 const std::function<std::shared_ptr<const T>()>& make) {
        std::shared_ptr<Slot> slot;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            auto& entry = slots_[key];
            if (!entry)
                entry = std::make_shared<Slot>();
            slot = entry;
        }
        std::call_once(slot->once, [&] { slot->value = make(); });
        return std::static_pointer_cast<const T>(slot->value);
    }

private:
    struct Slot {
        std::once_flag once;
        std::shared_ptr<const void> value;
    };
    std::mutex mutex_;
    std::map<std::string, std::shared_ptr<Slot>> slots_;
};

} // namespace fc
