// The bench's auto-against-fixed comparison (issue 20, item 4): an auto run is on the fixed-m
// frontier unless a fixed m of the same scene, mode and variant is both faster (median time
// ratio) and more accurate (visible error); the dominations that also hold beyond the runs'
// frame-to-frame spread (interquartile ranges apart) are listed separately. Hand-made runs.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/bench/bench_results.h"

namespace monoplane::app {
namespace {

BenchRun run(std::string scene, std::optional<double> m, bool automatic, double ratio, double p25,
             double p75, double error_arcmin) {
    BenchRun r;
    r.scene = std::move(scene);
    r.mode = "hybrid";
    r.variant = "occlusion-cull";
    r.mono_plane = m;
    r.mono_plane_auto = automatic;
    r.time_ratio = ratio;
    r.time_ratio_p25 = p25;
    r.time_ratio_p75 = p75;
    r.visible_error_arcmin = error_arcmin;
    return r;
}

TEST(BenchFrontier, AutoIsDominatedOnlyByAFixedMThatIsFasterAndMoreAccurate) {
    BenchReport report;
    report.runs = {
        run("beams", 20.0, true, 0.85, 0.80, 0.90, 5.9),
        run("beams", 8.0, false, 0.80, 0.70, 0.79, 15.0),   // faster, less accurate
        run("beams", 31.0, false, 0.84, 0.81, 0.88, 3.8),   // faster and more accurate, by noise
        run("beams", 40.0, false, 0.70, 0.65, 0.75, 2.9),   // faster beyond the spread
        run("beams", 12.0, false, 0.95, 0.90, 1.00, 1.0),   // more accurate, slower
        run("spheres", 3.0, false, 0.10, 0.05, 0.15, 0.1),  // another scene: no comparison
    };
    mark_auto_frontier(report);
    const BenchRun& automatic = report.runs[0];
    ASSERT_TRUE(automatic.on_fixed_m_frontier.has_value());
    EXPECT_FALSE(*automatic.on_fixed_m_frontier);
    EXPECT_EQ(automatic.dominated_by, (std::vector<std::string>{"m=31", "m=40"}));
    EXPECT_EQ(automatic.dominated_beyond_spread_by, (std::vector<std::string>{"m=40"}));
    EXPECT_FALSE(report.runs[1].on_fixed_m_frontier.has_value()) << "fixed runs are not marked";
}

TEST(BenchFrontier, AutoFasterOrMoreAccurateThanEveryFixedMIsOnTheFrontier) {
    BenchReport report;
    report.runs = {
        run("landscape", 20.0, true, 0.90, 0.88, 0.92, 5.0),
        run("landscape", 8.0, false, 0.85, 0.80, 0.87, 14.0),
        run("landscape", 31.0, false, 0.95, 0.93, 0.97, 3.0),
        run("landscape", 20.0, false, 0.90, 0.88, 0.92, 5.0),  // equal: not better in either
    };
    BenchRun far = run("landscape", 1000.0, false, 1.0, 0.98, 1.02, 0.0);
    far.mono_plane_is_far = true;
    report.runs.push_back(far);
    BenchRun other_variant = run("landscape", 40.0, false, 0.5, 0.4, 0.6, 1.0);
    other_variant.variant = "no-opt";
    report.runs.push_back(other_variant);
    mark_auto_frontier(report);
    ASSERT_TRUE(report.runs[0].on_fixed_m_frontier.has_value());
    EXPECT_TRUE(*report.runs[0].on_fixed_m_frontier);
    EXPECT_TRUE(report.runs[0].dominated_by.empty());
    EXPECT_TRUE(report.runs[0].dominated_beyond_spread_by.empty());

    // A far run that were faster would be named "m=far".
    report.runs[4].time_ratio = 0.5;
    report.runs[4].time_ratio_p75 = 0.6;
    mark_auto_frontier(report);
    EXPECT_EQ(report.runs[0].dominated_by, (std::vector<std::string>{"m=far"}));
    EXPECT_EQ(report.runs[0].dominated_beyond_spread_by, (std::vector<std::string>{"m=far"}));
}

}  // namespace
}  // namespace monoplane::app
