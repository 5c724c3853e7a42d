#include "engine/vk/gpu_timer.h"

#include "engine/vk/resources.h"
#include "engine/vk/vk_check.h"

#include <stdexcept>

namespace pf {
namespace {

// Both ends of a scope are written at ALL_COMMANDS: the timestamp is taken
// once every earlier command in the queue has finished all its stages. A
// TOP_OF_PIPE begin would be stamped as soon as the command is reached, while
// earlier work may still be running, so a scope would absorb the tail of what
// came before it. BOTTOM_OF_PIPE would mean the same as ALL_COMMANDS here,
// but synchronization2 deprecates TOP/BOTTOM_OF_PIPE.
// The cost is that scopes measure serialised time, not overlap.
constexpr VkPipelineStageFlags2 kTimestampStage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;

uint32_t timestampValidBits(const GpuContext& ctx) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, families.data());
    return ctx.queueFamily < count ? families[ctx.queueFamily].timestampValidBits : 0;
}

} // namespace

GpuTimer createGpuTimer(const GpuContext& ctx, uint32_t maxScopes) {
    if (maxScopes == 0) throw std::invalid_argument("a GPU timer needs room for at least one scope");
    GpuTimer timer;
    timer.maxScopes = maxScopes;
    const uint32_t validBits = timestampValidBits(ctx);
    timer.nanosecondsPerTick = ctx.properties.limits.timestampPeriod;
    timer.supported = validBits > 0 && timer.nanosecondsPerTick > 0.0;
    if (!timer.supported) return timer;
    timer.validBitsMask = validBits >= 64 ? ~uint64_t(0) : (uint64_t(1) << validBits) - 1;

    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * maxScopes;
    VK_CHECK(vkCreateQueryPool(ctx.device, &info, nullptr, &timer.queryPool));
    return timer;
}

void destroyGpuTimer(const GpuContext& ctx, GpuTimer& timer) {
    vkDestroyQueryPool(ctx.device, timer.queryPool, nullptr);
    timer = {};
}

void resetGpuTimer(VkCommandBuffer cmd, GpuTimer& timer) {
    timer.scopes.clear();
    timer.openScopes.clear();
    timer.frameRecorded = true;
    if (timer.supported) vkCmdResetQueryPool(cmd, timer.queryPool, 0, 2 * timer.maxScopes);
}

void beginScope(VkCommandBuffer cmd, GpuTimer& timer, const char* name) {
    if (timer.scopes.size() >= timer.maxScopes)
        throw std::length_error("GPU timer scope '" + std::string(name) + "' exceeds the " +
                                std::to_string(timer.maxScopes) + " scopes the timer was created for");
    const uint32_t index = uint32_t(timer.scopes.size());
    timer.scopes.push_back({name});
    timer.openScopes.push_back(index);
    if (timer.supported) vkCmdWriteTimestamp2(cmd, kTimestampStage, timer.queryPool, 2 * index);
}

void beginScopeOutsideRendering(VkCommandBuffer cmd, GpuTimer& timer, const char* name) {
    beginScope(cmd, timer, name);
    if (timer.supported)
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                      VK_ACCESS_2_NONE);
}

void endScope(VkCommandBuffer cmd, GpuTimer& timer) {
    if (timer.openScopes.empty()) throw std::logic_error("endScope() without an open GPU timer scope");
    const uint32_t index = timer.openScopes.back();
    timer.openScopes.pop_back();
    timer.scopes[index].ended = true;
    if (timer.supported) vkCmdWriteTimestamp2(cmd, kTimestampStage, timer.queryPool, 2 * index + 1);
}

TimedScope::TimedScope(VkCommandBuffer cmd, GpuTimer* timer, const char* name, ScopeStart start)
    : cmd_(cmd), timer_(timer) {
    if (!timer_) return;
    if (start == ScopeStart::outsideRendering)
        beginScopeOutsideRendering(cmd_, *timer_, name);
    else
        beginScope(cmd_, *timer_, name);
}

TimedScope::~TimedScope() {
    if (timer_) endScope(cmd_, *timer_);
}

std::vector<ScopeTime> readGpuTimer(const GpuContext& ctx, const GpuTimer& timer) {
    std::vector<ScopeTime> times;
    if (!timer.supported || !timer.frameRecorded) return times;
    for (uint32_t i = 0; i < timer.scopes.size(); ++i) {
        if (!timer.scopes[i].ended) continue;
        struct {
            uint64_t ticks, available;
        } stamps[2];
        // No WAIT_BIT: the caller has waited for the fence; a query that is
        // still unavailable (frame never submitted) yields VK_NOT_READY.
        const VkResult result =
            vkGetQueryPoolResults(ctx.device, timer.queryPool, 2 * i, 2, sizeof(stamps), stamps, sizeof(stamps[0]),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
        if (result == VK_NOT_READY) continue;
        VK_CHECK(result);
        if (!stamps[0].available || !stamps[1].available) continue;
        // Masking the difference keeps it right across one wrap of the counter.
        const uint64_t ticks = (stamps[1].ticks - stamps[0].ticks) & timer.validBitsMask;
        times.push_back({timer.scopes[i].name, double(ticks) * timer.nanosecondsPerTick * 1e-6});
    }
    return times;
}

} // namespace pf
