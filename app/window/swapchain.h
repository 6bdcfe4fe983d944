// The window's swapchain: its images, their views and framebuffers for the UI render pass, and a
// "rendering finished" semaphore per image (a semaphore handed to a present may be reused only
// once that image is acquired again).
#pragma once

#include <vector>

#include "renderer/vk/context.h"

namespace monoplane::window {

struct SwapchainConfig {
    vk::SurfaceFormatKHR format;
    vk::PresentModeKHR present_mode = vk::PresentModeKHR::eFifo;
    bool transfer_src = false;  // images can be copied from (screenshots)
};

// Prefers an 8-bit UNORM format (Dear ImGui's colours are meant to be written as they are) and a
// present mode that never waits for the desktop's vertical blank, so that the window cannot slow
// down the headset's frame loop that drives it.
SwapchainConfig choose_swapchain_config(const vk::raii::PhysicalDevice& physical_device,
                                        vk::SurfaceKHR surface);

// The UI pass: clears the image and leaves it in `final_layout` (present, or transfer source for
// a screenshot). Passes that differ only in that are compatible, so one pipeline serves both.
vk::raii::RenderPass make_ui_render_pass(const vk::raii::Device& device, vk::Format format,
                                         vk::ImageLayout final_layout);

// The extent a new swapchain gets for a framebuffer of that size; zero when minimised.
vk::Extent2D swapchain_extent(const vk::SurfaceCapabilitiesKHR& caps, int framebuffer_width,
                              int framebuffer_height);

class Swapchain {
  public:
    Swapchain() = default;
    // `extent` must be non-zero; `old` (may be null) is retired by the new swapchain.
    Swapchain(const vk_core::Context& ctx, vk::SurfaceKHR surface, const SwapchainConfig& config,
              vk::RenderPass pass, vk::Extent2D extent, vk::SwapchainKHR old);

    const vk::raii::SwapchainKHR& handle() const { return swapchain_; }
    vk::Extent2D extent() const { return extent_; }
    std::uint32_t image_count() const { return static_cast<std::uint32_t>(images_.size()); }
    vk::Image image(std::uint32_t i) const { return images_[i]; }
    vk::Framebuffer framebuffer(std::uint32_t i) const { return *framebuffers_[i]; }
    vk::Semaphore render_finished(std::uint32_t i) const { return *render_finished_[i]; }

  private:
    vk::raii::SwapchainKHR swapchain_{nullptr};
    vk::Extent2D extent_;
    std::vector<vk::Image> images_;
    std::vector<vk::raii::ImageView> views_;
    std::vector<vk::raii::Framebuffer> framebuffers_;
    std::vector<vk::raii::Semaphore> render_finished_;
};

}  // namespace monoplane::window
