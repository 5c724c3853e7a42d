// Watching a set of files for changes (plantfield --watch, docs/PLANT_PREVIEW.md).
//
// Polled, not inotify: a stat of each file every few hundred milliseconds is
// portable (std::filesystem only), costs nothing next to a frame for the
// dozen files a plant or scene reads, and sees every way an editor saves —
// in place, or a new file renamed over the old (which an inotify watch on
// the old file's inode would lose). A file's stamp is its modification time
// and size; a content hash would also catch a save within one timestamp tick
// of the same size, at the price of reading every file (surfaces can be
// megabytes) each poll, while filesystems stamp in nanoseconds.
//
// Debounced: a change is reported only once the files have kept the same
// stamps for `settle`, so a save written in pieces, or an editor's write
// then rename, is one change, not two rebuilds, and never a half-written file.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace pf {

using WatchClock = std::chrono::steady_clock;

// What a poll sees of a file: missing, or its modification time and size.
struct FileStamp {
    bool exists = false;
    std::filesystem::file_time_type modified{};
    uintmax_t size = 0;
    bool operator==(const FileStamp&) const = default;
};

FileStamp stampOf(const std::filesystem::path& path);

struct FileWatch {
    std::vector<std::filesystem::path> paths;
    std::vector<FileStamp> reported;                 // per path: the stamp last reported (or seen at the start)
    std::vector<FileStamp> pending;                  // per path: the latest stamp while a change settles
    std::optional<WatchClock::time_point> changedAt; // when `pending` last changed; empty: nothing settling
    WatchClock::duration settle{};
};

// Watches `paths` from their stamps now: what they hold now is no change.
FileWatch watchFiles(std::vector<std::filesystem::path> paths,
                     WatchClock::duration settle = std::chrono::milliseconds(200));

// Watches `paths` instead, keeping the stamps last reported of those it
// already watched (a change while the caller rebuilt from them is still
// seen) and stamping the others now.
void rewatchFiles(FileWatch& watch, std::vector<std::filesystem::path> paths);

// Stamps every file at `now` and returns the paths whose stamp differs from
// the one last reported, once those stamps have held for the watch's
// settle time; each change is reported once. A file removed is a change, and
// so is one that appears.
std::vector<std::filesystem::path> pollChanges(FileWatch& watch, WatchClock::time_point now);

} // namespace pf
