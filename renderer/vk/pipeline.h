// Shader modules and a small description of a graphics pipeline for dynamic rendering; every pass
// builds its pipelines through this so state defaults (reversed Z, back-face culling) live once.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

vk::raii::ShaderModule make_shader(const Context& ctx, std::span<const std::uint32_t> spirv);

struct GraphicsPipelineDesc {
    vk::PipelineLayout layout;
    vk::ShaderModule vertex;
    // Constants the vertex shader's specialization constants take (optional).
    const vk::SpecializationInfo* vertex_specialization = nullptr;
    vk::ShaderModule geometry;  // optional (single-pass stereo duplicating primitives)
    vk::ShaderModule fragment;  // may be null for depth-only passes
    const vk::SpecializationInfo* fragment_specialization = nullptr;  // optional
    std::vector<vk::VertexInputBindingDescription> vertex_bindings;
    std::vector<vk::VertexInputAttributeDescription> vertex_attributes;
    std::vector<vk::Format> color_formats;
    vk::Format depth_format = vk::Format::eUndefined;
    vk::CullModeFlags cull = vk::CullModeFlagBits::eBack;
    bool depth_test = true;
    bool depth_write = true;
    // Reversed Z: nearer is greater.
    vk::CompareOp depth_compare = vk::CompareOp::eGreaterOrEqual;
    bool depth_bias = false;
    // MSAA: the rasterisation samples of every attachment (ImageDesc::samples).
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
    // MSAA: the first colour output's alpha becomes the fragment's sample coverage.
    bool alpha_to_coverage = false;
    // Depth clamping instead of clipping at the near and far planes (needs the device's
    // depthClamp, DeviceCapabilities::depth_clamp).
    bool depth_clamp = false;
    // Blending of every colour attachment; none by default (the output replaces the target).
    std::optional<vk::PipelineColorBlendAttachmentState> blend;
    // Per colour attachment, the channels written (an empty flag set leaves that attachment as
    // it is); empty: every channel of every attachment.
    std::vector<vk::ColorComponentFlags> color_write_masks;
    // VK_KHR_multiview: the views each draw covers (bit i: layer i); 0 without multiview. Must
    // equal the view mask of the rendering the pipeline is used in.
    std::uint32_t view_mask = 0;
};

// Viewport and scissor are dynamic state, set by the pass for each target.
vk::raii::Pipeline make_graphics_pipeline(const Context& ctx, const GraphicsPipelineDesc& desc);

vk::raii::Pipeline make_compute_pipeline(const Context& ctx, vk::PipelineLayout layout,
                                         vk::ShaderModule compute);

void set_viewport_and_scissor(const vk::raii::CommandBuffer& cmd, vk::Extent2D extent);

// How many pipelines make_graphics_pipeline and make_compute_pipeline have created in this
// process, on any thread: a frame that creates one after warm-up stalls while the driver compiles
// it (the headset's frame log and the tests read the count before and after frames).
std::uint64_t pipelines_created();

}  // namespace monoplane::vk_core
