#include "renderer/modes/auto_mono_plane.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <utility>

#include "common/programming_error.h"
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
    : scene_(scene), chooser_(std::move(params)) {
    for (std::uint32_t s = 0; s < vk_core::FrameRing::kFramesInFlight; ++s) {
        // Cleared and filled by the unit (a transfer, then the count's storage writes).
        histograms_.emplace_back(
            ctx, MONOPLANE_DEPTH_HISTOGRAM_WORDS * sizeof(std::uint32_t),
            vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst,
            vk_core::MemoryUse::kHostVisible);
    }
}

const plan::MonoPlaneDecision& AutoMonoPlane::choose(const StereoViewInputs& views,
                                                     vk::Extent2D eye_extent,
                                                     std::optional<double> nearest) {
    const rig::RigInputs eyes = rig_inputs_for(views, static_cast<int>(eye_extent.width),
                                               static_cast<int>(eye_extent.height));
    const double depth = farthest_content_depth(scene_, views);
    decision_ = chooser_.next(eyes, depth, nearest).value_or_throw();
    // The bins span the first frame's clip range (a renderer keeps its near and far).
    if (!range_) range_ = passes::DepthHistogramRange{views.near, views.far};
    return decision_;
}

const vk_core::Buffer& AutoMonoPlane::histogram_buffer(std::uint32_t slot) const {
    MONOPLANE_EXPECTS(slot < histograms_.size());
    return histograms_[slot];
}

void AutoMonoPlane::complete(std::uint32_t slot, bool histogram_recorded,
                             const profile::FrameStats& stats) {
    if (histogram_recorded) {
        std::array<std::uint32_t, MONOPLANE_DEPTH_HISTOGRAM_WORDS> words{};
        std::memcpy(words.data(), histogram_buffer(slot).mapped(), sizeof(words));
        const passes::DepthHistogramRange range = histogram_range();
        last_histogram_ = plan::depth_histogram_of(words, range.near, range.far);
        chooser_.record(last_histogram_, cost_of(stats));
    } else {
        chooser_.record(std::nullopt, cost_of(stats));
    }
}

}  // namespace monoplane::modes
