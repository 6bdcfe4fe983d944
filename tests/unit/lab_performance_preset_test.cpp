// The launcher's session settings (app/lab/performance_preset.h): the presets resolved for a
// protocol, the `study run` options each stands for, eye sizes as the OpenXR session makes them,
// and the frame-time verdict with its budget and advice. Expected values are worked out by hand
// here (90 Hz: 1000 / 90 = 11.1 ms), never taken from the code under test.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/lab/performance_preset.h"
#include "study/protocol.h"

namespace monoplane::lab {
namespace {

using Args = std::vector<std::string>;

study::Protocol protocol_with(const std::string& scenes, const std::string& render) {
    const std::string text = "name = \"p\"\nscenes = [" + scenes +
                             "]\nmono_planes = [3, 8]\nalternatives = [\"stereo\", \"hybrid\"]\n" +
                             "[render]\n" + render + "\n";
    auto parsed = study::parse_protocol(text, "p.toml");
    EXPECT_TRUE(parsed.ok()) << (parsed.ok() ? "" : parsed.error().message);
    return std::move(parsed).value_or_throw();
}

study::Protocol fink_like() {
    return protocol_with("\"beams\", \"landscape\", \"spheres\"",
                         "anti_aliasing = \"taa\"\nssao = \"per-eye\"\ndetail = \"medium\"");
}

TEST(PerformancePreset, NamesRunFromFullToMinimal) {
    const auto names = performance_preset_names();
    ASSERT_EQ(names.size(), 4u);
    EXPECT_EQ(names[0], "full");
    EXPECT_EQ(names[1], "balanced");
    EXPECT_EQ(names[2], "fast");
    EXPECT_EQ(names[3], "minimal");
}

TEST(PerformancePreset, ResolvedForAProtocolKeepItsAntiAliasingAndSsao) {
    const std::vector<PerformancePreset> presets = presets_for(fink_like());
    ASSERT_EQ(presets.size(), 4u);
    const double scales[] = {1.0, 0.7, 0.5, 0.25};
    const char* details[] = {"medium", "medium", "medium", "test"};
    for (std::size_t i = 0; i < presets.size(); ++i) {
        SCOPED_TRACE(presets[i].name);
        EXPECT_EQ(presets[i].resolution_scale, scales[i]);
        EXPECT_EQ(presets[i].detail, details[i]);
        EXPECT_EQ(presets[i].protocol_detail, i < 3);
        // study run has no option for these: the protocol's values, whatever the preset.
        EXPECT_EQ(presets[i].anti_aliasing, "taa");
        EXPECT_EQ(presets[i].ssao, "per-eye");
        EXPECT_NE(presets[i].description.find("anti-aliasing taa"), std::string::npos);
    }
    EXPECT_NE(presets[3].description.find("detail test instead of the protocol's medium"),
              std::string::npos)
        << presets[3].description;
}

TEST(PerformancePreset, StudyRunArgumentsNameOnlyWhatDiffersFromTheDefaults) {
    const std::vector<PerformancePreset> presets = presets_for(fink_like());
    EXPECT_EQ(study_run_arguments(presets[0]), Args{});
    EXPECT_EQ(study_run_arguments(presets[1]), (Args{"--resolution-scale", "0.7"}));
    EXPECT_EQ(study_run_arguments(presets[2]), (Args{"--resolution-scale", "0.5"}));
    EXPECT_EQ(study_run_arguments(presets[3]),
              (Args{"--detail", "test", "--resolution-scale", "0.25"}));
}

TEST(PerformancePreset, MinimalKeepsTheDetailWhereLoweringItChangesNothing) {
    // Already the lowest detail.
    const study::Protocol at_test = protocol_with("\"spheres\"", "detail = \"test\"");
    const PerformancePreset minimal = preset_for(at_test, "minimal").value_or_throw();
    EXPECT_TRUE(minimal.protocol_detail);
    EXPECT_EQ(minimal.detail, "test");
    EXPECT_EQ(study_run_arguments(minimal), (Args{"--resolution-scale", "0.25"}));
    EXPECT_EQ(minimal.anti_aliasing, "none");  // the protocol's default
}

TEST(PerformancePreset, UnknownNameIsRefusedWithTheChoices) {
    const Result<PerformancePreset> preset = preset_for(fink_like(), "ultra");
    ASSERT_FALSE(preset.ok());
    EXPECT_EQ(preset.error().message,
              "no performance preset 'ultra': choose full, balanced, fast or minimal");
}

TEST(PerformancePreset, EyeSizeRoundsAsTheSwapchainsDo) {
    // Vive: 1344 x 1512. 0.7 -> 940.8 x 1058.4 -> 941 x 1058; 0.25 -> 336 x 378.
    EXPECT_EQ(scaled_eye_size(1344, 1512, 0.7).width, 941);
    EXPECT_EQ(scaled_eye_size(1344, 1512, 0.7).height, 1058);
    EXPECT_EQ(scaled_eye_size(1344, 1512, 0.25).width, 336);
    EXPECT_EQ(scaled_eye_size(1344, 1512, 0.25).height, 378);
    // Never below 16 pixels: 40 * 0.05 = 2.
    EXPECT_EQ(scaled_eye_size(40, 40, 0.05).width, 16);
}

TEST(FrameTimeVerdict, MissingTheBudgetSaysByHowMuchAndNamesTheLowerPresets) {
    // 90 Hz: 11.11 ms; 180 / 11.11 = 16.2.
    const FrameTimeVerdict v = judge_frame_time("balanced", 180.0, 90.0);
    EXPECT_NEAR(v.budget_ms, 11.111, 0.001);
    EXPECT_NEAR(v.ratio, 16.2, 0.001);
    EXPECT_FALSE(v.fits);
    EXPECT_EQ(v.text,
              "cannot reach 90 Hz: about 180 ms per frame, 16x too slow; choose 'fast' "
              "or 'minimal'");
}

TEST(FrameTimeVerdict, AdviceNamesTheMostFaithfulPresetEstimatedToFit) {
    // 72 Hz: 13.89 ms. balanced 20 ms misses (1.44x), fast 9.8 ms fits.
    const std::vector<PresetEstimate> estimates = {
        {"full", 41.0}, {"balanced", 20.0}, {"fast", 9.8}, {"minimal", 3.0}};
    const FrameTimeVerdict v = judge_frame_time("full", 41.0, 72.0, estimates);
    EXPECT_NEAR(v.budget_ms, 13.889, 0.001);
    EXPECT_EQ(v.text,
              "cannot reach 72 Hz: about 41.0 ms per frame, 3.0x too slow; choose 'fast' "
              "(about 9.8 ms per frame)");
}

TEST(FrameTimeVerdict, TheDocumentedExamplesAt90Hz) {
    // docs/lab.md (Session settings) quotes these. 41 / 11.11 = 3.69.
    const std::vector<PresetEstimate> estimates = {{"balanced", 20.0}, {"fast", 9.8}};
    EXPECT_EQ(judge_frame_time("full", 41.0, 90.0, estimates).text,
              "cannot reach 90 Hz: about 41.0 ms per frame, 3.7x too slow; choose 'fast' (about "
              "9.8 ms per frame)");
    const std::vector<PresetEstimate> slow = {{"minimal", 25.0}};
    EXPECT_EQ(judge_frame_time("fast", 60.0, 90.0, slow).text,
              "cannot reach 90 Hz: about 60.0 ms per frame, 5.4x too slow; even 'minimal' needs "
              "about 25.0 ms per frame; this device cannot keep 90 Hz with this protocol: the "
              "headset will show frames late (the session's frame log counts each missed one)");
}

TEST(FrameTimeVerdict, WhenNothingCheaperFitsItSaysTheDeviceCannotKeepTheRate) {
    const std::vector<PresetEstimate> estimates = {{"fast", 60.0}, {"minimal", 25.0}};
    const FrameTimeVerdict v = judge_frame_time("fast", 60.0, 90.0, estimates);
    EXPECT_EQ(v.text.substr(0, v.text.find(';')),
              "cannot reach 90 Hz: about 60.0 ms per frame, 5.4x too slow");
    EXPECT_NE(v.text.find("even 'minimal' needs about 25.0 ms per frame; this device cannot keep "
                          "90 Hz with this protocol"),
              std::string::npos)
        << v.text;
    const FrameTimeVerdict lowest = judge_frame_time("minimal", 5500.0, 90.0);
    // 5500 / 11.11 = 495.
    EXPECT_NE(lowest.text.find("about 5.5 s per frame, 495x too slow; no preset is cheaper"),
              std::string::npos)
        << lowest.text;
}

TEST(FrameTimeVerdict, FitsWithinTheBudgetAndWarnsWhenTight) {
    const FrameTimeVerdict ok = judge_frame_time("full", 8.2, 90.0);
    EXPECT_TRUE(ok.fits);
    EXPECT_FALSE(ok.tight);
    EXPECT_EQ(ok.text, "reaches 90 Hz: about 8.2 ms per frame of 11.1 ms");
    // 10.5 of 11.11 is 94.5 %: above the 90 % margin.
    const FrameTimeVerdict tight = judge_frame_time("full", 10.5, 90.0);
    EXPECT_TRUE(tight.fits);
    EXPECT_TRUE(tight.tight);
    EXPECT_EQ(tight.text,
              "only just reaches 90 Hz: about 10.5 ms per frame of 11.1 ms; a busier view may "
              "miss frames");
    // 120 Hz: 8.33 ms, which 8.2 still fits (98 %).
    EXPECT_TRUE(judge_frame_time("full", 8.2, 120.0).tight);
}

TEST(FrameTimeVerdict, AnUnreportedRateIsAssumedAndSaidSo) {
    const FrameTimeVerdict v = judge_frame_time("full", 5.0, 0.0);
    EXPECT_EQ(v.refresh_hz, 90.0);
    EXPECT_EQ(v.text,
              "reaches 90 Hz (assumed: the headset check measures the headset's rate): about "
              "5.0 ms per frame of 11.1 ms");
}

}  // namespace
}  // namespace monoplane::lab
