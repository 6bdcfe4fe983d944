// Hybrid's blended chunks nearer than m or straddling it (alphaMode BLEND), a pass kind written
// as one unit: a blended surface has no single depth, so it cannot be mapped through the mono
// plane; each is drawn once into each eye after the composite, back to front, blended over the
// composite's colour and tested against its linear depth, with depth clamping instead of clipping
// at the eyes' far plane m so that a pane straddling m is drawn whole (the forward shading's
// after-composite program, renderer/passes/forward/forward.frag with MONOPLANE_AFTER_COMPOSITE).
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <map>
#include <utility>

#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/pass_unit.h"
#endif

namespace monoplane::passes::transparency {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// Per eye in a hybrid frame that draws C, when the scene has blended chunks: one step, "draw",
// of the eye's blended list into its HDR image, tested against its linear depth (sampled).
void place(plan::UnitPlacement& placement) {
    if (!placement.options().blended || !placement.draws_mono()) return;
    for (plan::ViewId eye : plan::kEyeViews) {
        plan::PlannedPass& pass = placement.add_pass(eye);
        pass.statistics_scope = pass.name;
        plan::PlanResources& r = placement.resources();
        graph::Step& step = pass.steps.emplace_back();
        step.name = "draw";
        graph::StepBuilder(step)
            .use(r.shared(plan::BufferRole::kDrawLists), graph::Use::kIndirectArgs)
            .use(r.shared(plan::BufferRole::kPredicates), graph::Use::kIndirectArgs)
            .use(r.shared(plan::ImageRole::kShadowMap), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kLinearDepth), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kHdr), graph::Use::kColorBlend);
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kTransparency, plan::UnitSlot::kAfterComposite,
                               "hybrid's blended chunks nearer than m, per eye after the composite",
                               &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

class TransparencyRecorder final : public UnitRecorder {
  public:
    TransparencyRecorder(const vk_core::Context& ctx, const UnitScene& scene,
                         const ForwardSettings& settings)
        : nearest_(vk_core::make_texel_sampler(ctx)),
          program_(ctx, scene.textures->layout(), config(scene, settings)) {}

    void record(UnitRecording& r) override {
        const plan::ViewId eye = r.pass().view;
        auto [entry, added] = sets_.try_emplace(std::make_pair(r.values().slot, eye));
        Sets& sets = entry->second;
        if (added) {
            sets.view = program_.make_view_set();
            sets.composite_depth = program_.make_merged_depth_set();
        }
        // The slot's last frame has completed: its sets are free to rewrite.
        program_.write_view_set(*sets.view, r.view_constants(eye),
                                r.image(plan::ViewId::kNone, plan::ImageRole::kShadowMap).view(),
                                r.scene().shadow_sampler);
        program_.write_composite_depth(
            *sets.composite_depth, r.image(eye, plan::ImageRole::kLinearDepth).view(), *nearest_);
        const vk_core::Image& hdr = r.image(eye, plan::ImageRole::kHdr);
        // One eye at a time in every stereo form: the eye's own list holds its blended chunks.
        const CullView view = eye == plan::ViewId::kLeft ? CullView::kLeft : CullView::kRight;
        program_.record_after_composite(r.cmd(), AfterCompositeTargets{hdr, hdr.desc().extent},
                                        *sets.view, *sets.composite_depth, *r.scene().geometry,
                                        *r.scene().textures, r.chunk_draws(view).blended);
    }

  private:
    struct Sets {
        vk_core::DescriptorSet view;             // set 0: the eye's constants, the shadow map
        vk_core::DescriptorSet composite_depth;  // set 1: the eye's linear depth
    };

    static ForwardConfig config(const UnitScene& scene, const ForwardSettings& settings) {
        ForwardConfig config;
        config.vertex_work = settings.vertex_work;
        config.masked_chunks = scene.masked_chunks;
        config.blended_chunks = true;
        config.programs = ForwardPrograms::kBlendedAfterComposite;
        return config;
    }

    vk::raii::Sampler nearest_{nullptr};
    ForwardPass program_;
    std::map<std::pair<std::uint32_t, plan::ViewId>, Sets> sets_;  // per frame slot and eye
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene& scene,
                                            const UnitPasses&, const UnitSettings& settings) {
    return std::make_unique<TransparencyRecorder>(ctx, scene, settings.forward);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::transparency
