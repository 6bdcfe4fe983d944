// `--variant auto`: which of hybrid's depth-based savings to use (MonoCulling: no-opt, discard,
// occlusion-cull), chosen by measuring them on this device, scene and view. The three draw the
// same images (tests/gpu/culling_test.cpp), so the renderer may switch between frames without a
// visible change; what differs is whether the merged depth pyramid and occlusion culling cost
// less than the C fragments and chunks they save, which depends on the device (papers/000 Fig. 5
// found the savings "close to zero or even negative" for m < 8 on a GPU; docs/benchmarks.md
// finds the same on llvmpipe). A cost model predicts this only as well as its unit costs; a
// measurement of the real frames is what the model would be fitted to anyway.
//
// Policy: explore the candidates interleaved (a, b, c, a, b, c, ...) for rounds_per_trial rounds,
// ignoring the first round (it pays one-off costs: pipelines, the pyramid's allocation); choose the
// one with the lowest median GPU time; use it for exploit_frames frames; then explore again.
// Starting over (reset) is the caller's call when the costs change (another m).
//
// Pure and deterministic: the same times give the same choices. Vulkan-free.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/plan/render_choices.h"

namespace monoplane::plan {

struct VariantChooserParams {
    int rounds_per_trial = 4;  // at least 2: the first round is not counted
    int exploit_frames = 240;  // about 2.7 s at 90 Hz before measuring again
};

class VariantChooser {
  public:
    static constexpr std::array<MonoCulling, 3> kCandidates = {
        MonoCulling::kNoOpt, MonoCulling::kDiscard, MonoCulling::kOcclusionCull};

    explicit VariantChooser(VariantChooserParams params = {});

    // The variant to render the next frame with.
    MonoCulling next() const;
    // The GPU time of the frame just rendered with next()'s variant.
    void record(double gpu_frame_ms);
    // Forgets every measurement: the next frames explore again.
    void reset();
    // The variant the last completed trial chose; none before the first trial ends.
    std::optional<MonoCulling> chosen() const { return chosen_; }

  private:
    VariantChooserParams params_;
    int frame_in_phase_ = 0;  // exploring: the trial's frame; exploiting: frames used
    bool exploring_ = true;
    std::array<std::vector<double>, kCandidates.size()> samples_;
    std::optional<MonoCulling> chosen_;
};

}  // namespace monoplane::plan
