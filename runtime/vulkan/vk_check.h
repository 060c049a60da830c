// Turning VkResult codes into the error messages of the backend's API.
//
// Every Vulkan call that can fail goes through check(), so each failure names the call that
// failed and the result it returned ("vkCreateGraphicsPipelines failed: VK_ERROR_...").
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace facet::runtime::vulkan {

// The enumerator's name, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY", or "VkResult(<n>)" if unknown.
std::string resultName(VkResult result);

// True for VK_SUCCESS. Otherwise sets *error to "<call> failed: <result name>" and returns false.
bool check(VkResult result, const char* call, std::string* error);

}  // namespace facet::runtime::vulkan
