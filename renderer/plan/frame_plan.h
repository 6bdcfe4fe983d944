// The frame plan: which passes a frame runs, in what order, what each reads and writes, under
// which GPU predicate, and, for a pass the frame leaves out, why. A pure function of the mode, the
// renderer's options, the frame's rig and the device's capabilities: the renderer
// (renderer/modes/mode_renderer.h) only executes it, render --json and bench.json report it
// ("plan"), and tests/unit/frame_plan_test.cpp checks it without a GPU.
//
// The plans (docs/architecture.md prints them as plan_frame produces them):
//   stereo:          culling, shadow*, per eye {forward: chunks, sky}, [ssao],
//                    [per eye {taa}], per eye {tonemap}, read-back
//                    (stereo-multiview, stereo-gs, stereo-instanced: one eyes.forward for
//                    both eyes)
//   hybrid:          culling, shadow*, per eye {forward n..m: chunks, sky only if C has nothing},
//                    [depth pyramid, [occlusion culling]], C {forward m-eps..f + sky}, [C's ssao],
//                    per eye {composite C through M_{E->C}}, [per eye {blended chunks nearer
//                    than m, tested against the composite's depth}], [ssao of the near content],
//                    [per eye {taa}], per eye {tonemap}, [C's tonemap], [depth histogram],
//                    read-back; without TAA and SSAO each composite also tone maps into the eye's
//                    display image (one full-screen pass per eye), and the eye's tonemap runs only
//                    when C had nothing (the composite is then skipped), or not at all
//   hybrid-farfield: as hybrid with C at the eyes' centre, no pyramid, an offset copy
// (* only when the light's region changed). A scene with blended chunks (alphaMode BLEND) draws
// them last in each forward pass; in hybrid, C draws those wholly beyond m and the eyes the
// others in their transparency passes, after the composite. With m >= f (the rig's mono_skipped)
// hybrid's executed passes are exactly stereo's: nothing lies beyond the plane.
//
// Every kind of pass is a unit (renderer/plan/pass_unit.h): plan_frame places the units slot by
// slot in the order above, then reads what they placed (the GPU predicates' reads, the passes
// nothing reads).
//
// When may this be called: any time; it allocates and touches no device.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/plan/frame_resources.h"
#include "renderer/plan/render_choices.h"

namespace monoplane::plan {

// What a pass does; the executor records each kind with one function.
enum class PassKind {
    kCulling,           // GPU chunk culling into the views' indirect draw lists and predicates
    kShadow,            // the sun's shadow map
    kForward,           // a view's forward pass (draws below): left, right, eyes or mono
    kDepthPyramid,      // the merged depth pyramid of both eyes (papers/000 Sect. 4.4)
    kOcclusionCulling,  // C's list re-sorted against the pyramid
    kComposite,         // C mapped into an eye (eq. 5) or offset-copied (hybrid-farfield)
    kTransparency,      // hybrid: an eye's blended chunks nearer than m, after the composite
    // Ambient occlusion: view kMono is C's, once for both eyes (hybrid); view kNone the eyes'
    // (near content only in hybrid).
    kSsao,
    kTaa,             // an eye's temporal anti-aliasing resolve
    kTonemap,         // an eye's (or C's) tone mapping into its display image
    kDepthHistogram,  // both eyes' final depth counted into bins (--mono-plane auto)
    kReadback,        // images, depths, AO and draw lists to the host; not part of GPU time
    // A pass kind added as one unit alone (renderer/plan/pass_unit.h): PlannedPass::unit names
    // it. The built-in kinds above that are written as units (kTaa) keep their kind.
    kUnit,
};
std::string pass_kind_name(PassKind kind);  // "culling", "forward", "ssao", ...
// The one name of a planned pass: its kind's name, after its view's for a pass of one view
// ("shadow", "left.forward", "mono.ssao", "right.tonemap"). It keys the profiler's scopes,
// bench.json's "passes" and `render --json`'s plan; code compares kinds and views, never names.
std::string pass_name(PassKind kind, ViewId view);
// The pass of that name, or nullopt: what reads a name back (bench.json, a command's option).
std::optional<std::pair<PassKind, ViewId>> parse_pass_name(const std::string& name);
// The pass a pipeline-statistics scope (PlannedPass::statistics_scope) counts: a view's forward
// pass, whose scope is the view's name ("left", "eyes", "mono"), or another pass of one view,
// whose scope is its name ("left.composite", "right.transparency"); nullopt for anything else.
std::optional<std::pair<PassKind, ViewId>> statistics_scope_pass(const std::string& scope);
// A pass a stereo frame never runs: what hybrid adds (C's forward pass, the pyramid, occlusion
// culling, C's SSAO, the composites, the eyes' transparency after them, C's tone mapping).
bool runs_only_in_hybrid(PassKind kind, ViewId view);

// A predicate the GPU evaluates from the culling pass's words (VK_EXT_conditional_rendering):
// the plan cannot know, the GPU skips. Without conditional rendering every predicate is kAlways.
enum class GpuPredicate {
    kAlways,
    kMonoAny,          // C's list is not empty
    kMonoNone,         // C's list is empty (the eyes then draw their own sky)
    kMonoDepthTested,  // C has something and an eye drew something (a pyramid was built)
};
std::string gpu_predicate_name(GpuPredicate predicate);  // "always", "mono-any", ...

// What a forward pass draws, in order; each step may run under a GPU predicate.
// With kDepthPrepass first, the chunk steps after it test depth for equality and write none, so
// each visible pixel is shaded about once whatever the draw order (docs/benchmarks.md measures
// the fragments it saves); without it they test and write as usual. The chunk steps draw the
// opaque chunks, then the masked ones (alphaMode MASK: fragments below the cut-off dropped, with
// MSAA alpha to coverage); kBlended draws the blended ones last.
enum class DrawStep {
    kMaskHidden,         // C only, before the pre-pass: pixels hidden in both eyes at depth 1
    kDepthPrepass,       // the view's chunk list, depth only (no fragment shader)
    kChunks,             // the view's chunk list, every fragment shaded
    kChunksShowRouting,  // the debug view "routing": chunks coloured by the lists they are in
    kSky,                // the sky where nothing was drawn
    // The view's blended chunks (alphaMode BLEND) in the list's order, back to front, over what
    // the steps before drew: depth tested, not written; colour blended by the base colour's
    // alpha (glTF: straight alpha, "over"); linear depth and velocity keep what lies behind.
    kBlended,
};
std::string draw_step_name(DrawStep step);  // "mask-hidden", "depth-prepass", "chunks", ...

struct PlannedDraw {
    DrawStep step = DrawStep::kChunks;
    GpuPredicate when = GpuPredicate::kAlways;
    bool operator==(const PlannedDraw&) const = default;
};

struct PlannedPass {
    PassKind kind = PassKind::kCulling;
    // A pass of a unit: the unit's name (PassUnitDeclaration::name; for kUnit it stands for the
    // kind's), which the renderer records it by; "" for the kinds the renderer records itself.
    std::string unit;
    // pass_name(kind, view) (a unit's: its name for the kind's): the profiler's scope and the
    // key of bench.json's "passes".
    std::string name;
    // The camera it draws for; kNone for passes over every view (culling, shadow, pyramid, ssao,
    // read-back).
    ViewId view = ViewId::kNone;
    // The pipeline-statistics scope of the pass (per-view counters in render/bench), or "".
    // Forward passes count under their view, composites under "<eye>.composite".
    std::string statistics_scope;
    // What the pass records, in order, and how each step uses the frame's resources (typed
    // handles into FramePlan::resources). The executor places the compiled barriers before each.
    std::vector<graph::Step> steps;
    GpuPredicate when = GpuPredicate::kAlways;  // the whole pass
    std::vector<PlannedDraw> draws;             // kForward only
    // kComposite: the composite also tone maps, writing the eye's display image whole (C's
    // colour where the eye drew nothing, the eye's own elsewhere) instead of C's colour into the
    // eye's HDR image. Planned where nothing but the eye's tonemap reads that HDR image after
    // the composite; the tonemap is then left out, or runs only if mono-none.
    bool writes_display = false;
    // Set when this frame leaves the pass out: why, for a reader ("light region unchanged: the
    // shadow map is reused", "m >= far: nothing lies beyond the mono plane", "culled: nothing
    // reads mono.display", ...).
    std::optional<std::string> skipped;
};

struct FramePlan {
    std::vector<PlannedPass> passes;  // in execution order, skipped ones where they would run
    graph::ResourceTable resources;   // every resource a pass uses
    std::vector<ResourceKey> keys;    // keys[handle index]: what the executor binds
    // Uses after the last pass: the host's reads of the read-back buffers, and the images other
    // components read between frames (display images for a headset's swapchain, the eyes'
    // linear depth for its depth layer).
    std::vector<graph::ResourceUse> exports;

    // The passes that run, in order.
    std::vector<const PlannedPass*> executed() const;
    // The names of the passes that run, in order (what tests compare).
    std::vector<std::string> executed_names() const;
    // The pass of that kind for that view (kNone: the pass over every view), or nullptr.
    const PlannedPass* find(PassKind kind, ViewId view = ViewId::kNone) const;
    // A unit's pass (PassUnitDeclaration::name) for that view, or nullptr.
    const PlannedPass* find_unit(const std::string& unit, ViewId view = ViewId::kNone) const;
    // Whether this frame runs that pass (planned and not skipped).
    bool runs(PassKind kind, ViewId view = ViewId::kNone) const;
    // The names of the resources a pass reads (a read-modify-write included) or writes, in the
    // order its steps first use them: what tests and `render --json` show.
    std::vector<std::string> reads(const PlannedPass& pass) const;
    std::vector<std::string> writes(const PlannedPass& pass) const;
    // The handle of a resource by key, or nullopt when no pass uses it.
    std::optional<std::uint16_t> handle(const ResourceKey& key) const;
    // The passes as the graph's compile step sees them (runs = not skipped).
    std::vector<graph::GraphPass> graph_passes() const;
};

// What the renderer was built with (RendererOptions, less what does not change the plan).
struct PlanOptions {
    Mode mode = Mode::kStereo;
    StereoPass stereo_pass = StereoPass::kTwoPasses;
    AntiAliasing anti_aliasing = AntiAliasing::kNone;
    bool ssao = false;  // any SSAO variant
    // papers/002's stereo-consistent SSAO (its steps run over both eyes at once); else per eye.
    bool ssao_stereo = false;
    bool depth_prepass = false;  // RendererOptions::depth_prepass
    bool read_back = true;       // display images (and C's tone-mapped image) to the host
    bool read_back_depth = false;
    bool read_back_ao = false;
    bool read_back_draw_lists = false;
    // `--mono-plane auto`: the eyes' final depth is counted for the next frames' choice of m.
    bool depth_histogram = false;
    // Keep each eye's tone mapping a pass of its own even where the composite could write the
    // display image (PlannedPass::writes_display): the comparisons of tests and benchmarks.
    bool separate_tonemap = false;
    // The scene has blended chunks (alphaMode BLEND): each view draws them last; in hybrid the
    // eyes draw theirs after the composite (PassKind::kTransparency).
    bool blended = false;
    bool operator==(const PlanOptions&) const = default;
};

// What this frame brings.
struct PlanFrame {
    // The rig's verdict (rig::Rig::mono_skipped): nothing lies beyond the mono plane (m >= far),
    // so hybrid draws no C. Ignored in stereo.
    bool mono_skipped = false;
    // The variant this frame uses: never kAuto (the renderer resolves it; plan_frame refuses it).
    MonoCulling mono_culling = MonoCulling::kOcclusionCull;
    DebugView debug = DebugView::kNone;
    // The light's region moved since the shadow map was drawn (or it never was).
    bool shadow_needed = true;
    // A pass unit's debug view shown this frame (PassUnitDeclaration::debug_view: "depth"), or
    // "" for none; beside `debug`, which names the built-in ones.
    std::string unit_debug_view;
    bool operator==(const PlanFrame&) const = default;
};

struct PlanDevice {
    bool conditional_rendering = false;  // VK_EXT_conditional_rendering: GPU predicates
    // independentBlend: a pipeline may write one colour attachment and leave another, as the
    // composite that writes the display image does (PlannedPass::writes_display); without it the
    // tone mapping stays a pass of its own. Almost every device has it, hence the default.
    bool independent_blend = true;
    bool operator==(const PlanDevice&) const = default;
};

// Why C is not depth-tested against what the eyes drew this frame (papers/000 Sect. 4.4: no
// merged depth pyramid is built, C masks no hidden pixels and culls no hidden chunks), or
// nullopt when it is: a hybrid frame that draws C, monoplane's own hybrid (the far field's offset
// copy is another mapping), not the debug view of C's whole image, not the variant no-opt. One
// rule for the pyramid, the occlusion culling and C's mask.
std::optional<std::string> depth_test_skip_reason(const PlanOptions& options,
                                                  const PlanFrame& frame);

// The plan of one frame with the pass kinds written as units (renderer/plan/pass_unit.h), each
// placed at its slot: TAA is one, so a plan without the registered units has no TAA resolve.
// passes::plan_frame (renderer/passes/pass_unit_declarations.h) passes every registered unit.
struct PassUnitDeclaration;
FramePlan plan_frame(const PlanOptions& options, const PlanFrame& frame, const PlanDevice& device,
                     const std::vector<PassUnitDeclaration>& units);

}  // namespace monoplane::plan
