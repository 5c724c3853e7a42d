// Turns a failed Vulkan call into an exception that names the call and the
// result, so tools can print it and exit instead of crashing.
#pragma once

#include <vulkan/vulkan.h>

namespace pf {

const char* vkResultName(VkResult result);
[[noreturn]] void throwVkError(VkResult result, const char* call, const char* file, int line);

} // namespace pf

#define VK_CHECK(call)                                                                                                 \
    do {                                                                                                               \
        VkResult vkCheckResult_ = (call);                                                                              \
        if (vkCheckResult_ != VK_SUCCESS) ::pf::throwVkError(vkCheckResult_, #call, __FILE__, __LINE__);               \
    } while (0)
