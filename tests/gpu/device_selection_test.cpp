// Device choice over synthetic device lists: no GPU needed, but it lives with the Vulkan library.
#include <gtest/gtest.h>

#include "renderer/vk/device_selection.h"

namespace monoplane::vk_core {
namespace {

DeviceInfo device(int index, const char* name, vk::PhysicalDeviceType type, bool suitable = true) {
    DeviceInfo d;
    d.index = index;
    d.name = name;
    d.type = type;
    d.suitable = suitable;
    d.unsuitable_reason = suitable ? "" : "needs Vulkan 1.3";
    return d;
}

const std::vector<DeviceInfo> kMachine = {
    device(0, "llvmpipe (LLVM 15.0.6, 256 bits)", vk::PhysicalDeviceType::eCpu),
    device(1, "Old GPU", vk::PhysicalDeviceType::eDiscreteGpu, false),
    device(2, "NVIDIA H100", vk::PhysicalDeviceType::eDiscreteGpu),
    device(3, "Intel UHD", vk::PhysicalDeviceType::eIntegratedGpu),
};

TEST(DeviceSelection, PrefersASuitableDiscreteGpu) {
    EXPECT_EQ(*select_device(kMachine, ""), 2);
}

TEST(DeviceSelection, FallsBackToTheCpuRasterizer) {
    const std::vector<DeviceInfo> cpu_only = {kMachine[0], kMachine[1]};
    EXPECT_EQ(*select_device(cpu_only, ""), 0);
}

TEST(DeviceSelection, IntegratedBeatsCpu) {
    EXPECT_EQ(*select_device({kMachine[0], kMachine[3]}, ""), 3);
}

TEST(DeviceSelection, ByIndexAndByNamePart) {
    EXPECT_EQ(*select_device(kMachine, "0"), 0);
    EXPECT_EQ(*select_device(kMachine, "LLVMPIPE"), 0);
    EXPECT_EQ(*select_device(kMachine, "h100"), 2);
}

TEST(DeviceSelection, ErrorsNameTheProblemAndListTheDevices) {
    const auto out_of_range = select_device(kMachine, "7");
    ASSERT_FALSE(out_of_range.ok());
    EXPECT_NE(out_of_range.error().message.find("no device with that index"), std::string::npos);
    EXPECT_NE(out_of_range.error().message.find("NVIDIA H100"), std::string::npos);

    const auto unsuitable = select_device(kMachine, "1");
    ASSERT_FALSE(unsuitable.ok());
    EXPECT_NE(unsuitable.error().message.find("needs Vulkan 1.3"), std::string::npos);

    EXPECT_FALSE(select_device(kMachine, "radeon").ok());
    EXPECT_FALSE(select_device({}, "").ok());
    EXPECT_FALSE(select_device({kMachine[1]}, "").ok());
}

}  // namespace
}  // namespace monoplane::vk_core
