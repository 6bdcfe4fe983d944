// The Vulkan instance, the chosen device and its queue: created once per process (or per test).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "renderer/vk/device_selection.h"
#include "renderer/vk/vulkan.h"

namespace monoplane::vk_core {

// Lets a caller take over creating the instance and the device while the Context still decides
// what they need (API version, layers, extensions, features). An OpenXR runtime is such a caller:
// with XR_KHR_vulkan_enable2 it creates both itself and names the physical device to use.
struct ContextCreationHooks {
    // Creates the instance from the Context's create info; returns the handle or a message.
    std::function<Result<VkInstance>(const VkInstanceCreateInfo&)> create_instance;
    // The physical device to use (instead of select_device()).
    std::function<Result<VkPhysicalDevice>(VkInstance)> physical_device;
    // Creates the device on that physical device from the Context's create info.
    std::function<Result<VkDevice>(VkPhysicalDevice, const VkDeviceCreateInfo&)> create_device;
};

struct ContextOptions {
    // Khronos validation layer, its synchronisation validation included, with a message counter;
    // tests turn it on and fail on any message.
    bool validation = false;
    std::string device_selector;  // see select_device()
    // Extensions beyond monoplane's own, e.g. a window's surface extensions (GLFW) and
    // VK_KHR_swapchain; a missing one is an error naming it.
    std::vector<std::string> instance_extensions;
    std::vector<std::string> device_extensions;
    ContextCreationHooks hooks;  // empty members: created here
};

// Counts validation warnings and errors; keeps the first few messages for the test's report.
class ValidationMessages {
  public:
    void record(const std::string& message);
    std::size_t count() const { return count_.load(); }
    std::vector<std::string> first_messages() const;

  private:
    std::atomic<std::size_t> count_{0};
    mutable std::mutex mutex_;
    std::vector<std::string> first_;
};

// Optional device features, enabled when the device has them.
struct DeviceCapabilities {
    bool pipeline_statistics = false;
    bool geometry_shader = false;
    bool multiview = false;
    // Colour attachments written with different channel masks by one pipeline: the composite
    // that writes the display image and keeps the eye's linear depth (renderer/passes/composite).
    bool independent_blend = false;
    // Depth clamping: hybrid draws blended chunks straddling the mono plane into the eyes after
    // the composite with the eyes' projection, whose far plane is m (renderer/passes/forward).
    bool depth_clamp = false;
    // Instanced stereo: the vertex shader reads the draw's base instance (Vulkan 1.1's
    // shaderDrawParameters) and writes gl_Layer (VK_EXT_shader_viewport_index_layer, enabled
    // when offered; Vulkan 1.2's shaderOutputLayer would need the feature structure the device
    // chain leaves out beside VK_KHR_draw_indirect_count).
    bool shader_draw_parameters = false;
    bool vertex_shader_layer = false;
    // VK_EXT_conditional_rendering: passes whose inputs the GPU culling left empty are skipped
    // without a round trip to the CPU (the draws and dispatches of such a pass do nothing).
    bool conditional_rendering = false;
    float timestamp_period_ns = 1.0f;
    std::uint32_t timestamp_valid_bits = 0;
    // Anisotropic texture filtering (imported scenes' textures): 1 without samplerAnisotropy.
    float max_sampler_anisotropy = 1.0f;
    // drawIndirectFirstInstance: the culling pass's draws carry the chunk index as first
    // instance, which the debug view "routing" and textured scenes read.
    bool draw_indirect_first_instance = false;
    // Sides of 2D images and layers of array images the device allows.
    std::uint32_t max_image_dimension_2d = 4096;
    std::uint32_t max_image_array_layers = 256;
};

class Context {
  public:
    // May be called at any time; fails with a message a user can act on (no loader, no device,
    // validation requested but the layer is not installed).
    static Result<std::unique_ptr<Context>> create(const ContextOptions& options);

    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    ~Context();

    const vk::raii::Instance& instance() const { return instance_; }
    const vk::raii::PhysicalDevice& physical_device() const { return physical_device_; }
    const vk::raii::Device& device() const { return device_; }
    const vk::raii::Queue& queue() const { return queue_; }
    std::uint32_t queue_family() const { return queue_family_; }
    const DeviceInfo& device_info() const { return device_info_; }
    const DeviceCapabilities& capabilities() const { return capabilities_; }
    const ValidationMessages& validation_messages() const { return *validation_messages_; }

    // Whether the device was created with this extension (one of ContextOptions's or our own).
    bool has_device_extension(std::string_view name) const;

    // Runs `record` on a fresh primary command buffer, submits it and waits for completion.
    // May be called from one thread at a time.
    void submit_and_wait(const std::function<void(const vk::raii::CommandBuffer&)>& record) const;

  private:
    Context() = default;
    // The steps of create(), in order; each fills its members or says why it cannot.
    std::optional<Error> create_instance(const ContextOptions& options);
    std::optional<Error> choose_device(const ContextOptions& options);  // and its capabilities
    std::optional<Error> create_device(const ContextOptions& options);

    vk::raii::Context loader_;
    vk::raii::Instance instance_{nullptr};
    std::unique_ptr<ValidationMessages> validation_messages_ =
        std::make_unique<ValidationMessages>();
    vk::raii::DebugUtilsMessengerEXT messenger_{nullptr};
    vk::raii::PhysicalDevice physical_device_{nullptr};
    vk::raii::Device device_{nullptr};
    vk::raii::Queue queue_{nullptr};
    vk::raii::CommandPool command_pool_{nullptr};
    std::uint32_t queue_family_ = 0;
    std::vector<std::string> device_extensions_;
    DeviceInfo device_info_;
    DeviceCapabilities capabilities_;
};

}  // namespace monoplane::vk_core
