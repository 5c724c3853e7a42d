#include "lsystem/raytrace/expansion_cache.h"

#include <algorithm>

namespace lsys {

std::shared_ptr<const ExpandedObject> findExpansion(ExpansionCache& cache, uint32_t object) {
    const std::lock_guard lock(cache.mutex);
    if (!cache.objects[object].expansion) return nullptr;
    CachedExpansion& held = cache.objects[object];
    cache.recency.splice(cache.recency.begin(), cache.recency, held.recency);
    return held.expansion;
}

std::shared_ptr<const ExpandedObject> holdExpansion(ExpansionCache& cache, uint32_t object,
                                                    std::shared_ptr<const ExpandedObject> expansion, uint64_t bytes) {
    const std::lock_guard lock(cache.mutex);
    ++cache.stats.expansions;
    if (cache.objects[object].expansion) return cache.objects[object].expansion;
    if (bytes > cache.budgetBytes) return expansion;
    while (cache.stats.bytesHeld + bytes > cache.budgetBytes) {
        CachedExpansion& oldest = cache.objects[cache.recency.back()];
        cache.stats.bytesHeld -= oldest.bytes;
        oldest = {};
        cache.recency.pop_back();
        ++cache.stats.evictions;
    }
    cache.recency.push_front(object);
    cache.objects[object] = {expansion, bytes, cache.recency.begin()};
    cache.stats.bytesHeld += bytes;
    cache.stats.peakBytes = std::max(cache.stats.peakBytes, cache.stats.bytesHeld);
    return expansion;
}

ExpansionStats expansionStats(ExpansionCache& cache) {
    const std::lock_guard lock(cache.mutex);
    return cache.stats;
}

} // namespace lsys
