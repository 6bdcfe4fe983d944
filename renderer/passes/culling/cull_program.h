// The chunk culling's compute program (cull_chunks.comp), as the culling units record it: the
// frustum phase (culling_unit.cpp: every view's list, each chunk's level of detail and routing)
// and the occlusion phase (renderer/passes/occlusion_culling/: C's list again, against the merged
// depth pyramid of both eyes). One dispatch each; the render graph places the barriers.
//
// When may this be called: on the thread that owns the device; bind() on a set no pending frame
// reads, dispatch() inside the pass's step.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "renderer/passes/culling/chunk_lists.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"

namespace monoplane::passes {

// What the program reads and writes: the inputs no step declares (ChunkLists::inputs) and the
// declared draw lists, counts (the predicates' words) and levels of detail.
struct CullBuffers {
    CullInputs inputs;
    const vk_core::Buffer* commands = nullptr;
    const vk_core::Buffer* counts = nullptr;
    const vk_core::Buffer* lod_state = nullptr;
};

class CullProgram {
  public:
    enum class Phase : std::uint32_t { kFrustum = 0, kOcclusion = 1 };

    // The phase it will record: the frustum phase's sets name an image of the program's own
    // where the occlusion phase's name the pyramid.
    CullProgram(const vk_core::Context& ctx, Phase phase);

    vk_core::DescriptorSet make_set() const;
    // Points `set` at `buffers` and, for the occlusion phase, at the merged depth pyramid (every
    // mip, in general layout); nullptr for the frustum phase, which never reads it: the set then
    // names a 1 x 1 image of the program's own.
    void bind(vk::DescriptorSet set, const CullBuffers& buffers,
              const vk_core::Image* merged_depth) const;
    void dispatch(const vk::raii::CommandBuffer& cmd, vk::DescriptorSet set, Phase phase) const;

  private:
    const vk_core::Context& ctx_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    vk::raii::Sampler nearest_{nullptr};        // the pyramid's texels, every mip
    std::optional<vk_core::Image> no_pyramid_;  // the frustum phase's
};

// The recorder of both culling units: one dispatch of `phase` per pass, under the pass's GPU
// predicate, with one descriptor set per frame slot, pointed each frame at the buffers the step
// hands over (UnitRecording::buffer for the declared ones, cull_inputs for the others) and, in
// the occlusion phase, at the merged depth pyramid the step declares.
std::unique_ptr<UnitRecorder> make_cull_recorder(const vk_core::Context& ctx,
                                                 CullProgram::Phase phase);

}  // namespace monoplane::passes
