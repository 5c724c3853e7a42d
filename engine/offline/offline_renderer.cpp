#include "offline_renderer.h"

#include "engine/vk/capture.h"
#include "engine/vk/resources.h"

#include <chrono>
#include <stdexcept>
#include <string>

namespace pf {

FieldView frameView(const Camera& camera, double t, double dt, bool firstFrame, std::optional<uint32_t> forcedLod) {
    FieldView view;
    view.camera = camera;
    view.time = float(t);
    view.deltaTime = float(dt);
    view.firstFrame = firstFrame;
    view.forcedLod = forcedLod;
    return view;
}

OfflineRenderer::OfflineRenderer(FieldContent content, OfflineSettings settings) : settings_(std::move(settings)) {
    if (!settings_.camera) {
        const CameraPath path = content.scene.camera;
        settings_.camera = [path](double t) { return cameraAt(path, t); };
    }
    createHeadlessContext(ctx_, settings_.gpu);
    renderer_ = std::make_unique<FieldRenderer>(ctx_, std::move(content), settings_.render);
    target_ = createRenderTarget(ctx_, settings_.size, renderer_->antialiasing());
    timer_ = createGpuTimer(ctx_, 16);
}

OfflineRenderer::~OfflineRenderer() {
    destroyGpuTimer(ctx_, timer_);
    destroyRenderTarget(target_);
}

void OfflineRenderer::checkFrame(uint32_t index) {
    if (mode_ == Mode::times)
        throw std::invalid_argument("frame " + std::to_string(index) +
                                    " of the sequence: this renderer has drawn frames at given times instead");
    if (mode_ == Mode::frames && index < framesDrawn_)
        throw std::invalid_argument("frame " + std::to_string(index) + " of the sequence: frames go forward and " +
                                    std::to_string(framesDrawn_ - 1) + " was drawn (a new renderer starts again)");
    mode_ = Mode::frames;
}

// Frames before `index` not drawn yet are drawn here, so that frame index
// is the one a whole run draws.
FieldView OfflineRenderer::nextFrameView(uint32_t index) {
    for (uint32_t i = framesDrawn_; i < index; ++i) drawFrame(i);
    const double step = 1.0 / settings_.fps;
    const double time = settings_.start + index * step;
    ++framesDrawn_;
    lastTime_ = time;
    return frameView(settings_.camera(time), time, index == 0 ? 0.0 : step, index == 0, settings_.forcedLod);
}

void OfflineRenderer::drawFrame(uint32_t index) {
    checkFrame(index);
    renderer_->setView(nextFrameView(index), settings_.size);
    submitAndWait(ctx_, [&](VkCommandBuffer cmd) { renderer_->record(cmd, target_, &timer_); });
}

RgbaImage OfflineRenderer::frame(uint32_t index) {
    checkFrame(index);
    return capture(nextFrameView(index));
}

RgbaImage OfflineRenderer::render(double t, const std::optional<Camera>& camera) {
    if (mode_ == Mode::frames)
        throw std::invalid_argument("a frame at a given time: this renderer draws a sequence of numbered frames");
    const bool first = mode_ == Mode::unused;
    if (!first && t < lastTime_)
        throw std::invalid_argument("time " + std::to_string(t) + " is before the last frame's " +
                                    std::to_string(lastTime_) + ": frames go forward (a new renderer starts again)");
    mode_ = Mode::times;
    const double dt = first ? 0.0 : t - lastTime_;
    lastTime_ = t;
    return capture(frameView(camera ? *camera : settings_.camera(t), t, dt, first, settings_.forcedLod));
}

RgbaImage OfflineRenderer::capture(const FieldView& view) {
    renderer_->setView(view, settings_.size);
    const auto start = std::chrono::steady_clock::now();
    RgbaImage image = captureFrame(
        ctx_, target_, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer_->record(cmd, t, &timer_); });
    lastWallMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return image;
}

FieldFrameStats OfflineRenderer::stats() const {
    return mode_ == Mode::unused ? FieldFrameStats{} : renderer_->readStats();
}

std::vector<ScopeTime> OfflineRenderer::gpuTimes() const { return readGpuTimer(ctx_, timer_); }

} // namespace pf
