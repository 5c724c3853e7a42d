#include "engine/scene/file_watch.h"

#include <algorithm>

namespace pf {

FileStamp stampOf(const std::filesystem::path& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status)) return {};
    FileStamp stamp;
    stamp.exists = true;
    stamp.modified = std::filesystem::last_write_time(path, error);
    // A folder's size is the filesystem's business; its time changes with its entries.
    if (std::filesystem::is_regular_file(status)) stamp.size = std::filesystem::file_size(path, error);
    return stamp;
}

FileWatch watchFiles(std::vector<std::filesystem::path> paths, WatchClock::duration settle) {
    FileWatch watch;
    watch.paths = std::move(paths);
    for (const std::filesystem::path& path : watch.paths) watch.reported.push_back(stampOf(path));
    watch.pending = watch.reported;
    watch.settle = settle;
    return watch;
}

void rewatchFiles(FileWatch& watch, std::vector<std::filesystem::path> paths) {
    std::vector<FileStamp> stamps;
    for (const std::filesystem::path& path : paths) {
        const auto known = std::find(watch.paths.begin(), watch.paths.end(), path);
        stamps.push_back(known != watch.paths.end() ? watch.reported[size_t(known - watch.paths.begin())]
                                                    : stampOf(path));
    }
    watch.paths = std::move(paths);
    watch.reported = std::move(stamps);
    watch.pending = watch.reported;
    watch.changedAt.reset();
}

std::vector<std::filesystem::path> pollChanges(FileWatch& watch, WatchClock::time_point now) {
    std::vector<FileStamp> stamps;
    for (const std::filesystem::path& path : watch.paths) stamps.push_back(stampOf(path));
    if (stamps != watch.pending) { // still being written: wait for it to hold still
        watch.pending = std::move(stamps);
        watch.changedAt = now;
        return {};
    }
    if (!watch.changedAt || now - *watch.changedAt < watch.settle) return {};
    watch.changedAt.reset();
    std::vector<std::filesystem::path> changed;
    for (size_t i = 0; i < watch.paths.size(); ++i)
        if (watch.pending[i] != watch.reported[i]) changed.push_back(watch.paths[i]);
    watch.reported = watch.pending;
    return changed;
}

} // namespace pf
