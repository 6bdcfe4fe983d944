// Forward shading (papers/000 Sect. 5; forward_pass.h has the programs), a pass kind written as
// one unit at two slots: the eyes' passes (one per eye, or one for both in single-pass stereo)
// right after the shadow map, and in the hybrid modes C's pass after the merged depth pyramid
// and the occlusion culling. Each pass draws its view's chunk list (the culling's) in the steps
// its draws list: in hybrid C first masks the pixels both eyes hide, the eyes draw their sky only
// where C has nothing, and the eyes' blended chunks wait for the composite (the transparency).
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#include <algorithm>

#ifdef MONOPLANE_UNIT_RECORDER
#include <map>
#include <optional>
#include <utility>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/pass_unit.h"
#endif

namespace monoplane::passes::forward {
namespace {

using plan::DrawStep;
using plan::ImageRole;
using plan::ViewId;

// Whether the pass's draws begin with C's mask of the pixels both eyes hide.
bool masks_hidden(const plan::PlannedPass& pass) {
    return std::any_of(pass.draws.begin(), pass.draws.end(),
                       [](const plan::PlannedDraw& d) { return d.step == DrawStep::kMaskHidden; });
}

}  // namespace

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

using graph::Use;
using plan::GpuPredicate;
using plan::PlannedDraw;

// What a forward pass draws into and reads.
struct ForwardUses {
    std::vector<ViewId> views;  // one eye, C, or both eyes (single-pass stereo)
    bool velocity = false;      // TAA
    bool multisampled = false;  // MSAA: drawn into the sample images, resolved into hdr, linear
    bool masks_hidden = false;  // C's mask-hidden draw reads the merged pyramid
};

// One step, "draw": the draw lists' commands and counts (the counts share the predicates'
// buffer), the shadow map, and each view's targets.
std::vector<graph::Step> forward_steps(plan::PlanResources& r, const ForwardUses& uses) {
    std::vector<graph::Step> steps;
    graph::Step& draw = steps.emplace_back();
    draw.name = "draw";
    graph::StepBuilder step(draw);
    step.use(r.shared(plan::BufferRole::kDrawLists), Use::kIndirectArgs)
        .use(r.shared(plan::BufferRole::kPredicates), Use::kIndirectArgs)
        .use(r.shared(ImageRole::kShadowMap), Use::kSampledFragment);
    if (uses.masks_hidden) step.use(r.shared(ImageRole::kMergedDepth), Use::kGeneralSampled);
    for (ViewId view : uses.views) {
        if (uses.multisampled) {
            step.use(r.image(view, ImageRole::kHdrSamples), Use::kColorWrite)
                .use(r.image(view, ImageRole::kLinearDepthSamples), Use::kColorWrite)
                .use(r.image(view, ImageRole::kDepthSamples), Use::kDepthWrite);
        } else {
            step.use(r.image(view, ImageRole::kDepth), Use::kDepthWrite);
        }
        // Drawn, or resolved into from the samples.
        step.use(r.image(view, ImageRole::kHdr), Use::kColorWrite)
            .use(r.image(view, ImageRole::kLinearDepth), Use::kColorWrite);
        if (uses.velocity) step.use(r.image(view, ImageRole::kVelocity), Use::kColorWrite);
    }
    return steps;
}

// The chunk step of a forward pass: shaded, or coloured by routing in that debug view.
DrawStep chunk_step(const plan::PlanFrame& frame) {
    return frame.debug == plan::DebugView::kRouting ? DrawStep::kChunksShowRouting
                                                    : DrawStep::kChunks;
}

// The eyes draw their own sky in stereo, and in hybrid only when C has nothing to draw (which
// only the GPU knows; without predicates C always draws the sky).
std::vector<PlannedDraw> eye_draws(const plan::UnitPlacement& placement) {
    const plan::PlanOptions& options = placement.options();
    std::vector<PlannedDraw> draws;
    if (options.depth_prepass) draws.push_back({DrawStep::kDepthPrepass});
    draws.push_back({chunk_step(placement.frame())});
    if (!placement.draws_mono()) {
        draws.push_back({DrawStep::kSky});
    } else if (placement.predicated()) {
        draws.push_back({DrawStep::kSky, GpuPredicate::kMonoNone});
    }
    // In hybrid the eyes' blended chunks wait for the composite (the transparency unit).
    if (options.blended && !placement.draws_mono()) draws.push_back({DrawStep::kBlended});
    return draws;
}

std::vector<PlannedDraw> mono_draws(const plan::UnitPlacement& placement) {
    const plan::PlanOptions& options = placement.options();
    std::vector<PlannedDraw> draws;
    if (!plan::depth_test_skip_reason(options, placement.frame())) {
        // Pixels hidden in both eyes get the nearest depth first; early depth testing then
        // rejects every fragment there. No pyramid (no eye drew anything): nothing to mask.
        draws.push_back({DrawStep::kMaskHidden, placement.when(GpuPredicate::kMonoDepthTested)});
    }
    if (options.depth_prepass) draws.push_back({DrawStep::kDepthPrepass});
    draws.push_back({chunk_step(placement.frame())});
    draws.push_back({DrawStep::kSky, placement.when(GpuPredicate::kMonoAny)});
    // Only the blended chunks wholly beyond m: they are mapped like the rest of C.
    if (options.blended) draws.push_back({DrawStep::kBlended});
    return draws;
}

plan::PlannedPass& add_forward(plan::UnitPlacement& placement, ViewId view,
                               std::vector<ViewId> views, std::vector<PlannedDraw> draws) {
    const plan::AntiAliasing aa = placement.options().anti_aliasing;
    plan::PlannedPass& pass = placement.add_pass(view);
    pass.statistics_scope = plan::view_name(view);
    pass.draws = std::move(draws);
    ForwardUses uses;
    uses.views = std::move(views);
    uses.velocity = aa == plan::AntiAliasing::kTaa;
    uses.multisampled = aa != plan::AntiAliasing::kNone && aa != plan::AntiAliasing::kTaa;
    uses.masks_hidden = masks_hidden(pass);
    pass.steps = forward_steps(placement.resources(), uses);
    return pass;
}

void place(plan::UnitPlacement& placement) {
    if (placement.slot() == plan::UnitSlot::kMonoForward) {
        plan::PlannedPass& pass =
            add_forward(placement, ViewId::kMono, {ViewId::kMono}, mono_draws(placement));
        pass.skipped = placement.no_mono_reason();
        return;
    }
    if (placement.options().stereo_pass != plan::StereoPass::kTwoPasses) {
        add_forward(placement, ViewId::kEyes, {plan::kEyeViews.begin(), plan::kEyeViews.end()},
                    eye_draws(placement));
        return;
    }
    for (ViewId eye : plan::kEyeViews) add_forward(placement, eye, {eye}, eye_draws(placement));
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kForward,
                               {plan::UnitSlot::kEyesForward, plan::UnitSlot::kMonoForward},
                               "each view's chunks shaded, then its sky", &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

CullView cull_view(ViewId view) {
    switch (view) {
        case ViewId::kLeft:
            return CullView::kLeft;
        case ViewId::kRight:
            return CullView::kRight;
        case ViewId::kMono:
            return CullView::kMono;
        default:
            return CullView::kBothEyes;
    }
}

// A pass's targets, as its step declared them (kEyes: the two-layer images of both eyes).
struct Targets {
    std::optional<MultisampleTargets> multisample;
    std::optional<ForwardTargets> forward;

    Targets(UnitRecording& r, vk::Extent2D area, bool clear_color) {
        const ViewId view = r.pass().view;
        if (r.declares(view, ImageRole::kHdrSamples)) {
            multisample.emplace(MultisampleTargets{r.image(view, ImageRole::kHdrSamples),
                                                   r.image(view, ImageRole::kLinearDepthSamples),
                                                   r.image(view, ImageRole::kDepthSamples)});
        }
        forward.emplace(ForwardTargets{
            r.image(view, ImageRole::kHdr),
            multisample ? nullptr : &r.image(view, ImageRole::kDepth),
            r.image(view, ImageRole::kLinearDepth), area, clear_color,
            r.declares(view, ImageRole::kVelocity) ? &r.image(view, ImageRole::kVelocity) : nullptr,
            multisample ? &*multisample : nullptr});
    }
};

class ForwardRecorder final : public UnitRecorder {
  public:
    ForwardRecorder(const vk_core::Context& ctx, const UnitScene& scene, const UnitPasses& passes,
                    const ForwardSettings& settings)
        : nearest_(vk_core::make_texel_sampler(ctx)),
          no_pyramid_(ctx, vk_core::ImageDesc{
                               {1, 1}, vk::Format::eR32Sfloat, vk::ImageUsageFlagBits::eSampled}) {
        ForwardConfig config;
        config.velocity = passes.any_declares(ViewId::kLeft, ImageRole::kVelocity) ||
                          passes.any_declares(ViewId::kMono, ImageRole::kVelocity);
        config.samples = static_cast<vk::SampleCountFlagBits>(settings.msaa_samples);
        config.vertex_work = settings.vertex_work;
        config.masked_chunks = scene.masked_chunks;
        config.blended_chunks = scene.blended_chunks;
        const vk::DescriptorSetLayout textures = scene.textures->layout();
        if (passes.any([](const plan::PlannedPass& p) { return p.view != ViewId::kEyes; })) {
            one_view_.emplace(ctx, textures, config);
        }
        if (passes.any([](const plan::PlannedPass& p) { return p.view == ViewId::kEyes; })) {
            config.stereo = settings.stereo_pass;
            both_eyes_.emplace(ctx, textures, config);
        }
        // Never read: in the layout the pyramid is read in, as a set that names it requires (a
        // set with a binding left unwritten crashes lavapipe when bound).
        vk_core::initialise_image(ctx, no_pyramid_,
                                  executor::layout_for(graph::Use::kGeneralSampled));
    }

    void record(UnitRecording& r) override {
        const plan::PlannedPass& pass = r.pass();
        const ForwardPass& program = pass.view == ViewId::kEyes ? *both_eyes_ : *one_view_;
        std::vector<ForwardDraw> draws;
        for (const plan::PlannedDraw& draw : pass.draws) {
            draws.push_back({draw.step, r.predicate(draw.when)});
        }
        // The eyes' images whole, C's viewport (eq. 8) of its allocation. Pixels hidden in both
        // eyes stay unwritten: cleared where a later reader would see stale values there.
        const bool mono = pass.view == ViewId::kMono;
        const vk::Extent2D area =
            mono ? r.values().mono_area : r.image(pass.view, ImageRole::kHdr).desc().extent;
        const bool clear = mono && masks_hidden(pass) && r.values().mono_hidden_pixels_read;
        const Targets targets(r, area, clear);
        const Sets& sets = sets_for(r, program);
        const UnitScene& scene = r.scene();
        program.record(r.cmd(), *targets.forward, *sets.view, *sets.merged_depth, *scene.geometry,
                       *scene.textures, r.chunk_draws(cull_view(pass.view)), draws);
    }

  private:
    // A view's sets in one frame slot: set 0 (its constants, the shadow map) and set 1 (the
    // merged depth pyramid and the routing bits), rewritten every frame the slot records (its
    // last frame has completed).
    struct Sets {
        vk_core::DescriptorSet view;
        vk_core::DescriptorSet merged_depth;
    };

    const Sets& sets_for(UnitRecording& r, const ForwardPass& program) {
        const ViewId view = r.pass().view;
        auto [entry, added] = sets_.try_emplace({r.values().slot, view});
        Sets& sets = entry->second;
        if (added) {
            sets.view = program.make_view_set();
            sets.merged_depth = program.make_merged_depth_set();
        }
        program.write_view_set(*sets.view, r.view_constants(view),
                               r.image(ViewId::kNone, ImageRole::kShadowMap).view(),
                               r.scene().shadow_sampler);
        // Only C's mask reads the pyramid (its step declares it); the routing view reads the
        // routing bits; a pass that does not declare the pyramid names an image of its own.
        const vk::ImageView pyramid = r.declares(ViewId::kNone, ImageRole::kMergedDepth)
                                          ? r.image(ViewId::kNone, ImageRole::kMergedDepth).view()
                                          : no_pyramid_.view();
        program.write_merged_depth(*sets.merged_depth, pyramid, *nearest_,
                                   r.cull_inputs().routing->handle());
        return sets;
    }

    vk::raii::Sampler nearest_{nullptr};
    vk_core::Image no_pyramid_;
    std::optional<ForwardPass> one_view_;                    // C, and each eye of two-pass stereo
    std::optional<ForwardPass> both_eyes_;                   // single-pass stereo
    std::map<std::pair<std::uint32_t, ViewId>, Sets> sets_;  // per frame slot and view
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene& scene,
                                            const UnitPasses& passes,
                                            const UnitSettings& settings) {
    return std::make_unique<ForwardRecorder>(ctx, scene, passes, settings.forward);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::forward
