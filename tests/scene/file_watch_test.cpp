// engine/scene/file_watch.h: a change is reported once, after it has held
// still for the settle time; unchanged files never; a removed file and one
// that appears are changes. Modification times are set explicitly, so the
// tests do not depend on the filesystem's timestamp resolution or on sleeping.
#include "engine/scene/file_watch.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pf::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr WatchClock::duration kSettle = 200ms;

// Writes text and sets the file's time `second` seconds past a fixed epoch.
void writeAt(const fs::path& path, const std::string& text, int second) {
    std::ofstream(path, std::ios::binary) << text;
    fs::last_write_time(path, fs::file_time_type(std::chrono::seconds(1'700'000'000 + second)));
}

TEST(FileWatch, AChangeIsReportedOnceAfterItSettles) {
    const fs::path file = testFolder() / "plant.lsys";
    writeAt(file, "Axiom: F\n", 0);
    FileWatch watch = watchFiles({file}, kSettle);
    const WatchClock::time_point t0 = WatchClock::now();
    EXPECT_TRUE(pollChanges(watch, t0).empty());

    writeAt(file, "Axiom: FF\n", 1);
    EXPECT_TRUE(pollChanges(watch, t0 + 10ms).empty()) << "reported before it settled";
    EXPECT_TRUE(pollChanges(watch, t0 + 100ms).empty()) << "reported before it settled";
    EXPECT_EQ(pollChanges(watch, t0 + 250ms), std::vector<fs::path>{file});
    EXPECT_TRUE(pollChanges(watch, t0 + 500ms).empty()) << "one change reported twice";
    EXPECT_TRUE(pollChanges(watch, t0 + 2s).empty()) << "one change reported twice";
}

TEST(FileWatch, UnchangedFilesAreNotReported) {
    const fs::path a = testFolder() / "a.lsys", b = testFolder() / "b.v";
    writeAt(a, "Axiom: F\n", 0);
    writeAt(b, "angle increment: 30\n", 0);
    FileWatch watch = watchFiles({a, b}, kSettle);
    const WatchClock::time_point t0 = WatchClock::now();
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(pollChanges(watch, t0 + i * 300ms).empty());

    writeAt(b, "angle increment: 45\n", 2);
    pollChanges(watch, t0 + 2s);
    EXPECT_EQ(pollChanges(watch, t0 + 3s), std::vector<fs::path>{b}) << "only the changed file";
}

TEST(FileWatch, ARemovedFileAndOneThatAppearsAreChanges) {
    const fs::path file = testFolder() / "plant.map", later = testFolder() / "plant.v";
    writeAt(file, "colours", 0);
    fs::remove(later); // left by an earlier run
    FileWatch watch = watchFiles({file, later}, kSettle);
    const WatchClock::time_point t0 = WatchClock::now();
    fs::remove(file);
    pollChanges(watch, t0);
    EXPECT_EQ(pollChanges(watch, t0 + 1s), std::vector<fs::path>{file});

    writeAt(later, "angle increment: 30\n", 5);
    pollChanges(watch, t0 + 2s);
    EXPECT_EQ(pollChanges(watch, t0 + 3s), std::vector<fs::path>{later});
}

// A save written in pieces (or written, then renamed over the file) is one
// change, reported once its last piece has held still for the settle time.
TEST(FileWatch, ASaveInPiecesIsOneChange) {
    const fs::path file = testFolder() / "plant.lsys";
    writeAt(file, "Axiom: F\n", 0);
    FileWatch watch = watchFiles({file}, kSettle);
    const WatchClock::time_point t0 = WatchClock::now();
    writeAt(file, "Axiom: F", 1); // the first half
    EXPECT_TRUE(pollChanges(watch, t0).empty());
    writeAt(file, "Axiom: F\nF -> FF\n", 1); // the rest, within the same second: the size tells
    EXPECT_TRUE(pollChanges(watch, t0 + 150ms).empty());
    EXPECT_TRUE(pollChanges(watch, t0 + 300ms).empty()) << "the settle time restarts at each piece";
    EXPECT_EQ(pollChanges(watch, t0 + 400ms).size(), 1u);
    EXPECT_TRUE(pollChanges(watch, t0 + 1s).empty());
}

// A change undone before it settled is no change.
TEST(FileWatch, AChangeUndoneBeforeItSettlesIsNotReported) {
    const fs::path file = testFolder() / "plant.lsys";
    writeAt(file, "Axiom: F\n", 0);
    FileWatch watch = watchFiles({file}, kSettle);
    const WatchClock::time_point t0 = WatchClock::now();
    writeAt(file, "Axiom: G\nG -> F\n", 1);
    pollChanges(watch, t0);
    writeAt(file, "Axiom: F\n", 0);
    pollChanges(watch, t0 + 50ms);
    EXPECT_TRUE(pollChanges(watch, t0 + 1s).empty());
}

// Watching the files of a rebuild keeps what was seen of those watched
// before: a change made while the rebuild ran is still reported.
TEST(FileWatch, RewatchingKeepsTheStampsOfFilesWatchedBefore) {
    const fs::path kept = testFolder() / "plant.l", added = testFolder() / "plant.v";
    writeAt(kept, "Axiom: F\n", 0);
    writeAt(added, "angle increment: 30\n", 0);
    FileWatch watch = watchFiles({kept}, kSettle);
    writeAt(kept, "Axiom: FF\n", 3); // while the caller rebuilt
    rewatchFiles(watch, {kept, added});
    const WatchClock::time_point t0 = WatchClock::now();
    pollChanges(watch, t0);
    EXPECT_EQ(pollChanges(watch, t0 + 1s), std::vector<fs::path>{kept});
}

} // namespace
} // namespace pf::test
