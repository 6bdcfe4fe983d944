// What a full-screen pass shares: one triangle over its target (shared/fullscreen.vert), a
// fragment shader of its own writing one colour attachment whole (no depth, no blending, no
// culling), its inputs in descriptor set 0 and its parameters in push constants. The tone mapping,
// TAA's resolve and the depth debug view are such passes.
//
// When may this be called: make_fullscreen_pipeline with the pass, on the thread that owns the
// device; record_fullscreen while the frame's command buffer records, with `target` in its
// declared colour-write use (the executor's).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/vk/context.h"
#include "renderer/vk/image.h"

namespace monoplane::passes {

// The vertex shader of that one triangle, for a full-screen pass that builds a pipeline of its
// own (the composite blends, the SSAO apply pass draws into a subset of the target).
vk::raii::ShaderModule make_fullscreen_vertex_shader(const vk_core::Context& ctx);

// The pipeline drawing `fragment` (SPIR-V words) over one colour attachment of `format`.
vk::raii::Pipeline make_fullscreen_pipeline(const vk_core::Context& ctx, vk::PipelineLayout layout,
                                            std::span<const std::uint32_t> fragment,
                                            vk::Format format);

// The draw over all of `target` with set 0 `inputs` and the fragment stage's push constants
// `push`. The target's earlier contents are not kept, unless `when` is given: then the GPU may
// skip the draw, and the target keeps what an earlier pass wrote.
void record_fullscreen(const vk::raii::CommandBuffer& cmd, const vk_core::Image& target,
                       vk::Pipeline pipeline, vk::PipelineLayout layout, vk::DescriptorSet inputs,
                       std::span<const std::byte> push,
                       const std::optional<Predicate>& when = std::nullopt);

}  // namespace monoplane::passes
