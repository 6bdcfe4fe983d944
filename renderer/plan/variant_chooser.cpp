#include "renderer/plan/variant_chooser.h"

#include <algorithm>
#include <limits>

#include "common/programming_error.h"

namespace monoplane::plan {
namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

VariantChooser::VariantChooser(VariantChooserParams params) : params_(params) {
    MONOPLANE_EXPECTS(params_.rounds_per_trial >= 2 && params_.exploit_frames >= 1);
}

MonoCulling VariantChooser::next() const {
    if (!exploring_) return *chosen_;
    return kCandidates[static_cast<std::size_t>(frame_in_phase_) % kCandidates.size()];
}

void VariantChooser::record(double gpu_frame_ms) {
    const int trial_frames = params_.rounds_per_trial * static_cast<int>(kCandidates.size());
    if (!exploring_) {
        if (++frame_in_phase_ >= params_.exploit_frames) {
            exploring_ = true;
            frame_in_phase_ = 0;
            for (auto& s : samples_) s.clear();
        }
        return;
    }
    const auto candidate = static_cast<std::size_t>(frame_in_phase_) % kCandidates.size();
    const int round = frame_in_phase_ / static_cast<int>(kCandidates.size());
    if (round > 0) samples_[candidate].push_back(gpu_frame_ms);
    if (++frame_in_phase_ < trial_frames) return;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < kCandidates.size(); ++c) {
        const double m = median(samples_[c]);
        if (m < best) {  // ties keep the earlier, cheaper-to-build candidate
            best = m;
            chosen_ = kCandidates[c];
        }
    }
    exploring_ = false;
    frame_in_phase_ = 0;
}

void VariantChooser::reset() {
    exploring_ = true;
    frame_in_phase_ = 0;
    for (auto& s : samples_) s.clear();
}

}  // namespace monoplane::plan
