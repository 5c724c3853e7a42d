// The default memory budget's inputs (lsystem/common/machine_memory.h): the
// /proc fields, the cgroup limits of a process and its ancestors read from a
// cgroup tree laid out in a scratch folder as the kernel lays it out, and the
// resource limits.

#include "lsystem/common/machine_memory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "test_support.h"

namespace lsys::test {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("plantfield_machine_memory_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(MachineMemory, ProcFieldsAreReadInBytes) {
    const std::string meminfo = "MemTotal:       32768000 kB\nMemFree:         1000 kB\n"
                                "MemAvailable:   24000000 kB\nBuffers:          100 kB\n";
    EXPECT_EQ(procKilobytesField(meminfo, "MemAvailable"), 24000000ull * 1024);
    EXPECT_EQ(procKilobytesField(meminfo, "MemTotal"), 32768000ull * 1024);
    EXPECT_EQ(procKilobytesField(meminfo, "Available"), std::nullopt); // whole keys only
    EXPECT_EQ(procKilobytesField("VmPeak:\t  9000 kB\nVmSize:\t    8192 kB\n", "VmSize"), 8192ull * 1024);
    EXPECT_EQ(procKilobytesField("MemTotal: 1 kB\n", "MemAvailable"), std::nullopt);
    EXPECT_EQ(procKilobytesField("", "MemAvailable"), std::nullopt);
}

TEST(MachineMemory, BudgetIsThreeQuartersOfTheSmallestHeadroom) {
    EXPECT_EQ(budgetBytesFrom({.available = 24ull << 30}), (24ull << 30) / 4 * 3);
    EXPECT_EQ(budgetBytesFrom({.available = 24ull << 30, .cgroup = 4ull << 30, .addressSpace = 8ull << 30}),
              3ull << 30);
    EXPECT_EQ(budgetBytesFrom({.available = 24ull << 30, .data = 400}), 300u);
    EXPECT_EQ(budgetBytesFrom({}), std::nullopt);
    EXPECT_GT(machineMemoryBudget().limitBytes, 0u);
    EXPECT_LT(machineMemoryBudget().limitBytes, UINT64_MAX);
}

TEST(MachineMemory, ResourceLimitsLeaveTheirLimitLessWhatIsUsed) {
    EXPECT_EQ(rlimitHeadroom(UINT64_MAX, 1000), std::nullopt); // RLIM_INFINITY
    EXPECT_EQ(rlimitHeadroom(4096, 1000), 3096u);
    EXPECT_EQ(rlimitHeadroom(4096, 9000), 0u);
}

TEST(MachineMemory, UnifiedCgroupLimitOfAnAncestorBindsTheProcess) {
    const fs::path root = freshDir("v2");
    writeFile(root / "ci/memory.max", "4294967296\n");
    writeFile(root / "ci/memory.current", "1073741824\n");
    writeFile(root / "ci/job/memory.max", "max\n");
    writeFile(root / "ci/job/memory.current", "536870912\n");
    EXPECT_EQ(cgroupHeadroom("0::/ci/job\n", root), 3ull << 30);
    writeFile(root / "ci/job/memory.max", "2147483648\n");
    EXPECT_EQ(cgroupHeadroom("0::/ci/job\n", root), (2ull << 30) - (512ull << 20));
    EXPECT_EQ(cgroupHeadroom("0::/elsewhere\n", root), std::nullopt) << "the root's own files are not a limit";
    fs::remove_all(root);
}

TEST(MachineMemory, UnifiedCgroupBesideVersionOneIsUnderUnified) {
    const fs::path root = freshDir("hybrid");
    writeFile(root / "unified/svc/memory.max", "1000000\n");
    writeFile(root / "unified/svc/memory.current", "400000\n");
    EXPECT_EQ(cgroupHeadroom("1:cpu:/\n0::/svc\n", root), 600000u);
    fs::remove_all(root);
}

TEST(MachineMemory, VersionOneMemoryControllerIsRead) {
    const fs::path root = freshDir("v1");
    // The v1 "no limit" value, on the mount's root.
    writeFile(root / "memory/memory.limit_in_bytes", "9223372036854771712\n");
    writeFile(root / "memory/memory.usage_in_bytes", "964644864\n");
    writeFile(root / "memory/runner/memory.limit_in_bytes", "2147483648\n");
    writeFile(root / "memory/runner/memory.usage_in_bytes", "1073741824\n");
    const std::string cgroup = "9:name=systemd:/\n5:devices:/\n4:cpu,memory:/runner\n0::/\n";
    EXPECT_EQ(cgroupHeadroom(cgroup, root), 1ull << 30);
    EXPECT_EQ(cgroupHeadroom("4:memory:/\n", root), std::nullopt);
    fs::remove_all(root);
}

TEST(MachineMemory, ACgroupPathOutsideTheContainersViewIsReadFromTheMountsRoot) {
    // Inside a container the host's cgroup path is listed but the container
    // sees its own cgroup as the mount's root.
    const fs::path root = freshDir("container");
    writeFile(root / "memory/memory.limit_in_bytes", "4294967296\n");
    writeFile(root / "memory/memory.usage_in_bytes", "0\n");
    EXPECT_EQ(cgroupHeadroom("4:memory:/docker/0123abcd\n", root), 4ull << 30);
    fs::remove_all(root);
}

} // namespace
} // namespace lsys::test
