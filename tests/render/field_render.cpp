#include "field_render.h"

namespace pf::test {

FieldShotResult renderField(const GpuContext& ctx, const FieldShot& shot) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/" + shot.scene);
    FieldRenderSettings settings;
    settings.shadows = shot.shadows;
    settings.antialiasing = shot.antialiasing;
    FieldShotResult result;
    {
        FieldRenderer renderer(ctx, buildFieldContent(scene), settings);
        RenderTarget target = createRenderTarget(ctx, shot.size, renderer.antialiasing());
        FieldView view;
        view.camera = shot.camera.value_or(cameraAt(scene.camera, shot.time));
        view.time = float(shot.time);
        view.forcedLod = shot.forcedLod;
        renderer.setView(view, shot.size);
        result.image =
            captureFrame(ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer.record(cmd, t); });
        result.stats = renderer.readStats();
        destroyRenderTarget(target);
    }
    return result;
}

} // namespace pf::test
