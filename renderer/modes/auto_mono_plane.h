// `--mono-plane auto` inside a renderer (issue 20): each frame's m from the chooser
// (renderer/plan/mono_plane_chooser.h, the policy), fed by the content's depth from the chunks'
// bounds (content_depth.h), the depth histogram of the frames the GPU completed (counted by the
// depth histogram unit, renderer/passes/depth_histogram, into this object's buffers) and their
// pass times.
//
// When may this be used: by one ModeRenderer, whose frames it sees in submission order (choose,
// then the histogram recorded into the frame's slot, then complete when the slot completes).
#pragma once

#include <optional>
#include <vector>

#include "renderer/modes/view_setup.h"
#include "renderer/passes/shared/unit_settings.h"
#include "renderer/plan/mono_plane_chooser.h"
#include "renderer/profile/frame_stats.h"
#include "renderer/vk/buffer.h"
#include "scenes/scene.h"

namespace monoplane::modes {

class AutoMonoPlane {
  public:
    // The scene must outlive this.
    AutoMonoPlane(const vk_core::Context& ctx, const scenes::Scene& scene,
                  plan::AutoMonoPlaneParams params);

    // This frame's decision for the eyes and head in `views` at the renderer's eye size, with
    // overlap k and grazing angle as the frame's rig will have them. Throws UserError for eyes
    // the rig refuses.
    // nearest: the nearest m allowed (FrameInputs::nearest_auto_plane).
    const plan::MonoPlaneDecision& choose(const StereoViewInputs& views, vk::Extent2D eye_extent,
                                          std::optional<double> nearest);
    const plan::MonoPlaneDecision& last() const { return decision_; }

    // The buffer the frame in `slot` counts its eyes' final depths into (host-visible,
    // MONOPLANE_DEPTH_HISTOGRAM_WORDS words), and the clip range its bins span: the first chosen
    // frame's (a renderer keeps its near and far).
    const vk_core::Buffer& histogram_buffer(std::uint32_t slot) const;
    passes::DepthHistogramRange histogram_range() const {
        return range_.value_or(passes::DepthHistogramRange{});
    }
    // A completed frame: its histogram (if it recorded one) and pass times go to the chooser.
    void complete(std::uint32_t slot, bool histogram_recorded, const profile::FrameStats& stats);
    // The histogram of the last completed frame that recorded one (tests: its counts against the
    // read-back depth).
    const std::optional<plan::DepthHistogram>& last_histogram() const { return last_histogram_; }

  private:
    const scenes::Scene& scene_;
    plan::MonoPlaneChooser chooser_;
    std::vector<vk_core::Buffer> histograms_;           // per frame slot
    std::optional<passes::DepthHistogramRange> range_;  // set by the first choose()
    plan::MonoPlaneDecision decision_;
    std::optional<plan::DepthHistogram> last_histogram_;
};

}  // namespace monoplane::modes
