// The recording half of a pass kind written as one unit (renderer/plan/pass_unit.h has the
// declaring half). A unit is one source file in its own folder under renderer/passes/: its
// declaration (where a frame places it, what each step reads and writes) and its recorder side by
// side, registered by one line in renderer/passes/pass_unit_list.h.
//
// A recorder reaches the frame only through UnitRecording: the images its current step declared
// (any other is a programming error, in every build), the next of its declared steps (whose
// barriers the executor records), the GPU predicates and the frame's values. It records no
// barrier and names no layout but through its declared uses (executor::layout_for).
//
// When may this be called: make() with the renderer, on the thread that owns the device;
// record() on the thread that records the frame, inside the pass's scope (the renderer begins it
// and its first step).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "renderer/passes/culling/chunk_lists.h"
#include "renderer/passes/shadow/shadow_map.h"
#include "renderer/passes/shared/composite_values.h"
#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/passes/shared/scene_geometry.h"
#include "renderer/passes/shared/scene_textures.h"
#include "renderer/passes/shared/unit_settings.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"
#include "renderer/vk/image.h"

namespace monoplane::passes {

// What a frame's recording of a unit knows of the frame beyond its images.
struct UnitFrameValues {
    double mono_plane = 0.0;  // m in metres, when the frame draws C (use_mono)
    bool use_mono = false;
    std::uint32_t slot = 0;  // the frame-in-flight slot (its resources are free to rewrite)
    // TAA's history starts anew this frame (the first frame, a jump in frame index or in m):
    // the last frame's resolve is not to be read.
    bool history_restarted = true;
    UnitSettings settings;  // the renderer's options for the units
    // How C maps into the eyes this frame: set for the composite's passes (PassKind::kComposite).
    CompositeValues composite;
    // C's viewport in its images (eq. 8): the part of its allocation this frame drew, when
    // use_mono.
    vk::Extent2D mono_area{};
    // C's pixels that both eyes hide, which C's forward pass leaves unwritten, are read later in
    // this frame (C's image read back, C's SSAO): the pass clears them first.
    bool mono_hidden_pixels_read = false;
    // World -> the shadow map's clip space this frame (fit_light_view_proj), float32 as the GPU.
    glm::mat4 light_view_proj{1.0f};
    // Homographies from C's pixels to each eye's pixels (rig::mono_pixel_to_eye_pixel, with
    // TAA's jitter): set for the depth pyramid's pass (PassKind::kDepthPyramid).
    std::array<glm::dmat3, 2> mono_pixel_to_eye{glm::dmat3(1.0), glm::dmat3(1.0)};
};

// The scene a renderer draws, as its units may use it: what every renderer of the scene shares
// (modes::SceneResources), which outlives the renderer and its recorders.
struct UnitScene {
    const SceneGeometry* geometry = nullptr;  // vertex and index buffers, every level of detail
    const SceneTextures* textures = nullptr;  // set 2 of the forward shaders
    ShadowCasters shadow_casters;             // the shadow map's draws
    ShadowParams shadow;                      // the shadow map's size and depth bias
    vk::Sampler shadow_sampler;               // how the forward shaders compare against the map
    bool masked_chunks = false;   // alphaMode MASK chunks: the alpha-tested pipelines are needed
    bool blended_chunks = false;  // alphaMode BLEND chunks: the blending pipelines are needed
};

// The passes of one unit that the renderer's frames may run (those of every plan it may make),
// which the unit's recorder makes its pipelines for when it is made: never one mid-run.
struct UnitPasses {
    // Each pass with the plan it belongs to (for its resource table).
    std::vector<std::pair<const plan::FramePlan*, const plan::PlannedPass*>> passes;

    // Whether `test` holds for any of the passes.
    bool any(const std::function<bool(const plan::PlannedPass&)>& test) const;
    // Whether a step of any of the passes declares `view`'s image `role`.
    bool any_declares(plan::ViewId view, plan::ImageRole role) const;
};

class UnitRecording {
  public:
    virtual ~UnitRecording() = default;
    virtual const vk::raii::CommandBuffer& cmd() const = 0;
    virtual const plan::PlannedPass& pass() const = 0;
    virtual const UnitFrameValues& values() const = 0;
    // The image of `view`'s `role` this frame. The pass's current step must declare it: any other
    // stops the program, naming the pass, the step and the image. kEyes: single-pass stereo's
    // two-layer image whose layers are both eyes' images of `role` (the step must declare both).
    virtual const vk_core::Image& image(plan::ViewId view, plan::ImageRole role) = 0;
    // Whether the pass's current step declares `view`'s image `role`: what image() hands over
    // (a recorder whose declaration chose between images asks which).
    virtual bool declares(plan::ViewId view, plan::ImageRole role) const = 0;
    // The same for `view`'s buffer `role` (kNone: a shared buffer).
    virtual bool declares(plan::ViewId view, plan::BufferRole role) const = 0;
    // Every image of `view`'s `role` this frame, for a role that is several (SSAO's scratch
    // images, in SsaoImages::scratch()'s order), under image()'s rule.
    virtual std::vector<const vk_core::Image*> images(plan::ViewId view, plan::ImageRole role) = 0;
    // `view`'s constants this frame (passes::ViewConstants: its matrices, camera and head), which
    // the renderer uploads before the frame's first pass: any pass may read them, no step
    // declares them.
    virtual const vk_core::Buffer& view_constants(plan::ViewId view) const = 0;
    // What the chunk culling reads and writes beside its declared buffers (ChunkLists::inputs):
    // the scene's tables, the frame's constants and draw order (uploaded before the frame's
    // first pass), each chunk's routing bits (only the culling writes them).
    virtual CullInputs cull_inputs() const = 0;
    // A view's chunk draws from the culling's lists (the indirect commands and their counts),
    // under image()'s rule for the draw lists and the predicates.
    virtual ChunkDraws chunk_draws(CullView view) = 0;
    // The buffer of `view`'s `role` this frame (kNone: the frame's own, as the depth histogram's),
    // under the same rule.
    virtual const vk_core::Buffer& buffer(plan::ViewId view, plan::BufferRole role) = 0;
    // Begins the pass's next declared step (the first is begun for the recorder), by name.
    virtual void next_step(std::string_view step) = 0;
    // The GPU predicate of a planned `when` (nullopt: always, or no conditional rendering).
    virtual std::optional<Predicate> predicate(plan::GpuPredicate when) const = 0;
    // The scene the renderer draws.
    virtual const UnitScene& scene() const = 0;
};

class UnitRecorder {
  public:
    virtual ~UnitRecorder() = default;
    // Records one of the unit's planned passes (recording.pass()).
    virtual void record(UnitRecording& recording) = 0;
};

}  // namespace monoplane::passes
