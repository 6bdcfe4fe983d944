// Swapchains as VkImages on the application's device (XR_KHR_vulkan_enable2). spec (Vulkan
// swapchain images): an acquired and waited color image is in COLOR_ATTACHMENT_OPTIMAL (depth:
// DEPTH_STENCIL_ATTACHMENT_OPTIMAL) and the application releases it in that layout, so simxr
// puts every image in that layout once, at creation.
#include <algorithm>
#include <array>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

// In order of preference (spec: xrEnumerateSwapchainFormats lists the runtime's preferred first).
constexpr std::array<VkFormat, 4> kFormats = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB,
                                              VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT};
constexpr uint32_t kImageCount = 3;
constexpr uint32_t kMaxSize = 16384;

// spec (XrSwapchainCreateFlagBits): a static swapchain is acquired and released only once, so
// one image is all it needs.
bool is_static(const XrSwapchainCreateInfo& info) {
    return (info.createFlags & XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT) != 0;
}

bool is_depth(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT;
}

VkImageUsageFlags vulkan_usage(XrSwapchainUsageFlags usage, bool depth) {
    // Layout transitions to the attachment layouts need the matching attachment usage, and the
    // frame dump copies from the image.
    VkImageUsageFlags flags =
        VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
        (depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
    if (usage & XR_SWAPCHAIN_USAGE_UNORDERED_ACCESS_BIT) flags |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (usage & XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT) flags |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (usage & XR_SWAPCHAIN_USAGE_SAMPLED_BIT) flags |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (usage & XR_SWAPCHAIN_USAGE_INPUT_ATTACHMENT_BIT_KHR) {
        flags |= VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;
    }
    return flags;
}

VkImageLayout attachment_layout(bool depth) {
    return depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                 : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
}

XrResult create_images(Swapchain& swapchain, VkImageUsageFlags usage, VkImageCreateFlags flags) {
    const VulkanDevice& vk = swapchain.session->vulkan;
    auto image_info = vk_struct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    image_info.flags = flags;
    image_info.imageType = VK_IMAGE_TYPE_2D;
    image_info.format = swapchain.format;
    image_info.extent = {swapchain.info.width, swapchain.info.height, 1};
    image_info.mipLevels = swapchain.info.mipCount;
    image_info.arrayLayers = swapchain.info.arraySize;
    image_info.samples = VK_SAMPLE_COUNT_1_BIT;
    image_info.tiling = VK_IMAGE_TILING_OPTIMAL;
    image_info.usage = usage;
    image_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    image_info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    for (std::size_t i = 0; i < swapchain.states.size(); ++i) {
        VkImage image = VK_NULL_HANDLE;
        if (vk.vkCreateImage(vk.device(), &image_info, nullptr, &image) != VK_SUCCESS) {
            return XR_ERROR_RUNTIME_FAILURE;
        }
        swapchain.images.push_back(image);
        VkMemoryRequirements requirements{};
        vk.vkGetImageMemoryRequirements(vk.device(), image, &requirements);
        auto allocate = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex =
            vk.memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        if (allocate.memoryTypeIndex == UINT32_MAX) {
            allocate.memoryTypeIndex = vk.memory_type(requirements.memoryTypeBits, 0);
        }
        VkDeviceMemory memory = VK_NULL_HANDLE;
        if (vk.vkAllocateMemory(vk.device(), &allocate, nullptr, &memory) != VK_SUCCESS) {
            return XR_ERROR_RUNTIME_FAILURE;
        }
        swapchain.memory.push_back(memory);
        if (vk.vkBindImageMemory(vk.device(), image, memory, 0) != VK_SUCCESS) {
            return XR_ERROR_RUNTIME_FAILURE;
        }
    }
    const bool moved = vk.submit_and_wait([&](VkCommandBuffer commands) {
        for (VkImage image : swapchain.images) {
            auto barrier = vk_struct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
            barrier.srcAccessMask = 0;
            barrier.dstAccessMask = swapchain.depth ? VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT
                                                    : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
            barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            barrier.newLayout = attachment_layout(swapchain.depth);
            barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = image;
            barrier.subresourceRange = {
                swapchain.depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT, 0,
                VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
            const VkPipelineStageFlags dst_stage =
                swapchain.depth ? VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                      VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT
                                : VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
            vk.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, dst_stage, 0, 0,
                                    nullptr, 0, nullptr, 1, &barrier);
        }
    });
    return moved ? XR_SUCCESS : XR_ERROR_RUNTIME_FAILURE;
}

}  // namespace

void destroy_swapchain(Swapchain* swapchain) {
    const VulkanDevice& vk = swapchain->session->vulkan;
    for (VkImage image : swapchain->images) vk.vkDestroyImage(vk.device(), image, nullptr);
    for (VkDeviceMemory memory : swapchain->memory) vk.vkFreeMemory(vk.device(), memory, nullptr);
    std::erase(swapchain->session->swapchains, swapchain);
    unregister_object(swapchain);
}

XrResult XRAPI_CALL xrEnumerateSwapchainFormats(XrSession handle, uint32_t capacity,
                                                uint32_t* count, int64_t* formats) {
    std::lock_guard lock(runtime_mutex());
    if (lookup<Session>(handle) == nullptr) return XR_ERROR_HANDLE_INVALID;
    return fill_array<int64_t>(capacity, count, formats,
                               std::vector<int64_t>(kFormats.begin(), kFormats.end()));
}

XrResult XRAPI_CALL xrCreateSwapchain(XrSession handle, const XrSwapchainCreateInfo* info,
                                      XrSwapchain* swapchain_handle) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SWAPCHAIN_CREATE_INFO) || swapchain_handle == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->createFlags & XR_SWAPCHAIN_CREATE_PROTECTED_CONTENT_BIT) {
        return XR_ERROR_FEATURE_UNSUPPORTED;
    }
    const auto format = static_cast<VkFormat>(info->format);
    if (std::find(kFormats.begin(), kFormats.end(), format) == kFormats.end()) {
        return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    }
    if (info->width == 0 || info->height == 0 || info->width > kMaxSize ||
        info->height > kMaxSize || info->arraySize == 0 || info->mipCount == 0) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->sampleCount != 1 || info->faceCount != 1) return XR_ERROR_FEATURE_UNSUPPORTED;

    const bool depth = is_depth(format);
    const VkImageUsageFlags usage = vulkan_usage(info->usageFlags, depth);
    const VkImageCreateFlags flags = (info->usageFlags & XR_SWAPCHAIN_USAGE_MUTABLE_FORMAT_BIT)
                                         ? VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT
                                         : 0;
    VkImageFormatProperties limits{};
    const VulkanDevice& vk = session->vulkan;
    if (vk.vkGetPhysicalDeviceImageFormatProperties(vk.binding().physical_device, format,
                                                    VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
                                                    usage, flags, &limits) != VK_SUCCESS ||
        info->width > limits.maxExtent.width || info->height > limits.maxExtent.height ||
        info->arraySize > limits.maxArrayLayers || info->mipCount > limits.maxMipLevels) {
        return XR_ERROR_FEATURE_UNSUPPORTED;
    }

    auto swapchain = std::make_unique<Swapchain>();
    swapchain->session = session;
    swapchain->info = *info;
    swapchain->info.next = nullptr;
    swapchain->format = format;
    swapchain->depth = depth;
    swapchain->states.assign(is_static(*info) ? 1 : kImageCount, Swapchain::ImageState::available);
    Swapchain* raw = swapchain.get();
    session->swapchains.push_back(raw);
    *swapchain_handle = register_object<XrSwapchain>(std::move(swapchain));
    if (XrResult result = create_images(*raw, usage, flags); result != XR_SUCCESS) {
        destroy_swapchain(raw);
        *swapchain_handle = XR_NULL_HANDLE;
        return result;
    }
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrDestroySwapchain(XrSwapchain handle) {
    std::lock_guard lock(runtime_mutex());
    Swapchain* swapchain = lookup<Swapchain>(handle);
    if (swapchain == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_swapchain(swapchain);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrEnumerateSwapchainImages(XrSwapchain handle, uint32_t capacity,
                                               uint32_t* count,
                                               XrSwapchainImageBaseHeader* images) {
    std::lock_guard lock(runtime_mutex());
    const Swapchain* swapchain = lookup<Swapchain>(handle);
    if (swapchain == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *count = static_cast<uint32_t>(swapchain->images.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < swapchain->images.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    auto* vulkan_images = reinterpret_cast<XrSwapchainImageVulkan2KHR*>(images);
    if (vulkan_images == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::size_t i = 0; i < swapchain->images.size(); ++i) {
        if (vulkan_images[i].type != XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR) {
            return XR_ERROR_VALIDATION_FAILURE;
        }
        vulkan_images[i].image = swapchain->images[i];
    }
    return XR_SUCCESS;
}

// spec (xrAcquireSwapchainImage): images are acquired in a fixed order; with none available, or
// for a static swapchain acquired before, the call is XR_ERROR_CALL_ORDER_INVALID.
XrResult XRAPI_CALL xrAcquireSwapchainImage(XrSwapchain handle,
                                            const XrSwapchainImageAcquireInfo* info,
                                            uint32_t* index) {
    std::lock_guard lock(runtime_mutex());
    Swapchain* swapchain = lookup<Swapchain>(handle);
    if (swapchain == nullptr) return XR_ERROR_HANDLE_INVALID;
    if ((info != nullptr && info->type != XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO) ||
        index == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const uint32_t next = swapchain->next_to_acquire;
    if (swapchain->states[next] != Swapchain::ImageState::available ||
        (is_static(swapchain->info) && swapchain->acquired_once)) {
        return XR_ERROR_CALL_ORDER_INVALID;
    }
    swapchain->acquired_once = true;
    swapchain->states[next] = Swapchain::ImageState::acquired;
    swapchain->in_flight.push_back(next);
    swapchain->next_to_acquire = (next + 1) % static_cast<uint32_t>(swapchain->images.size());
    *index = next;
    return XR_SUCCESS;
}

// spec (xrWaitSwapchainImage): waits on the oldest acquired image; with none acquired, or with
// one already waited and not yet released, the call is XR_ERROR_CALL_ORDER_INVALID.
XrResult XRAPI_CALL xrWaitSwapchainImage(XrSwapchain handle, const XrSwapchainImageWaitInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Swapchain* swapchain = lookup<Swapchain>(handle);
    if (swapchain == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (swapchain->in_flight.empty() ||
        swapchain->states[swapchain->in_flight.front()] != Swapchain::ImageState::acquired) {
        return XR_ERROR_CALL_ORDER_INVALID;
    }
    // simxr's images are ready at once: nothing reads them but the frame dump, which waits.
    swapchain->states[swapchain->in_flight.front()] = Swapchain::ImageState::waited;
    return XR_SUCCESS;
}

// spec (xrReleaseSwapchainImage): releases the oldest waited image; with none waited the call
// is XR_ERROR_CALL_ORDER_INVALID.
XrResult XRAPI_CALL xrReleaseSwapchainImage(XrSwapchain handle,
                                            const XrSwapchainImageReleaseInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Swapchain* swapchain = lookup<Swapchain>(handle);
    if (swapchain == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info != nullptr && info->type != XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (swapchain->in_flight.empty() ||
        swapchain->states[swapchain->in_flight.front()] != Swapchain::ImageState::waited) {
        return XR_ERROR_CALL_ORDER_INVALID;
    }
    const uint32_t index = swapchain->in_flight.front();
    swapchain->in_flight.pop_front();
    swapchain->states[index] = Swapchain::ImageState::available;
    swapchain->last_released = index;
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
