#include "tests/simxr/runtime_fixture.h"

#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>

#include <unistd.h>

namespace monoplane::simxr::testing {
namespace {

std::vector<std::string>& validation_messages() {
    static std::vector<std::string> messages;
    return messages;
}

VKAPI_ATTR VkBool32 VKAPI_CALL count_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void*) {
    validation_messages().push_back(data->pMessage != nullptr ? data->pMessage : "");
    return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT messenger_info() {
    auto info = vk_struct<VkDebugUtilsMessengerCreateInfoEXT>(
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &count_message;
    return info;
}

XRAPI_ATTR XrBool32 XRAPI_CALL record_xr_message(XrDebugUtilsMessageSeverityFlagsEXT,
                                                 XrDebugUtilsMessageTypeFlagsEXT,
                                                 const XrDebugUtilsMessengerCallbackDataEXT* data,
                                                 void*) {
    std::string text = data->messageId != nullptr ? data->messageId : "";
    if (data->message != nullptr) text += std::string(": ") + data->message;
    xr_validation_messages().push_back(text);
    return XR_FALSE;
}

template <class Pfn>
void load(XrInstance instance, const char* name, Pfn& function) {
    ASSERT_EQ(
        xrGetInstanceProcAddr(instance, name, reinterpret_cast<PFN_xrVoidFunction*>(&function)),
        XR_SUCCESS)
        << name;
}

}  // namespace

std::vector<std::string>& xr_validation_messages() {
    static std::vector<std::string> messages;
    return messages;
}

XrResult create_instance_with_script(const std::filesystem::path& dir, const std::string& script,
                                     const std::vector<const char*>& extensions,
                                     XrInstance* instance, bool xr_validation,
                                     XrDebugUtilsMessengerEXT* messenger) {
    std::filesystem::create_directories(dir);
    const std::filesystem::path script_path = dir / "script.toml";
    std::ofstream(script_path) << script;
    // The loader reads these when the instance is created.
    setenv("XR_RUNTIME_JSON", SIMXR_MANIFEST, 1);
    setenv("SIMXR_SCRIPT", script_path.c_str(), 1);
    auto info = xr_struct<XrInstanceCreateInfo>(XR_TYPE_INSTANCE_CREATE_INFO);
    std::snprintf(info.applicationInfo.applicationName, XR_MAX_APPLICATION_NAME_SIZE,
                  "simxr_runtime_test");
    info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
    std::vector<const char*> enabled = extensions;
    const char* layers[] = {"XR_APILAYER_LUNARG_core_validation"};
    if (xr_validation) {
        enabled.push_back(XR_EXT_DEBUG_UTILS_EXTENSION_NAME);
        info.enabledApiLayerCount = 1;
        info.enabledApiLayerNames = layers;
    }
    info.enabledExtensionCount = static_cast<uint32_t>(enabled.size());
    info.enabledExtensionNames = enabled.data();
    const XrResult created = xrCreateInstance(&info, instance);
    if (!xr_validation || XR_FAILED(created) || messenger == nullptr) return created;
    PFN_xrCreateDebugUtilsMessengerEXT create = nullptr;
    xrGetInstanceProcAddr(*instance, "xrCreateDebugUtilsMessengerEXT",
                          reinterpret_cast<PFN_xrVoidFunction*>(&create));
    if (create == nullptr) return XR_ERROR_FUNCTION_UNSUPPORTED;
    auto messenger_info = xr_struct<XrDebugUtilsMessengerCreateInfoEXT>(
        XR_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    messenger_info.messageSeverities = XR_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                       XR_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageTypes = XR_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                  XR_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                  XR_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT |
                                  XR_DEBUG_UTILS_MESSAGE_TYPE_CONFORMANCE_BIT_EXT;
    messenger_info.userCallback = &record_xr_message;
    const XrResult made = create(*instance, &messenger_info, messenger);
    if (XR_FAILED(made)) return made;
    // The layer of OpenXR SDK 1.0.20 calls messengers only once an object has a debug name
    // (app/headset/xr_validation.cpp says more).
    PFN_xrSetDebugUtilsObjectNameEXT set_name = nullptr;
    xrGetInstanceProcAddr(*instance, "xrSetDebugUtilsObjectNameEXT",
                          reinterpret_cast<PFN_xrVoidFunction*>(&set_name));
    if (set_name == nullptr) return XR_ERROR_FUNCTION_UNSUPPORTED;
    auto name = xr_struct<XrDebugUtilsObjectNameInfoEXT>(XR_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
    name.objectType = XR_OBJECT_TYPE_INSTANCE;
    name.objectHandle = reinterpret_cast<uint64_t>(*instance);
    name.objectName = "simxr_runtime_test";
    return set_name(*instance, &name);
}

void SimxrTest::start(const std::string& script_text, FixtureOptions options) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("simxr_" + std::string(test->name()) + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    validation_messages().clear();
    xr_validation_messages().clear();
    std::vector<const char*> xr_extensions = {XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME};
    if (options.eye_gaze) xr_extensions.push_back(XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
    ASSERT_EQ(create_instance_with_script(dir_, script_text, xr_extensions, &instance_,
                                          options.xr_validation, &xr_messenger_),
              XR_SUCCESS);
    load(instance_, "xrGetVulkanGraphicsRequirements2KHR", xrGetVulkanGraphicsRequirements2KHR);
    load(instance_, "xrCreateVulkanInstanceKHR", xrCreateVulkanInstanceKHR);
    load(instance_, "xrGetVulkanGraphicsDevice2KHR", xrGetVulkanGraphicsDevice2KHR);
    load(instance_, "xrCreateVulkanDeviceKHR", xrCreateVulkanDeviceKHR);

    auto system_info = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    ASSERT_EQ(xrGetSystem(instance_, &system_info, &system_), XR_SUCCESS);
    if (options.query_requirements) {
        auto requirements =
            xr_struct<XrGraphicsRequirementsVulkan2KHR>(XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR);
        ASSERT_EQ(xrGetVulkanGraphicsRequirements2KHR(instance_, system_, &requirements),
                  XR_SUCCESS);
        EXPECT_EQ(requirements.minApiVersionSupported, XR_MAKE_VERSION(1, 0, 0));
    }

    // The Vulkan instance, created by the runtime, with validation and a message counter.
    const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    const VkDebugUtilsMessengerCreateInfoEXT messenger = messenger_info();
    auto app = vk_struct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.apiVersion = VK_API_VERSION_1_1;
    auto vk_info = vk_struct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    vk_info.pNext = &messenger;
    vk_info.pApplicationInfo = &app;
    vk_info.enabledLayerCount = 1;
    vk_info.ppEnabledLayerNames = layers;
    vk_info.enabledExtensionCount = 1;
    vk_info.ppEnabledExtensionNames = extensions;
    auto xr_vk_info =
        xr_struct<XrVulkanInstanceCreateInfoKHR>(XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR);
    xr_vk_info.systemId = system_;
    xr_vk_info.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
    xr_vk_info.vulkanCreateInfo = &vk_info;
    VkResult vk_result = VK_ERROR_UNKNOWN;
    ASSERT_EQ(xrCreateVulkanInstanceKHR(instance_, &xr_vk_info, &vk_instance_, &vk_result),
              XR_SUCCESS);
    ASSERT_EQ(vk_result, VK_SUCCESS);
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(vk_instance_, "vkCreateDebugUtilsMessengerEXT"));
    ASSERT_NE(create_messenger, nullptr);
    ASSERT_EQ(create_messenger(vk_instance_, &messenger, nullptr, &messenger_), VK_SUCCESS);

    auto device_get =
        xr_struct<XrVulkanGraphicsDeviceGetInfoKHR>(XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR);
    device_get.systemId = system_;
    device_get.vulkanInstance = vk_instance_;
    ASSERT_EQ(xrGetVulkanGraphicsDevice2KHR(instance_, &device_get, &physical_device_), XR_SUCCESS);

    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, families.data());
    while (queue_family_ < family_count &&
           (families[queue_family_].queueFlags & VK_QUEUE_GRAPHICS_BIT) == 0) {
        ++queue_family_;
    }
    ASSERT_LT(queue_family_, family_count);
    const float priority = 1.0f;
    auto queue_info =
        vk_struct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue_info.queueFamilyIndex = queue_family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    auto device_info = vk_struct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    auto xr_device_info =
        xr_struct<XrVulkanDeviceCreateInfoKHR>(XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR);
    xr_device_info.systemId = system_;
    xr_device_info.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
    xr_device_info.vulkanPhysicalDevice = physical_device_;
    xr_device_info.vulkanCreateInfo = &device_info;
    ASSERT_EQ(xrCreateVulkanDeviceKHR(instance_, &xr_device_info, &device_, &vk_result),
              XR_SUCCESS);
    ASSERT_EQ(vk_result, VK_SUCCESS);
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

    if (options.create_session) {
        const XrGraphicsBindingVulkan2KHR vulkan = binding();
        const XrSessionCreateInfo info = session_info(&vulkan);
        ASSERT_EQ(xrCreateSession(instance_, &info, &session_), XR_SUCCESS);
    }
}

void SimxrTest::TearDown() {
    if (session_ != XR_NULL_HANDLE) {
        EXPECT_EQ(xrDestroySession(session_), XR_SUCCESS);
    }
    if (xr_messenger_ != XR_NULL_HANDLE) {
        PFN_xrDestroyDebugUtilsMessengerEXT destroy = nullptr;
        xrGetInstanceProcAddr(instance_, "xrDestroyDebugUtilsMessengerEXT",
                              reinterpret_cast<PFN_xrVoidFunction*>(&destroy));
        ASSERT_NE(destroy, nullptr);
        EXPECT_EQ(destroy(xr_messenger_), XR_SUCCESS);
    }
    if (instance_ != XR_NULL_HANDLE) {
        EXPECT_EQ(xrDestroyInstance(instance_), XR_SUCCESS);
    }
    if (device_ != VK_NULL_HANDLE) {
        vkDeviceWaitIdle(device_);
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_ != VK_NULL_HANDLE) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(vk_instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(vk_instance_, messenger_, nullptr);
    }
    if (vk_instance_ != VK_NULL_HANDLE) vkDestroyInstance(vk_instance_, nullptr);
    std::string text;
    for (const std::string& message : validation_messages()) text += message + "\n";
    EXPECT_EQ(validation_messages().size(), 0u) << text;
    std::string xr_text;
    for (const std::string& message : xr_validation_messages()) xr_text += message + "\n";
    EXPECT_EQ(xr_validation_messages().size(), 0u) << "OpenXR validation:\n" << xr_text;
    std::filesystem::remove_all(dir_);
}

XrGraphicsBindingVulkan2KHR SimxrTest::binding() const {
    auto vulkan = xr_struct<XrGraphicsBindingVulkan2KHR>(XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR);
    vulkan.instance = vk_instance_;
    vulkan.physicalDevice = physical_device_;
    vulkan.device = device_;
    vulkan.queueFamilyIndex = queue_family_;
    vulkan.queueIndex = 0;
    return vulkan;
}

XrSessionCreateInfo SimxrTest::session_info(const XrGraphicsBindingVulkan2KHR* vulkan) const {
    auto info = xr_struct<XrSessionCreateInfo>(XR_TYPE_SESSION_CREATE_INFO);
    info.next = vulkan;
    info.systemId = system_;
    return info;
}

XrSessionBeginInfo SimxrTest::begin_info() const {
    auto info = xr_struct<XrSessionBeginInfo>(XR_TYPE_SESSION_BEGIN_INFO);
    info.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    return info;
}

XrPath SimxrTest::path(const char* text) const {
    XrPath atom = XR_NULL_PATH;
    EXPECT_EQ(xrStringToPath(instance_, text, &atom), XR_SUCCESS) << text;
    return atom;
}

std::vector<XrSessionState> SimxrTest::poll_states() {
    std::vector<XrSessionState> states;
    auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    while (xrPollEvent(instance_, &event) == XR_SUCCESS) {
        if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
            const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
            EXPECT_EQ(changed.session, session_);
            states.push_back(changed.state);
        } else {
            ++other_events_;
        }
        event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    }
    return states;
}

XrFrameState SimxrTest::empty_frame() {
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    EXPECT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    EXPECT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
    end.displayTime = state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
    return state;
}

void SimxrTest::begin_and_focus() {
    poll_states();
    const XrSessionBeginInfo info = begin_info();
    ASSERT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    for (int frame = 0; frame < 10; ++frame) {
        empty_frame();
        const std::vector<XrSessionState> states = poll_states();
        if (!states.empty() && states.back() == XR_SESSION_STATE_FOCUSED) return;
    }
    FAIL() << "the session never became FOCUSED";
}

void SimxrTest::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
    auto pool_info = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool_info.queueFamilyIndex = queue_family_;
    VkCommandPool pool = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateCommandPool(device_, &pool_info, nullptr, &pool), VK_SUCCESS);
    auto allocate =
        vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    allocate.commandPool = pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    ASSERT_EQ(vkAllocateCommandBuffers(device_, &allocate, &commands), VK_SUCCESS);
    auto begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    vkBeginCommandBuffer(commands, &begin);
    record(commands);
    vkEndCommandBuffer(commands);
    auto submit = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    ASSERT_EQ(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), VK_SUCCESS);
    vkQueueWaitIdle(queue_);
    vkDestroyCommandPool(device_, pool, nullptr);
}

void SimxrTest::clear_image(VkImage image, VkClearColorValue colour) {
    submit_and_wait([&](VkCommandBuffer commands) {
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        auto barrier = vk_struct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
        barrier.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image;
        barrier.subresourceRange = range;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                             VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                             &barrier);
        vkCmdClearColorImage(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1,
                             &range);
        // The spec's contract: released in COLOR_ATTACHMENT_OPTIMAL.
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        barrier.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, 0, nullptr, 0,
                             nullptr, 1, &barrier);
    });
}

}  // namespace monoplane::simxr::testing
