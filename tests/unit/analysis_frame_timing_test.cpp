// Frame timing per trial from the frame log: shares, the protocol's threshold, practice and
// unlogged trials left out.
#include <gtest/gtest.h>

#include "analysis/frame_timing.h"

namespace monoplane::analysis {
namespace {

TrialRow trial(int index, int frames, int missed, bool practice = false, double threshold = 0.05) {
    TrialRow t;
    t.source = "a.sqlite";
    t.participant = "P01";
    t.session_id = 1;
    t.trial_index = index;
    t.practice = practice;
    t.frames_shown = frames;
    t.frames_missed = missed;
    t.missed_frame_threshold = threshold;
    return t;
}

TEST(FrameTiming, FlagsTrialsAboveTheProtocolsShare) {
    const std::vector<TrialRow> trials = {
        trial(0, 100, 50, true),       // practice: not data
        trial(1, 200, 10),             // 5 %: at the threshold, not above it
        trial(2, 200, 11),             // 5.5 %: flagged
        trial(3, 0, 0),                // no frame log (a headless session)
        trial(4, 80, 20, false, 0.3),  // 25 % under its own protocol's 30 %
        trial(5, 90, 0),
    };
    const FrameTimingSummary s = summarize_frame_timing(trials);
    EXPECT_EQ(s.trials_with_log, 4);
    EXPECT_EQ(s.flagged, 1);
    ASSERT_EQ(s.trials.size(), 4u);
    EXPECT_EQ(s.trials[0].trial_index, 1);
    EXPECT_DOUBLE_EQ(s.trials[0].share, 0.05);
    EXPECT_FALSE(s.trials[0].flagged);
    EXPECT_EQ(s.trials[1].trial_index, 2);
    EXPECT_DOUBLE_EQ(s.trials[1].share, 0.055);
    EXPECT_TRUE(s.trials[1].flagged);
    EXPECT_DOUBLE_EQ(s.trials[2].share, 0.25);
    EXPECT_FALSE(s.trials[2].flagged);
    EXPECT_DOUBLE_EQ(s.trials[3].share, 0.0);
}

TEST(FrameTiming, NoLogNoTrials) {
    const FrameTimingSummary s = summarize_frame_timing({trial(0, 0, 0)});
    EXPECT_EQ(s.trials_with_log, 0);
    EXPECT_EQ(s.flagged, 0);
    EXPECT_TRUE(s.trials.empty());
}

}  // namespace
}  // namespace monoplane::analysis
