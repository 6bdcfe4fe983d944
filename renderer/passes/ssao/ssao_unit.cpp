// Screen-space ambient occlusion (papers/002; ssao_pass.h has the method), a pass kind written as
// one unit. In the hybrid modes C's pass ("mono.ssao", after C's forward pass, before the
// composite) computes the far region's AO once for both eyes and multiplies C's colour by it;
// the eyes' pass ("ssao", once every surface is in the eyes' HDR images, before TAA) computes
// each eye's AO, per eye or stereo-consistently, and multiplies the eyes' colour by it, in
// hybrid only over their near content.
//
// One table of steps (ssao_steps.h) drives both halves: the declaration turns each step into its
// uses of the frame's images, the recorder into its dispatch.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/passes/ssao/ssao_steps.h"
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <map>
#include <memory>
#include <set>
#include <utility>

#include "common/programming_error.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/ssao/ssao_pass.h"
#endif

namespace monoplane::passes::ssao {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

using plan::ImageRole;
using plan::ViewId;

constexpr Dispatch kPerViewDispatches[] = {Dispatch::kEstimate, Dispatch::kFilterX,
                                           Dispatch::kFilterY};
constexpr const char* kPerViewNames[] = {"estimate", "filter-x", "filter-y"};

// The eyes' stereo-consistent steps, each once per eye (left, then right): the left eye estimates,
// the right reprojects the left's estimate where its visibility map allows.
struct StereoAction {
    const char* name;
    Dispatch left;
    Dispatch right;
};
constexpr StereoAction kStereoActions[] = {
    {"visibility", Dispatch::kStereoVisibility, Dispatch::kStereoVisibility},
    {"estimate", Dispatch::kStereoEstimate, Dispatch::kStereoReprojectedEstimate},
    {"filter-x", Dispatch::kStereoFilterX, Dispatch::kStereoFilterX},
    {"filter-y", Dispatch::kStereoFilterY, Dispatch::kStereoFilterY},
};

// C's pass in the hybrid modes that draw C: the far region's AO, computed once for both eyes (C
// alone sees it), skipped on the GPU when C has nothing.
void place_mono(plan::UnitPlacement& placement) {
    plan::PlannedPass& pass = placement.add_pass(ViewId::kMono);
    pass.steps = declared_steps(placement.resources(), mono_steps(), false);
    pass.when = placement.when(plan::GpuPredicate::kMonoAny);
    pass.skipped = placement.no_mono_reason();
}

void place(plan::UnitPlacement& placement) {
    const plan::PlanOptions& options = placement.options();
    if (!options.ssao) return;
    if (placement.slot() == plan::UnitSlot::kMonoPostProcessing) {
        place_mono(placement);
        return;
    }
    plan::PlannedPass& pass = placement.add_pass();
    // In hybrid the far region already carries C's AO: the eye's depth tells which pixels.
    pass.steps = declared_steps(placement.resources(), eye_steps(options.ssao_stereo),
                                placement.draws_mono());
}

void add_compute_uses(plan::PlanResources& r, graph::StepBuilder& step, ViewId view) {
    step.use(r.image(view, ImageRole::kLinearDepth), graph::Use::kSampledCompute)
        .use(r.image(view, ImageRole::kAoScratch), graph::Use::kStorageWrite)
        .use(r.image(view, ImageRole::kAo), graph::Use::kStorageWrite);
}

}  // namespace

std::vector<Step> mono_steps() {
    std::vector<Step> steps;
    for (int i = 0; i < 3; ++i) {
        steps.push_back({kPerViewNames[i], kPerViewDispatches[i], ViewId::kMono, ViewId::kMono});
    }
    steps.push_back({"apply", Dispatch::kApply, ViewId::kMono, ViewId::kMono});
    return steps;
}

std::vector<Step> eye_steps(bool stereo) {
    std::vector<Step> steps;
    if (stereo) {
        for (const StereoAction& action : kStereoActions) {
            steps.push_back(
                {std::string(action.name) + "-left", action.left, ViewId::kLeft, ViewId::kRight});
            steps.push_back(
                {std::string(action.name) + "-right", action.right, ViewId::kRight, ViewId::kLeft});
        }
    } else {
        for (ViewId eye : plan::kEyeViews) {
            for (int i = 0; i < 3; ++i) {
                steps.push_back({plan::view_name(eye) + "." + kPerViewNames[i],
                                 kPerViewDispatches[i], eye, eye});
            }
        }
    }
    for (ViewId eye : plan::kEyeViews) {
        steps.push_back({plan::view_name(eye) + ".apply", Dispatch::kApply, eye, eye});
    }
    return steps;
}

const Step* step_named(std::string_view name) {
    static const std::vector<Step> every = [] {
        std::vector<Step> all = mono_steps();
        for (bool stereo : {false, true}) {
            for (Step& step : eye_steps(stereo)) {
                // The applies are the same in both forms.
                if (stereo && step.dispatch == Dispatch::kApply) continue;
                all.push_back(std::move(step));
            }
        }
        return all;
    }();
    for (const Step& step : every) {
        if (step.name == name) return &step;
    }
    return nullptr;
}

std::vector<graph::Step> declared_steps(plan::PlanResources& r, const std::vector<Step>& steps,
                                        bool near_only) {
    std::vector<graph::Step> declared;
    for (const Step& step : steps) {
        graph::Step& planned = declared.emplace_back();
        planned.name = step.name;
        graph::StepBuilder uses(planned);
        if (step.dispatch == Dispatch::kApply) {
            uses.use(r.image(step.self, ImageRole::kAo), graph::Use::kSampledFragment)
                .use(r.image(step.self, ImageRole::kHdr), graph::Use::kColorBlend);
            if (near_only && step.self != ViewId::kMono) {
                uses.use(r.image(step.self, ImageRole::kDepth), graph::Use::kDepthTest);
            }
        } else if (step.self == step.other) {
            add_compute_uses(r, uses, step.self);
        } else {
            // Each stereo dispatch binds both eyes' images.
            for (ViewId eye : plan::kEyeViews) add_compute_uses(r, uses, eye);
        }
    }
    return declared;
}

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(
        plan::PassKind::kSsao,
        {plan::UnitSlot::kMonoPostProcessing, plan::UnitSlot::kEyesPostProcessing},
        "screen-space ambient occlusion (--ssao per-eye|stereo), C's far region once in hybrid",
        &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

class SsaoRecorder final : public UnitRecorder {
  public:
    explicit SsaoRecorder(const vk_core::Context& ctx) : pass_(ctx) {}

    void record(UnitRecording& r) override {
        const plan::PlannedPass& pass = r.pass();
        bound_.clear();
        if (pass.view == plan::ViewId::kMono) {
            // C's viewport (eq. 8) of its allocation, every pixel computed.
            with_predicate(r.cmd(), r.predicate(pass.when),
                           [&] { record_steps(r, r.values().mono_area, SsaoPass::kEveryPixel); });
            return;
        }
        // In hybrid, pixels well beyond m take C's AO: their own estimate is not needed.
        const UnitFrameValues& values = r.values();
        const float skip_beyond = values.use_mono ? static_cast<float>(values.mono_plane) +
                                                        SsaoPass::skip_margin(values.settings.ssao)
                                                  : SsaoPass::kEveryPixel;
        record_steps(r, r.image(plan::ViewId::kLeft, plan::ImageRole::kAo).desc().extent,
                     skip_beyond);
    }

  private:
    // Every declared step of the pass, in order, as the table of steps says.
    void record_steps(UnitRecording& r, vk::Extent2D area, float skip_beyond) {
        const std::vector<graph::Step>& declared = r.pass().steps;
        for (std::size_t s = 0; s < declared.size(); ++s) {
            if (s > 0) r.next_step(declared[s].name);
            const Step* step = step_named(declared[s].name);
            if (step == nullptr) {
                programming_error(r.pass().name + ": no SSAO step '" + declared[s].name + "'");
            }
            record_step(r, *step, area, skip_beyond);
        }
    }

    void record_step(UnitRecording& r, const Step& step, vk::Extent2D area, float skip_beyond) {
        const SsaoBindings& self = bound(r, step.self);
        if (step.dispatch != Dispatch::kApply) {
            pass_.dispatch(r.cmd(), step.dispatch, self, bound(r, step.other), area,
                           r.values().settings.ssao, skip_beyond);
            return;
        }
        // In hybrid the eyes' apply is depth-tested against their near content (declared so).
        const bool near_only = r.declares(step.self, plan::ImageRole::kDepth);
        pass_.apply(r.cmd(), self, r.image(step.self, plan::ImageRole::kHdr), area,
                    near_only ? &r.image(step.self, plan::ImageRole::kDepth) : nullptr);
    }

    // The view's bindings in this frame slot, pointed at this frame's images the first time a
    // step of the pass touches the view (a computing step: it declares them all).
    const SsaoBindings& bound(UnitRecording& r, plan::ViewId view) {
        std::unique_ptr<SsaoBindings>& bindings = bindings_[{r.values().slot, view}];
        if (!bindings) bindings = pass_.make_bindings();
        if (bound_.insert(view).second) {
            SsaoViewImages images;
            images.constants = &r.view_constants(view);
            images.linear_depth = &r.image(view, plan::ImageRole::kLinearDepth);
            images.ao = &r.image(view, plan::ImageRole::kAo);
            images.scratch = r.images(view, plan::ImageRole::kAoScratch);
            pass_.bind(*bindings, images);
        }
        return *bindings;
    }

    SsaoPass pass_;
    // Per frame slot and view: the slot's last frame has completed when it is recorded again.
    std::map<std::pair<std::uint32_t, plan::ViewId>, std::unique_ptr<SsaoBindings>> bindings_;
    std::set<plan::ViewId> bound_;  // the views bound in the pass being recorded
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<SsaoRecorder>(ctx);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::ssao
