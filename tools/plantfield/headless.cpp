// Headless frames: one --capture, a --frames sequence, and --stats.
#include "field_setup.h"
#include "modes.h"

#include "engine/image/image.h"
#include "engine/vk/capture.h"
#include "engine/vk/gpu_timer.h"
#include "engine/vk/resources.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace pf {
namespace {

nlohmann::json statsJson(const PlantfieldOptions& o, const GpuContext& ctx, const FieldRenderer& renderer,
                         const FieldFrameStats& stats, const std::vector<ScopeTime>& gpu, double time, double wallMs) {
    nlohmann::json j;
    j["scene"] = inputName(o);
    j["device"] = ctx.properties.deviceName;
    j["size"] = {o.size.width, o.size.height};
    j["time"] = time;
    j["instances"] = stats.instances;
    j["models"] = renderer.content().models.models.size();
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) j["plants_per_lod"][kLodNames[lod]] = stats.plantsPerLod[lod];
    j["visible_entries"] = stats.visibleEntries();
    j["culled"] = stats.culled();
    j["occluded"] = stats.occluded;
    for (uint32_t c = 0; c < DRAW_CLASS_COUNT; ++c) j["draws"][kDrawClassNames[c]] = stats.draws[c];
    j["triangles"] = stats.triangles;
    nlohmann::json& shadow = j["shadow"];
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod)
        shadow["casters_per_lod"][kLodNames[lod]] = stats.shadowCastersPerLod[lod];
    shadow["cache_casters"] = stats.shadowCacheCasters;
    shadow["cache_renders"] = stats.shadowCacheRenders;
    nlohmann::json& clusters = j["clusters"];
    clusters["far_nodes"] = stats.clustersFar;
    clusters["far_plants"] = stats.clusterFarPlants;
    clusters["near_leaves"] = stats.nearLeaves;
    clusters["near_plants"] = stats.nearPlants;
    j["joints_simulated"] = renderer.simulatedJoints();
    j["indirect_count"] = ctx.drawIndirectCount;
    nlohmann::json ms = nlohmann::json::object();
    double total = 0;
    for (const ScopeTime& s : gpu) {
        ms[s.name] = s.milliseconds;
        if (!nestedInColourPass(s.name)) total += s.milliseconds;
    }
    ms["total"] = total;
    j["gpu_ms"] = ms;
    j["frame_wall_ms"] = wallMs;
    j["gpu_bytes"] = renderer.gpuBytes();
    return j;
}

std::string framePath(const std::string& dir, uint32_t index) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04u.png", index);
    return (std::filesystem::path(dir) / name).string();
}

} // namespace

int runHeadless(const PlantfieldOptions& o) {
    std::optional<PreviewOrbit> orbit;
    FieldContent content = loadFieldContent(o, &orbit);
    const Scene scene = content.scene;
    GpuContext ctx;
    createHeadlessContext(ctx, gpuOptions(o));
    const VkExtent2D extent{o.size.width, o.size.height};
    {
        FieldRenderer renderer(ctx, std::move(content), renderSettings(o));
        RenderTarget target = createRenderTarget(ctx, extent, renderer.antialiasing());
        GpuTimer timer = createGpuTimer(ctx, 16);
        if (!o.outDir.empty()) std::filesystem::create_directories(o.outDir);

        const uint32_t frames = o.outDir.empty() ? 1 : o.frames;
        // --frame-range A:B: the sequence stops after B, and the frames
        // before A are recorded as the whole run records them, only not
        // read back or written. A frame carries state to the next (the
        // plants' motion from rest at the first frame's time − 5 s, LOD
        // fades, the shadow cache, the depth pyramid), so frame A is then
        // the whole run's bit for bit.
        const uint32_t first = o.frameRange ? o.frameRange->first : 0;
        const uint32_t end = o.frameRange ? o.frameRange->last + 1 : frames;
        const bool terminal = isatty(fileno(stderr));
        const double step = 1.0 / o.fps;
        double wallMs = 0, time = o.time;
        for (uint32_t i = 0; i < end; ++i) {
            time = o.time + i * step;
            renderer.setView(pathView(o, scene, time, i == 0 ? 0.0 : step, i == 0, orbit), extent);
            if (i < first) {
                submitAndWait(ctx, [&](VkCommandBuffer cmd) { renderer.record(cmd, target, &timer); });
                if (terminal) std::fprintf(stderr, "\rplantfield: frame %u/%u (before the range)\x1b[K", i + 1, frames);
                continue;
            }
            const auto start = std::chrono::steady_clock::now();
            const RgbaImage image = captureFrame(
                ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer.record(cmd, t, &timer); });
            wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (!o.outDir.empty()) {
                writePng(framePath(o.outDir, i), image);
                if (terminal) std::fprintf(stderr, "\rplantfield: frame %u/%u\x1b[K", i + 1, frames);
            }
            if (!o.capturePath.empty() && i + 1 == end) writePng(o.capturePath, image);
        }
        if (o.frameRange)
            std::fprintf(stderr, "\rplantfield: frames %u to %u of %u -> %s\n", first, end - 1, frames,
                         o.outDir.c_str());
        else if (!o.outDir.empty())
            std::fprintf(stderr, "\rplantfield: %u frames -> %s\n", frames, o.outDir.c_str());
        const FieldFrameStats stats = renderer.readStats();
        if (o.stats)
            std::cout << statsJson(o, ctx, renderer, stats, readGpuTimer(ctx, timer), time, wallMs).dump(2) << "\n";
        std::fprintf(stderr, "plantfield: %ux%u on %s: %u plants (%s), %.1f M triangles%s%s\n", o.size.width,
                     o.size.height, ctx.properties.deviceName, stats.instances, plantsPerLodText(stats).c_str(),
                     double(stats.triangles) / 1e6, o.capturePath.empty() ? "" : " -> ", o.capturePath.c_str());
        destroyGpuTimer(ctx, timer);
        destroyRenderTarget(target);
    }
    destroyContext(ctx);
    return 0;
}

} // namespace pf
