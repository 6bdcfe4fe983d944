// The launcher's frame-time probe (app/lab/frame_time_probe.h) on a validated device: an estimate
// that is positive and finite, every condition of the protocol rendered at its nearest m, a
// cheaper preset drawing fewer fragments (pipeline statistics: deterministic, unlike any time,
// which these tests never compare), the schedule under a spent budget, cancelling, and refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/lab/frame_time_probe.h"
#include "study/protocol.h"
#include "tests/gpu/gpu_test.h"

namespace monoplane::lab {
namespace {

// One scene, both alternatives, TAA as fink2019 renders; the smallest detail keeps the test short.
constexpr const char* kProtocol = R"(name = "probe"
scenes = ["spheres"]
mono_planes = [8, 1.6]
alternatives = ["stereo", "hybrid"]
[render]
anti_aliasing = "taa"
detail = "test"
)";

class FrameTimeProbeTest : public testing::GpuTest {
  protected:
    FrameTimeProbeRequest request(const std::string& preset) const {
        FrameTimeProbeRequest r;
        r.protocol = study::parse_protocol(kProtocol, "probe.toml").value_or_throw();
        r.preset = preset_for(r.protocol, preset).value_or_throw();
        r.hmd = hmd::load_hmd_profile("vive").value_or_throw();
        // A small headset: the Vive's aspect at a tenth of its size.
        r.recommended_width = 128;
        r.recommended_height = 144;
        r.budget_s = 1e6;  // every frame: these tests never depend on how long a frame takes
        return r;
    }
};

TEST_F(FrameTimeProbeTest, EstimatesEveryConditionAtTheNearestPlane) {
    const Result<FrameTimeEstimate> estimate = probe_frame_time(ctx(), request("full"));
    ASSERT_TRUE(estimate.ok()) << estimate.error().message;
    EXPECT_TRUE(std::isfinite(estimate->frame_ms));
    EXPECT_GT(estimate->frame_ms, 0.0);
    EXPECT_TRUE(estimate->complete);
    EXPECT_EQ(estimate->eye_width, 128);
    EXPECT_EQ(estimate->eye_height, 144);
    EXPECT_EQ(estimate->device, ctx().device_info().name);
    ASSERT_EQ(estimate->conditions.size(), 2u);
    double slowest = 0.0;
    for (const ProbeCondition& c : estimate->conditions) {
        EXPECT_EQ(c.scene, "spheres");
        EXPECT_EQ(c.mono_plane, 1.6);
        EXPECT_EQ(c.frames, 3);
        EXPECT_GT(c.frame_ms, 0.0);
        EXPECT_GT(c.fragments, 0u);
        slowest = std::max(slowest, c.frame_ms);
    }
    EXPECT_EQ(estimate->conditions[0].alternative, "stereo");
    EXPECT_EQ(estimate->conditions[1].alternative, "hybrid");
    // The estimate is the slowest condition's median, named.
    EXPECT_EQ(estimate->frame_ms, slowest);
    EXPECT_NE(estimate->slowest.find("spheres / "), std::string::npos);
    EXPECT_NE(estimate->slowest.find(" at 1.6 m"), std::string::npos);
}

TEST_F(FrameTimeProbeTest, ACheaperPresetDrawsFewerFragments) {
    const Result<FrameTimeEstimate> full = probe_frame_time(ctx(), request("full"));
    const Result<FrameTimeEstimate> fast = probe_frame_time(ctx(), request("fast"));
    ASSERT_TRUE(full.ok()) << full.error().message;
    ASSERT_TRUE(fast.ok()) << fast.error().message;
    // fast: half the width and height, 64 x 72: a quarter of the pixels.
    EXPECT_EQ(fast->eye_width, 64);
    EXPECT_EQ(fast->eye_height, 72);
    for (std::size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(full->conditions[i].alternative);
        const double ratio = static_cast<double>(full->conditions[i].fragments) /
                             static_cast<double>(fast->conditions[i].fragments);
        // The same view at 4x the pixels: about 4x the fragments (edges and the shading quads
        // of small triangles keep it from being exact).
        EXPECT_GT(ratio, 3.0);
        EXPECT_LT(ratio, 5.0);
    }
}

TEST_F(FrameTimeProbeTest, ASpentBudgetStillMeasuresTheFirstCondition) {
    FrameTimeProbeRequest r = request("minimal");
    r.budget_s = 0.0;
    const Result<FrameTimeEstimate> estimate = probe_frame_time(ctx(), r);
    ASSERT_TRUE(estimate.ok()) << estimate.error().message;
    EXPECT_FALSE(estimate->complete);
    ASSERT_EQ(estimate->conditions.size(), 2u);
    EXPECT_EQ(estimate->conditions[0].frames, 1);
    EXPECT_EQ(estimate->conditions[1].frames, 0);
    EXPECT_EQ(estimate->frame_ms, estimate->conditions[0].frame_ms);
    EXPECT_GT(estimate->frame_ms, 0.0);
}

TEST_F(FrameTimeProbeTest, ReportsProgressBeforeEveryFrameAndCancels) {
    std::vector<ProbeProgress> seen;
    const Result<FrameTimeEstimate> estimate =
        probe_frame_time(ctx(), request("minimal"), [&](const ProbeProgress& p) {
            seen.push_back(p);
            return true;
        });
    ASSERT_TRUE(estimate.ok()) << estimate.error().message;
    // The setup, then 2 conditions x (1 warm-up + 3 measured) frames.
    ASSERT_EQ(seen.size(), 9u);
    EXPECT_EQ(seen[0].condition, "preparing the scenes");
    for (std::size_t i = 0; i < seen.size(); ++i) {
        EXPECT_EQ(seen[i].frames_planned, 8);
        EXPECT_EQ(seen[i].frames_done, i == 0 ? 0 : static_cast<int>(i) - 1);
    }
    EXPECT_EQ(seen[1].condition, "spheres / stereo at 1.6 m");

    int calls = 0;
    const Result<FrameTimeEstimate> cancelled =
        probe_frame_time(ctx(), request("minimal"), [&](const ProbeProgress& p) {
            ++calls;
            return p.frames_done < 3;
        });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().message, "the frame-time probe was cancelled");
    EXPECT_EQ(calls, 5);  // setup, frames 0, 1 and 2, and the refused fourth
}

TEST_F(FrameTimeProbeTest, RefusesAMissingEyeSize) {
    FrameTimeProbeRequest r = request("full");
    r.recommended_width = 0;
    const Result<FrameTimeEstimate> estimate = probe_frame_time(ctx(), r);
    ASSERT_FALSE(estimate.ok());
    EXPECT_EQ(estimate.error().message,
              "the frame-time probe needs the headset's recommended eye size (got 0 x 144)");
}

TEST(FrameTimeProbeOwnDevice, MakesItsOwnValidatedDevice) {
    FrameTimeProbeRequest r;
    r.protocol = study::parse_protocol(kProtocol, "probe.toml").value_or_throw();
    r.preset = preset_for(r.protocol, "minimal").value_or_throw();
    r.hmd = hmd::load_hmd_profile("vive").value_or_throw();
    r.recommended_width = 128;
    r.recommended_height = 144;
    vk_core::ContextOptions options;
    options.validation = true;  // any message refuses the estimate
    if (const char* device = std::getenv("MONOPLANE_TEST_DEVICE")) options.device_selector = device;
    const Result<FrameTimeEstimate> estimate = probe_frame_time(options, r);
    ASSERT_TRUE(estimate.ok()) << estimate.error().message;
    EXPECT_EQ(estimate->eye_width, 32);
    EXPECT_EQ(estimate->eye_height, 36);
    EXPECT_GT(estimate->frame_ms, 0.0);
}

}  // namespace
}  // namespace monoplane::lab
