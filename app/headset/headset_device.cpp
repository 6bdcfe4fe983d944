#include "app/headset/headset_device.h"

#include <utility>

namespace monoplane::headset {

HeadsetDevice::HeadsetDevice(std::unique_ptr<vk_core::Context> vulkan,
                             std::unique_ptr<OpenXrHeadset> headset)
    : vulkan_(std::move(vulkan)), headset_(std::move(headset)) {}

Result<HeadsetDevice> HeadsetDevice::create(std::unique_ptr<OpenXrHeadset> headset,
                                            vk_core::ContextOptions options) {
    options.hooks = headset->vulkan_hooks();
    Result<std::unique_ptr<vk_core::Context>> vulkan = vk_core::Context::create(options);
    MONOPLANE_TRY(vulkan);
    return HeadsetDevice(std::move(vulkan).value(), std::move(headset));
}

}  // namespace monoplane::headset
