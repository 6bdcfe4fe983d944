// FrameTimes: scene frames and other frames kept apart, medians of per-frame sums per step.
#include <gtest/gtest.h>

#include "app/headset/frame_times.h"

namespace monoplane::headset {
namespace {

TEST(FrameTimes, MediansOfSceneFramesOnly) {
    FrameTimes times;
    // Three scene frames: render 10, 30, 20 ms (the second in two parts), OpenXR end 1, 3, 2.
    times.add(FrameStep::kRender, 10.0);
    times.add(FrameStep::kOpenXrEnd, 1.0);
    times.end_frame(true);
    times.add(FrameStep::kRender, 12.0);
    times.add(FrameStep::kRender, 18.0);
    times.add(FrameStep::kOpenXrEnd, 3.0);
    times.end_frame(true);
    times.add(FrameStep::kRender, 20.0);
    times.add(FrameStep::kOpenXrEnd, 2.0);
    times.end_frame(true);
    // A neutral frame, not counted in the medians.
    times.add(FrameStep::kRender, 500.0);
    times.end_frame(false);
    times.add_gpu_ms(8.0);
    times.add_gpu_ms(9.0);

    EXPECT_EQ(times.scene_frames(), 3);
    EXPECT_DOUBLE_EQ(times.step_ms_median(FrameStep::kRender), 20.0);
    EXPECT_DOUBLE_EQ(times.step_ms_median(FrameStep::kOpenXrEnd), 2.0);
    EXPECT_DOUBLE_EQ(times.step_ms_median(FrameStep::kWindow), 0.0);
    // Totals 11, 33, 22: median 22.
    EXPECT_DOUBLE_EQ(times.scene_frame_ms_median(), 22.0);
    EXPECT_DOUBLE_EQ(times.gpu_ms_median(), 8.5);
    const std::string summary = times.summary();
    EXPECT_NE(summary.find("3 of scenes, 1 others"), std::string::npos) << summary;
    EXPECT_NE(summary.find("22.0 ms of wall time"), std::string::npos) << summary;
    EXPECT_NE(summary.find("render 20.0 ms"), std::string::npos) << summary;
}

TEST(FrameTimes, NothingMeasuredIsZero) {
    const FrameTimes times;
    EXPECT_EQ(times.scene_frames(), 0);
    EXPECT_DOUBLE_EQ(times.scene_frame_ms_median(), 0.0);
    EXPECT_DOUBLE_EQ(times.gpu_ms_median(), 0.0);
}

TEST(FrameTimes, AMissedSlotIsAGapOfMoreThanOneAndAHalfPeriods) {
    constexpr std::int64_t kPeriod = 11'111'111;                   // 90 Hz
    EXPECT_FALSE(missed_slot(0, kPeriod, kPeriod));                // the next slot
    EXPECT_FALSE(missed_slot(0, kPeriod + kPeriod / 2, kPeriod));  // 1.5 periods: not yet
    EXPECT_TRUE(missed_slot(0, kPeriod + kPeriod / 2 + 1, kPeriod));
    EXPECT_TRUE(missed_slot(0, 2 * kPeriod, kPeriod));  // one slot skipped
    EXPECT_FALSE(missed_slot(0, 5 * kPeriod, 0));       // no period known
}

}  // namespace
}  // namespace monoplane::headset
