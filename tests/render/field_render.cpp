#include "field_render.h"

namespace pf::test {

FieldSequence::FieldSequence(const GpuContext& ctx, const std::string& scene, VkExtent2D size,
                             const FieldRenderSettings& settings)
    : ctx_(ctx), scene_(loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/" + scene)), size_(size) {
    renderer_ = std::make_unique<FieldRenderer>(ctx, buildFieldContent(scene_), settings);
    target_ = createRenderTarget(ctx, size, renderer_->antialiasing());
}

FieldSequence::~FieldSequence() {
    destroyRenderTarget(target_);
    renderer_.reset();
}

FieldShotResult FieldSequence::frame(const FieldView& view) {
    renderer_->setView(view, size_);
    FieldShotResult result;
    result.image =
        captureFrame(ctx_, target_, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer_->record(cmd, t); });
    result.stats = renderer_->readStats();
    return result;
}

std::vector<int> shadowDarkening(const RgbaImage& lit, const RgbaImage& shadowed) {
    std::vector<int> d(lit.pixels.size() / 4);
    for (size_t i = 0; i < d.size(); ++i) d[i] = int(lit.pixels[i * 4 + 1]) - int(shadowed.pixels[i * 4 + 1]);
    return d;
}

FieldShotResult renderField(const GpuContext& ctx, const FieldShot& shot) {
    FieldRenderSettings settings;
    settings.shadows = shot.shadows;
    settings.antialiasing = shot.antialiasing;
    FieldSequence sequence(ctx, shot.scene, shot.size, settings);
    FieldView view;
    view.camera = shot.camera.value_or(cameraAt(sequence.scene().camera, shot.time));
    view.time = float(shot.time);
    view.forcedLod = shot.forcedLod;
    return sequence.frame(view);
}

} // namespace pf::test
