#include "app/headset/simxr/frame_dump.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include <stb_image_write.h>

namespace monoplane::simxr {
namespace {

// A host-visible buffer on the application's device, freed on scope exit.
struct HostBuffer {
    const VulkanDevice& vk;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;

    HostBuffer(const VulkanDevice& device, VkDeviceSize size) : vk(device) {
        auto info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
        info.size = size;
        info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        if (vk.vkCreateBuffer(vk.device(), &info, nullptr, &buffer) != VK_SUCCESS) return;
        VkMemoryRequirements requirements{};
        vk.vkGetBufferMemoryRequirements(vk.device(), buffer, &requirements);
        auto allocate = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex =
            vk.memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                            VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        if (allocate.memoryTypeIndex == UINT32_MAX ||
            vk.vkAllocateMemory(vk.device(), &allocate, nullptr, &memory) != VK_SUCCESS ||
            vk.vkBindBufferMemory(vk.device(), buffer, memory, 0) != VK_SUCCESS) {
            release();
        }
    }
    ~HostBuffer() { release(); }
    HostBuffer(const HostBuffer&) = delete;
    HostBuffer& operator=(const HostBuffer&) = delete;

    bool ok() const { return buffer != VK_NULL_HANDLE && memory != VK_NULL_HANDLE; }
    void release() {
        if (buffer != VK_NULL_HANDLE) vk.vkDestroyBuffer(vk.device(), buffer, nullptr);
        if (memory != VK_NULL_HANDLE) vk.vkFreeMemory(vk.device(), memory, nullptr);
        buffer = VK_NULL_HANDLE;
        memory = VK_NULL_HANDLE;
    }
};

VkImageMemoryBarrier layout_change(VkImage image, uint32_t layer, VkImageLayout from,
                                   VkImageLayout to, VkAccessFlags src, VkAccessFlags dst) {
    auto barrier = vk_struct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.srcAccessMask = src;
    barrier.dstAccessMask = dst;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, layer, 1};
    return barrier;
}

void record_copy(const VulkanDevice& vk, VkCommandBuffer commands, VkImage image,
                 const XrSwapchainSubImage& sub_image, VkBuffer buffer) {
    const uint32_t layer = sub_image.imageArrayIndex;
    const VkImageMemoryBarrier to_source =
        layout_change(image, layer, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_ACCESS_TRANSFER_READ_BIT);
    vk.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                            &to_source);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
    region.imageOffset = {sub_image.imageRect.offset.x, sub_image.imageRect.offset.y, 0};
    region.imageExtent = {static_cast<uint32_t>(sub_image.imageRect.extent.width),
                          static_cast<uint32_t>(sub_image.imageRect.extent.height), 1};
    vk.vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1,
                              &region);
    // Back to the layout the application expects on its next acquire.
    const VkImageMemoryBarrier back =
        layout_change(image, layer, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0,
                      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    auto to_host = vk_struct<VkBufferMemoryBarrier>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER);
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    to_host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.buffer = buffer;
    to_host.size = VK_WHOLE_SIZE;
    vk.vkCmdPipelineBarrier(
        commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr,
        1, &to_host, 1, &back);
}

}  // namespace

bool dump_sub_image(Session& session, const XrSwapchainSubImage& sub_image,
                    const std::filesystem::path& file) {
    const Swapchain* swapchain = lookup<Swapchain>(sub_image.swapchain);
    if (swapchain == nullptr || swapchain->depth || !swapchain->last_released) return true;
    const VulkanDevice& vk = session.vulkan;
    const auto width = static_cast<uint32_t>(sub_image.imageRect.extent.width);
    const auto height = static_cast<uint32_t>(sub_image.imageRect.extent.height);
    const VkDeviceSize size = VkDeviceSize{width} * height * 4;
    HostBuffer host(vk, size);
    const VkImage image = swapchain->images[*swapchain->last_released];
    if (!host.ok() || !vk.submit_and_wait([&](VkCommandBuffer commands) {
            record_copy(vk, commands, image, sub_image, host.buffer);
        })) {
        std::fprintf(stderr, "simxr: could not copy a swapchain image for %s\n",
                     file.string().c_str());
        return false;
    }
    std::vector<unsigned char> pixels(size);
    void* mapped = nullptr;
    if (vk.vkMapMemory(vk.device(), host.memory, 0, size, 0, &mapped) != VK_SUCCESS) return false;
    std::memcpy(pixels.data(), mapped, size);
    vk.vkUnmapMemory(vk.device(), host.memory);
    if (swapchain->format == VK_FORMAT_B8G8R8A8_SRGB) {
        for (std::size_t i = 0; i < pixels.size(); i += 4) std::swap(pixels[i], pixels[i + 2]);
    }
    if (stbi_write_png(file.c_str(), static_cast<int>(width), static_cast<int>(height), 4,
                       pixels.data(), static_cast<int>(width * 4)) == 0) {
        std::fprintf(stderr, "simxr: could not write %s (dump_dir in %s)\n", file.string().c_str(),
                     session.instance->script.source.c_str());
        return false;
    }
    return true;
}

}  // namespace monoplane::simxr
