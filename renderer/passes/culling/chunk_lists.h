// The chunk lists of GPU chunk culling (papers/000 Sect. 4.4 "View Frustum Culling" and
// "Occlusion Culling"): the buffers the culling units fill and every forward pass draws from.
// The culling unit (culling_unit.cpp) sorts the scene's chunks into the eyes' lists and C's list
// with one compute dispatch per frame and writes their indirect draw commands and counts, with no
// per-chunk work on the CPU; in the occlusion-cull variant the occlusion culling unit
// (renderer/passes/occlusion_culling/) re-sorts C's list after the merged depth pyramid.
// This holds their state between frames: the lists, the counts and the predicates of
// cull_constants.h, each chunk's last level of detail and routing bits, the frame's constants and
// the draw order (uploaded before the frame), and the host's copies of the counts and lists.
//
// When may this be called: on the thread that owns the device; set_frame and set_draw_order
// before the frame's command buffer is recorded, the read-back accessors once the slot's frame
// has completed.
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
// The buffers the culling reads and writes that no step of the frame declares (ChunkLists::
// inputs): the scene's chunk and level tables, the frame's constants, the draw order, and each
// chunk's routing bits.
struct CullInputs {
    const vk_core::Buffer* chunks = nullptr;
    const vk_core::Buffer* levels = nullptr;
    const vk_core::Buffer* constants = nullptr;
    const vk_core::Buffer* order = nullptr;
    const vk_core::Buffer* routing = nullptr;
};

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

class ChunkLists {
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

    // chunk_table, level_table: made for the same scene; they must outlive the lists.
    ChunkLists(const vk_core::Context& ctx, const scenes::Scene& scene,
               const vk_core::Buffer& chunk_table, const vk_core::Buffer& level_table);

    // Stages the frame's constants for the frame's command buffer; call before recording it.
    void set_frame(const CullFrame& frame, vk_core::FrameUploads& uploads);
    // Stages the order in which the chunks are walked and their draws listed: a permutation of
    // the chunk indices (front_to_back_order). The buffer keeps it for later frames: call before
    // the first frame and when the order changes (a wrong size is a programming error).
    void set_draw_order(std::span<const std::uint32_t> order, vk_core::FrameUploads& uploads);

    // The buffers the culling writes and the read-back copies (the frame plan's draw_lists,
    // predicates, lod_state, counts_readback and lists_readback): the draw lists, the counts,
    // each chunk's last level, the slot's copy of the counts, and the one copy of the lists.
    const vk_core::Buffer& commands_buffer() const { return commands_; }
    const vk_core::Buffer& counts_buffer() const { return counts_; }
    const vk_core::Buffer& lod_state() const { return lod_state_; }
    // What the culling reads and writes beside them, which no step declares: the frame's
    // constants and the draw order (uploaded before the frame's first pass), each chunk's routing
    // bits (only the culling writes them), and the scene's tables.
    CullInputs inputs() const { return {&chunks_, &levels_, &constants_, &order_, &routing_}; }
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
    // The chunk indices of a view's list, class by class, each (read back with the lists), once
    // the slot's frame, the last to read lists back, has completed.
    std::vector<std::uint32_t> drawn_chunks(CullView view, std::uint32_t slot = 0) const;
    // The same list's draw commands: each names its chunk in firstInstance, its level of detail
    // by its index range, and the eyes it draws by its instance count.
    std::vector<vk::DrawIndexedIndirectCommand> drawn_commands(CullView view,
                                                               std::uint32_t slot = 0) const;

  private:
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
};

}  // namespace monoplane::passes
