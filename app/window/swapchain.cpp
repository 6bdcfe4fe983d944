#include "app/window/swapchain.h"

#include <algorithm>
#include <limits>

namespace monoplane::window {

SwapchainConfig choose_swapchain_config(const vk::raii::PhysicalDevice& physical_device,
                                        vk::SurfaceKHR surface) {
    SwapchainConfig config;
    const auto formats = physical_device.getSurfaceFormatsKHR(surface);
    config.format = formats.front();
    for (const vk::Format wanted : {vk::Format::eB8G8R8A8Unorm, vk::Format::eR8G8B8A8Unorm}) {
        const auto found = std::find_if(formats.begin(), formats.end(), [&](const auto& f) {
            return f.format == wanted && f.colorSpace == vk::ColorSpaceKHR::eSrgbNonlinear;
        });
        if (found != formats.end()) {
            config.format = *found;
            break;
        }
    }
    const auto modes = physical_device.getSurfacePresentModesKHR(surface);
    for (const vk::PresentModeKHR wanted :
         {vk::PresentModeKHR::eMailbox, vk::PresentModeKHR::eImmediate}) {
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) {
            config.present_mode = wanted;
            break;
        }
    }
    const auto caps = physical_device.getSurfaceCapabilitiesKHR(surface);
    config.transfer_src =
        static_cast<bool>(caps.supportedUsageFlags & vk::ImageUsageFlagBits::eTransferSrc);
    return config;
}

vk::raii::RenderPass make_ui_render_pass(const vk::raii::Device& device, vk::Format format,
                                         vk::ImageLayout final_layout) {
    const vk::AttachmentDescription attachment(
        {}, format, vk::SampleCountFlagBits::e1, vk::AttachmentLoadOp::eClear,
        vk::AttachmentStoreOp::eStore, vk::AttachmentLoadOp::eDontCare,
        vk::AttachmentStoreOp::eDontCare, vk::ImageLayout::eUndefined, final_layout);
    const vk::AttachmentReference color(0, vk::ImageLayout::eColorAttachmentOptimal);
    const vk::SubpassDescription subpass({}, vk::PipelineBindPoint::eGraphics, {}, color);
    using Stage = vk::PipelineStageFlagBits;
    using Access = vk::AccessFlagBits;
    const std::array dependencies{
        // The acquire semaphore is waited for at colour output; the clear must come after it.
        vk::SubpassDependency(VK_SUBPASS_EXTERNAL, 0, Stage::eColorAttachmentOutput,
                              Stage::eColorAttachmentOutput, {}, Access::eColorAttachmentWrite),
        // A screenshot copies the image right after the pass.
        vk::SubpassDependency(0, VK_SUBPASS_EXTERNAL, Stage::eColorAttachmentOutput,
                              Stage::eTransfer, Access::eColorAttachmentWrite,
                              Access::eTransferRead),
    };
    return vk::raii::RenderPass(device,
                                vk::RenderPassCreateInfo({}, attachment, subpass, dependencies));
}

vk::Extent2D swapchain_extent(const vk::SurfaceCapabilitiesKHR& caps, int framebuffer_width,
                              int framebuffer_height) {
    if (caps.currentExtent.width != std::numeric_limits<std::uint32_t>::max()) {
        return caps.currentExtent;
    }
    const auto clamp = [](int size, std::uint32_t lo, std::uint32_t hi) {
        return std::clamp(static_cast<std::uint32_t>(std::max(size, 0)), lo, hi);
    };
    if (framebuffer_width <= 0 || framebuffer_height <= 0) return vk::Extent2D(0, 0);
    return vk::Extent2D(
        clamp(framebuffer_width, caps.minImageExtent.width, caps.maxImageExtent.width),
        clamp(framebuffer_height, caps.minImageExtent.height, caps.maxImageExtent.height));
}

Swapchain::Swapchain(const vk_core::Context& ctx, vk::SurfaceKHR surface,
                     const SwapchainConfig& config, vk::RenderPass pass, vk::Extent2D extent,
                     vk::SwapchainKHR old)
    : extent_(extent) {
    const auto caps = ctx.physical_device().getSurfaceCapabilitiesKHR(surface);
    std::uint32_t image_count = caps.minImageCount + 1;
    if (caps.maxImageCount != 0) image_count = std::min(image_count, caps.maxImageCount);
    vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eColorAttachment;
    if (config.transfer_src) usage |= vk::ImageUsageFlagBits::eTransferSrc;
    // Opaque where offered; otherwise the lowest mode the surface supports (one always is).
    const auto alpha_bits = static_cast<VkCompositeAlphaFlagsKHR>(caps.supportedCompositeAlpha);
    const auto alpha =
        (caps.supportedCompositeAlpha & vk::CompositeAlphaFlagBitsKHR::eOpaque)
            ? vk::CompositeAlphaFlagBitsKHR::eOpaque
            : static_cast<vk::CompositeAlphaFlagBitsKHR>(alpha_bits & (~alpha_bits + 1u));
    const vk::SwapchainCreateInfoKHR info({}, surface, image_count, config.format.format,
                                          config.format.colorSpace, extent, 1, usage,
                                          vk::SharingMode::eExclusive, {}, caps.currentTransform,
                                          alpha, config.present_mode, VK_TRUE, old);
    swapchain_ = vk::raii::SwapchainKHR(ctx.device(), info);
    images_ = swapchain_.getImages();
    for (const vk::Image image : images_) {
        views_.emplace_back(
            ctx.device(),
            vk::ImageViewCreateInfo(
                {}, image, vk::ImageViewType::e2D, config.format.format, {},
                vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1)));
        framebuffers_.emplace_back(
            ctx.device(),
            vk::FramebufferCreateInfo({}, pass, *views_.back(), extent.width, extent.height, 1));
        render_finished_.emplace_back(ctx.device(), vk::SemaphoreCreateInfo());
    }
}

}  // namespace monoplane::window
