#pragma once
// What this process may allocate on the machine it runs on: the default
// memory budget (machineMemoryBudget in memory_budget.h) is 3/4 of the
// smallest of these headrooms. Available memory alone is blind to the limits
// CI runners and containers set: a cgroup's memory limit (the kernel's OOM
// killer ends the process past it) and the process's RLIMIT_AS and
// RLIMIT_DATA (past them malloc fails). Each headroom is the limit less what
// is already used, so a budget taken late in a run (after the Vulkan driver
// mapped its memory) still fits.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace lsys {

// Bytes left under each limit; nullopt where there is no such limit or it
// cannot be read.
struct MemoryHeadroom {
    std::optional<uint64_t> available;    // MemAvailable in /proc/meminfo
    std::optional<uint64_t> cgroup;       // the tightest memory limit of the process's cgroup and its ancestors
    std::optional<uint64_t> addressSpace; // RLIMIT_AS less VmSize
    std::optional<uint64_t> data;         // RLIMIT_DATA less VmData
};

// The headrooms of this process now.
MemoryHeadroom machineMemoryHeadroom();

// 3/4 of the smallest headroom (the rest left to the system and to what the
// stages do not count); nullopt when none is known.
std::optional<uint64_t> budgetBytesFrom(const MemoryHeadroom& headroom);

// The value of a "Key:   1234 kB" line of /proc/meminfo or /proc/self/status,
// in bytes; nullopt without such a line.
std::optional<uint64_t> procKilobytesField(std::string_view text, std::string_view key);

// The headroom under the cgroup memory limits of the process whose
// /proc/self/cgroup reads `procSelfCgroup`, with the cgroup file systems
// mounted at `cgroupRoot` (/sys/fs/cgroup): the unified hierarchy (v2:
// memory.max less memory.current, at ROOT or ROOT/unified) and the v1 memory
// controller (memory.limit_in_bytes less memory.usage_in_bytes at
// ROOT/memory), each level from the process's cgroup up to the root, since a
// limit set on a parent binds its children. A path that is not there (a
// container sees its own cgroup as the mount's root) is looked up from the
// mount's root instead. nullopt when no level has a limit.
std::optional<uint64_t> cgroupHeadroom(std::string_view procSelfCgroup, const std::filesystem::path& cgroupRoot);

// The room under a soft resource limit given the bytes already used; nullopt
// for RLIM_INFINITY (passed as UINT64_MAX).
std::optional<uint64_t> rlimitHeadroom(uint64_t softLimit, uint64_t used);

} // namespace lsys
