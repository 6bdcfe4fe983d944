#include "simxr/frame_dump.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
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

// How a kind of swapchain image is copied: its aspect, the layout the application releases it in
// (XR_KHR_vulkan_enable2: the attachment layout), and the stages and accesses of that use, which
// the copy waits for and the application's next use waits on.
struct Attachment {
    VkImageAspectFlags aspect;
    VkImageLayout layout;
    VkPipelineStageFlags stages;
    VkAccessFlags writes;
    VkAccessFlags accesses;
};

constexpr Attachment kColour{
    VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
constexpr Attachment kDepth{
    VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};

VkImageMemoryBarrier layout_change(VkImage image, VkImageAspectFlags aspect, uint32_t layer,
                                   VkImageLayout from, VkImageLayout to, VkAccessFlags src,
                                   VkAccessFlags dst) {
    auto barrier = vk_struct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.srcAccessMask = src;
    barrier.dstAccessMask = dst;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, 0, 1, layer, 1};
    return barrier;
}

void record_copy(const VulkanDevice& vk, VkCommandBuffer commands, VkImage image,
                 const Attachment& attachment, const XrSwapchainSubImage& sub_image,
                 VkBuffer buffer) {
    const uint32_t layer = sub_image.imageArrayIndex;
    const VkImageMemoryBarrier to_source = layout_change(
        image, attachment.aspect, layer, attachment.layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
        attachment.writes, VK_ACCESS_TRANSFER_READ_BIT);
    vk.vkCmdPipelineBarrier(commands, attachment.stages, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                            nullptr, 0, nullptr, 1, &to_source);
    VkBufferImageCopy region{};
    region.imageSubresource = {attachment.aspect, 0, layer, 1};
    region.imageOffset = {sub_image.imageRect.offset.x, sub_image.imageRect.offset.y, 0};
    region.imageExtent = {static_cast<uint32_t>(sub_image.imageRect.extent.width),
                          static_cast<uint32_t>(sub_image.imageRect.extent.height), 1};
    vk.vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1,
                              &region);
    // Back to the layout the application expects on its next acquire.
    const VkImageMemoryBarrier back =
        layout_change(image, attachment.aspect, layer, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      attachment.layout, 0, attachment.accesses);
    auto to_host = vk_struct<VkBufferMemoryBarrier>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER);
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    to_host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.buffer = buffer;
    to_host.size = VK_WHOLE_SIZE;
    vk.vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                            attachment.stages | VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                            &to_host, 1, &back);
}

// The sub-image's rectangle of the swapchain's last released image, texel_size bytes a texel,
// rows top to bottom; empty (with a message on stderr) if the copy fails.
std::vector<unsigned char> read_sub_image(Session& session, const Swapchain& swapchain,
                                          const Attachment& attachment,
                                          const XrSwapchainSubImage& sub_image, uint32_t texel_size,
                                          const std::filesystem::path& file) {
    const VulkanDevice& vk = session.vulkan;
    const auto width = static_cast<uint32_t>(sub_image.imageRect.extent.width);
    const auto height = static_cast<uint32_t>(sub_image.imageRect.extent.height);
    const VkDeviceSize size = VkDeviceSize{width} * height * texel_size;
    HostBuffer host(vk, size);
    const VkImage image = swapchain.images[*swapchain.last_released];
    void* mapped = nullptr;
    if (!host.ok() || !vk.submit_and_wait([&](VkCommandBuffer commands) {
            record_copy(vk, commands, image, attachment, sub_image, host.buffer);
        }) ||
        vk.vkMapMemory(vk.device(), host.memory, 0, size, 0, &mapped) != VK_SUCCESS) {
        std::fprintf(stderr, "simxr: could not copy a swapchain image for %s\n",
                     file.string().c_str());
        return {};
    }
    std::vector<unsigned char> texels(size);
    std::memcpy(texels.data(), mapped, size);
    vk.vkUnmapMemory(vk.device(), host.memory);
    return texels;
}

// XR_KHR_composition_layer_depth (revision 6) maps view-space depth to window depth with the
// homogeneous transform T = [b-a a; 0 1] [-f/(f-n) -fn/(f-n); -1 0] applied to (z, 1), where
// a = minDepth, b = maxDepth, n = nearZ, f = farZ. Solved for the distance s = -z in front of
// the eye, with t = (d - a) / (b - a): 1/s = (1 - t)/n + t/f. Inverse distance is linear in t,
// which covers reversed depth (n > f) and an infinite plane (1/inf = 0) with no special case.
// Window depths outside [a, b] are clamped to it: the mapping only promises that range.
double view_distance(float window_depth, const XrCompositionLayerDepthInfoKHR& depth) {
    const double t = (static_cast<double>(window_depth) - depth.minDepth) /
                     (static_cast<double>(depth.maxDepth) - depth.minDepth);
    if (std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
    const double clamped = std::clamp(t, 0.0, 1.0);
    const double inverse = (1.0 - clamped) / static_cast<double>(depth.nearZ) +
                           clamped / static_cast<double>(depth.farZ);
    return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
}

// PFM (portable float map): "Pf" (one channel), width and height, then the scale, whose negative
// sign says little-endian; float32 rows follow from the bottom row up.
bool write_pfm(const std::filesystem::path& file, uint32_t width, uint32_t height,
               const std::vector<float>& rows_top_down) {
    std::ofstream out(file, std::ios::binary);
    out << "Pf\n"
        << width << ' ' << height << '\n'
        << (std::endian::native == std::endian::little ? "-1.0" : "1.0") << '\n';
    for (uint32_t row = height; row-- > 0;) {
        out.write(reinterpret_cast<const char*>(rows_top_down.data() + std::size_t{row} * width),
                  static_cast<std::streamsize>(std::size_t{width} * sizeof(float)));
    }
    out.close();
    return !out.fail();
}

void report_write_failure(const Session& session, const std::filesystem::path& file) {
    std::fprintf(stderr, "simxr: could not write %s (dump_dir in %s)\n", file.string().c_str(),
                 session.instance->script.source.c_str());
}

}  // namespace

bool dump_sub_image(Session& session, const XrSwapchainSubImage& sub_image,
                    const std::filesystem::path& file) {
    const Swapchain* swapchain = lookup<Swapchain>(sub_image.swapchain);
    if (swapchain == nullptr || swapchain->depth || !swapchain->last_released) return true;
    std::vector<unsigned char> pixels =
        read_sub_image(session, *swapchain, kColour, sub_image, 4, file);
    if (pixels.empty()) return false;
    if (swapchain->format == VK_FORMAT_B8G8R8A8_SRGB) {
        for (std::size_t i = 0; i < pixels.size(); i += 4) std::swap(pixels[i], pixels[i + 2]);
    }
    const int width = sub_image.imageRect.extent.width;
    if (stbi_write_png(file.c_str(), width, sub_image.imageRect.extent.height, 4, pixels.data(),
                       width * 4) == 0) {
        report_write_failure(session, file);
        return false;
    }
    return true;
}

bool dump_depth_sub_image(Session& session, const XrCompositionLayerDepthInfoKHR& depth,
                          const std::filesystem::path& file) {
    const Swapchain* swapchain = lookup<Swapchain>(depth.subImage.swapchain);
    if (swapchain == nullptr || !swapchain->depth || !swapchain->last_released) return true;
    // D32_SFLOAT, simxr's only depth format: the depth aspect copies as one float a texel.
    const std::vector<unsigned char> texels =
        read_sub_image(session, *swapchain, kDepth, depth.subImage, sizeof(float), file);
    if (texels.empty()) return false;
    std::vector<float> distances(texels.size() / sizeof(float));
    for (std::size_t i = 0; i < distances.size(); ++i) {
        float window_depth = 0.0f;
        std::memcpy(&window_depth, texels.data() + i * sizeof(float), sizeof(float));
        distances[i] = static_cast<float>(view_distance(window_depth, depth));
    }
    if (!write_pfm(file, static_cast<uint32_t>(depth.subImage.imageRect.extent.width),
                   static_cast<uint32_t>(depth.subImage.imageRect.extent.height), distances)) {
        report_write_failure(session, file);
        return false;
    }
    return true;
}

}  // namespace monoplane::simxr
