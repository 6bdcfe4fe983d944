// The recorders of ModeRenderer: one per kind of planned pass (renderer/plan/frame_plan.h). None
// records a barrier: the executor (graph_executor.h) places the compiled ones before each step.
#include <algorithm>

#include "renderer/modes/mode_renderer_internals.h"
#include "renderer/passes/culling/cull_constants.h"
#include "rig/temporal_jitter.h"

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
    switch (pass.kind) {
        case plan::PassKind::kShadow:
            record_unit(cmd, pass, frame, sync);
            // Frames are waited for before the next is recorded, so the map holds this from now.
            resources_->shadow_drawn(frame.light_view_proj);
            break;
        case plan::PassKind::kForward:
            record_forward(cmd, pass);
            break;
        case plan::PassKind::kTransparency:
            record_transparency(cmd, pass);
            break;
        // The kinds written as units (renderer/passes/pass_unit_list.h).
        case plan::PassKind::kCulling:
        case plan::PassKind::kComposite:
        case plan::PassKind::kDepthPyramid:
        case plan::PassKind::kOcclusionCulling:
        case plan::PassKind::kSsao:
        case plan::PassKind::kReadback:
        case plan::PassKind::kTaa:
        case plan::PassKind::kTonemap:
        case plan::PassKind::kDepthHistogram:
        case plan::PassKind::kUnit:
            record_unit(cmd, pass, frame, sync);
            break;
    }
}

void ModeRenderer::record_forward(const vk::raii::CommandBuffer& cmd,
                                  const plan::PlannedPass& pass) {
    std::vector<passes::ForwardDraw> draws;
    for (const plan::PlannedDraw& draw : pass.draws) {
        draws.push_back({draw.step, predicate(draw.when)});
    }
    if (pass.view == plan::ViewId::kEyes) {
        // Both eyes in one pass, from the list of chunks either eye needs.
        eyes_forward_->record(cmd, eye_layers_->forward_targets(eye_extent_), *eye_pair_set_,
                              *merged_depth_set_, resources_->geometry(), resources_->textures(),
                              culling_.chunk_draws(passes::CullView::kBothEyes), draws);
        return;
    }
    if (pass.view == plan::ViewId::kMono) {
        // Pixels hidden in both eyes stay unwritten; C's image read back shows them black,
        // and C's SSAO must not read stale depths there.
        const bool masked = std::any_of(pass.draws.begin(), pass.draws.end(), [](const auto& d) {
            return d.step == plan::DrawStep::kMaskHidden;
        });
        const bool clear_color = masked && (options_.read_back || options_.ssao);
        forward_.record(cmd, mono_->forward_targets(clear_color), *mono_->forward_set,
                        *merged_depth_set_, resources_->geometry(), resources_->textures(),
                        culling_.chunk_draws(passes::CullView::kMono), draws);
        return;
    }
    const int e = plan::eye_index(pass.view);
    forward_.record(cmd, eyes_[e]->forward_targets(), *eyes_[e]->forward_set, *merged_depth_set_,
                    resources_->geometry(), resources_->textures(),
                    culling_.chunk_draws(static_cast<passes::CullView>(e)), draws);
}

void ModeRenderer::record_transparency(const vk::raii::CommandBuffer& cmd,
                                       const plan::PlannedPass& pass) {
    // One eye at a time in every stereo form: the eye's own list holds its blended chunks.
    const int e = plan::eye_index(pass.view);
    View& eye = *eyes_[e];
    forward_.record_after_composite(
        cmd, passes::AfterCompositeTargets{eye.hdr, eye_extent_}, *eye.forward_set,
        *eye.composite_depth_set, resources_->geometry(), resources_->textures(),
        culling_.draws(static_cast<passes::CullView>(e), MONOPLANE_CLASS_BLENDED));
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
