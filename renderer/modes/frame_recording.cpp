// ModeRenderer's recording of a planned pass: its barriers (the executor's, graph_executor.h),
// its profiler scopes, and its commands by its unit's recorder (unit_recording.cpp); the GPU
// predicates; and the composite's values, which the renderer works out each frame.
#include "renderer/modes/mode_renderer_internals.h"
#include "renderer/passes/culling/cull_constants.h"

namespace monoplane::modes {

void ModeRenderer::record_pass(const vk::raii::CommandBuffer& cmd, std::size_t index,
                               const FrameState& frame) {
    const plan::PlannedPass& pass = last_plan_.passes[index];
    // The barriers into the pass first, outside its timed scope, as its own commands' cost is.
    passes::StepSync& sync = executor_.begin_pass(cmd, index);
    const bool timed = pass.kind != plan::PassKind::kReadback;  // read-backs are not GPU frame time
    if (timed) profiler_.begin_pass(cmd, pass.name, pass.kind, pass.view);
    if (!pass.statistics_scope.empty()) {
        profiler_.begin_view(cmd, pass.statistics_scope, pass.kind, pass.view);
    }
    record_planned(cmd, pass, frame, sync);
    if (!pass.statistics_scope.empty()) profiler_.end_view(cmd);
    if (timed) profiler_.end_pass(cmd);
    executor_.end_pass();
}

std::optional<passes::Predicate> ModeRenderer::predicate(plan::GpuPredicate when) const {
    switch (when) {
        case plan::GpuPredicate::kAlways:
            return std::nullopt;
        case plan::GpuPredicate::kMonoAny:
            return culling_.predicate(MONOPLANE_PRED_MONO_ANY, false);
        case plan::GpuPredicate::kMonoNone:
            return culling_.predicate(MONOPLANE_PRED_MONO_ANY, true);
        case plan::GpuPredicate::kMonoDepthTested:
            return culling_.predicate(MONOPLANE_PRED_MONO_DEPTH_TESTED, false);
    }
    return std::nullopt;
}

void ModeRenderer::record_planned(const vk::raii::CommandBuffer& cmd, const plan::PlannedPass& pass,
                                  const FrameState& frame, passes::StepSync& sync) {
    // Every kind is written as a unit (renderer/passes/pass_unit_list.h).
    record_unit(cmd, pass, frame, sync);
    if (pass.kind == plan::PassKind::kShadow) {
        // Frames are waited for before the next is recorded, so the map holds this from now.
        resources_->shadow_drawn(frame.light_view_proj);
    }
}

passes::CompositeValues ModeRenderer::composite_values(const FrameState& frame) const {
    MONOPLANE_EXPECTS(mono_ != nullptr);
    const FrameInputs& inputs = *frame.inputs;
    passes::CompositeValues values;
    values.mono_allocation = glm::vec2(static_cast<float>(mono_->extent.width),
                                       static_cast<float>(mono_->extent.height));
    values.mapping = frame.farfield ? passes::CompositeMapping::kOffsetCopy
                                    : passes::CompositeMapping::kProjective;
    for (int e = 0; e < 2; ++e) {
        passes::CompositeEyeMapping& eye = values.eyes[e];
        if (frame.farfield) {
            eye.pixel_offset = frame.farfield->offsets[e];
            // Same pixel size: NDC velocities scale with the images' widths.
            eye.velocity_scale = glm::vec2(
                static_cast<float>(mono_->area.width) / static_cast<float>(eye_extent_.width),
                static_cast<float>(mono_->area.height) / static_cast<float>(eye_extent_.height));
            continue;
        }
        // Eq. 5 between the jittered clip spaces: C's image and the eye's are both displaced by
        // the jitter, so the mapping undoes one and applies the other.
        eye.eye_to_mono =
            glm::mat4(frame.mono_jitter * rig_->eye_to_mono[e] * glm::inverse(frame.eye_jitter));
        eye.velocity_scale = glm::vec2(rig::mono_velocity_to_eye(*rig_, e));
        // C's image is valid in [0, viewport / allocation] (Sect. 4.2). The image may be larger
        // than the rig's own allocation: it was sized for an earlier m.
        eye.uv_scale = glm::vec2(static_cast<float>(mono_->area.width),
                                 static_cast<float>(mono_->area.height)) /
                       values.mono_allocation;
    }
    if (inputs.debug == plan::DebugView::kTintMono) values.tint = 1.0f;
    if (inputs.debug == plan::DebugView::kStereoOnly)
        values.mapping = passes::CompositeMapping::kNothing;
    values.cover_all_pixels = inputs.debug == plan::DebugView::kMonoOnly;
    return values;
}

}  // namespace monoplane::modes
