// The merged depth pyramid of both eyes in C's image space (papers/000 Sect. 4.4): built after
// the eyes' near passes, it lets C discard fragments no eye will show and lets the culling pass
// drop C's chunks hidden in both eyes. Mip 0 of the image is the paper's level 2 (4 x 4 pixels
// per texel); levels 0 and 1 are never written. Values are reversed-Z depths of the eyes (whose
// far plane is m): the farthest over the region, 0 where some eye pixel sees past the near
// content, 1 where no eye pixel reads C at all.
// Reads: both eyes' depth (eDepthReadOnlyOptimal). Writes: the pyramid (always eGeneral).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/ext/matrix_double3x3.hpp>

#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/passes/shared/step_sync.h"
#include "renderer/vk/image.h"

namespace monoplane::passes {

class DepthPyramidPass {
  public:
    explicit DepthPyramidPass(const vk_core::Context& ctx);
    ~DepthPyramidPass();

    // Whether the pyramid already covers C's allocation (resize() would keep it).
    bool fits(vk::Extent2D mono_allocation) const;
    // (Re)creates the pyramid for C's allocation when it grows; returns true when it did (views
    // of it must be rebound). Call between frames, none of which in flight uses the pyramid.
    bool resize(vk::Extent2D mono_allocation);
    // The eyes' depth images (sampled usage) and their size; call once and after every
    // resize() that returned true.
    void set_eye_depths(vk::ImageView left, vk::ImageView right, vk::Extent2D eye_extent);

    // Builds all levels in three steps, each begun with sync.next(): "blocks" (the eyes' depth,
    // depth-read-only, to 4 x 4 minima), "merge" (level 0) and "reduce" (once per further
    // level). mono_to_eye: homographies from C's pixels to each eye's pixels
    // (rig::mono_pixel_to_eye_pixel). With a predicate the dispatches run only when it holds.
    void record(const vk::raii::CommandBuffer& cmd, StepSync& sync,
                const std::array<glm::dmat3, 2>& mono_to_eye,
                const std::optional<Predicate>& when) const;
    // The pyramid and the eyes' blocks, for the render graph (both live in general layout).
    vk_core::ImageRange pyramid_image() const;
    vk_core::ImageRange blocks_image() const;

    vk::ImageView view() const { return *all_mips_; }  // every mip, for texelFetch
    vk::Sampler sampler() const { return *nearest_; }
    vk::Extent2D extent() const { return extent_; }
    std::uint32_t mips() const { return mips_; }

  private:
    void create_image(vk::Extent2D extent);

    const vk_core::Context& ctx_;
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::DescriptorSetLayout merge_layout_{nullptr};
    vk::raii::DescriptorSetLayout reduce_layout_{nullptr};
    vk::raii::PipelineLayout merge_pipeline_layout_{nullptr};
    vk::raii::PipelineLayout reduce_pipeline_layout_{nullptr};
    vk::raii::Pipeline blocks_{nullptr};
    vk::raii::Pipeline merge_{nullptr};
    vk::raii::Pipeline reduce_{nullptr};
    vk::Extent2D extent_{0, 0};
    std::uint32_t mips_ = 0;
    vk::raii::Image image_{nullptr};
    vk_core::DeviceMemory memory_{nullptr};
    vk::raii::ImageView all_mips_{nullptr};
    std::vector<vk::raii::ImageView> mip_views_;
    vk::raii::DescriptorPool pool_{nullptr};
    vk::raii::DescriptorSet merge_set_{nullptr};
    std::vector<vk::raii::DescriptorSet> reduce_sets_;
    // Each eye's depth as 4 x 4 block minima (one layer per eye), eGeneral.
    vk::Extent2D blocks_extent_{0, 0};
    vk::raii::Image blocks_image_{nullptr};
    vk_core::DeviceMemory blocks_memory_{nullptr};
    vk::raii::ImageView blocks_view_{nullptr};
};

}  // namespace monoplane::passes
