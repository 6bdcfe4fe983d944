// XR_KHR_composition_layer_depth in simxr (docs/simxr.md): the extension is offered, projection
// views may carry their depth images, malformed depth structures get the spec's codes, and dumps
// hold each eye's distances. Expected distances come from the extension's window-from-view
// matrix run forwards here (view distance -> window depth), never from simxr's inverse.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>

#include "tests/simxr/runtime_fixture.h"

namespace monoplane::simxr::testing {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr uint32_t kWidth = 48;
constexpr uint32_t kHeight = 32;

struct TestSwapchain {
    XrSwapchain swapchain = XR_NULL_HANDLE;
    std::vector<VkImage> images;
};

TestSwapchain make_swapchain(XrSession session, VkFormat format, uint32_t array_size) {
    const bool depth = format == VK_FORMAT_D32_SFLOAT;
    auto info = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
    info.usageFlags = (depth ? XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                             : XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT) |
                      XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT;
    info.format = format;
    info.sampleCount = 1;
    info.width = kWidth;
    info.height = kHeight;
    info.faceCount = info.mipCount = 1;
    info.arraySize = array_size;
    TestSwapchain result;
    EXPECT_EQ(xrCreateSwapchain(session, &info, &result.swapchain), XR_SUCCESS);
    uint32_t count = 0;
    EXPECT_EQ(xrEnumerateSwapchainImages(result.swapchain, 0, &count, nullptr), XR_SUCCESS);
    std::vector<XrSwapchainImageVulkan2KHR> images(
        count, xr_struct<XrSwapchainImageVulkan2KHR>(XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR));
    EXPECT_EQ(
        xrEnumerateSwapchainImages(result.swapchain, count, &count,
                                   reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
        XR_SUCCESS);
    for (const auto& image : images) result.images.push_back(image.image);
    return result;
}

// A depth mapping as XrCompositionLayerDepthInfoKHR states it.
struct Mapping {
    float min_depth, max_depth, near_z, far_z;
};

// The window depth of a point `distance` metres in front of the eye: the extension's matrix
// T = [b-a a; 0 1] [-f/(f-n) -fn/(f-n); -1 0] applied to (z, 1), z = -distance, then divided by
// w. With a plane at infinity the first row is taken at its limit.
double window_depth(const Mapping& m, double distance) {
    const double a = m.min_depth, b = m.max_depth, n = m.near_z, f = m.far_z;
    double t00 = 0.0, t01 = 0.0;
    if (std::isinf(f)) {
        t00 = -b;
        t01 = -n * (b - a);
    } else if (std::isinf(n)) {
        t00 = -a;
        t01 = f * (b - a);
    } else {
        t00 = -(b * f - a * n) / (f - n);
        t01 = -f * n * (b - a) / (f - n);
    }
    const double z = -distance;
    return (t00 * z + t01) / -z;
}

XrCompositionLayerDepthInfoKHR depth_info(XrSwapchain swapchain, uint32_t layer, const Mapping& m) {
    auto depth =
        xr_struct<XrCompositionLayerDepthInfoKHR>(XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR);
    depth.subImage.swapchain = swapchain;
    depth.subImage.imageRect = {{0, 0},
                                {static_cast<int32_t>(kWidth), static_cast<int32_t>(kHeight)}};
    depth.subImage.imageArrayIndex = layer;
    depth.minDepth = m.min_depth;
    depth.maxDepth = m.max_depth;
    depth.nearZ = m.near_z;
    depth.farZ = m.far_z;
    return depth;
}

// A PFM file's header and its samples, rows top to bottom (the file stores them bottom up).
struct FloatMap {
    std::string header;
    uint32_t width = 0, height = 0;
    std::vector<float> rows_top_down;
    float at(uint32_t x, uint32_t y) const { return rows_top_down[std::size_t{y} * width + x]; }
};

FloatMap read_pfm(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    EXPECT_TRUE(in) << file;
    FloatMap map;
    std::string kind, scale;
    in >> kind >> map.width >> map.height >> scale;
    in.get();  // the single whitespace character after the scale
    std::ostringstream header;
    header << kind << '\n' << map.width << ' ' << map.height << '\n' << scale << '\n';
    map.header = header.str();
    std::vector<float> bottom_up(std::size_t{map.width} * map.height);
    in.read(reinterpret_cast<char*>(bottom_up.data()),
            static_cast<std::streamsize>(bottom_up.size() * sizeof(float)));
    EXPECT_TRUE(in) << file << ": fewer samples than the header says";
    map.rows_top_down.resize(bottom_up.size());
    for (uint32_t y = 0; y < map.height; ++y) {
        std::memcpy(&map.rows_top_down[std::size_t{y} * map.width],
                    &bottom_up[std::size_t{map.height - 1 - y} * map.width],
                    map.width * sizeof(float));
    }
    return map;
}

struct DepthOptions {
    bool enable_depth = true;
    // Off for simxr's own answers to invalid usage, which the OpenXR validation layer would
    // intercept (FixtureOptions::xr_validation).
    bool xr_validation = true;
};

class DepthLayerTest : public SimxrTest {
  protected:
    // start(), but with XR_KHR_composition_layer_depth enabled too when `enable_depth`. The
    // fixture's instance has XR_KHR_vulkan_enable2 only, so it is replaced by one with both
    // extensions, keeping the fixture's Vulkan instance, validation messenger and device.
    void start_with_depth(const std::string& script, DepthOptions options = {}) {
        start(script, {.create_session = false, .xr_validation = options.xr_validation});
        if (HasFatalFailure()) return;
        if (options.enable_depth) {
            // The OpenXR messenger is the old instance's child: it goes first.
            if (xr_messenger_ != XR_NULL_HANDLE) {
                PFN_xrDestroyDebugUtilsMessengerEXT destroy = nullptr;
                load("xrDestroyDebugUtilsMessengerEXT", destroy);
                ASSERT_EQ(destroy(xr_messenger_), XR_SUCCESS);
                xr_messenger_ = XR_NULL_HANDLE;
            }
            ASSERT_EQ(xrDestroyInstance(instance_), XR_SUCCESS);
            instance_ = XR_NULL_HANDLE;
            ASSERT_EQ(
                create_instance_with_script(dir_, script,
                                            {XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME,
                                             XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME},
                                            &instance_, options.xr_validation, &xr_messenger_),
                XR_SUCCESS);
            load("xrGetVulkanGraphicsRequirements2KHR", xrGetVulkanGraphicsRequirements2KHR);
            load("xrGetVulkanGraphicsDevice2KHR", xrGetVulkanGraphicsDevice2KHR);
            auto system_info = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
            system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
            ASSERT_EQ(xrGetSystem(instance_, &system_info, &system_), XR_SUCCESS);
            auto requirements = xr_struct<XrGraphicsRequirementsVulkan2KHR>(
                XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR);
            ASSERT_EQ(xrGetVulkanGraphicsRequirements2KHR(instance_, system_, &requirements),
                      XR_SUCCESS);
            auto device_get = xr_struct<XrVulkanGraphicsDeviceGetInfoKHR>(
                XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR);
            device_get.systemId = system_;
            device_get.vulkanInstance = vk_instance_;
            VkPhysicalDevice named = VK_NULL_HANDLE;
            ASSERT_EQ(xrGetVulkanGraphicsDevice2KHR(instance_, &device_get, &named), XR_SUCCESS);
            ASSERT_EQ(named, physical_device_);
        }
        const XrGraphicsBindingVulkan2KHR vulkan = binding();
        const XrSessionCreateInfo info = session_info(&vulkan);
        ASSERT_EQ(xrCreateSession(instance_, &info, &session_), XR_SUCCESS);
        begin_and_focus();
        auto space_info =
            xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
        space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
        space_info.poseInReferenceSpace.orientation.w = 1.0f;
        ASSERT_EQ(xrCreateReferenceSpace(session_, &space_info, &local_), XR_SUCCESS);
    }

    template <class Pfn>
    void load(const char* name, Pfn& function) {
        ASSERT_EQ(xrGetInstanceProcAddr(instance_, name,
                                        reinterpret_cast<PFN_xrVoidFunction*>(&function)),
                  XR_SUCCESS)
            << name;
    }

    // Acquires and waits the swapchain's next image; returns its index.
    uint32_t acquire(XrSwapchain swapchain) {
        uint32_t index = 0;
        EXPECT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
        auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
        wait.timeout = XR_INFINITE_DURATION;
        EXPECT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_SUCCESS);
        return index;
    }

    // Acquires, fills (colour: cleared; depth: `depths` per array layer) and releases.
    void render(const TestSwapchain& colour, const TestSwapchain& depth,
                const std::vector<std::vector<float>>& depths = {}) {
        clear_image(colour.images[acquire(colour.swapchain)], {{0.5f, 0.5f, 0.5f, 1.0f}});
        EXPECT_EQ(xrReleaseSwapchainImage(colour.swapchain, nullptr), XR_SUCCESS);
        const uint32_t index = acquire(depth.swapchain);
        for (uint32_t layer = 0; layer < depths.size(); ++layer) {
            fill_depth(depth.images[index], layer, depths[layer]);
        }
        EXPECT_EQ(xrReleaseSwapchainImage(depth.swapchain, nullptr), XR_SUCCESS);
    }

    // The depth analogue of the fixture's clear_image: copies `depths` (kWidth x kHeight, rows
    // top to bottom, each in [0, 1] as D32_SFLOAT requires) into one array layer from a host
    // buffer, leaving the image in DEPTH_STENCIL_ATTACHMENT_OPTIMAL, the layout the spec expects
    // on release.
    void fill_depth(VkImage image, uint32_t layer, const std::vector<float>& depths) {
        ASSERT_EQ(depths.size(), std::size_t{kWidth} * kHeight);
        const VkDeviceSize size = depths.size() * sizeof(float);
        auto buffer_info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
        buffer_info.size = size;
        buffer_info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        VkBuffer buffer = VK_NULL_HANDLE;
        ASSERT_EQ(vkCreateBuffer(device_, &buffer_info, nullptr, &buffer), VK_SUCCESS);
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(device_, buffer, &requirements);
        VkPhysicalDeviceMemoryProperties memory_properties{};
        vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties);
        const VkMemoryPropertyFlags wanted =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        auto allocate = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex = UINT32_MAX;
        for (uint32_t i = 0; i < memory_properties.memoryTypeCount; ++i) {
            if ((requirements.memoryTypeBits & (1u << i)) != 0 &&
                (memory_properties.memoryTypes[i].propertyFlags & wanted) == wanted) {
                allocate.memoryTypeIndex = i;
                break;
            }
        }
        ASSERT_NE(allocate.memoryTypeIndex, UINT32_MAX);
        VkDeviceMemory memory = VK_NULL_HANDLE;
        ASSERT_EQ(vkAllocateMemory(device_, &allocate, nullptr, &memory), VK_SUCCESS);
        ASSERT_EQ(vkBindBufferMemory(device_, buffer, memory, 0), VK_SUCCESS);
        void* mapped = nullptr;
        ASSERT_EQ(vkMapMemory(device_, memory, 0, size, 0, &mapped), VK_SUCCESS);
        std::memcpy(mapped, depths.data(), size);
        vkUnmapMemory(device_, memory);

        submit_and_wait([&](VkCommandBuffer commands) {
            const VkPipelineStageFlags fragment_tests = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                        VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
            auto barrier = vk_struct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
            barrier.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
            barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            barrier.oldLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
            barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = image;
            barrier.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, layer, 1};
            vkCmdPipelineBarrier(commands, fragment_tests, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                                 nullptr, 0, nullptr, 1, &barrier);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, layer, 1};
            region.imageExtent = {kWidth, kHeight, 1};
            vkCmdCopyBufferToImage(commands, buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                                   &region);
            barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            barrier.dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
            barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            barrier.newLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
            vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, fragment_tests, 0, 0,
                                 nullptr, 0, nullptr, 1, &barrier);
        });
        vkDestroyBuffer(device_, buffer, nullptr);
        vkFreeMemory(device_, memory, nullptr);
    }

    // Waits and begins a frame; returns its display time.
    XrTime begin_frame() {
        auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
        EXPECT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
        EXPECT_TRUE(state.shouldRender);
        EXPECT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
        return state.predictedDisplayTime;
    }

    // Ends the frame with one projection layer whose eyes show `colour` (the whole image) and
    // chain depth[eye] when it is not null.
    XrResult end_frame(XrTime time, XrSwapchain colour, const XrCompositionLayerDepthInfoKHR* left,
                       const XrCompositionLayerDepthInfoKHR* right) {
        XrCompositionLayerProjectionView views[2];
        const XrCompositionLayerDepthInfoKHR* depth[2] = {left, right};
        for (int eye = 0; eye < 2; ++eye) {
            views[eye] = xr_struct<XrCompositionLayerProjectionView>(
                XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
            views[eye].next = depth[eye];
            views[eye].pose.orientation.w = 1.0f;
            views[eye].fov = {-0.8f, 0.8f, 0.8f, -0.8f};
            views[eye].subImage.swapchain = colour;
            views[eye].subImage.imageRect = {
                {0, 0}, {static_cast<int32_t>(kWidth), static_cast<int32_t>(kHeight)}};
        }
        auto layer = xr_struct<XrCompositionLayerProjection>(XR_TYPE_COMPOSITION_LAYER_PROJECTION);
        layer.space = local_;
        layer.viewCount = 2;
        layer.views = views;
        const auto* layers = reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer);
        auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
        end.displayTime = time;
        end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
        end.layerCount = 1;
        end.layers = &layers;
        return xrEndFrame(session_, &end);
    }

    XrSpace local_ = XR_NULL_HANDLE;
};

TEST_F(DepthLayerTest, ExtensionIsOfferedWithTheSpecVersion) {
    start_with_depth("");
    uint32_t count = 0;
    ASSERT_EQ(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr), XR_SUCCESS);
    std::vector<XrExtensionProperties> properties(
        count, xr_struct<XrExtensionProperties>(XR_TYPE_EXTENSION_PROPERTIES));
    ASSERT_EQ(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, properties.data()),
              XR_SUCCESS);
    int found = 0;
    for (const XrExtensionProperties& extension : properties) {
        if (std::string(extension.extensionName) == XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME) {
            ++found;
            EXPECT_EQ(extension.extensionVersion, XR_KHR_composition_layer_depth_SPEC_VERSION);
        }
    }
    EXPECT_EQ(found, 1);
}

TEST_F(DepthLayerTest, FramesWithDepthPerViewAreAccepted) {
    start_with_depth("");
    const TestSwapchain colour = make_swapchain(session_, VK_FORMAT_R8G8B8A8_UNORM, 1);
    const TestSwapchain depth = make_swapchain(session_, VK_FORMAT_D32_SFLOAT, 2);
    // Standard, reversed (nearZ > farZ), and each with a plane at infinity; a narrowed range.
    const Mapping mappings[] = {{0.0f, 1.0f, 0.1f, 1000.0f},
                                {0.0f, 1.0f, 1000.0f, 0.1f},
                                {0.0f, 1.0f, 0.1f, kInfinity},
                                {0.0f, 1.0f, kInfinity, 0.1f},
                                {0.25f, 0.75f, 0.5f, 20.0f}};
    for (const Mapping& m : mappings) {
        SCOPED_TRACE(::testing::Message() << "nearZ " << m.near_z << " farZ " << m.far_z);
        const XrTime time = begin_frame();
        render(colour, depth);
        const XrCompositionLayerDepthInfoKHR left = depth_info(depth.swapchain, 0, m);
        const XrCompositionLayerDepthInfoKHR right = depth_info(depth.swapchain, 1, m);
        EXPECT_EQ(end_frame(time, colour.swapchain, &left, &right), XR_SUCCESS);
    }
    EXPECT_EQ(xrDestroySwapchain(colour.swapchain), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(depth.swapchain), XR_SUCCESS);
}

TEST_F(DepthLayerTest, MalformedDepthInfoGetsTheSpecsCode) {
    start_with_depth("", {.xr_validation = false});
    const TestSwapchain colour = make_swapchain(session_, VK_FORMAT_R8G8B8A8_UNORM, 1);
    const TestSwapchain depth = make_swapchain(session_, VK_FORMAT_D32_SFLOAT, 2);
    const TestSwapchain unreleased = make_swapchain(session_, VK_FORMAT_D32_SFLOAT, 1);
    const XrTime time = begin_frame();
    render(colour, depth);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        const char* what;
        std::function<void(XrCompositionLayerDepthInfoKHR&)> change;
        XrResult expected;
    };
    const Case cases[] = {
        {"null swapchain", [](auto& d) { d.subImage.swapchain = XR_NULL_HANDLE; },
         XR_ERROR_HANDLE_INVALID},
        {"swapchain never released", [&](auto& d) { d.subImage.swapchain = unreleased.swapchain; },
         XR_ERROR_LAYER_INVALID},
        {"colour swapchain", [&](auto& d) { d.subImage.swapchain = colour.swapchain; },
         XR_ERROR_VALIDATION_FAILURE},
        {"rect past the right edge", [](auto& d) { d.subImage.imageRect.offset.x = 1; },
         XR_ERROR_SWAPCHAIN_RECT_INVALID},
        {"negative offset", [](auto& d) { d.subImage.imageRect.offset.y = -1; },
         XR_ERROR_SWAPCHAIN_RECT_INVALID},
        {"negative width", [](auto& d) { d.subImage.imageRect.extent.width = -4; },
         XR_ERROR_SWAPCHAIN_RECT_INVALID},
        {"imageArrayIndex = arraySize", [](auto& d) { d.subImage.imageArrayIndex = 2; },
         XR_ERROR_VALIDATION_FAILURE},
        {"minDepth < 0", [](auto& d) { d.minDepth = -0.1f; }, XR_ERROR_VALIDATION_FAILURE},
        {"maxDepth > 1", [](auto& d) { d.maxDepth = 1.5f; }, XR_ERROR_VALIDATION_FAILURE},
        {"minDepth = maxDepth", [](auto& d) { d.minDepth = d.maxDepth = 0.5f; },
         XR_ERROR_VALIDATION_FAILURE},
        {"minDepth > maxDepth",
         [](auto& d) {
             d.minDepth = 1.0f;
             d.maxDepth = 0.0f;
         },
         XR_ERROR_VALIDATION_FAILURE},
        {"minDepth NaN", [&](auto& d) { d.minDepth = nan; }, XR_ERROR_VALIDATION_FAILURE},
        {"nearZ = 0", [](auto& d) { d.nearZ = 0.0f; }, XR_ERROR_VALIDATION_FAILURE},
        {"farZ < 0", [](auto& d) { d.farZ = -1.0f; }, XR_ERROR_VALIDATION_FAILURE},
        {"nearZ = farZ", [](auto& d) { d.nearZ = d.farZ = 2.0f; }, XR_ERROR_VALIDATION_FAILURE},
        {"both infinite", [](auto& d) { d.nearZ = d.farZ = kInfinity; },
         XR_ERROR_VALIDATION_FAILURE},
        {"farZ NaN", [&](auto& d) { d.farZ = nan; }, XR_ERROR_VALIDATION_FAILURE},
    };
    const Mapping valid{0.0f, 1.0f, 1000.0f, 0.1f};
    const XrCompositionLayerDepthInfoKHR left = depth_info(depth.swapchain, 0, valid);
    for (const Case& c : cases) {
        XrCompositionLayerDepthInfoKHR right = depth_info(depth.swapchain, 1, valid);
        c.change(right);
        // A failed xrEndFrame leaves the frame begun, so the same frame is ended again.
        EXPECT_EQ(end_frame(time, colour.swapchain, &left, &right), c.expected) << c.what;
    }
    const XrCompositionLayerDepthInfoKHR right = depth_info(depth.swapchain, 1, valid);
    EXPECT_EQ(end_frame(time, colour.swapchain, &left, &right), XR_SUCCESS);
    for (const TestSwapchain* s : {&colour, &depth, &unreleased}) {
        EXPECT_EQ(xrDestroySwapchain(s->swapchain), XR_SUCCESS);
    }
}

TEST_F(DepthLayerTest, WithoutTheExtensionDepthIsIgnored) {
    // spec (fundamentals, next chains): the runtime ignores structures of extensions the
    // instance did not enable; the OpenXR validation layer would refuse the call instead.
    start_with_depth("dump_dir = \"dump\"\n", {.enable_depth = false, .xr_validation = false});
    const TestSwapchain colour = make_swapchain(session_, VK_FORMAT_R8G8B8A8_UNORM, 1);
    const TestSwapchain depth = make_swapchain(session_, VK_FORMAT_D32_SFLOAT, 1);
    const XrTime time = begin_frame();
    render(colour, depth);
    // Malformed on purpose: checked, it would be XR_ERROR_VALIDATION_FAILURE.
    XrCompositionLayerDepthInfoKHR bad = depth_info(depth.swapchain, 0, {1.0f, 0.0f, 0.0f, 0.0f});
    EXPECT_EQ(end_frame(time, colour.swapchain, &bad, &bad), XR_SUCCESS);
    const std::filesystem::path dump = dir_ / "dump";
    bool any_colour = false;
    for (const auto& entry : std::filesystem::directory_iterator(dump)) {
        const std::string name = entry.path().filename().string();
        EXPECT_EQ(name.find("_depth"), std::string::npos) << name;
        any_colour = any_colour || name.ends_with("_left.png");
    }
    EXPECT_TRUE(any_colour);
    EXPECT_EQ(xrDestroySwapchain(colour.swapchain), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(depth.swapchain), XR_SUCCESS);
}

// Every texel a distinct distance; the rectangle's top-left texel holds minDepth (the near
// plane) and the image's bottom-right texel maxDepth (the far plane), so orientation, the
// rectangle's offset and planes at infinity are all visible in the file.
double distance_at(uint32_t x, uint32_t y) {
    return 0.5 + 0.25 * x + 0.125 * y;
}

constexpr XrOffset2Di kRectOffset{8, 4};

std::vector<float> depth_image(const Mapping& m) {
    std::vector<float> depths(std::size_t{kWidth} * kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            depths[std::size_t{y} * kWidth + x] =
                static_cast<float>(window_depth(m, distance_at(x, y)));
        }
    }
    depths[std::size_t{kRectOffset.y} * kWidth + kRectOffset.x] = m.min_depth;
    depths.back() = m.max_depth;
    return depths;
}

TEST_F(DepthLayerTest, DumpsHoldEachEyesDistanceInMetres) {
    start_with_depth("dump_dir = \"dump\"\n");
    const TestSwapchain colour = make_swapchain(session_, VK_FORMAT_R8G8B8A8_UNORM, 1);
    const TestSwapchain depth = make_swapchain(session_, VK_FORMAT_D32_SFLOAT, 2);
    // Per frame: left eye (array layer 0), right eye (layer 1).
    const Mapping frames[][2] = {
        // Reversed-Z with an infinite far plane (window depth 0.1 / distance: the spec's nearZ
        // is the plane at minDepth, here infinity) and a standard mapping on a narrowed range.
        {{0.0f, 1.0f, kInfinity, 0.1f}, {0.25f, 0.75f, 0.5f, 20.0f}},
        // Standard with an infinite far plane (1 - 0.1 / distance); reversed finite, as
        // monoplane renders (0.1 m -> 1, 1000 m -> 0).
        {{0.0f, 1.0f, 0.1f, kInfinity}, {0.0f, 1.0f, 1000.0f, 0.1f}},
    };
    // Spot checks of window_depth itself, by hand (reversed infinite is 0.1 / s); 1e-8 allows
    // for 0.1f not being 0.1.
    EXPECT_NEAR(window_depth(frames[0][0], 2.0), 0.05, 1e-8);
    EXPECT_NEAR(window_depth(frames[1][0], 2.0), 0.95, 1e-8);
    EXPECT_NEAR(window_depth(frames[0][1], 0.5), 0.25, 1e-8);
    EXPECT_NEAR(window_depth(frames[0][1], 20.0), 0.75, 1e-8);

    std::vector<std::int64_t> frame_numbers;
    for (const auto& eyes : frames) {
        const XrTime time = begin_frame();
        render(colour, depth, {depth_image(eyes[0]), depth_image(eyes[1])});
        XrCompositionLayerDepthInfoKHR infos[2];
        for (uint32_t eye = 0; eye < 2; ++eye) {
            infos[eye] = depth_info(depth.swapchain, eye, eyes[eye]);
            infos[eye].subImage.imageRect = {kRectOffset,
                                             {static_cast<int32_t>(kWidth) - kRectOffset.x,
                                              static_cast<int32_t>(kHeight) - kRectOffset.y}};
        }
        ASSERT_EQ(end_frame(time, colour.swapchain, &infos[0], &infos[1]), XR_SUCCESS);
    }
    // begin_and_focus ran the frames before these; their numbers are the dump's.
    const std::filesystem::path dump = dir_ / "dump";
    std::vector<std::filesystem::path> lefts;
    for (const auto& entry : std::filesystem::directory_iterator(dump)) {
        if (entry.path().filename().string().ends_with("_left_depth.pfm")) {
            lefts.push_back(entry.path());
        }
    }
    std::sort(lefts.begin(), lefts.end());
    ASSERT_EQ(lefts.size(), std::size(frames));
    for (std::size_t f = 0; f < lefts.size(); ++f) {
        std::string stem = lefts[f].filename().string();
        stem.resize(stem.size() - std::strlen("_left_depth.pfm"));
        EXPECT_TRUE(std::filesystem::exists(dump / (stem + "_left.png")));
        for (uint32_t eye = 0; eye < 2; ++eye) {
            const Mapping& m = frames[f][eye];
            const std::filesystem::path file =
                dump / (stem + (eye == 0 ? "_left_depth.pfm" : "_right_depth.pfm"));
            SCOPED_TRACE(file.filename().string());
            const FloatMap map = read_pfm(file);
            // One channel, the sub-image's size, little-endian (negative scale).
            EXPECT_EQ(map.header, "Pf\n40 28\n-1.0\n");
            ASSERT_EQ(map.rows_top_down.size(), std::size_t{40} * 28);
            // The planes: exactly nearZ at the rectangle's top-left, farZ at its bottom-right.
            EXPECT_EQ(map.at(0, 0), m.near_z);
            EXPECT_EQ(map.at(39, 27), m.far_z);
            for (uint32_t y = 0; y < map.height; ++y) {
                for (uint32_t x = 0; x < map.width; ++x) {
                    if ((x == 0 && y == 0) || (x == 39 && y == 27)) continue;
                    const double expected = distance_at(x + kRectOffset.x, y + kRectOffset.y);
                    // float window depths: relative error ~ ulp * ds/dd * d / s, < 1e-4 here.
                    ASSERT_NEAR(map.at(x, y), expected, 1e-4 * expected) << x << ", " << y;
                }
            }
        }
    }
    EXPECT_EQ(xrDestroySwapchain(colour.swapchain), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(depth.swapchain), XR_SUCCESS);
}

}  // namespace
}  // namespace monoplane::simxr::testing
