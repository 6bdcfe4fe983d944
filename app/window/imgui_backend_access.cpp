// Compiles Dear ImGui's Vulkan backend (shipped by Debian as a source file only) in this
// translation unit, so that the accessors below can read its file-local backend data.
#include "imgui_impl_vulkan.cpp"  // NOLINT(bugprone-suspicious-include)

#include "app/window/imgui_backend_access.h"

namespace monoplane::window {

VkDescriptorSetLayout imgui_vulkan_set_layout() {
    return ImGui_ImplVulkan_GetBackendData()->DescriptorSetLayout;
}

VkPipelineLayout imgui_vulkan_pipeline_layout() {
    return ImGui_ImplVulkan_GetBackendData()->PipelineLayout;
}

}  // namespace monoplane::window
