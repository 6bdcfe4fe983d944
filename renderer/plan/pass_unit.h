// A pass kind written as one unit: where a frame places it and what each of its steps reads and
// writes (this half, Vulkan-free, so that the plan stays pure), beside the code that records it
// (renderer/passes/shared/pass_unit.h), in one source file: renderer/passes/<unit>/<unit>_unit.cpp
// compiles twice, its declaration with MONOPLANE_UNIT_DECLARATION into the Vulkan-free
// monoplane_pass_declarations, its recorder with MONOPLANE_UNIT_RECORDER into monoplane_passes.
// A unit is added by its own folder under renderer/passes/ (its source and shader) and one line
// in renderer/passes/pass_unit_list.h; nothing in the plan, the executor or the renderer names a
// unit of a kind of its own. A built-in kind written as a unit (TAA, the depth histogram) keeps
// its PassKind, which the renderer records through the unit, and a unit with user settings has
// its member in UnitSettings (renderer/passes/shared/unit_settings.h), which the renderer fills.
//
// plan_frame (frame_plan.h) calls each unit's place() at the unit's slot with the frame's inputs;
// place() adds the unit's passes, if any, with their steps' declared uses. From there the unit's
// passes are planned passes like any other: the executor places their barriers and checks their
// steps, the graph culls them when nothing reads what they write and keeps their images' memory
// apart from what they use, the profiler times them under pass_name's key ("left.depth_view"),
// and at record time a unit may touch only the resources its current step declared
// (step_declares below, checked in every build).
//
// When may this be called: any time; pure, no device.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "renderer/graph/frame_graph.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/pass_steps.h"

namespace monoplane::plan {

// Where in the frame a unit's passes go. The built-in kinds' order is plan_frame's; a unit takes
// its place between them.
enum class UnitSlot {
    // First in the frame: a unit whose outputs every later pass may read (the chunk culling).
    kFrameStart,
    // After the culling, before the eyes' forward passes: a unit the forward passes read (the
    // shadow map).
    kAfterCulling,
    // The eyes' forward passes (one per eye, or one for both in single-pass stereo).
    kEyesForward,
    // In the hybrid modes only, after the eyes' forward passes, before C's: a unit that reads
    // what the eyes drew to save C's work (the merged depth pyramid, then the occlusion
    // culling, in the order pass_unit_list.h registers them).
    kAfterEyesForward,
    // In the hybrid modes only, after the eyes' (and the pyramid, and the occlusion culling): C's
    // forward pass.
    kMonoForward,
    // In the hybrid modes only, after C's forward pass, before the composite: a unit that
    // post-processes C's colour before it is mapped into the eyes (C's SSAO).
    kMonoPostProcessing,
    // In the hybrid modes only, after C's passes, before the eyes' blended chunks: a unit that
    // maps C into the eyes (the composite).
    kComposite,
    // In the hybrid modes only, after the composite: a unit that draws into the eyes over what
    // the composite mapped (the blended chunks nearer than m, per eye).
    kAfterComposite,
    // After the eyes' forward passes, the composite and the blended chunks: a unit that
    // post-processes the eyes' HDR colour with every surface in place (the eyes' SSAO).
    kEyesPostProcessing,
    // After the eyes' post-processing, before their tone mapping: a unit that resolves an eye's
    // colour (TAA, whose output the tone mapping then reads).
    kBeforeToneMapping,
    // The tone mapping itself, once the units have revised what they placed (the composite has
    // decided whether it writes the display image: PlannedPass::writes_display).
    kToneMapping,
    // After the eyes' (and C's) tone mapping, before the read-back: a unit that reads or replaces
    // the display images (a debug view) or reads the final depths (the depth histogram). Not
    // the eyes' HDR images: where a composite wrote the display image, they lack C's colour.
    kAfterToneMapping,
    // Last: the copies the host reads once the frame has completed (the read-back).
    kReadBack,
};

class UnitPlacement;
struct PassUnitDeclaration;

// The declaration of a built-in kind written as a unit: `kind` and the kind's name, its slot(s),
// its help and its placement (revise unset).
PassUnitDeclaration built_in_unit(PassKind kind, std::vector<UnitSlot> slots, std::string help,
                                  void (*place)(UnitPlacement& placement));
PassUnitDeclaration built_in_unit(PassKind kind, UnitSlot slot, std::string help,
                                  void (*place)(UnitPlacement& placement));

struct PassUnitDeclaration {
    // A built-in kind written as a unit names its kind (PassKind::kTaa): its passes are found
    // (FramePlan::find), named ("left.taa") and keyed by it. A kind added as a unit alone keeps
    // kUnit and goes by its name.
    PassKind kind = PassKind::kUnit;
    // The kind's name: pass_kind_name(kind) for a built-in kind; else the unit's own
    // ("depth_view"), which no built-in kind has. A pass of one view is "left.depth_view".
    std::string name;
    // Where its passes go: place() is called at each of these slots (UnitPlacement::slot() says
    // which), in plan_frame's order; most units have one.
    std::vector<UnitSlot> slots = {UnitSlot::kAfterToneMapping};
    // The `--debug-view` name that shows this unit ("depth"), for a unit that is a debug view:
    // PlanFrame::unit_debug_view selects it. Unset for a unit that place() decides alone.
    std::optional<std::string> debug_view;
    std::string help;  // what it shows, for a command's --help
    // Adds the unit's passes to this frame, if any (a plain function: a unit holds no state in
    // its declaration).
    void (*place)(UnitPlacement& placement) = nullptr;
    // Revises the passes place() added (UnitPlacement::own_passes) once every pass before the
    // tone mapping is placed, before the tone mapping itself; nullptr: nothing to revise. What
    // a unit can know only when it sees what comes after it: whether a later pass reads an image
    // it writes (UnitPlacement::used_after).
    void (*revise)(UnitPlacement& placement) = nullptr;
};

// What a unit's place() reads (the frame's inputs) and adds to (the plan).
class UnitPlacement {
  public:
    UnitPlacement(const PassUnitDeclaration& unit, UnitSlot slot, const PlanOptions& options,
                  const PlanFrame& frame, const PlanDevice& device, FramePlan& plan,
                  PlanResources& resources)
        : unit_(unit),
          slot_(slot),
          options_(options),
          frame_(frame),
          device_(device),
          plan_(plan),
          resources_(resources) {}

    // The slot being placed (one of PassUnitDeclaration::slots; for revise(), the tone
    // mapping's).
    UnitSlot slot() const { return slot_; }
    const PlanOptions& options() const { return options_; }
    const PlanFrame& frame() const { return frame_; }
    const PlanDevice& device() const { return device_; }
    // The passes placed so far (the kinds and units before this slot), to read.
    const FramePlan& plan() const { return plan_; }
    // The device evaluates GPU predicates (PlanDevice::conditional_rendering): a pass may run
    // under one (PlannedPass::when); without, every pass runs as planned.
    bool predicated() const { return device_.conditional_rendering; }
    // `predicate` where the device evaluates predicates, else kAlways.
    GpuPredicate when(GpuPredicate predicate) const {
        return predicated() ? predicate : GpuPredicate::kAlways;
    }
    // A hybrid mode that draws C this frame (something lies beyond m).
    bool draws_mono() const { return options_.mode != Mode::kStereo && !frame_.mono_skipped; }
    // Why a pass of C's (or one that maps C) is skipped this frame: set when a hybrid mode draws
    // no C (PlanFrame::mono_skipped), the words every such pass gives.
    std::optional<std::string> no_mono_reason() const;
    // Whether this frame shows this unit's debug view.
    bool debug_view_shown() const {
        return unit_.debug_view && frame_.unit_debug_view == *unit_.debug_view;
    }
    // The handles its steps use (images and buffers by view and role).
    PlanResources& resources() { return resources_; }
    // A pass of this unit for `view` (kNone: over every view), at the end of the plan so far;
    // its steps are the caller's to add (graph::StepBuilder).
    PlannedPass& add_pass(ViewId view = ViewId::kNone);
    // The host reads `buffer` once the frame has completed (a result the renderer takes back):
    // what keeps the passes that write it from being culled.
    void read_by_host(graph::BufferHandle buffer);
    // This unit's passes placed so far, in plan order, to revise (PassUnitDeclaration::revise).
    // Valid until the next add_pass.
    std::vector<PlannedPass*> own_passes();
    // Whether a pass placed after `pass` (one of the plan's) uses `image` in any step.
    bool used_after(const PlannedPass& pass, graph::ImageHandle image) const;

  private:
    const PassUnitDeclaration& unit_;
    UnitSlot slot_;
    const PlanOptions& options_;
    const PlanFrame& frame_;
    const PlanDevice& device_;
    FramePlan& plan_;
    PlanResources& resources_;
};

// Whether `step` declares a use of `resource` (a handle of the plan's resource table): what a
// unit's recording may touch in that step.
bool step_declares(const graph::Step& step, std::uint16_t resource);

}  // namespace monoplane::plan
