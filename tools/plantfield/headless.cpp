// Headless frames: one --capture, a --frames sequence, and --stats, drawn by
// the offline renderer (engine/offline/offline_renderer.h).
#include "field_setup.h"
#include "modes.h"
#include "output_check.h"

#include "engine/image/image.h"
#include "engine/image/video_encoder.h"
#include "engine/offline/frame_stats_json.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace pf {

int runHeadless(const PlantfieldOptions& o) {
    // Started before the field is built, so a machine without ffmpeg says so at once.
    std::optional<VideoEncoder> video;
    if (!o.videoPath.empty()) video.emplace(o.videoPath, o.size.width, o.size.height, o.fps);
    std::optional<PreviewOrbit> orbit;
    FieldContent content = loadFieldContent(o, &orbit);
    OfflineRenderer renderer(std::move(content), offlineSettings(o, orbit));
    if (!o.outDir.empty()) std::filesystem::create_directories(o.outDir);

    const uint32_t frames = std::max(o.frames, 1u);
    // --frame-range A:B: the sequence stops after B, and the frames before A
    // are drawn as the whole run draws them, only not read back or written:
    // frame A carries their state (offline_renderer.h), so it is the whole
    // run's bit for bit.
    const auto [first, end] = writtenFrames(o);
    const bool terminal = isatty(fileno(stderr));
    for (uint32_t i = 0; i < end; ++i) {
        if (i < first) {
            renderer.drawFrame(i);
            if (terminal) std::fprintf(stderr, "\rplantfield: frame %u/%u (before the range)\x1b[K", i + 1, frames);
            continue;
        }
        const RgbaImage image = renderer.frame(i);
        if (!o.outDir.empty()) writePng(framePath(o.outDir, i), image);
        if (video) video->addFrame(image);
        if (terminal && o.frames > 0) std::fprintf(stderr, "\rplantfield: frame %u/%u\x1b[K", i + 1, frames);
        if (!o.capturePath.empty() && i + 1 == end) writePng(o.capturePath, image);
    }
    if (video) video->finish();
    const std::string written = o.outDir + (!o.outDir.empty() && video ? " and " : "") + o.videoPath;
    if (o.frameRange)
        std::fprintf(stderr, "\rplantfield: frames %u to %u of %u -> %s\n", first, end - 1, frames, written.c_str());
    else if (o.frames > 0)
        std::fprintf(stderr, "\rplantfield: %u frames -> %s\n", frames, written.c_str());
    if (o.stats) std::cout << frameStatsJson(renderer, inputName(o)) << "\n";
    const FieldFrameStats stats = renderer.stats();
    std::fprintf(stderr, "plantfield: %ux%u on %s: %u plants (%s), %.1f M triangles%s%s\n", o.size.width, o.size.height,
                 renderer.context().properties.deviceName, stats.instances, plantsPerLodText(stats).c_str(),
                 double(stats.triangles) / 1e6, o.capturePath.empty() ? "" : " -> ", o.capturePath.c_str());
    return 0;
}

} // namespace pf
