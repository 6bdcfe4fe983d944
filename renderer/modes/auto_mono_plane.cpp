#include "renderer/modes/auto_mono_plane.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/result.h"
#include "renderer/modes/content_depth.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/vk/frame_ring.h"

namespace monoplane::modes {
namespace {

plan::FrameCost cost_of(const profile::FrameStats& stats) {
    plan::FrameCost cost;
    cost.frame_ms = stats.gpu_frame_ms;
    for (const profile::PassTime& pass : stats.passes) {
        plan::add_pass_time(cost, pass.kind, pass.view, pass.gpu_ms);
    }
    return cost;
}

}  // namespace

AutoMonoPlane::AutoMonoPlane(const vk_core::Context& ctx, const scenes::Scene& scene,
                             plan::AutoMonoPlaneParams params)
    : scene_(scene), chooser_(std::move(params)), ctx_(ctx) {}

const plan::MonoPlaneDecision& AutoMonoPlane::choose(const StereoViewInputs& views,
                                                     vk::Extent2D eye_extent,
                                                     std::optional<double> nearest) {
    const rig::RigInputs eyes = rig_inputs_for(views, static_cast<int>(eye_extent.width),
                                               static_cast<int>(eye_extent.height));
    const double depth = farthest_content_depth(scene_, views);
    decision_ = chooser_.next(eyes, depth, nearest).value_or_throw();
    if (!histogram_) {
        // The bins span the first frame's clip range (a renderer keeps its near and far).
        histogram_ = std::make_unique<passes::DepthHistogramPass>(
            ctx_, vk_core::FrameRing::kFramesInFlight, views.near, views.far);
        if (eye_depths_) histogram_->set_eye_depths(*eye_depths_, eye_extent_);
    }
    return decision_;
}

void AutoMonoPlane::set_eye_depths(std::array<vk::ImageView, 2> linear_depth,
                                   vk::Extent2D eye_extent) {
    eye_depths_ = linear_depth;
    eye_extent_ = eye_extent;
    if (histogram_) histogram_->set_eye_depths(linear_depth, eye_extent);
}

void AutoMonoPlane::record(const vk::raii::CommandBuffer& cmd, passes::StepSync& sync,
                           std::uint32_t slot) const {
    if (histogram_ && eye_depths_) histogram_->record(cmd, sync, slot);
}

void AutoMonoPlane::complete(std::uint32_t slot, bool histogram_recorded,
                             const profile::FrameStats& stats) {
    if (histogram_recorded && histogram_) {
        last_histogram_ = histogram_->result(slot);
        chooser_.record(last_histogram_, cost_of(stats));
    } else {
        chooser_.record(std::nullopt, cost_of(stats));
    }
}

}  // namespace monoplane::modes
