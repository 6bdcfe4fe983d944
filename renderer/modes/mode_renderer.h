// The render modes (stereo, hybrid, hybrid-farfield), executed from the frame plan (renderer/plan/
// frame_plan.h: which passes run, in what order, what each reads and writes): the renderer owns
// the views' images, the chunk lists and the pyramid, prepares a frame's matrices and culling,
// asks plan_frame for the passes and has each recorded by its unit's recorder
// (renderer/passes/pass_units.h), through what UnitRecording offers of the frame. The executor
// records every barrier and layout transition. One GPU culling pass sorts the chunks into the
// views' indirect draw lists; predicates computed by it skip, on the GPU, C and the composite
// when C has nothing to draw, and the pyramid when no eye drew anything.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/executor/graph_executor.h"
#include "renderer/modes/auto_mono_plane.h"
#include "renderer/modes/scene_resources.h"
#include "renderer/modes/view_setup.h"
#include "renderer/passes/culling/chunk_lists.h"
#include "renderer/passes/depth_pyramid/depth_pyramid.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shadow/shadow_map.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/unit_settings.h"
#include "renderer/passes/ssao/ssao_pass.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/lod_selection.h"
#include "renderer/plan/pass_unit.h"
#include "renderer/plan/render_choices.h"
#include "renderer/plan/variant_chooser.h"
#include "renderer/profile/frame_profiler.h"
#include "renderer/vk/frame_ring.h"
#include "renderer/vk/frame_uploads.h"
#include "rig/rig.h"

namespace monoplane::modes {

// MSAA's sample count for Vulkan: e1 for none and TAA.
vk::SampleCountFlagBits msaa_samples(plan::AntiAliasing aa);

struct RendererOptions {
    plan::StereoPass stereo_pass = plan::StereoPass::kTwoPasses;
    // The benchmark's vertex-heavy configuration (passes::ForwardConfig::vertex_work).
    std::uint32_t vertex_work = 0;
    passes::ShadowParams shadow;
    passes::TonemapParams tonemap;
    plan::AntiAliasing anti_aliasing = plan::AntiAliasing::kNone;
    passes::TaaParams taa;
    std::optional<passes::SsaoVariant> ssao;  // none: no ambient occlusion
    passes::SsaoParams ssao_params;
    bool read_back_ao = false;  // the eyes' AO to the host (needs ssao)
    // A depth-only pass before each forward pass, whose shading then tests for equality: each
    // visible pixel shaded once whatever the draw order. Off by default: on llvmpipe the pass
    // costs more than the shading it saves (docs/benchmarks.md, "Shading each pixel once").
    bool depth_prepass = false;
    // Tone map each eye in a pass of its own in hybrid even where the composite could write the
    // display image itself (PlanOptions::separate_tonemap): tests and the paired benchmark.
    bool separate_tonemap = false;
    bool read_back = true;              // display images to the host (PNGs, tests)
    bool read_back_depth = false;       // linear depth to the host (tests, later analyses)
    bool read_back_draw_lists = false;  // each view's chunk list to the host (tests)
    // `--mono-plane auto` (hybrid modes): every frame's m is chosen by the renderer within this
    // budget (renderer/plan/mono_plane_chooser.h) and FrameInputs::mono_plane is ignored; each
    // frame's FrameStats carry the m chosen and why.
    std::optional<plan::AutoMonoPlaneParams> auto_mono_plane;
    // Level of detail (`--lod`, `--lod-error-px`): each view draws each chunk at the coarsest
    // level whose projected error stays within error_px (renderer/plan/lod_selection.h).
    plan::LodOptions lod;
};

// The frame plan's options for a renderer of `mode` built with `options` (one rule for the
// renderer, its benchmarks and its memory planning): blended_chunks, the scene has alphaMode
// BLEND chunks; depth_histogram, `--mono-plane auto` counts the eyes' depths.
plan::PlanOptions plan_options_of(plan::Mode mode, const RendererOptions& options,
                                  bool blended_chunks, bool depth_histogram);

struct FrameInputs {
    StereoViewInputs views;
    double mono_plane = 8.0;  // m, metres in front of the eyes (hybrid modes)
    double overlap_k = 2.0;   // k of eq. 3
    // Grazing surfaces down to this angle (radians) show no cutting line: rig::RigInputs.
    double grazing_angle = 0.017453292519943295;
    double view_blend_band = 0.3;  // metres below m over which view vectors blend (Sect. 4.3)
    plan::DebugView debug = plan::DebugView::kNone;
    // A pass unit's debug view instead (passes::unit_debug_views(): "depth"), or "".
    std::string unit_debug_view{};
    plan::MonoCulling mono_culling = plan::MonoCulling::kOcclusionCull;
    // Drives TAA's jitter and tells whether the history continues: a frame whose index does not
    // follow the renderer's previous one starts the history anew. Unset: the next index.
    std::optional<std::uint64_t> frame_index{};
    // With RendererOptions::auto_mono_plane: the nearest m the chooser may take this frame
    // (a study's hybrid-auto trial at distance m); unset: AutoMonoPlaneParams::min_mono_plane.
    std::optional<double> nearest_auto_plane{};
};

// Where an eye looked from in the last frame, as rasterised (TAA's jitter included): what a
// measurement on its read-back images needs to reproject pixels.
struct EyeFrameGeometry {
    glm::dmat4 view_proj{1.0};
    glm::dvec3 position{0.0};
};

// An eye's linear depth on the GPU after the last submitted frame, for commands recorded after
// it (submit_frame's record_after): the image and the layout the frame's passes left it in.
struct EyeDepthImage {
    const vk_core::Image* image = nullptr;
    vk::ImageLayout layout = vk::ImageLayout::eUndefined;
};

class TransientMemory;

class ModeRenderer {
  public:
    // The scene must outlive the renderer. nearest_mono_plane sizes C's render target once
    // (eq. 8 allocation); 0 sizes it for the first frame's m and grows it if a later m needs more.
    // Uploads the scene for this renderer alone.
    ModeRenderer(const vk_core::Context& ctx, const scenes::Scene& scene, plan::Mode mode,
                 vk::Extent2D eye_extent, const RendererOptions& options,
                 double nearest_mono_plane = 0.0);
    // The same over a scene's shared GPU resources (geometry, chunk table, shadow map), made with
    // options.shadow; refuses (UserError) resources made with other shadow parameters.
    ModeRenderer(const vk_core::Context& ctx, std::shared_ptr<SceneResources> resources,
                 plan::Mode mode, vk::Extent2D eye_extent, const RendererOptions& options,
                 double nearest_mono_plane = 0.0);
    ~ModeRenderer();

    // Frames in flight (vk_core::FrameRing, two): records and submits a frame without waiting
    // for the GPU, after collecting the frame that last used the slot (waiting for it only if it
    // has not completed). Fails (UserError) for inputs the rig refuses. record_after: commands
    // recorded after the frame's last pass into the same submission (a headset's swapchain
    // copies), not timed. With --variant auto (kAuto) each frame is waited for: its GPU time
    // chooses the next frame's variant.
    void submit_frame(const FrameInputs& inputs,
                      const std::function<void(const vk::raii::CommandBuffer&)>& record_after = {});
    // The statistics of the frames that completed since the last call, oldest first; waits for
    // none.
    std::vector<profile::FrameStats> take_completed();
    // Waits for every submitted frame; take_completed() then. The read-backs (eye_image, ...)
    // hold the last submitted frame's once it returns, and only then.
    std::vector<profile::FrameStats> finish_frames();
    // submit_frame and finish_frames: one frame, waited for, and its statistics.
    profile::FrameStats render_frame(
        const FrameInputs& inputs,
        const std::function<void(const vk::raii::CommandBuffer&)>& record_after = {});

    plan::Mode mode() const { return mode_; }
    vk::Extent2D eye_extent() const { return eye_extent_; }
    // Display images to the host from the next frame on (or not: timed benchmark frames).
    void set_read_back(bool read_back) { options_.read_back = read_back; }
    // The last frame's images (options.read_back).
    const RgbaImage& eye_image(Eye eye) const;
    // The last frame's tone-mapped eye on the GPU (R8G8B8A8_SRGB): TRANSFER_SRC_OPTIMAL, and
    // visible to transfer reads (copies, blits) recorded after the frame (record_after). For a
    // headset's swapchain; a command reading it must leave it in that layout, and the next frame
    // overwrites it.
    const vk_core::Image& display_image(Eye eye) const;
    // The last submitted frame's linear depth of the eye on the GPU (ForwardPass::
    // kLinearDepthFormat, sampled usage): metres in front of the eyes' plane, in hybrid C's depth
    // where the eye drew nothing near (the composite), MONOPLANE_SKY_LINEAR_DEPTH for the sky.
    // Under MSAA the resolved (sample-averaged) image; under TAA this frame's jittered depth, the
    // one the history resolve was fed. In record_after, or between frames; a command reading it
    // must leave it in that layout, and the next frame overwrites it.
    EyeDepthImage eye_linear_depth_image(Eye eye) const;
    // C's tone-mapped image, or nullptr when the last frame had none (stereo, or m >= f).
    const RgbaImage* mono_image() const;
    // Metres in front of the eyes' plane per pixel, MONOPLANE_SKY_LINEAR_DEPTH for the sky
    // (options.read_back_depth).
    const std::vector<float>& eye_linear_depth(Eye eye) const;
    // The eye's ambient occlusion in [0, 1] per pixel (options.ssao and read_back_ao); in hybrid
    // mode the far region shows C's AO as mapped into the eye.
    const std::vector<float>& eye_ao(Eye eye) const;
    const EyeFrameGeometry& eye_geometry(Eye eye) const;
    // Whether the last frame started TAA's history anew (no TAA: always).
    bool history_restarted() const { return !history_valid_; }
    // The rig of the last hybrid frame.
    const std::optional<rig::Rig>& last_rig() const { return rig_; }
    // The chunk indices the last frame drew in a view, in draw order (read_back_draw_lists).
    std::vector<std::uint32_t> drawn_chunks(passes::CullView view) const;
    // Their draw commands (read_back_draw_lists): level of detail and instance count included.
    std::vector<vk::DrawIndexedIndirectCommand> drawn_commands(passes::CullView view) const;
    // The scene's shared resources: its levels of detail, their build time.
    const SceneResources& scene_resources() const { return *resources_; }
    // The plan the last frame executed (render --json, bench.json).
    const plan::FramePlan& last_plan() const { return last_plan_; }
    // Tests only: frames from now on leave out the compiled barriers `drop` selects (what the
    // synchronisation validation layer must then report).
    void drop_barriers_for_test(executor::GraphExecutor::BarrierFilter drop) {
        executor_.drop_barriers_for_test(std::move(drop));
    }
    // The variant the last hybrid frame used (FrameInputs::mono_culling resolved: with kAuto,
    // the one the measurement chose or is trying).
    plan::MonoCulling last_variant() const { return last_variant_; }
    // With RendererOptions::auto_mono_plane: the last submitted frame's choice of m.
    const plan::MonoPlaneDecision* last_mono_plane_decision() const {
        return auto_mono_plane_ ? &auto_mono_plane_->last() : nullptr;
    }
    // With RendererOptions::auto_mono_plane: the depth histogram of the last completed frame
    // that counted one (null before), which with read_back_depth is eye_linear_depth's frame.
    const plan::DepthHistogram* last_depth_histogram() const {
        if (!auto_mono_plane_ || !auto_mono_plane_->last_histogram()) return nullptr;
        return &*auto_mono_plane_->last_histogram();
    }

  private:
    struct ForwardImages;
    struct View;
    struct MonoView;

    void ensure_mono_view(int width, int height);
    // Makes the pyramid large enough for C's allocation (its readers take it from the frame).
    void ensure_pyramid();
    // view_proj: as rasterised (jittered under TAA); unjittered: the same without the jitter,
    // for velocity.
    void update_view(View& view, const glm::dmat4& view_proj, const glm::dmat4& unjittered,
                     const glm::dvec3& position, const FrameInputs& inputs,
                     const glm::dvec3& mono_position, double blend_band,
                     const glm::dmat4& light_view_proj, double hidden_depth_threshold = 0.0);

    // A frame: its state, the plan for it, and one recorder per kind of pass.
    struct FrameState;
    FrameState prepare_frame(const FrameInputs& inputs);
    // The inputs with this frame's m: FrameInputs::mono_plane, or with auto_mono_plane the
    // chooser's (held in auto_inputs_ until the frame is recorded).
    const FrameInputs& resolve_mono_plane(const FrameInputs& inputs);
    // Whether TAA's history may continue from the last frame's m to this frame's.
    bool history_continues_at(double mono_plane) const;
    void build_frame_rig(const FrameInputs& inputs, FrameState& frame);
    void resolve_variant(const FrameInputs& inputs, FrameState& frame);
    void update_frame_views(const FrameInputs& inputs, FrameState& frame);
    // Makes last_plan_ this frame's plan (kept when nothing it depends on changed).
    void update_plan(const FrameInputs& inputs, const FrameState& frame);
    // The device images the plan's resources are this frame (resource_bindings.cpp).
    std::vector<executor::BoundResource> bind_resources();
    // An eye's or C's view (null for C before its first frame); not kNone or kEyes.
    const View* view_of(plan::ViewId view) const;
    std::vector<vk_core::ImageRange> view_images(const plan::ResourceKey& key) const;
    // The one device image of a view's resource (a pass unit's), or of a shared one offered to
    // units (the shadow map), or a programming error for a role that is several images or none
    // this frame.
    const vk_core::Image& view_image(const plan::ResourceKey& key) const;
    // Every device image of a view's resource (a pass unit's): SSAO's scratch images, or the one
    // image view_image gives.
    std::vector<const vk_core::Image*> view_image_set(const plan::ResourceKey& key) const;
    // The one device buffer of a resource this frame (a pass unit's; slot: the frame's), or a
    // programming error for one not offered to units (the LOD state is not).
    const vk_core::Buffer& frame_buffer(const plan::ResourceKey& key, std::uint32_t slot) const;
    // Before a view's images go: the executor must not take their states for new ones.
    void forget_images(const View& view);
    std::optional<passes::Predicate> predicate(plan::GpuPredicate when) const;
    // What the units' recorders are made with and read each frame (the renderer's options).
    passes::UnitSettings unit_settings() const;
    // The pass's barriers (the executor's), its profiler scopes, and its commands.
    void record_pass(const vk::raii::CommandBuffer& cmd, std::size_t pass, const FrameState& frame);
    void record_planned(const vk::raii::CommandBuffer& cmd, const plan::PlannedPass& pass,
                        const FrameState& frame, passes::StepSync& sync);
    // The frame's values for the units' recordings (FrameState::unit_values).
    passes::UnitFrameValues unit_frame_values(const FrameState& frame) const;
    // How C's image maps into each eye this frame (the composite unit's values).
    passes::CompositeValues composite_values(const FrameState& frame) const;
    // A pass unit's pass, by its recorder (made on its first pass; unit_recording.cpp).
    void record_unit(const vk::raii::CommandBuffer& cmd, const plan::PlannedPass& pass,
                     const FrameState& frame, passes::StepSync& sync);
    // Waits for the slot's frame (if one is in flight) and queues its statistics.
    void complete_frame(std::uint32_t slot);
    // complete_frame for every slot, oldest first: nothing of this renderer is in flight.
    void drain_frames();
    // A completed frame's statistics (the slot's queries and counts).
    profile::FrameStats collect_frame(std::uint32_t slot, double record_ms) const;
    // The read-back buffers to the host images, after a drain.
    void read_back_last_frame();
    // Whether the scene's routing flags may be honoured this frame (scenes::ChunkRouting).
    void decide_routing(const FrameInputs& inputs, passes::CullFrame& cull) const;

    const vk_core::Context& ctx_;
    std::shared_ptr<SceneResources> resources_;
    const scenes::Scene& scene_;
    plan::Mode mode_;
    vk::Extent2D eye_extent_;
    RendererOptions options_;
    double nearest_mono_plane_;
    bool blended_chunks_;  // the scene has alphaMode BLEND chunks (frame_plan.h: PlanOptions)
    passes::ChunkLists culling_;
    passes::DepthPyramid pyramid_;
    // The pass kinds written as units (renderer/passes/pass_units.h): their declarations, which
    // every plan places, and the recorders of those a frame has run, by name.
    std::vector<plan::PassUnitDeclaration> units_;
    std::map<std::string, std::unique_ptr<passes::UnitRecorder>> unit_recorders_;
    passes::UnitScene unit_scene_;  // the scene as the units use it (resources_'s)
    profile::FrameProfiler profiler_;
    // Single-pass stereo: both eyes' ViewConstants in one buffer (the eyes' forward pass's).
    std::optional<vk_core::Buffer> eye_pair_constants_;
    // Single-pass stereo: both eyes' forward images as two-layer images; outlives eyes_.
    std::unique_ptr<ForwardImages> eye_layers_;
    // Every plan this renderer may execute (transient_memory.h: possible_plans), over which its
    // transient images are placed in shared memory, and the eyes' shared memory; both outlive
    // eyes_ and mono_.
    std::vector<plan::FramePlan> possible_plans_;
    std::unique_ptr<TransientMemory> eye_memory_;
    std::array<std::unique_ptr<View>, 2> eyes_;
    std::unique_ptr<MonoView> mono_;
    bool mono_rendered_ = false;
    std::optional<rig::Rig> rig_;
    plan::FramePlan last_plan_;
    // Owns every frame's synchronisation: compiles the plan's barriers and records them.
    executor::GraphExecutor executor_;
    struct PlanInputs {
        plan::PlanOptions options;
        plan::PlanFrame frame;
        plan::PlanDevice device;
        bool operator==(const PlanInputs&) const = default;
    };
    std::optional<PlanInputs> last_plan_inputs_;  // what last_plan_ was made from
    // Where the draw order the culling pass holds was sorted from (front_to_back_order).
    std::optional<glm::dvec3> draw_order_viewer_;
    // --variant auto: measures the variants on this renderer's frames (reset when m changes).
    plan::VariantChooser variant_chooser_;
    double variant_mono_plane_ = -1.0;
    plan::MonoCulling last_variant_ = plan::MonoCulling::kNoOpt;
    // --mono-plane auto: the chooser, and the inputs of the frame being recorded with its m.
    std::unique_ptr<AutoMonoPlane> auto_mono_plane_;
    FrameInputs auto_inputs_;
    // TAA's history: which of each view's two output images holds it, and what it continues.
    std::uint64_t next_frame_index_ = 0;
    int history_parity_ = 0;
    bool history_valid_ = false;
    double history_mono_plane_ = -1.0;
    // Frames in flight: what the host fills for the next frame, what each submitted frame needs
    // at completion, the statistics completed and not yet taken.
    vk_core::FrameUploads uploads_;
    struct PendingFrame {
        double record_ms = 0.0;
        bool measuring_variant = false;
        bool depth_histogram = false;  // the plan counted the eyes' depth (auto m)
        std::optional<double> mono_plane{};
        std::string mono_plane_reason{};
    };
    std::array<std::optional<PendingFrame>, vk_core::FrameRing::kFramesInFlight> pending_;
    std::vector<profile::FrameStats> completed_;
    std::uint32_t last_slot_ = 0;  // the slot of the last submitted frame
    // Last: destroyed first, it waits for the frames in flight before anything they use goes.
    vk_core::FrameRing ring_;
};

}  // namespace monoplane::modes
