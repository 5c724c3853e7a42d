// plantfield: the renderer's command-line front end.
#include "engine/default_scene.h"
#include "options.h"

#include "engine/capture.h"
#include "engine/device.h"
#include "engine/present_loop.h"
#include "engine/window.h"

#include <cstdio>
#include <exception>
#include <iostream>

namespace pf {
namespace {

GpuOptions gpuOptions(const PlantfieldOptions& o) {
    GpuOptions g;
    g.validation = o.validation;
    g.deviceName = o.deviceName;
    return g;
}

int listDevices(const PlantfieldOptions& o) {
    GpuContext ctx;
    createInstance(ctx, gpuOptions(o));
    for (const PhysicalDeviceInfo& d : listPhysicalDevices(ctx.instance))
        std::printf("%s (%s, Vulkan %u.%u)\n", d.name.c_str(), d.type.c_str(), VK_API_VERSION_MAJOR(d.apiVersion),
                    VK_API_VERSION_MINOR(d.apiVersion));
    destroyContext(ctx);
    return 0;
}

int captureHeadless(const PlantfieldOptions& o, const DefaultScene& scene) {
    GpuContext ctx;
    createHeadlessContext(ctx, gpuOptions(o));
    const VkExtent2D extent{o.size.width, o.size.height};
    {
        SceneRenderer renderer(ctx, scene.geometry, VkSampleCountFlagBits(o.samples));
        RenderTarget target = createRenderTarget(ctx, extent, renderer.samples());
        renderer.setFrameUniforms(makeFrameUniforms(defaultCameraAt(scene, o.time), scene.environment, extent, float(o.time)));
        const RgbaImage image = captureFrame(ctx, renderer, target);
        destroyRenderTarget(ctx, target);
        writePng(o.capturePath, image);
    }
    std::fprintf(stderr, "plantfield: %s on %s: %ux%u, %zu segments -> %s\n", "captured", ctx.properties.deviceName,
                 o.size.width, o.size.height, scene.geometry.segments.size(), o.capturePath.c_str());
    destroyContext(ctx);
    return 0;
}

int runWindow(const PlantfieldOptions& o, const DefaultScene& scene) {
    Window window(o.size.width, o.size.height, "plantfield");
    GpuOptions g = gpuOptions(o);
    g.instanceExtensions = Window::requiredInstanceExtensions();
    GpuContext ctx;
    createInstance(ctx, g);
    VkSurfaceKHR surface = window.createSurface(ctx.instance);
    createDevice(ctx, g, surface);
    PresentStats stats;
    {
        SceneRenderer renderer(ctx, scene.geometry, VkSampleCountFlagBits(o.samples));
        PresentLoopOptions loop;
        loop.maxFrames = o.frames;
        loop.screenshotPath = o.capturePath;
        loop.frameUniforms = [&](double t, VkExtent2D extent) {
            return makeFrameUniforms(defaultCameraAt(scene, o.time + t), scene.environment, extent, float(o.time + t));
        };
        stats = runPresentLoop(ctx, window, surface, renderer, loop);
    }
    std::fprintf(stderr, "plantfield: %u frames in %.2f s (%.1f fps) on %s\n", stats.frames, stats.seconds,
                 stats.seconds > 0 ? stats.frames / stats.seconds : 0.0, ctx.properties.deviceName);
    vkDestroySurfaceKHR(ctx.instance, surface, nullptr);
    destroyContext(ctx);
    return 0;
}

} // namespace
} // namespace pf

int main(int argc, char** argv) {
    int exitCode = 0;
    const std::optional<pf::PlantfieldOptions> options = pf::parsePlantfieldOptions(argc, argv, &exitCode);
    if (!options) return exitCode;
    try {
        if (options->listDevices) return pf::listDevices(*options);
        const pf::DefaultScene scene = pf::buildDefaultScene();
        return options->window ? pf::runWindow(*options, scene) : pf::captureHeadless(*options, scene);
    } catch (const std::exception& e) {
        std::cerr << "plantfield: error: " << e.what() << "\n";
        return 1;
    }
}
