#include "renderer/vk/pipeline.h"

#include <atomic>

namespace monoplane::vk_core {

namespace {
std::atomic<std::uint64_t> created_pipelines{0};
}  // namespace

std::uint64_t pipelines_created() {
    return created_pipelines.load(std::memory_order_relaxed);
}

vk::raii::ShaderModule make_shader(const Context& ctx, std::span<const std::uint32_t> spirv) {
    return vk::raii::ShaderModule(ctx.device(),
                                  vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
}

vk::raii::Pipeline make_graphics_pipeline(const Context& ctx, const GraphicsPipelineDesc& desc) {
    std::vector<vk::PipelineShaderStageCreateInfo> stages;
    stages.emplace_back(vk::PipelineShaderStageCreateFlags(), vk::ShaderStageFlagBits::eVertex,
                        desc.vertex, "main", desc.vertex_specialization);
    if (desc.geometry) {
        stages.emplace_back(vk::PipelineShaderStageCreateFlags(),
                            vk::ShaderStageFlagBits::eGeometry, desc.geometry, "main");
    }
    if (desc.fragment) {
        stages.emplace_back(vk::PipelineShaderStageCreateFlags(),
                            vk::ShaderStageFlagBits::eFragment, desc.fragment, "main",
                            desc.fragment_specialization);
    }
    const vk::PipelineVertexInputStateCreateInfo vertex_input({}, desc.vertex_bindings,
                                                              desc.vertex_attributes);
    const vk::PipelineInputAssemblyStateCreateInfo input_assembly(
        {}, vk::PrimitiveTopology::eTriangleList);
    const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
    vk::PipelineRasterizationStateCreateInfo raster(
        {}, desc.depth_clamp ? VK_TRUE : VK_FALSE, VK_FALSE, vk::PolygonMode::eFill, desc.cull,
        vk::FrontFace::eCounterClockwise, desc.depth_bias ? VK_TRUE : VK_FALSE, 0.0f, 0.0f, 0.0f,
        1.0f);
    const vk::PipelineMultisampleStateCreateInfo multisample(
        {}, desc.samples, VK_FALSE, 0.0f, nullptr, desc.alpha_to_coverage ? VK_TRUE : VK_FALSE);
    const vk::PipelineDepthStencilStateCreateInfo depth({}, desc.depth_test, desc.depth_write,
                                                        desc.depth_compare);
    std::vector<vk::PipelineColorBlendAttachmentState> blend(
        desc.color_formats.size(),
        desc.blend.value_or(vk::PipelineColorBlendAttachmentState().setColorWriteMask(
            vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
            vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA)));
    for (std::size_t i = 0; i < desc.color_write_masks.size() && i < blend.size(); ++i) {
        blend[i].colorWriteMask = desc.color_write_masks[i];
    }
    const vk::PipelineColorBlendStateCreateInfo color_blend({}, VK_FALSE, vk::LogicOp::eCopy,
                                                            blend);
    std::vector<vk::DynamicState> dynamic = {vk::DynamicState::eViewport,
                                             vk::DynamicState::eScissor};
    if (desc.depth_bias) dynamic.push_back(vk::DynamicState::eDepthBias);
    const vk::PipelineDynamicStateCreateInfo dynamic_state({}, dynamic);
    const vk::PipelineRenderingCreateInfo rendering(desc.view_mask, desc.color_formats,
                                                    desc.depth_format);

    const vk::GraphicsPipelineCreateInfo info(
        {}, stages, &vertex_input, &input_assembly, nullptr, &viewport, &raster, &multisample,
        &depth, &color_blend, &dynamic_state, desc.layout, nullptr, 0, nullptr, -1, &rendering);
    created_pipelines.fetch_add(1, std::memory_order_relaxed);
    return vk::raii::Pipeline(ctx.device(), nullptr, info);
}

vk::raii::Pipeline make_compute_pipeline(const Context& ctx, vk::PipelineLayout layout,
                                         vk::ShaderModule compute) {
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, compute,
                                                  "main");
    created_pipelines.fetch_add(1, std::memory_order_relaxed);
    return vk::raii::Pipeline(ctx.device(), nullptr,
                              vk::ComputePipelineCreateInfo({}, stage, layout));
}

void set_viewport_and_scissor(const vk::raii::CommandBuffer& cmd, vk::Extent2D extent) {
    cmd.setViewport(0, vk::Viewport(0.0f, 0.0f, static_cast<float>(extent.width),
                                    static_cast<float>(extent.height), 0.0f, 1.0f));
    cmd.setScissor(0, vk::Rect2D({0, 0}, extent));
}

}  // namespace monoplane::vk_core
