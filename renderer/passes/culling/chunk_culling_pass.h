// GPU chunk culling (papers/000 Sect. 4.4 "View Frustum Culling" and "Occlusion Culling"): one
// compute dispatch per frame sorts the scene's chunks into the eyes' lists and C's list and
// writes their indirect draw commands and counts, with no per-chunk work on the CPU. In the
// occlusion-cull variant a second dispatch, after the merged depth pyramid, re-sorts C's list.
// Reads: the chunk table (uploaded once), per-frame planes, the merged depth pyramid (phase 1).
// Writes: draw commands, counts and the predicates of cull_constants.h.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>

#include "renderer/passes/culling/cull_constants.h"
#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/plan/lod_selection.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/frame_ring.h"
#include "renderer/vk/frame_uploads.h"
#include "scenes/lod_chain.h"
#include "scenes/scene.h"

namespace monoplane::passes {

enum class CullView {
    kLeft = MONOPLANE_CULL_LEFT,
    kRight = MONOPLANE_CULL_RIGHT,
    kMono = MONOPLANE_CULL_MONO,
    kBothEyes = MONOPLANE_CULL_BOTH_EYES,  // a list only: either eye's chunks (single-pass stereo)
};

// One frame's culling inputs: the world -> clip matrix of each view drawn (reversed Z; the
// eyes' far plane and C's near plane bound the regions), and the occlusion test's parameters.
struct CullFrame {
    std::array<std::optional<glm::dmat4>, MONOPLANE_CULL_VIEWS> view_proj;
    bool honour_force_mono = false;
    bool honour_force_stereo = false;
    glm::dvec2 mono_viewport{0.0};        // C's viewport in pixels (eq. 8)
    double hidden_depth_threshold = 0.0;  // the eyes' reversed-Z depth of m - eps
    std::uint32_t pyramid_mips = 1;
    // Instances per draw of the both-eyes list: 2 for instanced stereo (the eye is the instance
    // index minus the base instance), 1 for every other use.
    std::uint32_t both_eyes_instances = 1;
    // Hybrid: blended chunks wholly beyond m (the eyes' far plane) go to C alone, all others to the
    // eyes alone, whatever their far plane (MONOPLANE_CULL_SPLIT_BLENDED).
    bool split_blended = false;
    // Level of detail (renderer/plan/lod_selection.h): each drawn view's projection of errors,
    // and the budget in pixels (0: every chunk at full detail).
    std::array<plan::LodView, MONOPLANE_CULL_VIEWS> lod_views{};
    double lod_error_px = 0.0;
};

class ChunkCullingPass {
  public:
    // How many chunks of each alpha class (MONOPLANE_CLASS_*) the scene has.
    static std::array<std::uint32_t, MONOPLANE_CLASSES> class_sizes(const scenes::Scene& scene);
    // The counts word of a list's class (cull_constants.h).
    static std::uint32_t count_word(std::uint32_t list, std::uint32_t alpha_class);

    // The scene's chunk table on the GPU (bounds, draw ranges, routing flags, where its levels
    // of detail start): made once per scene and shared by every renderer of it
    // (renderer/modes/scene_resources.h).
    static vk_core::Buffer make_chunk_table(const vk_core::Context& ctx, const scenes::Scene& scene,
                                            const scenes::LodChain& lods);
    // Every chunk's levels (level 0 first) as LodRecords; first indices count from the start of
    // SceneGeometry's index buffer (the scene's indices, then the chain's).
    static vk_core::Buffer make_level_table(const vk_core::Context& ctx, const scenes::Scene& scene,
                                            const scenes::LodChain& lods);

    // chunk_table, level_table: made for the same scene; they must outlive the pass.
    ChunkCullingPass(const vk_core::Context& ctx, const scenes::Scene& scene,
                     const vk_core::Buffer& chunk_table, const vk_core::Buffer& level_table);

    // Points the occlusion test at the merged depth pyramid (a view of all its mips, in
    // eGeneral). Call between frames, before the first record().
    void set_merged_depth(vk::ImageView pyramid, vk::Sampler nearest) const;
    // Stages the frame's constants for the frame's command buffer; call before recording it.
    void set_frame(const CullFrame& frame, vk_core::FrameUploads& uploads);
    // Stages the order in which the chunks are walked and their draws listed: a permutation of
    // the chunk indices (front_to_back_order). The buffer keeps it for later frames: call before
    // the first frame and when the order changes (a wrong size is a programming error).
    void set_draw_order(std::span<const std::uint32_t> order, vk_core::FrameUploads& uploads);

    // Phase 0: all views' lists; phase 1: C's list again, with occlusion culling. The render graph
    // makes their results visible to the indirect draws, predicates and read-backs that follow.
    void record_frustum_phase(const vk::raii::CommandBuffer& cmd) const;
    void record_occlusion_phase(const vk::raii::CommandBuffer& cmd) const;
    // Copies the counts (into the frame-in-flight slot's own buffer; with lists, the draw lists
    // too, into one buffer for all slots) to host memory, after the frame's last use of them.
    void record_readback(const vk::raii::CommandBuffer& cmd, bool lists,
                         std::uint32_t slot = 0) const;

    // The buffers the read-back copies (the frame plan's draw_lists, predicates, counts_readback
    // and lists_readback): the draw lists, the counts, the slot's copy of the counts, and the
    // one copy of the lists.
    const vk_core::Buffer& commands_buffer() const { return commands_; }
    const vk_core::Buffer& counts_buffer() const { return counts_; }
    const vk_core::Buffer& counts_readback(std::uint32_t slot) const {
        return counts_readback_.at(slot);
    }
    const vk_core::Buffer& commands_readback() const { return commands_readback_; }

    // A view's draws of one alpha class; chunk_draws: all three.
    IndirectDraws draws(CullView view, std::uint32_t alpha_class = MONOPLANE_CLASS_OPAQUE) const;
    ChunkDraws chunk_draws(CullView view) const;
    // One uint32 of MONOPLANE_ROUTE_* bits per chunk, written every frame (storage buffer).
    vk::Buffer routing() const { return routing_.handle(); }
    // Conditional rendering on a counts word (MONOPLANE_PRED_*).
    Predicate predicate(std::uint32_t word, bool inverted = false) const;

    // After the slot's frame has completed.
    std::array<std::uint32_t, MONOPLANE_COUNT_WORDS> counts(std::uint32_t slot = 0) const;
    // The chunk indices of a view's list, class by class, each (record_readback with lists), once
    // the slot's frame, the last to read lists back, has completed.
    std::vector<std::uint32_t> drawn_chunks(CullView view, std::uint32_t slot = 0) const;
    // The same list's draw commands: each names its chunk in firstInstance, its level of detail
    // by its index range, and the eyes it draws by its instance count.
    std::vector<vk::DrawIndexedIndirectCommand> drawn_commands(CullView view,
                                                               std::uint32_t slot = 0) const;

  private:
    void make_pipeline();
    void write_descriptors() const;
    void record_phase(const vk::raii::CommandBuffer& cmd, std::uint32_t phase) const;
    // The first command of an alpha class within each list.
    std::uint32_t class_base(std::uint32_t alpha_class) const;

    std::uint32_t chunk_count_ = 0;
    std::array<std::uint32_t, MONOPLANE_CLASSES> class_sizes_{};
    const vk_core::Buffer& chunks_;
    const vk_core::Buffer& levels_;
    vk_core::Buffer lod_state_;  // per chunk and MONOPLANE_LOD_* group: last frame's level
    vk_core::Buffer commands_;
    vk_core::Buffer counts_;
    vk_core::Buffer routing_;
    vk_core::Buffer order_;
    vk_core::Buffer constants_;
    std::array<vk_core::Buffer, vk_core::FrameRing::kFramesInFlight> counts_readback_;
    vk_core::Buffer commands_readback_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::DescriptorPool pool_{nullptr};
    vk::raii::DescriptorSet set_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    const vk_core::Context& ctx_;
};

}  // namespace monoplane::passes
