// The eyes' swapchains of an OpenXR session: their size (the runtime's recommended one, scaled),
// their colour and depth formats, and each frame's acquired image.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "app/headset/eye_depth_writer.h"
#include "app/headset/openxr_headset_impl.h"

namespace monoplane::headset {
namespace {

// The formats the eyes can be copied into without changing their sRGB encoding (the renderer's
// display images are R8G8B8A8_SRGB); a blit converts the channel order where needed.
constexpr std::array kSwapchainFormats = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB};

}  // namespace

Result<void> OpenXrHeadset::Impl::create_swapchain(Swapchain& swapchain,
                                                   XrSwapchainUsageFlags usage, std::int64_t format,
                                                   vk::Extent2D extent) {
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.usageFlags = usage;
    info.format = format;
    info.sampleCount = 1;
    info.width = extent.width;
    info.height = extent.height;
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    MONOPLANE_TRY(check("xrCreateSwapchain", xrCreateSwapchain(session, &info, &swapchain.handle)));
    std::uint32_t count = 0;
    MONOPLANE_TRY(check("xrEnumerateSwapchainImages",
                        xrEnumerateSwapchainImages(swapchain.handle, 0, &count, nullptr)));
    swapchain.images.assign(count, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
    return check("xrEnumerateSwapchainImages",
                 xrEnumerateSwapchainImages(
                     swapchain.handle, count, &count,
                     reinterpret_cast<XrSwapchainImageBaseHeader*>(swapchain.images.data())));
}

Result<std::array<XrViewConfigurationView, 2>> OpenXrHeadset::Impl::view_configuration() const {
    std::uint32_t count = 0;
    MONOPLANE_TRY(check(
        "xrEnumerateViewConfigurationViews",
        xrEnumerateViewConfigurationViews(
            instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &count, nullptr)));
    if (count != 2) return Error{"the headset does not have two views"};
    std::array<XrViewConfigurationView, 2> config{};
    for (auto& c : config) c.type = XR_TYPE_VIEW_CONFIGURATION_VIEW;
    MONOPLANE_TRY(check("xrEnumerateViewConfigurationViews",
                        xrEnumerateViewConfigurationViews(instance, system,
                                                          XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO,
                                                          2, &count, config.data())));
    return config;
}

Result<vk::Extent2D> OpenXrHeadset::recommended_eye_extent() const {
    Result<std::array<XrViewConfigurationView, 2>> views = impl_->view_configuration();
    MONOPLANE_TRY(views);
    return vk::Extent2D((*views)[0].recommendedImageRectWidth,
                        (*views)[0].recommendedImageRectHeight);
}

Result<void> OpenXrHeadset::Impl::create_swapchains(const vk_core::Context& ctx, double scale,
                                                    vk::Extent2D& extent, vk::Format& format,
                                                    vk::Format& depth_format) {
    Result<std::array<XrViewConfigurationView, 2>> views = view_configuration();
    MONOPLANE_TRY(views);
    const std::array<XrViewConfigurationView, 2>& config = *views;
    const auto scaled = [scale](std::uint32_t size, std::uint32_t max) {
        const auto s = static_cast<std::uint32_t>(std::lround(size * scale));
        return std::clamp<std::uint32_t>(s, 16, max);
    };
    extent =
        vk::Extent2D(scaled(config[0].recommendedImageRectWidth, config[0].maxImageRectWidth),
                     scaled(config[0].recommendedImageRectHeight, config[0].maxImageRectHeight));

    std::uint32_t count = 0;
    MONOPLANE_TRY(check("xrEnumerateSwapchainFormats",
                        xrEnumerateSwapchainFormats(session, 0, &count, nullptr)));
    std::vector<std::int64_t> formats(count);
    xrEnumerateSwapchainFormats(session, count, &count, formats.data());
    std::int64_t chosen = 0;
    for (VkFormat wanted : kSwapchainFormats) {
        if (std::find(formats.begin(), formats.end(), wanted) != formats.end()) {
            chosen = wanted;
            break;
        }
    }
    if (chosen == 0) return Error{"the OpenXR runtime offers no 8-bit sRGB swapchain format"};
    format = static_cast<vk::Format>(chosen);
    static_cast<void>(ctx);

    for (Swapchain& swapchain : swapchains) {
        // Transfer usage: the eyes are blitted in, the mirror is blitted out.
        MONOPLANE_TRY(create_swapchain(swapchain,
                                       XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT |
                                           XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT |
                                           XR_SWAPCHAIN_USAGE_TRANSFER_SRC_BIT,
                                       chosen, extent));
    }

    // The eyes' depth, the same size as their colour (XR_KHR_composition_layer_depth pairs a
    // view's depth sub-image with its colour one). The runtime lists colour and depth formats
    // together; the first of eye_depth_formats() it offers is taken.
    depth_format = vk::Format::eUndefined;
    if (!depth_extension) return Ok{};
    for (vk::Format wanted : eye_depth_formats()) {
        if (std::find(formats.begin(), formats.end(), static_cast<std::int64_t>(wanted)) !=
            formats.end()) {
            depth_format = wanted;
            break;
        }
    }
    if (depth_format == vk::Format::eUndefined) {
        std::cerr << "note: the OpenXR runtime offers no depth swapchain format monoplane writes; "
                     "the eyes' depth is not submitted\n";
        return Ok{};
    }
    for (Swapchain& swapchain : depth_swapchains) {
        // Drawn as an attachment (eye_depth_writer.h) and nothing else.
        MONOPLANE_TRY(create_swapchain(swapchain, XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                       static_cast<std::int64_t>(depth_format), extent));
    }
    return Ok{};
}

Result<vk::Image> OpenXrHeadset::Impl::acquire(Swapchain& swapchain) {
    std::uint32_t index = 0;
    XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    MONOPLANE_TRY(check("xrAcquireSwapchainImage",
                        xrAcquireSwapchainImage(swapchain.handle, &acquire, &index)));
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    MONOPLANE_TRY(check("xrWaitSwapchainImage", xrWaitSwapchainImage(swapchain.handle, &wait)));
    swapchain.acquired = true;
    return vk::Image(swapchain.images[index].image);
}

Result<vk::Image> OpenXrHeadset::acquire_eye_image(int eye) {
    return impl_->acquire(impl_->swapchains[static_cast<std::size_t>(eye)]);
}

Result<vk::Image> OpenXrHeadset::acquire_eye_depth_image(int eye) {
    Impl::Swapchain& swapchain = impl_->depth_swapchains[static_cast<std::size_t>(eye)];
    if (swapchain.handle == XR_NULL_HANDLE) return Error{"no depth swapchains in this session"};
    return impl_->acquire(swapchain);
}

}  // namespace monoplane::headset
