#include "engine/window/render_scale.h"

#include <algorithm>
#include <cmath>

namespace pf {

RenderScaleSettings dynamicRenderScaleFor(VkPhysicalDeviceType device) {
    RenderScaleSettings settings;
    if (device == VK_PHYSICAL_DEVICE_TYPE_CPU) settings.scale = settings.minScale;
    return settings;
}

RenderScaleState startRenderScale(const RenderScaleSettings& settings) {
    RenderScaleState state;
    state.scale = std::clamp(settings.scale, settings.minScale, 1.0f);
    return state;
}

bool updateRenderScale(RenderScaleState& state, const RenderScaleSettings& settings, double frameMs) {
    if (!settings.dynamic || !(frameMs > 0.0)) return false;
    const float up = std::min(state.scale + settings.step, 1.0f);
    const double growth = double(up / state.scale) * double(up / state.scale);
    const bool slow = frameMs > settings.targetFrameMs * 1.1 && state.scale > settings.minScale;
    const bool fast = up > state.scale && frameMs * growth < settings.targetFrameMs * 0.9;
    state.leastSlowMs = !slow ? 0.0 : state.slowFrames == 0 ? frameMs : std::min(state.leastSlowMs, frameMs);
    state.slowFrames = slow ? state.slowFrames + 1 : 0;
    state.fastFrames = fast ? state.fastFrames + 1 : 0;
    if (state.slowFrames >= settings.settleFrames) {
        const double wanted = double(state.scale) * std::sqrt(settings.targetFrameMs / state.leastSlowMs);
        const double steps = std::max(1.0, std::ceil((double(state.scale) - wanted) / double(settings.step) - 1e-6));
        state.scale = std::max(state.scale - float(steps) * settings.step, settings.minScale);
    } else if (state.fastFrames >= settings.settleFrames) {
        state.scale = up;
    } else {
        return false;
    }
    state.slowFrames = state.fastFrames = 0;
    state.leastSlowMs = 0.0;
    return true;
}

VkExtent2D scaledExtent(VkExtent2D window, float scale) {
    auto side = [scale](uint32_t pixels) {
        return std::max(uint32_t(std::lround(double(pixels) * double(scale))), 1u);
    };
    return {side(window.width), side(window.height)};
}

} // namespace pf
