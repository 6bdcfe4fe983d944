#include "renderer/plan/frame_plan.h"

#include <algorithm>
#include <array>
#include <utility>

#include "common/name_table.h"
#include "common/programming_error.h"
#include "renderer/plan/pass_steps.h"
#include "renderer/plan/pass_unit.h"

namespace monoplane::plan {
namespace {

constexpr NameTable<PassKind> kPassKindNames = {{PassKind::kCulling, "culling"},
                                                {PassKind::kShadow, "shadow"},
                                                {PassKind::kForward, "forward"},
                                                {PassKind::kDepthPyramid, "depth_pyramid"},
                                                {PassKind::kOcclusionCulling, "occlusion_culling"},
                                                {PassKind::kComposite, "composite"},
                                                {PassKind::kTransparency, "transparency"},
                                                {PassKind::kSsao, "ssao"},
                                                {PassKind::kTaa, "taa"},
                                                {PassKind::kTonemap, "tonemap"},
                                                {PassKind::kDepthHistogram, "depth_histogram"},
                                                {PassKind::kReadback, "readback"},
                                                {PassKind::kUnit, "unit"}};
constexpr NameTable<GpuPredicate> kPredicateNames = {
    {GpuPredicate::kAlways, "always"},
    {GpuPredicate::kMonoAny, "mono-any"},
    {GpuPredicate::kMonoNone, "mono-none"},
    {GpuPredicate::kMonoDepthTested, "mono-depth-tested"}};
constexpr NameTable<DrawStep> kDrawStepNames = {
    {DrawStep::kMaskHidden, "mask-hidden"},
    {DrawStep::kDepthPrepass, "depth-prepass"},
    {DrawStep::kChunks, "chunks"},
    {DrawStep::kChunksShowRouting, "chunks-show-routing"},
    {DrawStep::kSky, "sky"},
    {DrawStep::kBlended, "blended"}};

// Why C's passes are skipped in a hybrid frame that draws no C (UnitPlacement::no_mono_reason).
constexpr const char* kNoMonoReason = "m >= far: nothing lies beyond the mono plane, no C";

class PlanBuilder {
  public:
    PlanBuilder(const PlanOptions& options, const PlanFrame& frame, const PlanDevice& device,
                const std::vector<PassUnitDeclaration>& units)
        : options_(options), frame_(frame), device_(device), units_(units), r_(plan_) {}

    FramePlan build() {
        add_units(UnitSlot::kFrameStart);
        add_units(UnitSlot::kAfterCulling);
        add_units(UnitSlot::kEyesForward);
        if (options_.mode != Mode::kStereo) {
            add_units(UnitSlot::kAfterEyesForward);
            add_units(UnitSlot::kMonoForward);
            add_units(UnitSlot::kMonoPostProcessing);
            add_units(UnitSlot::kComposite);
            add_units(UnitSlot::kAfterComposite);
        }
        add_post_processing();
        add_units(UnitSlot::kAfterToneMapping);
        add_units(UnitSlot::kReadBack);
        add_exports();
        declare_predicate_reads();
        cull_unread_passes();
        return std::move(plan_);
    }

  private:
    void add_post_processing() {
        add_units(UnitSlot::kEyesPostProcessing);
        add_units(UnitSlot::kBeforeToneMapping);
        revise_units();
        add_units(UnitSlot::kToneMapping);
    }

    void add_units(UnitSlot slot) {
        for (const PassUnitDeclaration& unit : units_) {
            if (std::find(unit.slots.begin(), unit.slots.end(), slot) == unit.slots.end()) {
                continue;
            }
            UnitPlacement placement(unit, slot, options_, frame_, device_, plan_, r_);
            unit.place(placement);
        }
    }

    // Every unit revises what it placed once the passes before the tone mapping are known (the
    // composite decides whether it writes the display image).
    void revise_units() {
        for (const PassUnitDeclaration& unit : units_) {
            if (unit.revise == nullptr) continue;
            UnitPlacement placement(unit, UnitSlot::kToneMapping, options_, frame_, device_, plan_,
                                    r_);
            unit.revise(placement);
        }
    }

    // What other components read between frames: a headset's compositor copies the display
    // images into its swapchain and samples the eyes' linear depth for its depth layer.
    void add_exports() {
        for (ViewId eye : kEyeViews) {
            plan_.exports.push_back(
                {r_.image(eye, ImageRole::kDisplay).index, graph::Use::kTransferSrc});
            plan_.exports.push_back(
                {r_.image(eye, ImageRole::kLinearDepth).index, graph::Use::kSampledFragment});
        }
    }

    // A pass the GPU skips by a predicate, whole or in some of its draws, reads the culling's
    // words (conditional rendering) in every step it records: one rule for every kind of pass.
    void declare_predicate_reads() {
        if (!device_.conditional_rendering) return;
        const graph::BufferHandle predicates = r_.shared(BufferRole::kPredicates);
        const auto conditional = [](GpuPredicate when) { return when != GpuPredicate::kAlways; };
        for (PlannedPass& pass : plan_.passes) {
            const bool draws_predicated =
                std::any_of(pass.draws.begin(), pass.draws.end(),
                            [&](const PlannedDraw& d) { return conditional(d.when); });
            if (!conditional(pass.when) && !draws_predicated) continue;
            for (graph::Step& step : pass.steps) {
                graph::StepBuilder(step).use(predicates, graph::Use::kConditional);
            }
        }
    }

    // A pass whose outputs nothing reads (up to the exports and what persists) does not run.
    void cull_unread_passes() {
        const std::vector<bool> needed =
            graph::needed_passes(plan_.resources, plan_.graph_passes(), plan_.exports);
        for (std::size_t p = 0; p < plan_.passes.size(); ++p) {
            PlannedPass& pass = plan_.passes[p];
            if (pass.skipped || needed[p]) continue;
            std::string outputs;
            for (const std::string& name : plan_.writes(pass)) {
                outputs += (outputs.empty() ? "" : ", ") + name;
            }
            pass.skipped = "culled: nothing reads " + outputs;
        }
    }

    const PlanOptions& options_;
    const PlanFrame& frame_;
    const PlanDevice& device_;
    const std::vector<PassUnitDeclaration>& units_;
    FramePlan plan_;
    PlanResources r_;
};

}  // namespace

std::optional<std::string> depth_test_skip_reason(const PlanOptions& options,
                                                  const PlanFrame& frame) {
    if (options.mode == Mode::kStereo) return "stereo: no C";
    if (frame.mono_skipped) return std::string(kNoMonoReason);
    if (options.mode == Mode::kHybridFarfield) return "hybrid-farfield: C is frustum-culled only";
    if (frame.debug == DebugView::kMonoOnly) return "debug view mono-only: C's whole image";
    if (frame.mono_culling == MonoCulling::kNoOpt) return "variant no-opt: no depth test";
    return std::nullopt;
}

std::string pass_kind_name(PassKind kind) {
    return name_of(kPassKindNames, kind);
}

std::string pass_name(PassKind kind, ViewId view) {
    const std::string kind_name = pass_kind_name(kind);
    return view == ViewId::kNone ? kind_name : view_name(view) + "." + kind_name;
}

std::optional<std::pair<PassKind, ViewId>> parse_pass_name(const std::string& name) {
    const std::size_t dot = name.find('.');
    const std::optional<ViewId> view =
        dot == std::string::npos ? ViewId::kNone : parse_view(name.substr(0, dot));
    const std::optional<PassKind> kind =
        parse_name(kPassKindNames, dot == std::string::npos ? name : name.substr(dot + 1));
    // "unit" names no pass: a unit's passes go by the unit's own name.
    if (!view || !kind || *kind == PassKind::kUnit ||
        (dot != std::string::npos && *view == ViewId::kNone)) {
        return std::nullopt;
    }
    return std::make_pair(*kind, *view);
}

std::optional<std::pair<PassKind, ViewId>> statistics_scope_pass(const std::string& scope) {
    if (const auto view = parse_view(scope); view && *view != ViewId::kNone) {
        return std::make_pair(PassKind::kForward, *view);
    }
    const auto pass = parse_pass_name(scope);
    if (!pass || pass->second == ViewId::kNone) return std::nullopt;
    return pass;
}

bool runs_only_in_hybrid(PassKind kind, ViewId view) {
    switch (kind) {
        case PassKind::kDepthPyramid:
        case PassKind::kOcclusionCulling:
        case PassKind::kComposite:
        case PassKind::kTransparency:
            return true;
        case PassKind::kForward:
        case PassKind::kSsao:
        case PassKind::kTonemap:
            return view == ViewId::kMono;
        default:
            return false;
    }
}

std::string gpu_predicate_name(GpuPredicate predicate) {
    return name_of(kPredicateNames, predicate);
}

std::string draw_step_name(DrawStep step) {
    return name_of(kDrawStepNames, step);
}

std::vector<const PlannedPass*> FramePlan::executed() const {
    std::vector<const PlannedPass*> result;
    for (const PlannedPass& pass : passes) {
        if (!pass.skipped) result.push_back(&pass);
    }
    return result;
}

std::vector<std::string> FramePlan::executed_names() const {
    std::vector<std::string> names;
    for (const PlannedPass* pass : executed()) names.push_back(pass->name);
    return names;
}

const PlannedPass* FramePlan::find(PassKind kind, ViewId view) const {
    for (const PlannedPass& pass : passes) {
        if (pass.kind == kind && pass.view == view) return &pass;
    }
    return nullptr;
}

const PlannedPass* FramePlan::find_unit(const std::string& unit, ViewId view) const {
    for (const PlannedPass& pass : passes) {
        if (pass.unit == unit && pass.view == view) return &pass;
    }
    return nullptr;
}

bool FramePlan::runs(PassKind kind, ViewId view) const {
    const PlannedPass* pass = find(kind, view);
    return pass != nullptr && !pass->skipped;
}

namespace {

// The distinct names of the resources a pass reads (or writes), in first-use order.
std::vector<std::string> resource_names(const FramePlan& plan, const PlannedPass& pass,
                                        bool writes) {
    std::vector<std::string> names;
    for (const graph::Step& step : pass.steps) {
        for (const graph::ResourceUse& use : step.uses) {
            const graph::UseScope scope = graph::use_scope(use.use);
            // A blend is both; attachment and storage writes are listed as writes.
            const bool reads = !scope.writes || use.use == graph::Use::kColorBlend;
            if (writes ? !scope.writes : !reads) continue;
            const std::string& name = plan.resources[use.resource].name;
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        }
    }
    return names;
}

}  // namespace

std::vector<std::string> FramePlan::reads(const PlannedPass& pass) const {
    return resource_names(*this, pass, false);
}

std::vector<std::string> FramePlan::writes(const PlannedPass& pass) const {
    return resource_names(*this, pass, true);
}

std::optional<std::uint16_t> FramePlan::handle(const ResourceKey& key) const {
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (keys[k] == key) return static_cast<std::uint16_t>(k);
    }
    return std::nullopt;
}

std::vector<graph::GraphPass> FramePlan::graph_passes() const {
    std::vector<graph::GraphPass> graph;
    for (const PlannedPass& pass : passes) {
        graph.push_back({pass.name, &pass.steps, !pass.skipped.has_value()});
    }
    return graph;
}

FramePlan plan_frame(const PlanOptions& options, const PlanFrame& frame, const PlanDevice& device,
                     const std::vector<PassUnitDeclaration>& units) {
    // The renderer resolves kAuto to this frame's variant first.
    MONOPLANE_EXPECTS(frame.mono_culling != MonoCulling::kAuto);
    for (const PassUnitDeclaration& unit : units) {
        MONOPLANE_EXPECTS(unit.place != nullptr);
        // A built-in kind's unit goes by the kind's name; any other unit's name stands for a
        // kind's in its passes' names, and must not read back as one.
        if (unit.kind != PassKind::kUnit && unit.name != pass_kind_name(unit.kind)) {
            programming_error("pass unit '" + unit.name + "' is kind '" +
                              pass_kind_name(unit.kind) + "' and must have its name");
        }
        if (unit.kind == PassKind::kUnit && parse_pass_name(unit.name)) {
            programming_error("pass unit '" + unit.name + "' has the name of a built-in kind");
        }
    }
    return PlanBuilder(options, frame, device, units).build();
}

PlannedPass& UnitPlacement::add_pass(ViewId view) {
    PlannedPass pass;
    pass.kind = unit_.kind;
    pass.unit = unit_.name;
    pass.name = view == ViewId::kNone ? unit_.name : view_name(view) + "." + unit_.name;
    pass.view = view;
    plan_.passes.push_back(std::move(pass));
    return plan_.passes.back();
}

void UnitPlacement::read_by_host(graph::BufferHandle buffer) {
    plan_.exports.push_back({buffer.index, graph::Use::kHostRead});
}

PassUnitDeclaration built_in_unit(PassKind kind, std::vector<UnitSlot> slots, std::string help,
                                  void (*place)(UnitPlacement& placement)) {
    PassUnitDeclaration unit;
    unit.kind = kind;
    unit.name = pass_kind_name(kind);
    unit.slots = std::move(slots);
    unit.help = std::move(help);
    unit.place = place;
    return unit;
}

PassUnitDeclaration built_in_unit(PassKind kind, UnitSlot slot, std::string help,
                                  void (*place)(UnitPlacement& placement)) {
    return built_in_unit(kind, std::vector{slot}, std::move(help), place);
}

std::optional<std::string> UnitPlacement::no_mono_reason() const {
    if (draws_mono()) return std::nullopt;
    return std::string(kNoMonoReason);
}

std::vector<PlannedPass*> UnitPlacement::own_passes() {
    std::vector<PlannedPass*> own;
    for (PlannedPass& pass : plan_.passes) {
        if (pass.unit == unit_.name) own.push_back(&pass);
    }
    return own;
}

bool UnitPlacement::used_after(const PlannedPass& pass, graph::ImageHandle image) const {
    bool after = false;
    for (const PlannedPass& other : plan_.passes) {
        if (after && std::any_of(other.steps.begin(), other.steps.end(), [&](const graph::Step& s) {
                return step_declares(s, image.index);
            })) {
            return true;
        }
        after = after || &other == &pass;
    }
    return false;
}

bool step_declares(const graph::Step& step, std::uint16_t resource) {
    return std::any_of(step.uses.begin(), step.uses.end(),
                       [&](const graph::ResourceUse& use) { return use.resource == resource; });
}

}  // namespace monoplane::plan
