// Forward shading of one view into an HDR target, then the sky where nothing was drawn.
// Reads: view constants (set 0, binding 0), the shadow map (binding 1).
// Writes: HDR colour, reversed-Z depth, linear depth (metres in front of the eyes' plane).
#pragma once

#include <optional>
#include <span>

#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/passes/shared/scene_geometry.h"
#include "renderer/passes/shared/view_constants.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

struct ForwardTargets {
    const vk_core::Image& hdr;           // kHdrFormat, colour attachment
    const vk_core::Image& depth;         // kDepthFormat, reversed Z
    const vk_core::Image& linear_depth;  // kLinearDepthFormat
    // The region drawn, from the images' top-left corner: the whole image for the eyes, the
    // viewport of eq. 8 inside its larger allocation for C.
    vk::Extent2D area;
    // Clear the colour targets first (black, sky depth) instead of leaving them undefined: only
    // where pixels may stay unwritten and are read anyway (C's image read back for mono.png
    // when fragments hidden in both eyes were discarded).
    bool clear_color = false;
};

// What a forward pass draws, in order; each step may run under a GPU predicate.
enum class ForwardStep {
    kChunks,               // the view's chunk list, every fragment shaded
    kChunksDiscardHidden,  // the same, discarding fragments hidden in both eyes (C only)
    kSky,                  // the sky where nothing was drawn
    kSkyDiscardHidden,     // the same, skipping pixels hidden in both eyes (C only)
    kChunksShowRouting,    // the debug view "routing": chunks coloured by the lists they are in
};
struct ForwardDraw {
    ForwardStep step = ForwardStep::kChunks;
    std::optional<Predicate> when;
};

class ForwardPass {
  public:
    static constexpr vk::Format kHdrFormat = vk::Format::eR16G16B16A16Sfloat;
    static constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;
    static constexpr vk::Format kLinearDepthFormat = vk::Format::eR32Sfloat;

    explicit ForwardPass(const vk_core::Context& ctx);

    vk::DescriptorSetLayout set_layout() const { return *set_layout_; }
    // Set 1 of the depth-tested and debug steps: the merged depth pyramid (binding 0, eGeneral)
    // and the culling pass's per-chunk routing words (binding 1).
    vk::DescriptorSetLayout merged_depth_layout() const { return *merged_depth_layout_; }

    // Expects the targets in eUndefined (their contents are replaced); leaves the colour targets
    // in eColorAttachmentOptimal and depth in eDepthAttachmentOptimal.
    // merged_depth_set is needed only by the *DiscardHidden and kChunksShowRouting steps.
    void record(const vk::raii::CommandBuffer& cmd, const ForwardTargets& targets,
                vk::DescriptorSet view_set, vk::DescriptorSet merged_depth_set,
                const SceneGeometry& geometry, const IndirectDraws& chunks,
                std::span<const ForwardDraw> steps) const;

  private:
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::DescriptorSetLayout merged_depth_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline geometry_pipeline_{nullptr};
    vk::raii::Pipeline discard_hidden_pipeline_{nullptr};
    vk::raii::Pipeline show_routing_pipeline_{nullptr};
    vk::raii::Pipeline sky_pipeline_{nullptr};
    vk::raii::Pipeline sky_discard_hidden_pipeline_{nullptr};
};

}  // namespace monoplane::passes
