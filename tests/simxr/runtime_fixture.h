// Drives simxr through the real OpenXR loader (XR_RUNTIME_JSON names the built manifest) the way
// an application does: instance, system, Vulkan instance and device through
// XR_KHR_vulkan_enable2 with the Khronos validation layer on, then a session. The OpenXR core
// validation layer (XR_APILAYER_LUNARG_core_validation) watches every OpenXR call too. Any
// message of either layer fails the test.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

// openxr_platform.h needs Vulkan's types declared first.
#include <vulkan/vulkan.h>

#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

namespace monoplane::simxr::testing {

template <class T>
T xr_struct(XrStructureType type) {
    T structure{};
    structure.type = type;
    return structure;
}

template <class T>
T vk_struct(VkStructureType type) {
    T structure{};
    structure.sType = type;
    return structure;
}

struct FixtureOptions {
    bool query_requirements = true;
    bool create_session = true;
    // Off only in tests of simxr's own answers to invalid usage: the OpenXR validation layer
    // would stop those calls before the runtime sees them.
    bool xr_validation = true;
    bool eye_gaze = false;  // enable XR_EXT_eye_gaze_interaction
};

// The OpenXR validation layer's messages since the last start() (or clear).
std::vector<std::string>& xr_validation_messages();

class SimxrTest : public ::testing::Test {
  protected:
    // Writes the script, points the loader at simxr and creates everything up to the session.
    void start(const std::string& script_text, FixtureOptions options = {});
    void TearDown() override;

    // Session states delivered by xrPollEvent until the queue is empty (other events counted).
    std::vector<XrSessionState> poll_states();
    // Polls IDLE/READY, begins the session and runs frames until FOCUSED is delivered.
    void begin_and_focus();
    // One frame with no layers; returns its frame state.
    XrFrameState empty_frame();

    XrSessionBeginInfo begin_info() const;
    XrSessionCreateInfo session_info(const XrGraphicsBindingVulkan2KHR* binding) const;
    XrGraphicsBindingVulkan2KHR binding() const;
    XrPath path(const char* text) const;

    // Records commands on a fresh command buffer of the binding's queue, submits and waits.
    void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);
    // Clears the swapchain image to a colour, leaving it in COLOR_ATTACHMENT_OPTIMAL.
    void clear_image(VkImage image, VkClearColorValue colour);

    std::filesystem::path dir_;
    XrInstance instance_ = XR_NULL_HANDLE;
    XrSystemId system_ = XR_NULL_SYSTEM_ID;
    XrSession session_ = XR_NULL_HANDLE;
    VkInstance vk_instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    VkQueue queue_ = VK_NULL_HANDLE;
    int other_events_ = 0;  // events that were not session state changes
    XrDebugUtilsMessengerEXT xr_messenger_ = XR_NULL_HANDLE;

    PFN_xrGetVulkanGraphicsRequirements2KHR xrGetVulkanGraphicsRequirements2KHR = nullptr;
    PFN_xrCreateVulkanInstanceKHR xrCreateVulkanInstanceKHR = nullptr;
    PFN_xrGetVulkanGraphicsDevice2KHR xrGetVulkanGraphicsDevice2KHR = nullptr;
    PFN_xrCreateVulkanDeviceKHR xrCreateVulkanDeviceKHR = nullptr;
};

// Creates an instance through the loader with the given script; for tests of xrCreateInstance.
// With `xr_validation`, the OpenXR validation layer and XR_EXT_debug_utils are enabled too and
// `messenger` receives a messenger recording into xr_validation_messages().
XrResult create_instance_with_script(const std::filesystem::path& dir, const std::string& script,
                                     const std::vector<const char*>& extensions,
                                     XrInstance* instance, bool xr_validation = false,
                                     XrDebugUtilsMessengerEXT* messenger = nullptr);

}  // namespace monoplane::simxr::testing
