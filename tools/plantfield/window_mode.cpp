// The real-time flythrough: camera-path playback or free flight (P toggles),
// with an on-screen overlay of frame time and what the cull pass drew.
#include "field_setup.h"
#include "modes.h"

#include "engine/vk/gpu_timer.h"
#include "engine/window/present_loop.h"
#include "engine/window/text_overlay.h"
#include "engine/window/window.h"
#include "engine/window/window_input.h"

#include <cstdio>

namespace pf {
namespace {

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

} // namespace

int runWindow(const PlantfieldOptions& o) {
    std::optional<PreviewOrbit> orbit;
    FieldContent content = loadFieldContent(o, &orbit);
    const Scene scene = content.scene;
    Window window(o.size.width, o.size.height, "plantfield");
    GpuOptions g = gpuOptions(o);
    g.instanceExtensions = Window::requiredInstanceExtensions();
    GpuContext ctx;
    createInstance(ctx, g);
    VkSurfaceKHR surface = window.createSurface(ctx.instance);
    createDevice(ctx, g, surface);
    PresentStats presented;
    {
        FieldRenderer renderer(ctx, std::move(content), renderSettings(o));
        GpuResources overlayResources(ctx); // destroyed at the end of this block, after the loop's last wait
        TextOverlay overlay = createTextOverlay(overlayResources);
        GpuTimer timer = createGpuTimer(ctx, 16);
        WindowInputState inputState;
        bool freeFlight = false;
        FreeFlight flight;
        FieldFrameStats stats;

        PresentLoopOptions loop;
        loop.maxFrames = o.frames;
        loop.screenshotPath = o.capturePath;
        loop.antialiasing = renderer.antialiasing();
        loop.renderScale = o.renderScale ? RenderScaleSettings{.dynamic = false, .scale = *o.renderScale}
                                         : dynamicRenderScaleFor(ctx.properties.deviceType);
        loop.prepare = [&](double t, double dt, VkExtent2D extent, double frameMs) {
            if (frameMs > 0) { // the previous frame has finished: its counters are ready
                stats = renderer.readStats();
                setOverlayText(overlay, overlayText(frameMs, stats, readGpuTimer(ctx, timer), freeFlight));
            }
            const WindowInput input = pollWindowInput(window.handle(), inputState);
            FieldView view = pathView(o, scene, o.time + t, dt, frameMs == 0, orbit);
            view.realTime = true;
            if (input.togglePathPlayback) {
                freeFlight = !freeFlight;
                if (freeFlight) flight = flightFromCamera(view.camera);
            }
            if (freeFlight) {
                updateFlight(flight, input.flight, float(dt));
                view.camera = cameraFromFlight(flight, view.camera);
            }
            renderer.setView(view, extent);
        };
        loop.record = [&](VkCommandBuffer cmd, const RenderTarget& target) {
            renderer.record(cmd, target, &timer);
            recordTextOverlay(cmd, overlay, target);
        };
        loop.titleSuffix = [&] { return " - " + std::to_string(stats.instances) + " plants"; };
        presented = runPresentLoop(ctx, window, surface, loop);
        destroyGpuTimer(ctx, timer);
    }
    std::fprintf(stderr, "plantfield: %u frames in %.2f s (%.1f fps) on %s, the last rendered at %ux%u\n",
                 presented.frames, presented.seconds,
                 presented.seconds > 0 ? presented.frames / presented.seconds : 0.0, ctx.properties.deviceName,
                 presented.renderExtent.width, presented.renderExtent.height);
    vkDestroySurfaceKHR(ctx.instance, surface, nullptr);
    destroyContext(ctx);
    return 0;
}

} // namespace pf
