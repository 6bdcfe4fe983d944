// GPU chunk culling (papers/000 Sect. 4.4 "View Frustum Culling"), a pass kind written as one
// unit: first in every frame, one compute dispatch (cull_chunks.comp, phase 0) sorts the scene's
// chunks into the eyes' lists and C's list, chooses each chunk's level of detail per group of
// views, writes the indirect draw commands and counts (the GPU predicates' words, cull_constants.h)
// and each chunk's routing bits. Every forward pass draws from its lists (ChunkLists, the
// renderer's).
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include "renderer/passes/culling/cull_program.h"
#include "renderer/passes/shared/pass_unit.h"
#endif

namespace monoplane::passes::culling {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// Every frame: "frustum" writes the lists, the counts and the levels of detail, reading the
// levels the last frame chose (the LOD state persists from frame to frame).
void place(plan::UnitPlacement& placement) {
    plan::PlannedPass& pass = placement.add_pass();
    plan::PlanResources& r = placement.resources();
    graph::Step& step = pass.steps.emplace_back();
    step.name = "frustum";
    graph::StepBuilder(step)
        .use(r.shared(plan::BufferRole::kDrawLists), graph::Use::kStorageWrite)
        .use(r.shared(plan::BufferRole::kPredicates), graph::Use::kStorageWrite)
        .use(r.shared(plan::BufferRole::kLodState), graph::Use::kStorageWrite);
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kCulling, plan::UnitSlot::kFrameStart,
                               "every view's chunk list, level of detail and draw counts", &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return make_cull_recorder(ctx, CullProgram::Phase::kFrustum);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::culling
