// An OpenXR headset and the Vulkan context its runtime created, owned together so that they are
// destroyed in the one order that is safe on every way out, an exception's unwinding included:
// OpenXR first (its swapchains, session and instance), Vulkan last. A runtime's swapchain images
// live on the Vulkan device, and destroying them calls into the Vulkan driver through the
// runtime: with the device (and the driver) gone first, that call crashes. Monado's
// out-of-process runtime did, every time its service died mid-session.
#pragma once

#include <memory>

#include "app/headset/openxr_headset.h"
#include "common/result.h"
#include "renderer/vk/context.h"

namespace monoplane::headset {

class HeadsetDevice {
  public:
    // Creates the Vulkan context through the headset's runtime (OpenXrHeadset::vulkan_hooks,
    // which replace the options' hooks) and keeps both. Call with a created headset, before its
    // session; on failure the headset goes with the error.
    static Result<HeadsetDevice> create(std::unique_ptr<OpenXrHeadset> headset,
                                        vk_core::ContextOptions options);

    // Both live as long as this object. Any time.
    OpenXrHeadset& headset() const { return *headset_; }
    const vk_core::Context& vulkan() const { return *vulkan_; }

  private:
    HeadsetDevice(std::unique_ptr<vk_core::Context> vulkan, std::unique_ptr<OpenXrHeadset> headset);

    // Members are destroyed in reverse order of declaration: the headset (session, swapchains,
    // instance) before the Vulkan context. This order is the point of the type.
    std::unique_ptr<vk_core::Context> vulkan_;
    std::unique_ptr<OpenXrHeadset> headset_;
};

}  // namespace monoplane::headset
