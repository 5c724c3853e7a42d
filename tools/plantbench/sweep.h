// The measurement: for each count, the scene's field with that many plants,
// warm-up frames, then measured frames of the GPU-driven path from one camera
// time or, with --path, from each of several along the camera path, the
// camera staying there or, with --fly, flying on along the path (and, with
// --compare naive, of the naive path at the slowest of them), each copying its
// image to a host buffer as a capture does, submitted and waited for.
#pragma once

#include "plantbench_options.h"

#include "engine/field/field_renderer.h"
#include "engine/field/field_scopes.h"
#include "engine/scene/scene.h"
#include "engine/vk/device.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace pf {

// The scopes plantbench times, in recording order: every scope of the
// renderer's frame (kFieldScopes), then "capture", plantbench's own copy of
// the resolved image to a host buffer after it (what a capture adds).
inline constexpr const char* kCapturePass = "capture";
inline constexpr auto kBenchPasses = [] {
    std::array<const char*, kFieldScopes.size() + 1> passes{};
    for (size_t p = 0; p < kFieldScopes.size(); ++p) passes[p] = kFieldScopes[p].name;
    passes.back() = kCapturePass;
    return passes;
}();
inline constexpr size_t kPassCount = kBenchPasses.size();

// True for the draw scopes inside "colour" (kFieldScopes' insideColour).
bool nestedInColor(size_t pass);

// Median and 95th percentile of one quantity over the measured frames;
// nullopt when no frame reported it (no timestamps on the device). p95 is
// the nearest-rank percentile.
struct Spread {
    double median = 0.0;
    double p95 = 0.0;
};
std::optional<Spread> spreadOf(std::vector<double> samples);

// What one path (GPU-driven or naive) measured over its frames.
struct PathTimes {
    Spread frameMs; // wall time of a frame: set the view, record, submit, wait
    Spread cpuMs;   // host time to set the view and record the command buffer
    // CPU time of all the process's threads over the frame: on a CPU device
    // (lavapipe) its rasteriser and compute threads are the process's, so
    // this is the frame's work, which other programs on the machine slow
    // down far less than its wall time.
    Spread processCpuMs;
    std::array<std::optional<Spread>, kPassCount> gpuMs; // per kBenchPasses entry
    uint64_t shadowCacheRenders = 0;                     // measured frames that drew the shadow cache
};

// The GPU-driven frame from one camera time.
struct CameraTimeResult {
    double time = 0.0;     // scene time on the camera path
    PathTimes driven;      // FieldRenderer::record
    FieldFrameStats stats; // of its last measured frame
};

struct CountResult {
    uint64_t count = 0;                      // requested
    double time = 0.0;                       // the camera time of `driven`: --time, or the worst of --path
    PathTimes driven;                        // the GPU-driven frame (FieldRenderer::record) at `time`
    FieldFrameStats stats;                   // of the last measured GPU-driven frame at `time`
    std::vector<CameraTimeResult> alongPath; // with --path: every time in order (`time` the slowest); else empty
    uint64_t gpuMemoryBytes = 0;             // after the frames, from the sweep's memory source
    uint64_t rendererBytes = 0;              // FieldRenderer::gpuBytes()
    std::optional<PathTimes> naive;          // with --compare naive, unless skipped
    uint64_t naiveTriangles = 0;
    uint64_t jointsSimulated = 0; // FieldRenderer::simulatedJoints(): joints the physics pass steps
    std::string note;             // why naive was skipped, or empty
    double buildSeconds = 0.0;    // CPU build of the field (not part of any frame)
    float terrainSize = 0.0f;     // side of the terrain the plants stand on, metres (grows with the count)
    std::string placementNote;    // FieldContent::note: the count could not keep the densities
};

struct SweepResult {
    std::string scenePath;
    std::string device;
    std::string memorySource; // "VK_EXT_memory_budget" or "renderer accounting"
    std::vector<CountResult> counts;
};

// The camera times each count is measured at: --time, or the --path times
// spread over the scene's camera path (timesAlongPath).
std::vector<double> measuredTimes(const PlantbenchOptions& o, const Scene& scene);

// Index of the time whose median frame wall time is the largest (the first
// of equals): the worst frame along the path.
size_t slowestTime(const std::vector<CameraTimeResult>& times);

// Fills `result` count by count (so a failure keeps what was measured).
// `scene` is o.scenePath loaded, with --seed applied. Throws SceneError for a
// plant the scene cannot grow, runtime_error for a request the device cannot
// hold or a failed Vulkan call.
void runSweep(const PlantbenchOptions& o, const Scene& scene, GpuContext& ctx, SweepResult& result);

} // namespace pf
