// The policy of `--mono-plane auto` (renderer/plan/mono_plane_chooser.h) on made-up frames: the
// floor from the budget (checked against the disparity's closed form d / (2 tan(A/2)), see
// rig_angular_error_test), gaps in a depth histogram, bounded steps, stereo when hybrid saves
// nothing, and the floor's precedence. Errors per step are measured with the rig's angular error,
// which rig_angular_error_test checks against the geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "renderer/plan/mono_plane_chooser.h"
#include "rig/angular_error.h"

namespace monoplane::plan {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kArcmin = 60.0 * 180.0 / 3.14159265358979323846;

rig::RigInputs vive() {
    rig::RigInputs in;
    in.eyes[rig::kLeft] = {-1.391937, 1.247409, -1.468819, 1.464287};
    in.eyes[rig::kRight] = {-1.246557, 1.398447, -1.465505, 1.472458};
    in.eye_width = 1344;
    in.eye_height = 1512;
    in.ipd = 0.064;
    return in;
}

// The disparity budget whose floor is m: 2 atan(d / 2m) in arcminutes.
double disparity_budget_for(double m) {
    return 2.0 * std::atan(0.064 / (2.0 * m)) * kArcmin;
}

AutoMonoPlaneParams disparity_params(double floor_m) {
    AutoMonoPlaneParams p;
    p.measure = rig::ErrorMeasure::kDisparity;
    p.error_budget_arcmin = disparity_budget_for(floor_m);
    return p;
}

double disparity_at(double m, double depth) {
    if (m >= 1000.0) return 0.0;
    rig::RigInputs in = vive();
    in.mono_plane = m;
    return rig::angular_error_at_depth(rig::build_rig(in).value_or_throw(), depth).disparity_arcmin;
}

// Pixels spread evenly (per bin) over the depths [from, to).
void fill(DepthHistogram& h, double from, double to, std::uint32_t per_bin) {
    for (int b = h.bin_of(from); b < h.bin_of(to); ++b)
        h.counts[static_cast<std::size_t>(b)] = per_bin;
    h.farthest = std::max(h.farthest, to);
}

// A hybrid frame whose C pass costs more than hybrid's own passes: hybrid pays.
const FrameCost kHybridPays{true, 10.0, 4.0, 1.0};
const FrameCost kHybridCostsMore{true, 10.0, 1.0, 3.0};

TEST(MonoPlaneChooser, WithoutAHistogramTheFloorIsTheNearestPlaneWithinBudget) {
    MonoPlaneChooser chooser(disparity_params(8.0));
    const MonoPlaneDecision d = chooser.next(vive(), kInf).value_or_throw();
    EXPECT_NEAR(d.mono_plane / 8.0, 1.0, 2e-3);  // the cache's 0.5 % depth margin at most
    EXPECT_EQ(d.floor, d.mono_plane);
    EXPECT_EQ(d.reason, "floor");
    EXPECT_FALSE(d.jumped);
    EXPECT_LE(d.error_arcmin, disparity_budget_for(8.0) + 1e-9);
}

TEST(MonoPlaneChooser, MovesIntoTheEmptyBandInBoundedSteps) {
    AutoMonoPlaneParams params = disparity_params(4.0);
    params.max_step_arcmin = 0.5;
    MonoPlaneChooser chooser(params);
    DepthHistogram h;
    fill(h, 1.0, 6.0, 5000);
    fill(h, 40.0, 200.0, 5000);
    double previous = chooser.next(vive(), 200.0).value_or_throw().mono_plane;
    for (int frame = 0; frame < 200; ++frame) {
        chooser.record(h, kHybridPays);
        const MonoPlaneDecision d = chooser.next(vive(), 200.0).value_or_throw();
        EXPECT_LE(std::abs(disparity_at(d.mono_plane, 200.0) - disparity_at(previous, 200.0)),
                  params.max_step_arcmin + 1e-7)
            << frame;
        EXPECT_LE(d.error_arcmin, params.error_budget_arcmin + 1e-9);
        EXPECT_FALSE(d.jumped);
        previous = d.mono_plane;
    }
    EXPECT_GT(previous, 6.0);
    EXPECT_LT(previous, 40.0);
    // The middle of the band in ratio: sqrt(6 x 40) = 15.5 m, to a bin (15 %).
    EXPECT_NEAR(std::log(previous / std::sqrt(6.0 * 40.0)), 0.0, 0.3);
}

TEST(MonoPlaneChooser, WithoutAGapItStaysAtTheFloor) {
    MonoPlaneChooser chooser(disparity_params(4.0));
    DepthHistogram h;
    fill(h, 1.0, 300.0, 3000);
    chooser.next(vive(), 300.0).value_or_throw();
    MonoPlaneDecision d;
    for (int frame = 0; frame < 20; ++frame) {
        chooser.record(h, kHybridPays);
        d = chooser.next(vive(), 300.0).value_or_throw();
    }
    EXPECT_EQ(d.mono_plane, d.floor);
    EXPECT_EQ(d.reason, "floor");
}

TEST(MonoPlaneChooser, ABandBeyondTheLastContentIsNoGap) {
    MonoPlaneChooser chooser(disparity_params(4.0));
    DepthHistogram h;
    fill(h, 1.0, 9.0, 3000);  // nothing beyond 9 m: nothing to save there
    chooser.next(vive(), 9.0).value_or_throw();
    chooser.record(h, kHybridPays);
    const MonoPlaneDecision d = chooser.next(vive(), 9.0).value_or_throw();
    EXPECT_EQ(d.mono_plane, d.floor);
}

TEST(MonoPlaneChooser, HeadsForStereoSmoothlyWhenHybridSavesNothing) {
    AutoMonoPlaneParams params = disparity_params(4.0);
    params.max_step_arcmin = 1.0;
    MonoPlaneChooser chooser(params);
    double previous = chooser.next(vive(), kInf).value_or_throw().mono_plane;
    MonoPlaneDecision d;
    int frames = 0;
    for (; frames < 500 && previous < 1000.0; ++frames) {
        chooser.record(std::nullopt, kHybridCostsMore);
        d = chooser.next(vive(), kInf).value_or_throw();
        EXPECT_GE(d.mono_plane, previous);
        // The last step to the far plane is from below one step of error.
        EXPECT_LE(std::abs(disparity_at(d.mono_plane, kInf) - disparity_at(previous, kInf)),
                  params.max_step_arcmin + 1e-7);
        previous = d.mono_plane;
    }
    EXPECT_EQ(previous, 1000.0);
    EXPECT_EQ(d.reason.rfind("stereo", 0), 0u) << d.reason;
    // From 4 m (about 55 arcmin) one arcminute at a time: dozens of frames, not one.
    EXPECT_GT(frames, 40);
}

TEST(MonoPlaneChooser, WithinTheTimeBudgetStereoAndTriedAgainWhenItIsMissed) {
    AutoMonoPlaneParams params = disparity_params(4.0);
    params.time_budget_ms = 11.0;
    params.max_step_arcmin = 100.0;  // no smoothing: the decisions themselves are tested
    params.reprobe_frames = 10;
    MonoPlaneChooser chooser(params);
    chooser.next(vive(), kInf).value_or_throw();
    // Stereo would take 6 + 4 - 1 = 9 ms (the frame, C again, less hybrid's own): within 11.
    chooser.record(std::nullopt, FrameCost{true, 6.0, 4.0, 1.0});
    MonoPlaneDecision d = chooser.next(vive(), kInf).value_or_throw();
    EXPECT_EQ(d.mono_plane, 1000.0);
    EXPECT_EQ(d.reason, "stereo: the estimated stereo frame fits the time budget");
    // Stereo frames now take 20 ms: after reprobe_frames of them hybrid is tried again.
    DepthHistogram h;
    fill(h, 1.0, 300.0, 3000);
    for (int frame = 0; frame < 40; ++frame) {
        chooser.record(h, FrameCost{false, 20.0, 0.0, 0.0});
        d = chooser.next(vive(), kInf).value_or_throw();
        if (d.mono_plane < 1000.0) break;
    }
    EXPECT_LT(d.mono_plane, 1000.0);
}

TEST(MonoPlaneChooser, ContentNearerThanTheNearestPlaneIsRenderedInStereo) {
    // A generous budget would allow m = 0.5 m for content ending at 1.2 m; the floor stays at
    // min_mono_plane (1.6 m), before which there is nothing to show through the plane.
    AutoMonoPlaneParams params = disparity_params(0.5);
    MonoPlaneChooser chooser(params);
    const MonoPlaneDecision d = chooser.next(vive(), 1.2).value_or_throw();
    EXPECT_EQ(d.floor, 1.6);
    EXPECT_EQ(d.mono_plane, 1000.0);
    EXPECT_EQ(d.error_arcmin, 0.0);
    EXPECT_EQ(d.reason, "stereo: no content beyond the floor");
    // Content reaching 2 m: hybrid at the floor.
    MonoPlaneChooser farther(params);
    EXPECT_EQ(farther.next(vive(), 2.0).value_or_throw().mono_plane, 1.6);
}

TEST(MonoPlaneChooser, AFrameMayRaiseOrLowerTheNearestPlane) {
    // A study's hybrid-auto trial at m = 30: never nearer than 30 m, whatever the budget allows.
    MonoPlaneChooser raised(disparity_params(8.0));
    EXPECT_EQ(raised.next(vive(), kInf, 30.0).value_or_throw().floor, 30.0);
    // ... and at m = 1: the budget's floor (8 m) still holds.
    MonoPlaneChooser lowered(disparity_params(8.0));
    EXPECT_NEAR(lowered.next(vive(), kInf, 1.0).value_or_throw().floor, 8.0, 1e-6);
}

TEST(MonoPlaneChooser, TheFloorOverrulesTheStepWhenFarContentAppears) {
    AutoMonoPlaneParams params = disparity_params(4.0);
    params.measure = rig::ErrorMeasure::kEye;
    params.error_budget_arcmin = 10.0;
    MonoPlaneChooser chooser(params);
    const double near_content = chooser.next(vive(), 12.0).value_or_throw().mono_plane;
    chooser.record(std::nullopt, kHybridPays);
    const MonoPlaneDecision d = chooser.next(vive(), kInf).value_or_throw();
    EXPECT_GT(d.mono_plane, near_content);
    EXPECT_EQ(d.mono_plane, d.floor);
    EXPECT_TRUE(d.jumped);
    EXPECT_LE(d.error_arcmin, 10.0 + 1e-9);
}

TEST(MonoPlaneChooser, SmallMovesOfTheTargetAreNotFollowed) {
    AutoMonoPlaneParams params = disparity_params(4.0);
    params.max_step_arcmin = 100.0;
    MonoPlaneChooser chooser(params);
    DepthHistogram a;
    fill(a, 1.0, 6.0, 5000);
    fill(a, 40.0, 200.0, 5000);
    chooser.next(vive(), 200.0).value_or_throw();
    chooser.record(a, kHybridPays);
    const double first = chooser.next(vive(), 200.0).value_or_throw().mono_plane;
    // The band's far edge moves from 40 to 44 m: its middle moves by 5 %, under the hysteresis.
    DepthHistogram b;
    fill(b, 1.0, 6.0, 5000);
    fill(b, 46.0, 200.0, 5000);
    chooser.record(b, kHybridPays);
    EXPECT_EQ(chooser.next(vive(), 200.0).value_or_throw().mono_plane, first);
}

TEST(MonoPlaneChooser, RefusesWhatTheBudgetSearchRefuses) {
    AutoMonoPlaneParams params;
    params.error_budget_arcmin = -1.0;
    MonoPlaneChooser chooser(params);
    EXPECT_FALSE(chooser.next(vive(), kInf));
}

// The chooser's "hybrid only" cost is what a stereo frame would not do, C's SSAO included; C's
// forward pass is counted apart, and the eyes' transparency passes not at all (their chunks a
// stereo frame draws in its forward passes). Each pass gets its own power of two in ms, so the
// sums say exactly which passes were counted.
TEST(MonoPlaneChooser, FrameCostCountsEveryPassOnlyHybridDoes) {
    const std::vector<std::pair<PassKind, ViewId>> passes = {
        {PassKind::kCulling, ViewId::kNone},      {PassKind::kShadow, ViewId::kNone},
        {PassKind::kForward, ViewId::kLeft},      {PassKind::kForward, ViewId::kRight},
        {PassKind::kDepthPyramid, ViewId::kNone}, {PassKind::kOcclusionCulling, ViewId::kNone},
        {PassKind::kForward, ViewId::kMono},      {PassKind::kSsao, ViewId::kMono},
        {PassKind::kComposite, ViewId::kLeft},    {PassKind::kComposite, ViewId::kRight},
        {PassKind::kTransparency, ViewId::kLeft}, {PassKind::kSsao, ViewId::kNone},
        {PassKind::kTaa, ViewId::kLeft},          {PassKind::kTonemap, ViewId::kLeft},
        {PassKind::kTonemap, ViewId::kMono},      {PassKind::kReadback, ViewId::kNone}};
    FrameCost cost;
    for (std::size_t i = 0; i < passes.size(); ++i) {
        add_pass_time(cost, passes[i].first, passes[i].second,
                      std::ldexp(1.0, static_cast<int>(i)));
    }
    EXPECT_TRUE(cost.hybrid);
    EXPECT_EQ(cost.mono_forward_ms, std::ldexp(1.0, 6));
    // depth_pyramid 2^4, occlusion_culling 2^5, mono.ssao 2^7, the composites 2^8 and 2^9,
    // mono.tonemap 2^14.
    EXPECT_EQ(cost.hybrid_only_ms, std::ldexp(1.0, 4) + std::ldexp(1.0, 5) + std::ldexp(1.0, 7) +
                                       std::ldexp(1.0, 8) + std::ldexp(1.0, 9) +
                                       std::ldexp(1.0, 14));
    FrameCost stereo;
    add_pass_time(stereo, PassKind::kForward, ViewId::kLeft, 3.0);
    add_pass_time(stereo, PassKind::kSsao, ViewId::kNone, 2.0);
    EXPECT_FALSE(stereo.hybrid);
    EXPECT_EQ(stereo.hybrid_only_ms, 0.0);
}

}  // namespace
}  // namespace monoplane::plan
