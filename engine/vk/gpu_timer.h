// GPU timestamps around named scopes of one frame's command buffer.
//
// Per frame: resetGpuTimer() at the start of the command buffer (outside any
// rendering), beginScope()/endScope() pairs around the work to time (they
// nest), then after the frame's fence readGpuTimer(). One frame in flight: the
// query pool is reused every frame.
#pragma once

#include "engine/vk/device.h"

#include <string>
#include <vector>

namespace pf {

struct ScopeTime {
    std::string name;
    double milliseconds = 0.0;
};

struct GpuTimer {
    // False when the queue family writes no timestamps (timestampValidBits 0)
    // or the device reports no tick length; every call is then a no-op apart
    // from the scope bookkeeping, and readGpuTimer() returns nothing.
    bool supported = false;
    VkQueryPool queryPool = VK_NULL_HANDLE; // two queries a scope: begin, end
    uint32_t maxScopes = 0;
    double nanosecondsPerTick = 0.0; // VkPhysicalDeviceLimits::timestampPeriod
    uint64_t validBitsMask = 0;      // timestamps wrap at timestampValidBits

    struct Scope {
        std::string name;
        bool ended = false;
    };
    std::vector<Scope> scopes;        // this frame's, in order of beginScope()
    std::vector<uint32_t> openScopes; // indices into scopes, innermost last
    bool frameRecorded = false;       // resetGpuTimer() was recorded at least once
};

// Throws when maxScopes is 0.
GpuTimer createGpuTimer(const GpuContext& ctx, uint32_t maxScopes);
void destroyGpuTimer(const GpuContext& ctx, GpuTimer& timer);

// Resets the queries and forgets last frame's scopes. Must be recorded
// outside dynamic rendering, before the frame's first beginScope().
void resetGpuTimer(VkCommandBuffer cmd, GpuTimer& timer);
// Throws when this frame already has maxScopes scopes.
void beginScope(VkCommandBuffer cmd, GpuTimer& timer, const char* name);
// beginScope for a scope that begins outside rendering (passes, dispatches,
// copies), followed by an execution dependency on everything before it, so
// that what is recorded next starts after the begin timestamp is written.
// lavapipe writes a timestamp at its next flush but runs a dispatch or copy
// as it meets it: without the dependency, the compute passes' work ran
// before their scopes began and fell outside them (the physics scope read
// 0.05 ms for 8 sub-steps that took about 10).
void beginScopeOutsideRendering(VkCommandBuffer cmd, GpuTimer& timer, const char* name);
// Ends the innermost open scope; throws when none is open.
void endScope(VkCommandBuffer cmd, GpuTimer& timer);

// Where a scope begins: around passes (beginScopeOutsideRendering), or
// around draws inside a rendering (beginScope: no dependency may be
// recorded there).
enum class ScopeStart { outsideRendering, insideRendering };

// A scope open for the object's lifetime; nothing when `timer` is null.
class TimedScope {
public:
    TimedScope(VkCommandBuffer cmd, GpuTimer* timer, const char* name, ScopeStart start = ScopeStart::outsideRendering);
    ~TimedScope();
    TimedScope(const TimedScope&) = delete;
    TimedScope& operator=(const TimedScope&) = delete;

private:
    VkCommandBuffer cmd_;
    GpuTimer* timer_;
};

// The durations of the last recorded frame's ended scopes, in the order they
// were begun. Call only after that frame's fence has signalled. Empty when
// timestamps are unsupported or no frame was recorded yet; a scope whose
// timestamps are not available is left out.
std::vector<ScopeTime> readGpuTimer(const GpuContext& ctx, const GpuTimer& timer);

} // namespace pf
