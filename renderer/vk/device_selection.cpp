#include "renderer/vk/device_selection.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

namespace monoplane::vk_core {
namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

int preference(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu:
            return 0;
        case vk::PhysicalDeviceType::eIntegratedGpu:
            return 1;
        case vk::PhysicalDeviceType::eVirtualGpu:
            return 2;
        case vk::PhysicalDeviceType::eCpu:
            return 3;
        default:
            return 4;
    }
}

std::string listing(const std::vector<DeviceInfo>& devices) {
    std::ostringstream out;
    for (const DeviceInfo& d : devices) {
        out << "\n  " << d.index << ": " << d.name << " (" << device_type_name(d.type) << ")";
        if (!d.suitable) out << " - unsuitable: " << d.unsuitable_reason;
    }
    return out.str();
}

std::string unsuitable_reason(const vk::raii::PhysicalDevice& device) {
    const auto properties = device.getProperties();
    if (properties.apiVersion < VK_API_VERSION_1_3) return "needs Vulkan 1.3";
    const auto chain =
        device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan13Features>();
    const auto& f10 = chain.get<vk::PhysicalDeviceFeatures2>().features;
    const auto& f13 = chain.get<vk::PhysicalDeviceVulkan13Features>();
    if (!f13.dynamicRendering) return "no dynamicRendering";
    if (!f13.synchronization2) return "no synchronization2";
    if (!f10.multiDrawIndirect) return "no multiDrawIndirect";
    bool has_graphics = false;
    for (const auto& family : device.getQueueFamilyProperties()) {
        const auto needed = vk::QueueFlagBits::eGraphics | vk::QueueFlagBits::eCompute;
        if ((family.queueFlags & needed) == needed) has_graphics = true;
    }
    if (!has_graphics) return "no graphics+compute queue";
    return "";
}

}  // namespace

std::string device_type_name(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu:
            return "discrete GPU";
        case vk::PhysicalDeviceType::eIntegratedGpu:
            return "integrated GPU";
        case vk::PhysicalDeviceType::eVirtualGpu:
            return "virtual GPU";
        case vk::PhysicalDeviceType::eCpu:
            return "CPU";
        default:
            return "other";
    }
}

std::vector<DeviceInfo> describe_devices(const vk::raii::Instance& instance) {
    std::vector<DeviceInfo> result;
    vk::raii::PhysicalDevices devices(instance);
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const auto properties = devices[i].getProperties();
        DeviceInfo info;
        info.index = static_cast<int>(i);
        info.name = properties.deviceName.data();
        info.type = properties.deviceType;
        info.api_version = properties.apiVersion;
        info.unsuitable_reason = unsuitable_reason(devices[i]);
        info.suitable = info.unsuitable_reason.empty();
        result.push_back(info);
    }
    return result;
}

Result<int> select_device(const std::vector<DeviceInfo>& devices, const std::string& selector) {
    if (devices.empty()) {
        return Error{
            "no Vulkan device found: install a driver (on machines without a GPU, "
            "Debian's mesa-vulkan-drivers provides llvmpipe)"};
    }
    if (selector.empty()) {
        const DeviceInfo* best = nullptr;
        for (const DeviceInfo& d : devices) {
            if (d.suitable && (!best || preference(d.type) < preference(best->type))) best = &d;
        }
        if (!best) return Error{"no suitable Vulkan device:" + listing(devices)};
        return best->index;
    }
    int index = -1;
    const auto [end, ec] =
        std::from_chars(selector.data(), selector.data() + selector.size(), index);
    if (ec == std::errc() && end == selector.data() + selector.size()) {
        if (index < 0 || index >= static_cast<int>(devices.size())) {
            return Error{"--device " + selector +
                         ": no device with that index:" + listing(devices)};
        }
        if (!devices[index].suitable) {
            return Error{"--device " + selector + ": device is unsuitable:" + listing(devices)};
        }
        return index;
    }
    for (const DeviceInfo& d : devices) {
        if (d.suitable && lower(d.name).find(lower(selector)) != std::string::npos) return d.index;
    }
    return Error{"--device " + selector +
                 ": no suitable device's name contains it:" + listing(devices)};
}

}  // namespace monoplane::vk_core
