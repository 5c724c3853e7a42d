#include "sweep.h"

#include "gpu_memory.h"
#include "progress.h"

#include "engine/vk/gpu_timer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <new>
#include <stdexcept>
#include <string_view>

namespace pf {

std::optional<Spread> spreadOf(std::vector<double> samples) {
    if (samples.empty()) return std::nullopt;
    std::sort(samples.begin(), samples.end());
    const size_t n = samples.size();
    Spread s;
    s.median = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
    s.p95 = samples[size_t(std::ceil(0.95 * double(n))) - 1];
    return s;
}

std::vector<double> measuredTimes(const PlantbenchOptions& o, const Scene& scene) {
    return o.pathTimes ? timesAlongPath(scene.camera, *o.pathTimes) : std::vector<double>{o.time};
}

size_t slowestTime(const std::vector<CameraTimeResult>& times) {
    size_t slowest = 0;
    for (size_t i = 1; i < times.size(); ++i)
        if (times[i].driven.frameMs.median > times[slowest].driven.frameMs.median) slowest = i;
    return slowest;
}

bool nestedInColor(size_t pass) { return pass < kFieldScopes.size() && kFieldScopes[pass].insideColor; }

namespace {

using Clock = std::chrono::steady_clock;

std::string secondsText(double seconds) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f", seconds);
    return text;
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of every thread of this process so far, milliseconds.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// The render target, the host buffer its captures go to and the timer of
// one count, released however the count ends.
struct FrameResources {
    FrameResources(const GpuContext& ctx, VkExtent2D extent, const Antialiasing& antialiasing)
        : ctx(ctx), resources(ctx), target(createRenderTarget(ctx, extent, antialiasing)),
          capture(createHostBuffer(resources, VkDeviceSize(extent.width) * extent.height * 4,
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT)),
          timer(createGpuTimer(ctx, uint32_t(kPassCount))) {}
    ~FrameResources() { destroyGpuTimer(ctx, timer); }

    const GpuContext& ctx;
    GpuResources resources; // the capture buffer
    RenderTarget target;
    Buffer capture;
    GpuTimer timer;
};

// What engine/vk/capture.cpp records after a frame: the resolved image (left in
// TRANSFER_SRC_OPTIMAL by the renderer) copied to a host buffer and made
// visible to the host, timed as the "capture" scope.
void recordCapture(VkCommandBuffer cmd, FrameResources& frame) {
    beginScopeOutsideRendering(cmd, frame.timer, kCapturePass);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {frame.target.extent.width, frame.target.extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, frame.target.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, frame.capture.buffer, 1,
                           &region);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    endScope(cmd, frame.timer);
}

enum class Path { Driven, Naive };

// Scene time between two frames of a still camera: the wind physics takes
// this frame's sub-steps (subStep 1/240 s: 4), as it would at 60 frames a
// second.
constexpr double kStillFrameSeconds = 1.0 / 60.0;

// The view of frame i of a measurement starting at `start`: the scene time
// runs on from there, and with --fly the camera follows its path with it
// and the physics steps as a window's does.
FieldView frameView(const PlantbenchOptions& o, const Scene& scene, const FieldView& start, uint32_t i) {
    const double seconds = o.flyFps ? 1.0 / *o.flyFps : kStillFrameSeconds;
    FieldView v = start;
    v.firstFrame = i == 0;
    const double t = double(start.time) + i * seconds;
    v.time = float(t);
    v.deltaTime = i == 0 ? 0.0f : float(seconds);
    if (o.flyFps) {
        v.camera = cameraAt(scene.camera, t);
        v.realTime = true; // the physics of a window at that rate (field_motion.h)
    }
    return v;
}

// Warm-up then measured frames of one path from `view`: the scene time runs
// on, so the physics has steps to take; the camera stays or flies (--fly).
PathTimes measurePath(const PlantbenchOptions& o, const Scene& scene, const GpuContext& ctx, FieldRenderer& renderer,
                      FrameResources& frame, const FieldView& view, Path path, const SweepProgress& progress,
                      double progressStart, double progressSpan) {
    std::vector<double> frameMs, cpuMs, processMs;
    std::array<std::vector<double>, kPassCount> gpuMs;
    const uint32_t all = o.warmup + o.frames;
    std::string name = path == Path::Driven ? "GPU-driven" : "naive";
    if (o.pathTimes) name += " at t = " + secondsText(view.time) + " s";
    uint64_t cacheRendersBefore = 0;
    for (uint32_t i = 0; i < all; ++i) {
        const bool warm = i < o.warmup;
        if (i == o.warmup) cacheRendersBefore = renderer.readStats().shadowCacheRenders;
        showProgress(progress, progressStart + progressSpan * double(i) / all,
                     name + (warm ? " warm-up " : " frame ") + std::to_string(warm ? i + 1 : i - o.warmup + 1) + "/" +
                         std::to_string(warm ? o.warmup : o.frames));
        const FieldView v = frameView(o, scene, view, i);
        const Clock::time_point start = Clock::now();
        const double processStart = processCpuMs();
        renderer.setView(v, frame.target.extent);
        double recordMs = 0.0;
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            if (path == Path::Driven)
                renderer.record(cmd, frame.target, &frame.timer);
            else
                renderer.recordNaive(cmd, frame.target, &frame.timer);
            recordCapture(cmd, frame);
            recordMs = msSince(start);
        });
        const double wallMs = msSince(start);
        const double frameProcessMs = processCpuMs() - processStart;
        if (warm) continue;
        frameMs.push_back(wallMs);
        cpuMs.push_back(recordMs);
        processMs.push_back(frameProcessMs);
        for (const ScopeTime& scope : readGpuTimer(ctx, frame.timer))
            for (size_t p = 0; p < kPassCount; ++p)
                if (scope.name == kBenchPasses[p]) gpuMs[p].push_back(scope.milliseconds);
    }
    PathTimes times;
    times.frameMs = *spreadOf(frameMs);
    times.cpuMs = *spreadOf(cpuMs);
    times.processCpuMs = *spreadOf(processMs);
    for (size_t p = 0; p < kPassCount; ++p) times.gpuMs[p] = spreadOf(gpuMs[p]);
    times.shadowCacheRenders = renderer.readStats().shadowCacheRenders - cacheRendersBefore;
    return times;
}

void refuseIf(const std::string& problem) {
    if (!problem.empty()) throw std::runtime_error(problem);
}

CountMode countMode(const PlantbenchOptions& o) { return o.densify ? CountMode::Densify : CountMode::NaturalDensity; }

// The scene's camera at time t, the scene time starting there.
FieldView viewAt(const Scene& scene, double t) {
    FieldView view;
    view.camera = cameraAt(scene.camera, t);
    view.time = float(t);
    return view;
}

CountResult measureCount(const PlantbenchOptions& o, GpuContext& ctx, const Scene& scene, uint64_t count, bool budget,
                         const HeapCapacity& heap, const SweepProgress& progress) {
    CountResult r;
    r.count = count;
    const Clock::time_point buildStart = Clock::now();
    const PlantCount plants{size_t(count), countMode(o)};
    showProgress(progress, 0.0, "placing plants"); // buildFieldContent reports only the models after
    FieldContent content = buildFieldContent(
        scene, plants,
        [&](size_t done, size_t all, const std::string& name) {
            showProgress(progress, 0.0,
                         "building plant models " + std::to_string(done) + "/" + std::to_string(all) + " (" + name +
                             ")");
        },
        o.memory);
    // The scene's plants and includes are known now: no output may replace them.
    if (const std::string problem = outputsProblem(o); !problem.empty()) throw SceneError(problem);
    r.buildSeconds = std::chrono::duration<double>(Clock::now() - buildStart).count();
    r.terrainSize = content.scene.terrain.size;
    r.placementNote = content.note;
    // Again with the model pool's size, now known.
    refuseIf(gpuMemoryProblem(
        count, estimatedFieldBytes(count, &content.models, o.size.width, o.size.height, o.antialiasing, o.shadows),
        ctx.properties.deviceName, heap));

    FieldRenderSettings settings;
    settings.antialiasing = o.antialiasing;
    settings.shadows = o.shadows;
    settings.occlusionCulling = o.occlusionCulling;
    settings.clusters.enabled = o.clusters;
    settings.memory = o.memory;
    showProgress(progress, 0.0, "uploading the field and baking impostors");
    FieldRenderer renderer(ctx, std::move(content), settings);
    FrameResources frame(ctx, {o.size.width, o.size.height}, renderer.antialiasing());

    const bool naive = o.compareNaive && count <= o.naiveMax;
    const std::vector<double> times = measuredTimes(o, scene);
    const double drivenSpan = (naive ? 0.5 : 1.0) / double(times.size());
    std::vector<CameraTimeResult> measured;
    for (size_t t = 0; t < times.size(); ++t) {
        const PathTimes driven = measurePath(o, scene, ctx, renderer, frame, viewAt(scene, times[t]), Path::Driven,
                                             progress, drivenSpan * double(t), drivenSpan);
        measured.push_back({times[t], driven, renderer.readStats()});
    }
    const CameraTimeResult& slowest = measured[slowestTime(measured)];
    r.time = slowest.time;
    r.driven = slowest.driven;
    r.stats = slowest.stats;
    if (o.pathTimes) r.alongPath = measured;
    r.rendererBytes = renderer.gpuBytes();
    r.jointsSimulated = renderer.simulatedJoints();
    r.gpuMemoryBytes = budget ? deviceLocalUsage(ctx) : r.rendererBytes;
    if (naive) {
        r.naive = measurePath(o, scene, ctx, renderer, frame, viewAt(scene, r.time), Path::Naive, progress, 0.5, 0.5);
        r.naiveTriangles = renderer.naiveTriangles();
    } else if (o.compareNaive) {
        r.note =
            "naive skipped: " + std::to_string(count) + " plants is above --naive-max " + std::to_string(o.naiveMax);
    }
    return r;
}

} // namespace

void runSweep(const PlantbenchOptions& o, const Scene& scene, GpuContext& ctx, SweepResult& result) {
    const bool budget = hasMemoryBudget(ctx);
    result.scenePath = o.scenePath;
    result.device = ctx.properties.deviceName;
    result.memorySource = budget ? "VK_EXT_memory_budget" : "renderer accounting";
    const HeapCapacity heap = largestDeviceLocalHeap(ctx, budget);
    // A CPU device (lavapipe) takes its "GPU" memory from the host too.
    const bool hostHoldsGpu = ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    // Refuse the whole sweep up front rather than after hours of smaller counts.
    for (uint64_t count : o.counts) {
        const uint64_t gpuBytes =
            estimatedFieldBytes(count, nullptr, o.size.width, o.size.height, o.antialiasing, o.shadows);
        refuseIf(gpuMemoryProblem(count, gpuBytes, ctx.properties.deviceName, heap));
        const std::string host =
            hostMemoryProblem(count, estimatedHostBytes(count, countMode(o)) + (hostHoldsGpu ? gpuBytes : 0), o.memory);
        if (!host.empty()) throw lsys::MemoryBudgetError(host);
    }

    SweepProgress progress = startProgress(o.counts.size());
    for (size_t i = 0; i < o.counts.size(); ++i) {
        progress.countIndex = i;
        progress.plants = o.counts[i];
        try {
            result.counts.push_back(measureCount(o, ctx, scene, o.counts[i], budget, heap, progress));
        } catch (const SceneError&) {
            throw;
        } catch (const lsys::MemoryBudgetError& e) {
            throw lsys::MemoryBudgetError("at " + std::to_string(o.counts[i]) + " plants " + e.what());
        } catch (const lsys::DerivationError&) { // a species past the module budget
            throw;
        } catch (const std::bad_alloc&) { // below the budget: a stage it does not count
            throw lsys::MemoryBudgetError("at " + std::to_string(o.counts[i]) +
                                          " plants the host ran out of memory: measure fewer plants or lower "
                                          "--memory-budget");
        } catch (const DeviceLimitError& e) { // more than the device takes: bad input, exit 2
            throw DeviceLimitError("at " + std::to_string(o.counts[i]) + " plants " + e.what());
        } catch (const std::runtime_error& e) {
            const std::string at = "at " + std::to_string(o.counts[i]) + " plants ";
            if (std::strstr(e.what(), "VK_ERROR_OUT_OF_DEVICE_MEMORY") != nullptr)
                throw DeviceLimitError(at + "the device ran out of GPU memory (measure fewer plants): " + e.what());
            throw std::runtime_error(at + "the frame failed: " + e.what());
        }
        finishCount(progress, result.counts.back());
    }
}

} // namespace pf
