#include "engine/vk/vk_check.h"

#include <stdexcept>
#include <string>

namespace pf {

const char* vkResultName(VkResult result) {
    switch (result) {
#define PF_RESULT_CASE(name)                                                                                           \
    case name: return #name;
        PF_RESULT_CASE(VK_SUCCESS)
        PF_RESULT_CASE(VK_NOT_READY)
        PF_RESULT_CASE(VK_TIMEOUT)
        PF_RESULT_CASE(VK_INCOMPLETE)
        PF_RESULT_CASE(VK_SUBOPTIMAL_KHR)
        PF_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        PF_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        PF_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        PF_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        PF_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        PF_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        PF_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        PF_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        PF_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        PF_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        PF_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        PF_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
        PF_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        PF_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef PF_RESULT_CASE
    default: return "VkResult(unknown)";
    }
}

void throwVkError(VkResult result, const char* call, const char* file, int line) {
    throw std::runtime_error(std::string("Vulkan call failed with ") + vkResultName(result) + ": " + call + " (" +
                             file + ":" + std::to_string(line) + ")");
}

} // namespace pf
