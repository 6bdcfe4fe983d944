#include "study/gaze_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "study/gaze_angles.h"

namespace monoplane::study {
namespace {

// A valid gaze sample with its angles, worked out once: I-DT measures dispersion in them.
struct GazeSample {
    std::int64_t time_ns = 0;
    std::array<double, 3> direction{0.0, 0.0, -1.0};
    double yaw_deg = 0.0;
    double pitch_deg = 0.0;
};

// Consecutive valid samples. A fixation never spans two runs: between them the eyes were not
// tracked (a blink) or the samples are not the ones summarised (another screen).
using SampleRun = std::vector<GazeSample>;

std::optional<GazeSample> valid_sample(const FrameRecord& frame) {
    if (!frame.gaze || !frame.gaze->valid) return std::nullopt;
    const std::array<double, 3>& d = frame.gaze->direction;
    return GazeSample{frame.display_time_ns, d, gaze_yaw_deg(d), gaze_pitch_deg(d)};
}

// The horizontal and vertical extent of a window's samples, grown a sample at a time.
class AngularExtent {
  public:
    void add(const GazeSample& s) {
        min_yaw_ = std::min(min_yaw_, s.yaw_deg);
        max_yaw_ = std::max(max_yaw_, s.yaw_deg);
        min_pitch_ = std::min(min_pitch_, s.pitch_deg);
        max_pitch_ = std::max(max_pitch_, s.pitch_deg);
    }
    // Salvucci and Goldberg's dispersion: horizontal plus vertical extent, degrees.
    double dispersion() const { return (max_yaw_ - min_yaw_) + (max_pitch_ - min_pitch_); }
    double dispersion_with(const GazeSample& s) const {
        AngularExtent grown = *this;
        grown.add(s);
        return grown.dispersion();
    }

  private:
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    double min_yaw_ = kInf, max_yaw_ = -kInf, min_pitch_ = kInf, max_pitch_ = -kInf;
};

// The fixation of run[first..last]: its times and its mean direction, renormalised.
Fixation make_fixation(const SampleRun& run, std::size_t first, std::size_t last) {
    std::array<double, 3> sum{0.0, 0.0, 0.0};
    for (std::size_t i = first; i <= last; ++i)
        for (int axis = 0; axis < 3; ++axis) sum[axis] += run[i].direction[axis];
    Fixation fixation;
    fixation.start_ns = run[first].time_ns;
    fixation.end_ns = run[last].time_ns;
    fixation.samples = static_cast<int>(last - first + 1);
    const double length = std::hypot(sum[0], sum[1], sum[2]);
    if (length > 0.0)
        for (int axis = 0; axis < 3; ++axis) fixation.direction[axis] = sum[axis] / length;
    return fixation;
}

// I-DT over one run: a window spanning the minimum duration that lies within the dispersion
// threshold grows while it stays within it and is a fixation; one that does not loses its first
// sample.
void detect_in_run(const SampleRun& run, const FixationParams& params,
                   std::vector<Fixation>& fixations) {
    const auto min_ns = static_cast<std::int64_t>(std::llround(params.min_duration_s * 1e9));
    std::size_t first = 0;
    while (first < run.size()) {
        std::size_t last = first;
        while (last < run.size() && run[last].time_ns - run[first].time_ns < min_ns) ++last;
        if (last == run.size()) return;  // what is left is shorter than a fixation
        AngularExtent extent;
        for (std::size_t i = first; i <= last; ++i) extent.add(run[i]);
        if (extent.dispersion() > params.max_dispersion_deg) {
            ++first;
            continue;
        }
        while (last + 1 < run.size() &&
               extent.dispersion_with(run[last + 1]) <= params.max_dispersion_deg)
            extent.add(run[++last]);
        fixations.push_back(make_fixation(run, first, last));
        first = last + 1;
    }
}

// 0 for a frame showing label 1, 1 for label 2, none for every other screen.
std::optional<int> label_shown(const FrameRecord& frame) {
    if (!frame.trial_index) return std::nullopt;
    if (frame.shown == "label1") return 0;
    if (frame.shown == "label2") return 1;
    return std::nullopt;
}

// One trial's counts as its frames come by.
struct TrialTally {
    TrialGaze gaze;
    std::vector<SampleRun> runs;
    int with_point = 0;
    int beyond = 0;
    std::array<double, 2> error_sum{0.0, 0.0};
    std::array<int, 2> error_count{0, 0};
};

void tally_gaze_point(TrialTally& tally, const GazePointRecord& point, int label) {
    ++tally.with_point;
    if (point.beyond_mono_plane()) ++tally.beyond;
    tally.error_sum[label] += point.error_arcmin;
    ++tally.error_count[label];
    std::optional<double>& max = tally.gaze.error_max_arcmin[label];
    max = max ? std::max(*max, point.error_arcmin) : point.error_arcmin;
}

TrialGaze finish(TrialTally& tally, const FixationParams& params) {
    TrialGaze& gaze = tally.gaze;
    if (tally.with_point > 0)
        gaze.share_beyond_m =
            static_cast<double>(tally.beyond) / static_cast<double>(tally.with_point);
    for (int label = 0; label < 2; ++label) {
        if (tally.error_count[label] == 0) continue;
        // Rounding can put the mean of equal errors an ulp above their maximum.
        const double mean = tally.error_sum[label] / tally.error_count[label];
        gaze.error_mean_arcmin[label] = std::min(mean, *gaze.error_max_arcmin[label]);
    }
    for (const SampleRun& run : tally.runs) detect_in_run(run, params, gaze.fixations);
    return std::move(gaze);
}

}  // namespace

std::vector<Fixation> detect_fixations(const std::vector<FrameRecord>& frames,
                                       const FixationParams& params) {
    std::vector<Fixation> fixations;
    SampleRun run;
    for (const FrameRecord& frame : frames) {
        if (std::optional<GazeSample> sample = valid_sample(frame)) {
            run.push_back(*sample);
            continue;
        }
        detect_in_run(run, params, fixations);
        run.clear();
    }
    detect_in_run(run, params, fixations);
    return fixations;
}

std::vector<TrialGaze> summarize_trial_gaze(const std::vector<FrameRecord>& frames,
                                            const FixationParams& params) {
    std::map<int, TrialTally> trials;
    // The trial whose last run is still growing: any frame that does not extend it ends it.
    std::optional<int> open_run;
    for (const FrameRecord& frame : frames) {
        const std::optional<int> label = label_shown(frame);
        const std::optional<GazeSample> sample = valid_sample(frame);
        if (!label) {
            open_run.reset();
            continue;
        }
        TrialTally& tally = trials[*frame.trial_index];
        tally.gaze.trial_index = *frame.trial_index;
        if (!sample) {
            if (frame.gaze) ++tally.gaze.invalid_samples;
            open_run.reset();
            continue;
        }
        ++tally.gaze.valid_samples;
        if (frame.gaze_point) tally_gaze_point(tally, *frame.gaze_point, *label);
        if (open_run != frame.trial_index) tally.runs.emplace_back();
        tally.runs.back().push_back(*sample);
        open_run = frame.trial_index;
    }
    std::vector<TrialGaze> summaries;
    for (auto& [index, tally] : trials) summaries.push_back(finish(tally, params));
    return summaries;
}

}  // namespace monoplane::study
