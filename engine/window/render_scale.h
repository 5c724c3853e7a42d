// Dynamic resolution for the window: the scene is rendered at a share of the
// window's size and blitted up to it, the share chosen from the frames' times
// so that a device that cannot fill every pixel in time (a CPU rasteriser)
// still shows a fluid flythrough. Pure state and arithmetic; the present loop
// (present_loop.h) resizes its render target when the scale changes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace pf {

struct RenderScaleSettings {
    bool dynamic = true;         // false: always `scale`
    float scale = 1.0f;          // the starting (or fixed) share of each side, minScale to 1
    double targetFrameMs = 66.7; // what the dynamic scale holds: 15 frames a second
    float minScale = 0.5f;       // a quarter of the pixels at most: below, the image turns to blocks
    float step = 0.125f;         // each change, in share of a side
    uint32_t settleFrames = 4;   // frames in a row that must ask for a change before it is made
};

struct RenderScaleState {
    float scale = 1.0f;
    uint32_t slowFrames = 0; // in a row slower than the target allows
    double leastSlowMs = 0;  // the fastest of those slow frames
    uint32_t fastFrames = 0; // in a row fast enough for one step up
};

// The dynamic scale for a device of this type: a CPU rasteriser (lavapipe)
// starts at minScale and rises while its frames allow, every other device at
// the whole window. A CPU device is far from the target at the whole window
// (a frame of the default forest at 1280×720 takes it ~4 times as long as at
// 640×360), so starting there shows seconds of slow frames before the share
// has come down; a GPU would show blocky first frames for nothing.
RenderScaleSettings dynamicRenderScaleFor(VkPhysicalDeviceType device);

RenderScaleState startRenderScale(const RenderScaleSettings& settings);

// Takes the last frame's time; returns true when the scale changed. A frame
// is slow above targetFrameMs · 1.1; after settleFrames of them the scale
// goes down by as many steps as the fastest of them asks for, taking its
// time as all pixels (scale · √(target / ms), at least one step): the
// window's first frames, at its whole size, reach the share it can hold in
// one change instead of one step per settleFrames. That underestimates the
// drop (not all of a frame shrinks with its pixels), so it never goes too
// far. A frame is fast when its time scaled by the pixels one step up would
// add, ((scale + step) / scale)², stays below targetFrameMs · 0.9 (an
// overestimate again), so the scale does not swing between two steps.
bool updateRenderScale(RenderScaleState& state, const RenderScaleSettings& settings, double frameMs);

// `window` scaled by `scale`, each side rounded and at least 1.
VkExtent2D scaledExtent(VkExtent2D window, float scale);

} // namespace pf
