#include "renderer/vk/context.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <string_view>

namespace monoplane::vk_core {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr std::size_t kKeptMessages = 16;

VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT /*severity*/,
                                                VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                void* user) {
    static_cast<ValidationMessages*>(user)->record(data->pMessage ? data->pMessage : "(empty)");
    return VK_FALSE;
}

bool has_layer(const vk::raii::Context& loader, const char* name) {
    const auto layers = loader.enumerateInstanceLayerProperties();
    return std::any_of(layers.begin(), layers.end(), [name](const vk::LayerProperties& layer) {
        return std::strcmp(layer.layerName.data(), name) == 0;
    });
}

std::uint32_t find_queue_family(const vk::raii::PhysicalDevice& device) {
    const auto families = device.getQueueFamilyProperties();
    const auto needed = vk::QueueFlagBits::eGraphics | vk::QueueFlagBits::eCompute;
    for (std::uint32_t i = 0; i < families.size(); ++i) {
        if ((families[i].queueFlags & needed) == needed) return i;
    }
    return 0;  // unreachable: select_device() only returns devices with such a family
}

bool has_extension(const std::vector<vk::ExtensionProperties>& available, std::string_view name) {
    return std::any_of(available.begin(), available.end(), [name](const auto& extension) {
        return std::string_view(extension.extensionName) == name;
    });
}

// Appends the caller's extensions after checking that they exist; the error names the first
// missing one and where it would come from.
std::optional<Error> add_extensions(const std::vector<std::string>& wanted,
                                    const std::vector<vk::ExtensionProperties>& available,
                                    const char* what, std::vector<const char*>& names) {
    for (const std::string& name : wanted) {
        if (!has_extension(available, name)) {
            return Error{std::string("the Vulkan ") + what + " extension " + name +
                         " is not available (a window needs a display and a WSI-capable driver)"};
        }
        if (std::find_if(names.begin(), names.end(), [&](const char* n) { return name == n; }) ==
            names.end()) {
            names.push_back(name.c_str());
        }
    }
    return std::nullopt;
}

// The index of the physical device a hook names (an OpenXR runtime's choice), if monoplane can
// use it.
Result<int> named_device(const vk::raii::Instance& instance, const std::vector<DeviceInfo>& devices,
                         const std::function<Result<VkPhysicalDevice>(VkInstance)>& name_device) {
    Result<VkPhysicalDevice> named = name_device(*instance);
    if (!named) return named.error();
    const vk::raii::PhysicalDevices physical(instance);
    for (std::size_t i = 0; i < physical.size(); ++i) {
        if (static_cast<VkPhysicalDevice>(*physical[i]) != *named) continue;
        if (!devices[i].suitable) {
            return Error{"the device the OpenXR runtime requires, '" + devices[i].name +
                         "', cannot run monoplane: " + devices[i].unsuitable_reason};
        }
        return static_cast<int>(i);
    }
    return Error{"the physical device named by the runtime is not one of the instance's devices"};
}

// The device's create info and every feature structure monoplane may enable.
using DeviceChain =
    vk::StructureChain<vk::DeviceCreateInfo, vk::PhysicalDeviceFeatures2,
                       vk::PhysicalDeviceVulkan11Features, vk::PhysicalDeviceHostQueryResetFeatures,
                       vk::PhysicalDeviceTimelineSemaphoreFeatures,
                       vk::PhysicalDeviceVulkan12Features, vk::PhysicalDeviceVulkan13Features,
                       vk::PhysicalDeviceConditionalRenderingFeaturesEXT>;

// Enables on `chain` the core features monoplane uses (the optional ones where the device has
// them). Vulkan 1.2's are asked for through their own structures, not through
// VkPhysicalDeviceVulkan12Features: an OpenXR runtime's xrCreateVulkanDeviceKHR may add
// VkPhysicalDeviceTimelineSemaphoreFeatures to the chain (Monado does unless the chain has one),
// and next to VkPhysicalDeviceVulkan12Features that is invalid
// (VUID-VkDeviceCreateInfo-pNext-02830). So the chain carries that structure itself, with
// timeline semaphores on where the device has them (what such runtimes want). The GPU culling
// writes each view's draw count: Vulkan 1.2's optional drawIndirectCount, which has no structure
// of its own outside VkPhysicalDeviceVulkan12Features; VK_KHR_draw_indirect_count, which devices
// with the feature offer, enables it (indirect_count_extension: the caller enables the
// extension). A device without the extension gets VkPhysicalDeviceVulkan12Features instead.
void enable_features(DeviceChain& chain, const vk::raii::PhysicalDevice& device,
                     bool indirect_count_extension) {
    const auto supported =
        device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan11Features,
                            vk::PhysicalDeviceVulkan12Features>();
    const auto& f10 = supported.get<vk::PhysicalDeviceFeatures2>().features;
    const bool timeline_semaphore =
        supported.get<vk::PhysicalDeviceVulkan12Features>().timelineSemaphore;
    vk::PhysicalDeviceFeatures& enable10 = chain.get<vk::PhysicalDeviceFeatures2>().features;
    enable10.multiDrawIndirect = VK_TRUE;
    enable10.drawIndirectFirstInstance = f10.drawIndirectFirstInstance;
    enable10.pipelineStatisticsQuery = f10.pipelineStatisticsQuery;
    enable10.geometryShader = f10.geometryShader;
    enable10.depthClamp = f10.depthClamp;
    enable10.samplerAnisotropy = f10.samplerAnisotropy;
    enable10.independentBlend = f10.independentBlend;
    chain.get<vk::PhysicalDeviceVulkan11Features>().multiview =
        supported.get<vk::PhysicalDeviceVulkan11Features>().multiview;
    chain.get<vk::PhysicalDeviceVulkan11Features>().shaderDrawParameters =
        supported.get<vk::PhysicalDeviceVulkan11Features>().shaderDrawParameters;
    if (indirect_count_extension) {
        chain.get<vk::PhysicalDeviceHostQueryResetFeatures>().hostQueryReset = VK_TRUE;
        chain.get<vk::PhysicalDeviceTimelineSemaphoreFeatures>().timelineSemaphore =
            timeline_semaphore;
        chain.unlink<vk::PhysicalDeviceVulkan12Features>();
    } else {
        auto& enable12 = chain.get<vk::PhysicalDeviceVulkan12Features>();
        enable12.drawIndirectCount = VK_TRUE;
        enable12.hostQueryReset = VK_TRUE;
        enable12.timelineSemaphore = timeline_semaphore;
        chain.unlink<vk::PhysicalDeviceHostQueryResetFeatures>();
        chain.unlink<vk::PhysicalDeviceTimelineSemaphoreFeatures>();
    }
    auto& enable13 = chain.get<vk::PhysicalDeviceVulkan13Features>();
    enable13.dynamicRendering = VK_TRUE;
    enable13.synchronization2 = VK_TRUE;
    // Required by Vulkan 1.3; glslc expresses compute local sizes with LocalSizeId for it.
    enable13.maintenance4 = VK_TRUE;
}

}  // namespace

void ValidationMessages::record(const std::string& message) {
    ++count_;
    std::lock_guard lock(mutex_);
    if (first_.size() < kKeptMessages) first_.push_back(message);
}

std::vector<std::string> ValidationMessages::first_messages() const {
    std::lock_guard lock(mutex_);
    return first_;
}

Context::~Context() {
    // Nothing may be destroyed while the GPU uses it; a lost device cannot be waited for, and a
    // destructor must not throw, so that case is left to the driver's teardown.
    if (*device_) static_cast<void>(device_.getDispatcher()->vkDeviceWaitIdle(*device_));
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
    std::unique_ptr<Context> ctx(new Context());
    try {
        if (auto error = ctx->create_instance(options)) return *error;
        if (auto error = ctx->choose_device(options)) return *error;
        if (auto error = ctx->create_device(options)) return *error;
    } catch (const vk::SystemError& e) {
        return Error{std::string("Vulkan initialisation failed: ") + e.what()};
    }
    return ctx;
}

std::optional<Error> Context::create_instance(const ContextOptions& options) {
    if (loader_.enumerateInstanceVersion() < VK_API_VERSION_1_3) {
        return Error{"the Vulkan loader is older than 1.3; install libvulkan1 from Debian 12"};
    }
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    if (options.validation) {
        if (!has_layer(loader_, kValidationLayer)) {
            return Error{std::string("validation requested but ") + kValidationLayer +
                         " is not installed (apt-get install vulkan-validationlayers)"};
        }
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }
    if (auto missing = add_extensions(options.instance_extensions,
                                      loader_.enumerateInstanceExtensionProperties(), "instance",
                                      extensions)) {
        return *missing;
    }
    const vk::ApplicationInfo app_info("monoplane", 1, "monoplane", 1, VK_API_VERSION_1_3);
    vk::InstanceCreateInfo instance_info({}, &app_info, layers, extensions);
    // With validation, the layer's synchronisation validation too: hazards between commands
    // (a missing or too narrow barrier) are reported like any other validation message.
    const std::array sync_validation = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
    const vk::ValidationFeaturesEXT features(sync_validation, {});
    if (options.validation) instance_info.setPNext(&features);
    if (options.hooks.create_instance) {
        Result<VkInstance> handle =
            options.hooks.create_instance(static_cast<const VkInstanceCreateInfo&>(instance_info));
        if (!handle) return handle.error();
        instance_ = vk::raii::Instance(loader_, *handle);
    } else {
        instance_ = vk::raii::Instance(loader_, instance_info);
    }

    if (options.validation) {
        using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
        using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
        const vk::DebugUtilsMessengerCreateInfoEXT messenger_info(
            {}, Severity::eWarning | Severity::eError,
            Type::eGeneral | Type::eValidation | Type::ePerformance, &on_debug_message,
            validation_messages_.get());
        messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, messenger_info);
    }
    return std::nullopt;
}

std::optional<Error> Context::choose_device(const ContextOptions& options) {
    const std::vector<DeviceInfo> devices = describe_devices(instance_);
    Result<int> chosen = options.hooks.physical_device
                             ? named_device(instance_, devices, options.hooks.physical_device)
                             : select_device(devices, options.device_selector);
    if (!chosen) return chosen.error();
    device_info_ = devices[*chosen];
    physical_device_ = std::move(vk::raii::PhysicalDevices(instance_)[*chosen]);
    queue_family_ = find_queue_family(physical_device_);

    const auto supported =
        physical_device_
            .getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan11Features,
                          vk::PhysicalDeviceVulkan12Features>();
    const auto& f10 = supported.get<vk::PhysicalDeviceFeatures2>().features;
    const auto& f11 = supported.get<vk::PhysicalDeviceVulkan11Features>();
    if (!supported.get<vk::PhysicalDeviceVulkan12Features>().drawIndirectCount) {
        return Error{"device '" + device_info_.name +
                     "' lacks drawIndirectCount (Vulkan 1.2), which the GPU culling needs; "
                     "choose another with --device (see `monoplane devices`)"};
    }
    DeviceCapabilities& caps = capabilities_;
    caps.pipeline_statistics = f10.pipelineStatisticsQuery;
    caps.geometry_shader = f10.geometryShader;
    caps.multiview = f11.multiview;
    caps.independent_blend = f10.independentBlend;
    caps.depth_clamp = f10.depthClamp;
    caps.shader_draw_parameters = f11.shaderDrawParameters;
    const auto device_extensions = physical_device_.enumerateDeviceExtensionProperties();
    caps.vertex_shader_layer =
        has_extension(device_extensions, VK_EXT_SHADER_VIEWPORT_INDEX_LAYER_EXTENSION_NAME);
    caps.conditional_rendering =
        std::any_of(device_extensions.begin(), device_extensions.end(), [](const auto& extension) {
            return std::string_view(extension.extensionName) ==
                   VK_EXT_CONDITIONAL_RENDERING_EXTENSION_NAME;
        });
    const auto properties = physical_device_.getProperties();
    caps.timestamp_period_ns = properties.limits.timestampPeriod;
    caps.max_sampler_anisotropy =
        f10.samplerAnisotropy ? properties.limits.maxSamplerAnisotropy : 1.0f;
    caps.draw_indirect_first_instance = f10.drawIndirectFirstInstance;
    caps.max_image_dimension_2d = properties.limits.maxImageDimension2D;
    caps.max_image_array_layers = properties.limits.maxImageArrayLayers;
    caps.timestamp_valid_bits =
        physical_device_.getQueueFamilyProperties()[queue_family_].timestampValidBits;
    return std::nullopt;
}

std::optional<Error> Context::create_device(const ContextOptions& options) {
    const auto device_extensions = physical_device_.enumerateDeviceExtensionProperties();
    const bool indirect_count_extension =
        has_extension(device_extensions, VK_KHR_DRAW_INDIRECT_COUNT_EXTENSION_NAME);
    DeviceChain chain;
    enable_features(chain, physical_device_, indirect_count_extension);
    std::vector<const char*> device_extension_names;
    if (indirect_count_extension) {
        device_extension_names.push_back(VK_KHR_DRAW_INDIRECT_COUNT_EXTENSION_NAME);
    }
    if (capabilities_.vertex_shader_layer) {
        device_extension_names.push_back(VK_EXT_SHADER_VIEWPORT_INDEX_LAYER_EXTENSION_NAME);
    }
    if (auto missing = add_extensions(options.device_extensions, device_extensions, "device",
                                      device_extension_names)) {
        return *missing;
    }
    if (capabilities_.conditional_rendering) {
        chain.get<vk::PhysicalDeviceConditionalRenderingFeaturesEXT>().conditionalRendering =
            VK_TRUE;
        device_extension_names.push_back(VK_EXT_CONDITIONAL_RENDERING_EXTENSION_NAME);
    } else {
        chain.unlink<vk::PhysicalDeviceConditionalRenderingFeaturesEXT>();
    }
    chain.get<vk::DeviceCreateInfo>().setPEnabledExtensionNames(device_extension_names);

    const float priority = 1.0f;
    const vk::DeviceQueueCreateInfo queue_info({}, queue_family_, 1, &priority);
    chain.get<vk::DeviceCreateInfo>().setQueueCreateInfos(queue_info);
    if (options.hooks.create_device) {
        Result<VkDevice> handle = options.hooks.create_device(
            *physical_device_,
            static_cast<const VkDeviceCreateInfo&>(chain.get<vk::DeviceCreateInfo>()));
        if (!handle) return handle.error();
        device_ = vk::raii::Device(physical_device_, *handle);
    } else {
        device_ = vk::raii::Device(physical_device_, chain.get<vk::DeviceCreateInfo>());
    }
    device_extensions_.assign(device_extension_names.begin(), device_extension_names.end());
    queue_ = vk::raii::Queue(device_, queue_family_, 0);
    command_pool_ = vk::raii::CommandPool(
        device_, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eTransient |
                                               vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                           queue_family_));
    return std::nullopt;
}

bool Context::has_device_extension(std::string_view name) const {
    return std::find(device_extensions_.begin(), device_extensions_.end(), name) !=
           device_extensions_.end();
}

void Context::submit_and_wait(
    const std::function<void(const vk::raii::CommandBuffer&)>& record) const {
    vk::raii::CommandBuffers buffers(
        device_,
        vk::CommandBufferAllocateInfo(*command_pool_, vk::CommandBufferLevel::ePrimary, 1));
    const vk::raii::CommandBuffer& cmd = buffers.front();
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    record(cmd);
    cmd.end();
    const vk::raii::Fence fence(device_, vk::FenceCreateInfo());
    const vk::CommandBufferSubmitInfo cmd_info(*cmd);
    queue_.submit2(vk::SubmitInfo2({}, {}, cmd_info, {}), *fence);
    // A frame on llvmpipe at benchmark resolutions can take seconds: wait without a deadline.
    while (device_.waitForFences(*fence, VK_TRUE, UINT64_MAX) == vk::Result::eTimeout) {
    }
}

}  // namespace monoplane::vk_core
