// The depth histogram of both eyes' final linear depth (renderer/plan/depth_histogram.h), for
// `--mono-plane auto`: one compute dispatch per eye into a host-visible buffer per frame slot,
// read when the frame completes. Reads: both eyes' linear depth (eShaderReadOnlyOptimal).
// Writes: the slot's buffer.
#pragma once

#include <array>
#include <vector>

#include "renderer/passes/shared/step_sync.h"
#include "renderer/plan/depth_histogram.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"

namespace monoplane::passes {

class DepthHistogramPass {
  public:
    // slots: frames in flight (vk_core::FrameRing::kFramesInFlight); near, far: the bins' range.
    DepthHistogramPass(const vk_core::Context& ctx, std::uint32_t slots, double near, double far);

    // The eyes' linear depth images; call before the first frame and whenever they change.
    void set_eye_depths(std::array<vk::ImageView, 2> linear_depth, vk::Extent2D eye_extent);
    // Clears the slot's buffer and counts both eyes into it: two steps ("clear", "count"), each
    // begun with sync.next().
    void record(const vk::raii::CommandBuffer& cmd, StepSync& sync, std::uint32_t slot) const;
    // The slot's histogram; call once its frame has completed.
    plan::DepthHistogram result(std::uint32_t slot) const;

  private:
    const vk_core::Context& ctx_;
    double near_ = 0.1;
    double far_ = 1000.0;
    vk::Extent2D extent_{0, 0};
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    std::vector<vk_core::Buffer> buffers_;                     // per slot
    std::vector<std::array<vk_core::DescriptorSet, 2>> sets_;  // per slot, per eye
};

}  // namespace monoplane::passes
