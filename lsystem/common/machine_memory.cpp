#include "lsystem/common/machine_memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>

namespace lsys {
namespace {

std::string fileText(const std::filesystem::path& path) {
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

std::optional<uint64_t> leadingNumber(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end == text.data()) return std::nullopt;
    return value;
}

// v1 reports "no limit" as the largest page-aligned signed 64-bit count; any
// limit past 2^62 bytes is none in practice.
constexpr uint64_t kNoCgroupLimit = 1ull << 62;

std::optional<uint64_t> headroomUnder(const std::filesystem::path& limitFile, const std::filesystem::path& usageFile) {
    const std::optional<uint64_t> limit = leadingNumber(fileText(limitFile)); // "max" (v2: none) reads as nullopt
    if (!limit || *limit >= kNoCgroupLimit) return std::nullopt;
    const uint64_t used = leadingNumber(fileText(usageFile)).value_or(0);
    return *limit > used ? *limit - used : 0;
}

std::optional<uint64_t> tighter(std::optional<uint64_t> a, std::optional<uint64_t> b) {
    if (!a) return b;
    if (!b) return a;
    return std::min(*a, *b);
}

// The cgroup path of a /proc/self/cgroup line whose controllers field names
// `controller` ("" is the unified hierarchy's "0::PATH" line).
std::optional<std::string> cgroupPathOf(std::string_view procSelfCgroup, std::string_view controller) {
    while (!procSelfCgroup.empty()) {
        const size_t end = procSelfCgroup.find('\n');
        const std::string_view line = procSelfCgroup.substr(0, end);
        procSelfCgroup.remove_prefix(end == std::string_view::npos ? procSelfCgroup.size() : end + 1);
        const size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string_view::npos || second == std::string_view::npos) continue;
        const std::string_view controllers = line.substr(first + 1, second - first - 1);
        const bool named =
            controller.empty()
                ? controllers.empty()
                : ("," + std::string(controllers) + ",").find("," + std::string(controller) + ",") != std::string::npos;
        if (named) return std::string(line.substr(second + 1));
    }
    return std::nullopt;
}

// The tightest headroom from `cgroup` (a path below `mount`) up to the mount's root.
std::optional<uint64_t> headroomUpFrom(const std::filesystem::path& mount, std::string_view cgroup,
                                       const char* limitName, const char* usageName) {
    std::filesystem::path level = mount / std::filesystem::path(cgroup).relative_path();
    std::error_code missing;
    if (!std::filesystem::is_directory(level, missing)) level = mount;
    std::optional<uint64_t> headroom;
    for (;;) {
        headroom = tighter(headroom, headroomUnder(level / limitName, level / usageName));
        if (level == mount || !level.has_relative_path()) break;
        level = level.parent_path();
    }
    return headroom;
}

} // namespace

std::optional<uint64_t> procKilobytesField(std::string_view text, std::string_view key) {
    for (size_t at = text.find(key); at != std::string_view::npos; at = text.find(key, at + 1)) {
        if (at != 0 && text[at - 1] != '\n') continue;
        std::string_view rest = text.substr(at + key.size());
        if (rest.empty() || rest.front() != ':') continue;
        const std::optional<uint64_t> kilobytes = leadingNumber(rest.substr(1));
        if (!kilobytes) return std::nullopt;
        return *kilobytes > UINT64_MAX / 1024 ? UINT64_MAX : *kilobytes * 1024;
    }
    return std::nullopt;
}

std::optional<uint64_t> cgroupHeadroom(std::string_view procSelfCgroup, const std::filesystem::path& cgroupRoot) {
    std::optional<uint64_t> headroom;
    if (const std::optional<std::string> unified = cgroupPathOf(procSelfCgroup, "")) {
        // Mounted at the root (a v2-only system) or at ROOT/unified beside v1 controllers.
        for (const std::filesystem::path& mount : {cgroupRoot, cgroupRoot / "unified"})
            headroom = tighter(headroom, headroomUpFrom(mount, *unified, "memory.max", "memory.current"));
    }
    if (const std::optional<std::string> v1 = cgroupPathOf(procSelfCgroup, "memory"))
        headroom = tighter(
            headroom, headroomUpFrom(cgroupRoot / "memory", *v1, "memory.limit_in_bytes", "memory.usage_in_bytes"));
    return headroom;
}

std::optional<uint64_t> rlimitHeadroom(uint64_t softLimit, uint64_t used) {
    if (softLimit == UINT64_MAX) return std::nullopt;
    return softLimit > used ? softLimit - used : 0;
}

std::optional<uint64_t> budgetBytesFrom(const MemoryHeadroom& headroom) {
    std::optional<uint64_t> smallest;
    for (const std::optional<uint64_t>& room :
         {headroom.available, headroom.cgroup, headroom.addressSpace, headroom.data})
        smallest = tighter(smallest, room);
    if (!smallest) return std::nullopt;
    return *smallest / 4 * 3;
}

MemoryHeadroom machineMemoryHeadroom() {
    const std::string status = fileText("/proc/self/status");
    const auto underLimit = [&](int resource, std::string_view usedKey) -> std::optional<uint64_t> {
        rlimit limit{};
        if (getrlimit(resource, &limit) != 0) return std::nullopt;
        const uint64_t soft = limit.rlim_cur == RLIM_INFINITY ? UINT64_MAX : uint64_t(limit.rlim_cur);
        return rlimitHeadroom(soft, procKilobytesField(status, usedKey).value_or(0));
    };
    return {procKilobytesField(fileText("/proc/meminfo"), "MemAvailable"),
            cgroupHeadroom(fileText("/proc/self/cgroup"), "/sys/fs/cgroup"), underLimit(RLIMIT_AS, "VmSize"),
            underLimit(RLIMIT_DATA, "VmData")};
}

} // namespace lsys
