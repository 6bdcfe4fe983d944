// What GPU tests read off a rendered frame: a view's pipeline statistics, whether a pass ran,
// and the largest difference between two read-back images (computed here, independently of the
// renderer's own comparisons).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "renderer/modes/view_setup.h"
#include "renderer/profile/frame_stats.h"

namespace monoplane::testing {

// FrameStats::views exist only where the device has pipelineStatisticsQuery.
inline const profile::ViewStatistics& view_of(const profile::FrameStats& stats,
                                              const std::string& name) {
    for (const profile::ViewStatistics& v : stats.views) {
        if (v.view == name) return v;
    }
    ADD_FAILURE() << "no statistics for the view " << name;
    static const profile::ViewStatistics missing;
    return missing;
}

inline bool has_pass(const profile::FrameStats& stats, const std::string& name) {
    return std::any_of(stats.passes.begin(), stats.passes.end(),
                       [&](const profile::PassTime& p) { return p.name == name; });
}

// The largest absolute difference of any channel of any pixel, in 8-bit levels; 255 (and a
// failure) when the images' sizes differ or they are empty.
inline int max_channel_difference(const modes::RgbaImage& a, const modes::RgbaImage& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    if (a.pixels.size() != b.pixels.size() || a.pixels.empty()) return 255;
    int worst = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        worst = std::max(worst, std::abs(a.pixels[i] - b.pixels[i]));
    }
    return worst;
}

}  // namespace monoplane::testing
