// Study conditions: render-mode names round-trip, and invalid
// conditions are refused with a message a user can act on.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "study/condition.h"

namespace monoplane::study {
namespace {

constexpr double kNear = 0.1;  // the paper's clip range (papers/000 Sect. 5.1)
constexpr double kFar = 1000.0;

TEST(RenderMode, CliNamesAreTheDesignsNames) {
    EXPECT_EQ(render_mode_name(RenderMode::Stereo), "stereo");
    EXPECT_EQ(render_mode_name(RenderMode::StereoMultiview), "stereo-multiview");
    EXPECT_EQ(render_mode_name(RenderMode::StereoGs), "stereo-gs");
    EXPECT_EQ(render_mode_name(RenderMode::StereoInstanced), "stereo-instanced");
    EXPECT_EQ(render_mode_name(RenderMode::Hybrid), "hybrid");
    EXPECT_EQ(render_mode_name(RenderMode::HybridFarfield), "hybrid-farfield");
}

TEST(RenderMode, EveryNameRoundTrips) {
    EXPECT_EQ(all_render_modes().size(), 7u);
    const Result<RenderMode> instanced = parse_render_mode("stereo-instanced");
    ASSERT_TRUE(instanced.ok()) << instanced.error().message;
    EXPECT_EQ(*instanced, RenderMode::StereoInstanced);
    EXPECT_EQ(render_mode_name(RenderMode::HybridAuto), "hybrid-auto");
    std::set<std::string_view> names;
    for (RenderMode mode : all_render_modes()) {
        const Result<RenderMode> parsed = parse_render_mode(render_mode_name(mode));
        ASSERT_TRUE(parsed.ok()) << parsed.error().message;
        EXPECT_EQ(*parsed, mode);
        names.insert(render_mode_name(mode));
    }
    EXPECT_EQ(names.size(), all_render_modes().size()) << "names must be distinct";
}

TEST(RenderMode, UnknownNameListsTheValidOnes) {
    for (std::string_view bad : {"Stereo", "mono", "", "hybrid ", "stereo_gs", "instanced"}) {
        const Result<RenderMode> parsed = parse_render_mode(bad);
        ASSERT_FALSE(parsed.ok()) << bad;
        const std::string& message = parsed.error().message;
        EXPECT_NE(message.find("'" + std::string(bad) + "'"), std::string::npos) << message;
        EXPECT_NE(message.find("stereo, stereo-multiview, stereo-gs, stereo-instanced, hybrid, "
                               "hybrid-farfield"),
                  std::string::npos)
            << message;
    }
}

TEST(Condition, ThePapersConditionsAreValid) {
    for (std::string_view scene : study_scene_names()) {
        for (double m : {1.6, 3.0, 8.0, 31.0, 39.5}) {  // the distances papers/000 names
            for (RenderMode mode : {RenderMode::Stereo, RenderMode::Hybrid}) {
                const Condition condition{std::string(scene), mode, m};
                const Result<Condition> valid = validate_condition(condition, kNear, kFar);
                ASSERT_TRUE(valid.ok()) << valid.error().message;
                EXPECT_EQ(valid->scene, condition.scene);
                EXPECT_EQ(valid->mode, mode);
                EXPECT_EQ(valid->mono_plane, m);
            }
        }
    }
}

TEST(Condition, SceneNames) {
    ASSERT_EQ(study_scene_names().size(), 3u);
    EXPECT_EQ(study_scene_names()[0], "beams");
    EXPECT_EQ(study_scene_names()[1], "landscape");
    EXPECT_EQ(study_scene_names()[2], "spheres");
}

TEST(Condition, Describe) {
    EXPECT_EQ(describe({"spheres", RenderMode::Hybrid, 8.0}), "spheres / hybrid / m = 8 m");
    EXPECT_EQ(describe({"beams", RenderMode::StereoGs, 39.5}), "beams / stereo-gs / m = 39.5 m");
    EXPECT_EQ(describe({"spheres", RenderMode::StereoInstanced, 3.0}),
              "spheres / stereo-instanced / m = 3 m");
}

TEST(Condition, UnknownSceneIsRefused) {
    const Result<Condition> result =
        validate_condition({"SPHERES", RenderMode::Hybrid, 8.0}, kNear, kFar);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find("unknown scene 'SPHERES'"), std::string::npos)
        << result.error().message;
    EXPECT_NE(result.error().message.find("beams, landscape, spheres"), std::string::npos);
}

TEST(Condition, MonoPlaneMustLieStrictlyInsideTheClipRange) {
    for (double m : {kNear, kFar, 0.05, 0.0, -1.0, 2000.0}) {
        const Result<Condition> result =
            validate_condition({"beams", RenderMode::Hybrid, m}, kNear, kFar);
        ASSERT_FALSE(result.ok()) << m;
        EXPECT_NE(result.error().message.find("strictly between near = 0.1 m and far = 1000 m"),
                  std::string::npos)
            << result.error().message;
    }
    // Just inside either end is fine.
    EXPECT_TRUE(
        validate_condition({"beams", RenderMode::Hybrid, std::nextafter(kNear, 1.0)}, kNear, kFar)
            .ok());
    EXPECT_TRUE(
        validate_condition({"beams", RenderMode::Hybrid, std::nextafter(kFar, 0.0)}, kNear, kFar)
            .ok());
}

TEST(Condition, NonFiniteMonoPlaneIsRefused) {
    for (double m :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()}) {
        const Result<Condition> result =
            validate_condition({"landscape", RenderMode::Hybrid, m}, kNear, kFar);
        ASSERT_FALSE(result.ok()) << m;
        EXPECT_NE(result.error().message.find("finite"), std::string::npos)
            << result.error().message;
    }
}

TEST(Condition, InvalidClipRangeIsRefused) {
    const Condition condition{"landscape", RenderMode::Stereo, 8.0};
    for (auto [near, far] : {std::pair{0.0, 1000.0}, std::pair{10.0, 1.0},
                             std::pair{0.1, std::numeric_limits<double>::infinity()},
                             std::pair{std::numeric_limits<double>::quiet_NaN(), 1000.0}}) {
        const Result<Condition> result = validate_condition(condition, near, far);
        ASSERT_FALSE(result.ok()) << near << " " << far;
        EXPECT_NE(result.error().message.find("0 < near < far"), std::string::npos)
            << result.error().message;
    }
}

}  // namespace
}  // namespace monoplane::study
