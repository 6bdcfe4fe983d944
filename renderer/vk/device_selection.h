// Choosing the physical device: a discrete GPU if there is one, else an integrated or virtual GPU,
// else the CPU rasterizer (llvmpipe/lavapipe); `--device` overrides with an index or a name part.
#pragma once

#include <string>
#include <vector>

#include "common/result.h"
#include "renderer/vk/vulkan.h"

namespace monoplane::vk_core {

struct DeviceInfo {
    int index = 0;
    std::string name;
    vk::PhysicalDeviceType type = vk::PhysicalDeviceType::eOther;
    std::uint32_t api_version = 0;
    bool suitable = false;  // Vulkan 1.3 with the features monoplane needs
    std::string unsuitable_reason;
};

// Describes every physical device the loader reports.
std::vector<DeviceInfo> describe_devices(const vk::raii::Instance& instance);

// selector: "" picks automatically; a number picks that index; anything else picks the first
// suitable device whose name contains it (case-insensitive). Errors list the devices available.
Result<int> select_device(const std::vector<DeviceInfo>& devices, const std::string& selector);

std::string device_type_name(vk::PhysicalDeviceType type);

}  // namespace monoplane::vk_core
