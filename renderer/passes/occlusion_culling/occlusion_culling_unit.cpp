// Occlusion culling of C's chunks (papers/000 Sect. 4.4 "Occlusion Culling"), a pass kind
// written as one unit: in monoplane's hybrid with the variant occlusion-cull, after the merged
// depth pyramid, the culling's program runs again (cull_chunks.comp in renderer/passes/culling,
// phase 1) and sorts C's list anew without the chunks both eyes hide (their routing gains
// MONOPLANE_ROUTE_HIDDEN). The GPU skips it when no eye drew anything nearer than m.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include "renderer/passes/culling/cull_program.h"
#include "renderer/passes/shared/pass_unit.h"
#endif

namespace monoplane::passes::occlusion_culling {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// After the pyramid (this unit is registered after it, at the same slot): "occlusion" reads the
// pyramid and the levels C's list was given, and rewrites the lists and counts.
void place(plan::UnitPlacement& placement) {
    const plan::PlanOptions& options = placement.options();
    if (options.mode == plan::Mode::kStereo) return;
    plan::PlannedPass& pass = placement.add_pass();
    plan::PlanResources& r = placement.resources();
    graph::Step& step = pass.steps.emplace_back();
    step.name = "occlusion";
    graph::StepBuilder(step)
        .use(r.shared(plan::ImageRole::kMergedDepth), graph::Use::kGeneralSampled)
        .use(r.shared(plan::BufferRole::kDrawLists), graph::Use::kStorageWrite)
        .use(r.shared(plan::BufferRole::kPredicates), graph::Use::kStorageWrite)
        .use(r.shared(plan::BufferRole::kLodState), graph::Use::kStorageRead);
    pass.when = placement.when(plan::GpuPredicate::kMonoDepthTested);
    pass.skipped = plan::depth_test_skip_reason(options, placement.frame());
    if (!pass.skipped && placement.frame().mono_culling != plan::MonoCulling::kOcclusionCull) {
        pass.skipped = "variant discard: C's hidden chunks are still drawn";
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kOcclusionCulling, plan::UnitSlot::kAfterEyesForward,
                               "C's chunk list without the chunks both eyes hide (occlusion-cull)",
                               &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return make_cull_recorder(ctx, CullProgram::Phase::kOcclusion);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::occlusion_culling
