// Fixations (I-DT, Salvucci and Goldberg 2000) and the per-trial gaze summary (issue 45) over
// made-up frame logs whose expectations are worked out by hand: directions built from their
// angles, times in whole nanoseconds at 90 Hz (a period of 11111111 ns).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "study/gaze_summary.h"

namespace monoplane::study {
namespace {

constexpr std::int64_t kPeriodNs = 11'111'111;  // 90 Hz
constexpr double kRad = std::numbers::pi / 180.0;

// The unit vector `yaw_deg` right of and `pitch_deg` above straight ahead (-z).
std::array<double, 3> direction(double yaw_deg, double pitch_deg = 0.0) {
    const double h = yaw_deg * kRad;
    const double v = pitch_deg * kRad;
    return {std::cos(v) * std::sin(h), std::sin(v), -std::cos(v) * std::cos(h)};
}

// Frame `index` of trial 0 showing label 1 at index periods, with a valid sample along `dir`.
FrameRecord looking(int index, const std::array<double, 3>& dir) {
    FrameRecord f;
    f.frame = index;
    f.trial_index = 0;
    f.shown = "label1";
    f.display_time_ns = index * kPeriodNs;
    f.gaze = GazeRecord{true, dir};
    return f;
}

FrameRecord blinking(int index) {
    FrameRecord f = looking(index, direction(0.0));
    f.gaze->valid = false;
    return f;
}

void expect_direction(const Fixation& f, const std::array<double, 3>& want) {
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(f.direction[i], want[i], 1e-12) << i;
}

// 0.3 s at 0 degrees (27 samples), a saccade through 2.5, 5 and 7.5 degrees, 0.2 s at 10 degrees
// right (18 samples): two fixations, the saccade in neither.
TEST(GazeFixations, ASaccadeSeparatesTwoFixations) {
    std::vector<FrameRecord> frames;
    int i = 0;
    for (; i < 27; ++i) frames.push_back(looking(i, direction(0.0)));
    for (double yaw : {2.5, 5.0, 7.5}) frames.push_back(looking(i++, direction(yaw)));
    for (; i < 48; ++i) frames.push_back(looking(i, direction(10.0)));
    const std::vector<Fixation> fixations = detect_fixations(frames);
    ASSERT_EQ(fixations.size(), 2u);
    EXPECT_EQ(fixations[0].start_ns, 0);
    EXPECT_EQ(fixations[0].end_ns, 26 * kPeriodNs);
    EXPECT_EQ(fixations[0].samples, 27);
    EXPECT_NEAR(fixations[0].duration_s(), 0.288888886, 1e-12);
    expect_direction(fixations[0], {0.0, 0.0, -1.0});
    EXPECT_EQ(fixations[1].start_ns, 30 * kPeriodNs);
    EXPECT_EQ(fixations[1].end_ns, 47 * kPeriodNs);
    EXPECT_EQ(fixations[1].samples, 18);
    expect_direction(fixations[1], {std::sin(10.0 * kRad), 0.0, -std::cos(10.0 * kRad)});
}

// The fixation's direction is the mean of its samples', renormalised: +-0.4 degrees either side
// average to straight ahead.
TEST(GazeFixations, TheDirectionIsTheRenormalisedMean) {
    std::vector<FrameRecord> frames;
    for (int i = 0; i < 20; ++i) frames.push_back(looking(i, direction(i % 2 ? 0.4 : -0.4)));
    const std::vector<Fixation> fixations = detect_fixations(frames);
    ASSERT_EQ(fixations.size(), 1u);
    expect_direction(fixations[0], {0.0, 0.0, -1.0});
    EXPECT_EQ(fixations[0].samples, 20);
}

// 0.4 s at one point with a blink of three frames (17-19) inside: the blink splits it in two.
// Frames whose gaze was not recorded at all split it as well.
TEST(GazeFixations, ABlinkSplitsAFixation) {
    std::vector<FrameRecord> frames;
    for (int i = 0; i < 36; ++i) frames.push_back(looking(i, direction(3.0, -2.0)));
    ASSERT_EQ(detect_fixations(frames).size(), 1u);
    for (int i : {17, 18, 19}) frames[i] = blinking(i);
    std::vector<Fixation> fixations = detect_fixations(frames);
    ASSERT_EQ(fixations.size(), 2u);
    EXPECT_EQ(fixations[0].start_ns, 0);
    EXPECT_EQ(fixations[0].end_ns, 16 * kPeriodNs);
    EXPECT_EQ(fixations[0].samples, 17);
    EXPECT_EQ(fixations[1].start_ns, 20 * kPeriodNs);
    EXPECT_EQ(fixations[1].end_ns, 35 * kPeriodNs);
    EXPECT_EQ(fixations[1].samples, 16);
    expect_direction(fixations[1], direction(3.0, -2.0));

    for (int i : {17, 18, 19}) frames[i] = looking(i, direction(3.0, -2.0));
    frames[18].gaze.reset();
    EXPECT_EQ(detect_fixations(frames).size(), 2u);
}

// The minimum duration is from the first sample's time to the last's: 0.1 s exactly is enough,
// a nanosecond less is not; nine samples at 90 Hz (0.089 s) make no fixation.
TEST(GazeFixations, ShorterThanTheMinimumDurationIsNone) {
    std::vector<FrameRecord> frames;
    for (int i = 0; i < 9; ++i) frames.push_back(looking(i, direction(0.0)));
    EXPECT_TRUE(detect_fixations(frames).empty());

    std::vector<FrameRecord> three = {looking(0, direction(1.0)), looking(1, direction(1.0)),
                                      looking(2, direction(1.0))};
    three[1].display_time_ns = 50'000'000;
    three[2].display_time_ns = 100'000'000;
    ASSERT_EQ(detect_fixations(three).size(), 1u);
    EXPECT_EQ(detect_fixations(three)[0].samples, 3);
    three[2].display_time_ns = 99'999'999;
    EXPECT_TRUE(detect_fixations(three).empty());
    EXPECT_EQ(detect_fixations(three, {.max_dispersion_deg = 1.0, .min_duration_s = 0.05}).size(),
              1u);
}

// A dispersion equal to the threshold is within it: identical samples (dispersion 0) fixate at a
// threshold of 0. Dispersion is the horizontal plus the vertical extent: samples at +-0.25
// degrees both ways spread 0.5 + 0.5 = 1 degree (not 0.5, the larger extent, nor 0.71, the
// diagonal).
TEST(GazeFixations, TheDispersionIsTheSumOfBothExtentsUpToTheThreshold) {
    std::vector<FrameRecord> still;
    for (int i = 0; i < 12; ++i) still.push_back(looking(i, direction(0.0)));
    EXPECT_EQ(detect_fixations(still, {.max_dispersion_deg = 0.0}).size(), 1u);
    still[5] = looking(5, direction(1e-6));
    EXPECT_TRUE(detect_fixations(still, {.max_dispersion_deg = 0.0}).empty());

    std::vector<FrameRecord> corners;
    for (int i = 0; i < 12; ++i) {
        const double yaw = i % 2 ? 0.25 : -0.25;
        const double pitch = i % 4 < 2 ? 0.25 : -0.25;
        corners.push_back(looking(i, direction(yaw, pitch)));
    }
    EXPECT_EQ(detect_fixations(corners, {.max_dispersion_deg = 1.0 + 1e-9}).size(), 1u);
    EXPECT_TRUE(detect_fixations(corners, {.max_dispersion_deg = 1.0 - 1e-9}).empty());
    EXPECT_TRUE(detect_fixations(corners, {.max_dispersion_deg = 0.75}).empty());
}

// A fixation grows while its dispersion stays within the threshold: a drift to 0.4 and 0.8
// degrees joins it, 1.2 does not.
TEST(GazeFixations, AFixationGrowsUntilTheThresholdIsPassed) {
    std::vector<FrameRecord> frames;
    int i = 0;
    for (; i < 20; ++i) frames.push_back(looking(i, direction(0.0)));
    for (double yaw : {0.4, 0.8, 1.2}) frames.push_back(looking(i++, direction(yaw)));
    const std::vector<Fixation> fixations = detect_fixations(frames);
    ASSERT_EQ(fixations.size(), 1u);
    EXPECT_EQ(fixations[0].samples, 22);
    EXPECT_EQ(fixations[0].end_ns, 21 * kPeriodNs);
}

// A frame of `trial` showing `shown` with a valid sample straight ahead and, where `error` is
// given, a gaze point at `depth` (none: the sky) for a mono plane at 8 m.
FrameRecord trial_frame(int index, std::optional<int> trial, const std::string& shown,
                        std::optional<double> error = std::nullopt,
                        std::optional<double> depth = std::nullopt) {
    FrameRecord f = looking(index, direction(0.0));
    f.trial_index = trial;
    f.shown = shown;
    if (error) f.gaze_point = GazePointRecord{*error, depth, 8.0};
    return f;
}

// A made-up log of two trials, counted by hand. Trial 3: label 1 with a point nearer than m
// (2 arcmin) and one at the sky (4 arcmin, beyond), a blink, a neutral frame (not counted),
// label 2 with a point beyond m (1 arcmin), a sample without a point, a frame without gaze.
// Trial 4: one point exactly at m (not beyond). Frames outside trials are not counted.
TEST(TrialGazeSummary, SharesMeansAndMaximaPerLabel) {
    std::vector<FrameRecord> frames = {
        trial_frame(0, std::nullopt, "neutral", 9.0, 20.0),
        trial_frame(1, 3, "label1", 2.0, 5.0),
        trial_frame(2, 3, "label1", 4.0),
        blinking(3),
        trial_frame(4, 3, "neutral", 9.0, 20.0),
        trial_frame(5, 3, "label2", 1.0, 10.0),
        trial_frame(6, 3, "label2"),
        trial_frame(7, 3, "label2"),
        trial_frame(8, 4, "label1", 6.0, 8.0),
    };
    frames[3].trial_index = 3;
    frames[7].gaze.reset();
    const std::vector<TrialGaze> trials = summarize_trial_gaze(frames);
    ASSERT_EQ(trials.size(), 2u);
    const TrialGaze& t3 = trials[0];
    EXPECT_EQ(t3.trial_index, 3);
    EXPECT_EQ(t3.valid_samples, 4);
    EXPECT_EQ(t3.invalid_samples, 1);
    ASSERT_TRUE(t3.share_beyond_m);
    EXPECT_DOUBLE_EQ(*t3.share_beyond_m, 2.0 / 3.0);
    EXPECT_EQ(t3.error_mean_arcmin[0], 3.0);
    EXPECT_EQ(t3.error_max_arcmin[0], 4.0);
    EXPECT_EQ(t3.error_mean_arcmin[1], 1.0);
    EXPECT_EQ(t3.error_max_arcmin[1], 1.0);
    EXPECT_TRUE(t3.fixations.empty());  // nine frames: far too short
    const TrialGaze& t4 = trials[1];
    EXPECT_EQ(t4.trial_index, 4);
    EXPECT_EQ(t4.valid_samples, 1);
    EXPECT_EQ(t4.invalid_samples, 0);
    EXPECT_EQ(t4.share_beyond_m, 0.0);
    EXPECT_EQ(t4.error_mean_arcmin[0], 6.0);
    EXPECT_EQ(t4.error_max_arcmin[0], 6.0);
    EXPECT_FALSE(t4.error_mean_arcmin[1]);
    EXPECT_FALSE(t4.error_max_arcmin[1]);
}

// A trial whose labels were shown without gaze (none recorded) is listed with no samples and no
// share; trials come in trial order whatever order their frames came in.
TEST(TrialGazeSummary, TrialsWithoutSamplesAndInTrialOrder) {
    std::vector<FrameRecord> frames = {trial_frame(0, 5, "label1"), trial_frame(1, 2, "label2")};
    frames[0].gaze.reset();
    const std::vector<TrialGaze> trials = summarize_trial_gaze(frames);
    ASSERT_EQ(trials.size(), 2u);
    EXPECT_EQ(trials[0].trial_index, 2);
    EXPECT_EQ(trials[0].valid_samples, 1);
    EXPECT_FALSE(trials[0].share_beyond_m);
    EXPECT_EQ(trials[1].trial_index, 5);
    EXPECT_EQ(trials[1].valid_samples, 0);
    EXPECT_EQ(trials[1].invalid_samples, 0);
    EXPECT_FALSE(trials[1].share_beyond_m);
    EXPECT_FALSE(trials[1].error_mean_arcmin[0]);
}

// A trial's fixations are over the frames showing its labels: a neutral screen between label 1
// and label 2 ends one (the eyes rested on the same point throughout), and the next trial's
// frames do not continue it.
TEST(TrialGazeSummary, FixationsDoNotSpanOtherScreensOrTrials) {
    std::vector<FrameRecord> frames;
    for (int i = 0; i < 15; ++i) frames.push_back(trial_frame(i, 0, "label1"));
    for (int i = 15; i < 25; ++i) frames.push_back(trial_frame(i, 0, "neutral"));
    for (int i = 25; i < 40; ++i) frames.push_back(trial_frame(i, 0, "label2"));
    for (int i = 40; i < 55; ++i) frames.push_back(trial_frame(i, 1, "label1"));
    EXPECT_EQ(detect_fixations(frames).size(), 1u);
    const std::vector<TrialGaze> trials = summarize_trial_gaze(frames);
    ASSERT_EQ(trials.size(), 2u);
    ASSERT_EQ(trials[0].fixations.size(), 2u);
    EXPECT_EQ(trials[0].fixations[0].start_ns, 0);
    EXPECT_EQ(trials[0].fixations[0].end_ns, 14 * kPeriodNs);
    EXPECT_EQ(trials[0].fixations[1].start_ns, 25 * kPeriodNs);
    EXPECT_EQ(trials[0].fixations[1].end_ns, 39 * kPeriodNs);
    ASSERT_EQ(trials[1].fixations.size(), 1u);
    EXPECT_EQ(trials[1].fixations[0].start_ns, 40 * kPeriodNs);
    EXPECT_EQ(trials[0].valid_samples, 30);
}

}  // namespace
}  // namespace monoplane::study
