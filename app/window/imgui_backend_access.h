// Two handles of Dear ImGui's Vulkan backend (1.86) that it does not export. That backend binds
// only its font texture (no user textures before 1.87's ImGui_ImplVulkan_AddTexture), and its set
// layout carries the font sampler as an immutable sampler, so a set of any other layout would not
// be "identically defined". The mirror texture therefore uses the backend's own layout, bound
// with the backend's own pipeline layout from a draw-list callback.
#pragma once

#include <vulkan/vulkan.h>

namespace monoplane::window {

// May be called between ImGui_ImplVulkan_Init() and ImGui_ImplVulkan_Shutdown().
VkDescriptorSetLayout imgui_vulkan_set_layout();
VkPipelineLayout imgui_vulkan_pipeline_layout();

}  // namespace monoplane::window
