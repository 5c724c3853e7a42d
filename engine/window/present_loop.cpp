#include "engine/window/present_loop.h"

#include "engine/vk/capture.h"
#include "engine/vk/vk_check.h"
#include "engine/window/swapchain.h"
#include "engine/window/window_blit.h"

#include <chrono>
#include <cstdio>

namespace pf {
namespace {

// The finished frame drawn over the swapchain image. The target comes and
// goes back in TRANSFER_SRC_OPTIMAL, where the renderer leaves it.
void recordWindowBlitToSwapchain(VkCommandBuffer cmd, const WindowBlit& blit, const RenderTarget& target,
                                 const Swapchain& swapchain, uint32_t imageIndex) {
    const VkImage swapImage = swapchain.images[imageIndex];
    // The frame's last writes (colour pass, FXAA, overlay) before the blit's
    // reads; the image it last presented is overwritten whole.
    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    imageBarrier(cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    recordWindowBlit(cmd, blit, swapchain.views[imageIndex], swapchain.extent);
    // Presentation needs no access mask: the semaphore signal makes the write available.
    imageBarrier(cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_IMAGE_LAYOUT_PRESENT_SRC_KHR});
    // Write-after-read: the next frame's colour pass or capture copy after the blit's reads.
    imageBarrier(cmd, target.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0,
                  VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
}

} // namespace

PresentStats runPresentLoop(const GpuContext& ctx, Window& window, VkSurfaceKHR surface,
                            const PresentLoopOptions& options) {
    Swapchain swapchain;
    swapchain = createSwapchain(ctx, surface, window.framebufferExtent(), swapchain);
    RenderScaleState scale = startRenderScale(options.renderScale);

    VkCommandBuffer cmd = allocateCommandBuffer(ctx);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore imageAcquired;
    VK_CHECK(vkCreateSemaphore(ctx.device, &semaphoreInfo, nullptr, &imageAcquired));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence frameDone;
    VK_CHECK(vkCreateFence(ctx.device, &fenceInfo, nullptr, &frameDone));

    // The target at `share` of the swapchain's size and its blit; call once
    // no frame uses the old one.
    RenderTarget target;
    WindowBlit blit;
    auto replaceTarget = [&](float share) {
        destroyRenderTarget(target);
        target = createRenderTarget(ctx, scaledExtent(swapchain.extent, share), options.antialiasing);
        blit = createWindowBlit(target.resources, target.color, swapchain.format);
    };
    replaceTarget(scale.scale);
    auto rebuild = [&] {
        vkDeviceWaitIdle(ctx.device);
        swapchain = createSwapchain(ctx, surface, window.framebufferExtent(), swapchain);
        replaceTarget(scale.scale);
    };

    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    Clock::time_point titleTime = start;
    uint32_t titleFrames = 0;
    PresentStats stats;
    double sceneTime = 0.0;
    double lastFrameMs = 0.0;
    Clock::time_point lastFrameStart = start;

    while (!window.shouldClose() && (options.maxFrames == 0 || stats.frames < options.maxFrames)) {
        window.pollEvents();
        const VkExtent2D size = window.framebufferExtent();
        if (size.width == 0 || size.height == 0) { // minimised: nothing to draw until restored
            window.waitEvents();
            continue;
        }

        // One frame in flight: the uniforms and command buffer are reused.
        VK_CHECK(vkWaitForFences(ctx.device, 1, &frameDone, VK_TRUE, UINT64_MAX));
        uint32_t imageIndex = 0;
        VkResult acquired = vkAcquireNextImageKHR(ctx.device, swapchain.swapchain, UINT64_MAX, imageAcquired,
                                                  VK_NULL_HANDLE, &imageIndex);
        if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
            rebuild();
            continue;
        }
        if (acquired != VK_SUBOPTIMAL_KHR) VK_CHECK(acquired);
        VK_CHECK(vkResetFences(ctx.device, 1, &frameDone));

        const double previousTime = sceneTime;
        sceneTime = options.fixedTimeStep > 0 ? stats.frames * options.fixedTimeStep
                                              : std::chrono::duration<double>(Clock::now() - start).count();
        const Clock::time_point frameStart = Clock::now();
        options.prepare(sceneTime, stats.frames == 0 ? 0.0 : sceneTime - previousTime, target.extent, lastFrameMs);

        VK_CHECK(vkResetCommandBuffer(cmd, 0));
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
        options.record(cmd, target);
        recordWindowBlitToSwapchain(cmd, blit, target, swapchain, imageIndex);
        VK_CHECK(vkEndCommandBuffer(cmd));

        VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
        wait.semaphore = imageAcquired;
        wait.stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT; // only the blit touches the swapchain image
        VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
        signal.semaphore = swapchain.renderFinished[imageIndex];
        signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        cmdInfo.commandBuffer = cmd;
        VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
        submit.waitSemaphoreInfoCount = 1;
        submit.pWaitSemaphoreInfos = &wait;
        submit.commandBufferInfoCount = 1;
        submit.pCommandBufferInfos = &cmdInfo;
        submit.signalSemaphoreInfoCount = 1;
        submit.pSignalSemaphoreInfos = &signal;
        VK_CHECK(vkQueueSubmit2(ctx.queue, 1, &submit, frameDone));

        VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
        present.waitSemaphoreCount = 1;
        present.pWaitSemaphores = &swapchain.renderFinished[imageIndex];
        present.swapchainCount = 1;
        present.pSwapchains = &swapchain.swapchain;
        present.pImageIndices = &imageIndex;
        VkResult presented = vkQueuePresentKHR(ctx.queue, &present);
        ++stats.frames;
        ++titleFrames;
        const Clock::time_point now = Clock::now();
        lastFrameMs = 1000.0 * std::chrono::duration<double>(frameStart - lastFrameStart).count();
        lastFrameStart = frameStart;
        if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
            size.width != swapchain.extent.width || size.height != swapchain.extent.height)
            rebuild();
        else
            VK_CHECK(presented);
        // The first frame's time is only its own start: no frame before it.
        if (stats.frames > 1 && updateRenderScale(scale, options.renderScale, lastFrameMs)) {
            vkDeviceWaitIdle(ctx.device);
            replaceTarget(scale.scale);
        }

        const double sinceTitle = std::chrono::duration<double>(now - titleTime).count();
        if (sinceTitle >= 0.5) {
            char title[128];
            std::snprintf(title, sizeof(title), "plantfield - %.2f ms (%.1f fps), rendered at %ux%u",
                          1000.0 * sinceTitle / titleFrames, titleFrames / sinceTitle, target.extent.width,
                          target.extent.height);
            window.setTitle(std::string(title) + (options.titleSuffix ? options.titleSuffix() : std::string()));
            titleTime = now;
            titleFrames = 0;
        }
    }
    VK_CHECK(vkDeviceWaitIdle(ctx.device));
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats.renderExtent = target.extent;

    // The screenshot at the window's size, whatever the last render scale.
    if (!options.screenshotPath.empty() && stats.frames > 0) {
        if (scale.scale != 1.0f) replaceTarget(1.0f); // the device is idle since the loop's end
        writePng(options.screenshotPath, captureFrame(ctx, target, options.record));
    }

    vkDestroyFence(ctx.device, frameDone, nullptr);
    vkDestroySemaphore(ctx.device, imageAcquired, nullptr);
    vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
    destroyRenderTarget(target);
    destroySwapchain(ctx, swapchain);
    return stats;
}

} // namespace pf
