// What a participant looked at during each trial (docs/gaze.md): from the frame log's gaze samples
// and gaze points (frame_record.h), per trial the share of the gaze beyond the mono plane, hybrid's
// error at the gaze point while each label was shown, and the fixations, found by the
// dispersion-threshold algorithm I-DT (Salvucci and Goldberg 2000). Pure: no I/O.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "study/frame_record.h"

namespace monoplane::study {

// I-DT's parameters: a fixation is a run of consecutive valid samples at least min_duration_s
// long whose dispersion (horizontal plus vertical extent of the gaze directions, in degrees of
// visual angle in the head's frame) stays within max_dispersion_deg. Invalid samples (blinks)
// end a run.
struct FixationParams {
    double max_dispersion_deg = 1.0;
    double min_duration_s = 0.1;
};

struct Fixation {
    std::int64_t start_ns = 0;  // display time of its first sample
    std::int64_t end_ns = 0;    // display time of its last sample
    // The mean gaze direction over its samples, a unit vector in the head's frame (-z ahead).
    std::array<double, 3> direction{0.0, 0.0, -1.0};
    int samples = 0;
    double duration_s() const { return static_cast<double>(end_ns - start_ns) * 1e-9; }
};

// The fixations among `frames` (one trial's or any run of frames, in display order; frames
// without a valid gaze sample break runs).
std::vector<Fixation> detect_fixations(const std::vector<FrameRecord>& frames,
                                       const FixationParams& params = {});

// One trial's gaze, from the frames that showed one of its labels (shown "label1" or "label2").
struct TrialGaze {
    int trial_index = 0;
    int valid_samples = 0;    // frames showing a label with a valid gaze sample
    int invalid_samples = 0;  // frames showing a label whose sample was not valid (blinks)
    // Of the valid samples with a gaze point: the share whose point lies beyond the mono plane
    // (the sky included). None without any gaze point.
    std::optional<double> share_beyond_m;
    // Hybrid's error at the gaze point, arcmin, over the gaze points while label 1 ([0]) and
    // label 2 ([1]) were shown: mean and maximum. None where that label has no gaze point.
    std::array<std::optional<double>, 2> error_mean_arcmin;
    std::array<std::optional<double>, 2> error_max_arcmin;
    // Over the frames showing a label: a frame of another screen or trial ends a run of samples
    // as a blink does, so no fixation spans the neutral screen between the labels.
    std::vector<Fixation> fixations;
};

// Per trial with at least one frame showing a label, in trial order (a trial never shown is
// absent). `frames`: a session's frame log (StudyStore::frames), in frame order.
std::vector<TrialGaze> summarize_trial_gaze(const std::vector<FrameRecord>& frames,
                                            const FixationParams& params = {});

}  // namespace monoplane::study
