// The real-time flythrough: camera-path playback or free flight (P toggles),
// with an on-screen overlay of frame time and what the cull pass drew; with
// --watch, the field rebuilt whenever its files change (live_reload.h).
#include "field_setup.h"
#include "live_reload.h"
#include "modes.h"

#include "engine/vk/gpu_timer.h"
#include "engine/window/present_loop.h"
#include "engine/window/text_overlay.h"
#include "engine/window/window.h"
#include "engine/window/window_input.h"

#include <algorithm>
#include <csignal>
#include <cstdio>

namespace pf {
namespace {

// Lines of a failed rebuild's message the overlay shows, and characters of
// each (all of it goes to stderr).
constexpr size_t kOverlayErrorLines = 6;
constexpr size_t kOverlayErrorColumns = 100;

std::string overlayText(double frameMs, const FieldFrameStats& stats, const std::vector<ScopeTime>& gpu,
                        bool freeFlight) {
    char text[512];
    int n = std::snprintf(text, sizeof(text), "%.1f fps  %.2f ms\nplants %u: %s\ntriangles %.2f M\n",
                          frameMs > 0 ? 1000.0 / frameMs : 0.0, frameMs, stats.instances,
                          plantsPerLodText(stats).c_str(), double(stats.triangles) / 1e6);
    for (const ScopeTime& s : gpu)
        if (n > 0 && size_t(n) < sizeof(text))
            n += std::snprintf(text + n, sizeof(text) - size_t(n), "%s %.2f ms  ", s.name.c_str(), s.milliseconds);
    std::string result(text);
    result += freeFlight ? "\nfree flight: WASD QE, mouse button to look, P: path" : "\ncamera path: P for free flight";
    return result;
}

// The failed rebuild's first lines, above the frame statistics.
std::string errorOverlayText(const std::string& error) {
    std::string text = "reload failed, drawing the last good build:\n";
    size_t start = 0;
    for (size_t line = 0; line < kOverlayErrorLines && start < error.size(); ++line) {
        const size_t end = std::min(error.find('\n', start), error.size());
        text += error.substr(start, std::min(end - start, kOverlayErrorColumns)) + "\n";
        start = end + 1;
    }
    return text + "\n";
}

// SIGINT and SIGTERM close the window as its close button does, so the
// --capture screenshot is still written (Ctrl+C in the terminal, a script
// ending a --watch session).
volatile std::sig_atomic_t closeRequested = 0;
extern "C" void requestWindowClose(int) { closeRequested = 1; }

} // namespace

int runWindow(const PlantfieldOptions& o) {
    FieldBuild first = buildField(o);
    if (first.failure)
        std::rethrow_exception(first.failure); // the first build's errors end the run, as without --watch
    std::optional<PreviewOrbit> orbit = first.orbit;
    FieldContent content = std::move(*first.content);
    Scene scene = content.scene;
    std::optional<FieldReloader> reloader;
    if (o.watch) {
        reloader = watchBuild(first);
        std::fprintf(stderr, "plantfield: watching %zu file%s of %s\n", first.files.size(),
                     first.files.size() == 1 ? "" : "s", inputName(o).c_str());
    }
    Window window(o.size.width, o.size.height, "plantfield");
    GpuOptions g = gpuOptions(o);
    g.instanceExtensions = Window::requiredInstanceExtensions();
    GpuContext ctx;
    createInstance(ctx, g);
    VkSurfaceKHR surface = window.createSurface(ctx.instance);
    createDevice(ctx, g, surface);
    closeRequested = 0;
    std::signal(SIGINT, requestWindowClose);
    std::signal(SIGTERM, requestWindowClose);
    PresentStats presented;
    {
        auto renderer = std::make_unique<FieldRenderer>(ctx, std::move(content), renderSettings(o));
        GpuResources overlayResources(ctx); // destroyed at the end of this block, after the loop's last wait
        TextOverlay overlay = createTextOverlay(overlayResources);
        GpuTimer timer = createGpuTimer(ctx, 16);
        WindowInputState inputState;
        bool freeFlight = false;
        FreeFlight flight;
        FieldFrameStats stats;
        std::string reloadError; // the last rebuild's, until a good one

        // A finished rebuild: its field into the renderer (the camera, free
        // flight and scene time go on), or its error onto the overlay.
        // Returns whether the renderer is new.
        auto applyRebuild = [&](FieldBuild& build) {
            if (build.content) {
                Scene next = build.content->scene;
                try {
                    replaceFieldContent(renderer, std::move(*build.content));
                    scene = std::move(next);
                    orbit = build.orbit;
                    reloadError.clear();
                    std::fprintf(stderr, "plantfield: reloaded %s\n", inputName(o).c_str());
                    return true;
                } catch (const std::exception& e) { // the GPU side: too many plants, out of device memory
                    build.error = e.what();
                }
            }
            reloadError = build.error.substr(0, build.error.find_last_not_of('\n') + 1);
            std::fprintf(stderr, "plantfield: error: %s\nplantfield: still drawing the last good build of %s\n",
                         reloadError.c_str(), inputName(o).c_str());
            return false;
        };

        PresentLoopOptions loop;
        loop.maxFrames = o.frames;
        loop.screenshotPath = o.capturePath;
        loop.antialiasing = renderer->antialiasing();
        loop.renderScale = o.renderScale ? RenderScaleSettings{.dynamic = false, .scale = *o.renderScale}
                                         : dynamicRenderScaleFor(ctx.properties.deviceType);
        loop.prepare = [&](double t, double dt, VkExtent2D extent, double frameMs) {
            if (closeRequested) window.requestClose();
            if (frameMs > 0) { // the previous frame has finished: its counters are ready
                stats = renderer->readStats();
                const std::string text = overlayText(frameMs, stats, readGpuTimer(ctx, timer), freeFlight);
                setOverlayText(overlay, reloadError.empty() ? text : errorOverlayText(reloadError) + text);
            }
            std::optional<FieldBuild> rebuilt;
            if (reloader) rebuilt = pollReload(*reloader, o, WatchClock::now());
            const bool fresh = rebuilt && applyRebuild(*rebuilt);
            const WindowInput input = pollWindowInput(window.handle(), inputState);
            FieldView view = pathView(o, scene, o.time + t, dt, frameMs == 0 || fresh, orbit);
            view.realTime = true;
            if (input.togglePathPlayback) {
                freeFlight = !freeFlight;
                if (freeFlight) flight = flightFromCamera(view.camera);
            }
            if (freeFlight) {
                updateFlight(flight, input.flight, float(dt));
                view.camera = cameraFromFlight(flight, view.camera);
            }
            renderer->setView(view, extent);
        };
        loop.record = [&](VkCommandBuffer cmd, const RenderTarget& target) {
            renderer->record(cmd, target, &timer);
            recordTextOverlay(cmd, overlay, target);
        };
        loop.titleSuffix = [&] { return " - " + std::to_string(stats.instances) + " plants"; };
        presented = runPresentLoop(ctx, window, surface, loop);
        destroyGpuTimer(ctx, timer);
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    std::fprintf(stderr, "plantfield: %u frames in %.2f s (%.1f fps) on %s, the last rendered at %ux%u\n",
                 presented.frames, presented.seconds,
                 presented.seconds > 0 ? presented.frames / presented.seconds : 0.0, ctx.properties.deviceName,
                 presented.renderExtent.width, presented.renderExtent.height);
    vkDestroySurfaceKHR(ctx.instance, surface, nullptr);
    destroyContext(ctx);
    return 0;
}

} // namespace pf
