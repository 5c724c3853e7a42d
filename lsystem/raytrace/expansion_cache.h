#pragma once
// The expanded objects a lazy tracer holds (docs/RAYTRACING.md, "Lazy
// expansion"): least recently used first out under a byte budget, as Robbins
// 1998 (§3) caches expanded branches. Guarded by one mutex and handing out
// shared pointers to immutable expansions, so threads tracing at once share
// what any of them expanded, and an expansion evicted while a ray uses it
// stays alive until that ray is done.

#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <vector>

namespace lsys {

struct ExpandedObject; // lazy_graph_tracer.h

struct ExpansionStats {
    uint64_t expansions = 0; // objects expanded on demand
    uint64_t evictions = 0;  // expansions dropped to stay within the budget
    uint64_t bytesHeld = 0;  // by the expansions the cache holds now
    uint64_t peakBytes = 0;  // the most it has held: never past the budget
};

struct CachedExpansion {
    std::shared_ptr<const ExpandedObject> expansion; // null when not held
    uint64_t bytes = 0;
    std::list<uint32_t>::iterator recency;
};

struct ExpansionCache {
    uint64_t budgetBytes = UINT64_MAX;
    std::mutex mutex;
    std::list<uint32_t> recency;          // held objects, most recently used first
    std::vector<CachedExpansion> objects; // by object, one for each of the graph's
    ExpansionStats stats;
};

// The held expansion of `object`, now the most recently used; null if none.
std::shared_ptr<const ExpandedObject> findExpansion(ExpansionCache& cache, uint32_t object);

// Counts a new expansion of `object` (`bytes` large) and holds it, evicting
// the least recently used until it fits; one larger than the whole budget is
// not held (the caller uses it and drops it). When another thread held one
// first, that one is returned.
std::shared_ptr<const ExpandedObject> holdExpansion(ExpansionCache& cache, uint32_t object,
                                                    std::shared_ptr<const ExpandedObject> expansion, uint64_t bytes);

ExpansionStats expansionStats(ExpansionCache& cache);

} // namespace lsys
