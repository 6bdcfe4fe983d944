// Fills an eye's depth swapchain image for XR_KHR_composition_layer_depth (docs/headsets.md,
// "Depth submission"), so that a runtime can reproject with depth: the renderer's linear depth
// (in hybrid the eye's own depth where near content is and C's beyond, as the composite wrote
// it) converted to the distance along the eye's view axis and encoded reversed-Z with the far
// plane at infinity, window depth = near / distance. The sky, the neutral screen, the
// questionnaire and the overlays (the label) are at infinity, window depth 0: the overlays sit at
// the same place in both eyes, so that is where they appear to be.
#pragma once

#include <map>
#include <vector>

#include <glm/mat3x3.hpp>

#include "app/headset/eye_compositor.h"
#include "renderer/modes/mode_renderer.h"
#include "rig/tangents.h"
#include "renderer/vk/descriptor_set.h"

namespace monoplane::headset {

// The depth formats the writer fills, best first: float depth keeps reversed-Z's precision far
// away (D32_SFLOAT); the UNORM ones work but quantise near / distance evenly.
const std::vector<vk::Format>& eye_depth_formats();
// The aspects of a depth swapchain image of that format (the stencil too where it has one).
vk::ImageAspectFlags depth_aspects(vk::Format format);

// An eye's depth as the renderer left it, and where the eye looks from.
struct EyeDepthSource {
    modes::EyeDepthImage linear_depth;  // metres in front of the eyes' plane; left in its layout
    rig::Tangents tangents;             // the eye's frustum, in its own frame
    // The rotation of directions from the head's frame to the eye's: identity for parallel
    // eyes; a canted eye's yaw relative to the head otherwise.
    glm::dmat3 head_to_eye{1.0};
    double eye_in_front = 0.0;  // metres the eye lies in front of the eyes' plane
};

class EyeDepthWriter {
  public:
    // `format`: the depth swapchains' (one of eye_depth_formats()).
    EyeDepthWriter(const vk_core::Context& ctx, vk::Format format);

    // Records the eye's depth into `target` (a swapchain image of the writer's format, in
    // DEPTH_STENCIL_ATTACHMENT_OPTIMAL as XR_KHR_vulkan_enable2 hands it out, left so):
    // `source` encoded for `near`, or infinity everywhere without one (no scene), then
    // infinity over `at_infinity` (the overlays' rectangles). The images are remembered: call
    // with the same swapchains' images only while they and the sources live.
    void record(const vk::raii::CommandBuffer& cmd, vk::Image target, vk::Extent2D extent,
                const EyeDepthSource* source, double near,
                const std::vector<PixelRect>& at_infinity);

  private:
    vk::ImageView target_view(vk::Image target);
    vk::DescriptorSet source_set(const vk_core::Image& linear_depth);

    const vk_core::Context& ctx_;
    vk::Format format_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::Sampler sampler_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    std::map<vk::Image, vk::raii::ImageView> targets_;
    // One set per renderer's eye image: the images never change, so the sets are written once.
    std::map<vk::ImageView, vk_core::DescriptorSet> sources_;
};

}  // namespace monoplane::headset
