// The shared name tables (common/name_table.h, common/render_mode_names.h) and the sides that read
// them: every value round-trips, the names are distinct, and the study's render modes and the
// renderer's choices spell each mode alike.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "common/render_mode_names.h"
#include "renderer/plan/render_choices.h"
#include "study/render_mode.h"
#include "study/trial_events.h"

namespace monoplane {
namespace {

enum class Fruit { Apple, Pear, Plum };
constexpr NameTable<Fruit> kFruitNames = {
    {Fruit::Apple, "apple"}, {Fruit::Pear, "pear"}, {Fruit::Plum, "plum"}};

TEST(NameTable, ReadsBothWays) {
    EXPECT_EQ(parse_name(kFruitNames, "pear"), Fruit::Pear);
    EXPECT_EQ(parse_name(kFruitNames, std::string("plum")), Fruit::Plum);
    EXPECT_EQ(parse_name(kFruitNames, "Pear"), std::nullopt);  // case-sensitive
    EXPECT_EQ(parse_name(kFruitNames, "pear "), std::nullopt);
    EXPECT_EQ(find_name(kFruitNames, Fruit::Apple), "apple");
    EXPECT_EQ(name_of(kFruitNames, Fruit::Plum), "plum");
    EXPECT_EQ(find_name(kFruitNames, static_cast<Fruit>(7)), "?");
    EXPECT_EQ(find_name(kFruitNames, static_cast<Fruit>(7), "unknown"), "unknown");
    EXPECT_EQ(joined_names(kFruitNames), "apple, pear, plum");
    EXPECT_EQ(joined_names(kFruitNames, "|"), "apple|pear|plum");
}

TEST(RenderModeNames, EveryNamedModeRoundTripsAndIsDistinct) {
    EXPECT_EQ(joined_names(kRenderModeNames),
              "stereo, stereo-multiview, stereo-gs, stereo-instanced, hybrid, hybrid-farfield, "
              "hybrid-auto");
    std::set<std::string_view> names;
    for (const auto& [mode, name] : kRenderModeNames) {
        EXPECT_EQ(parse_name(kRenderModeNames, name), mode) << name;
        EXPECT_EQ(find_name(kRenderModeNames, mode), name);
        names.insert(name);
    }
    EXPECT_EQ(names.size(), kRenderModeNames.size());
    EXPECT_EQ(joined_names(kAntiAliasingNames), "none, taa, msaa2, msaa4, msaa8");
}

// Each study mode is its named mode, so both sides print and parse the same text.
TEST(RenderModeNames, TheStudysModesAreTheNamedModes) {
    ASSERT_EQ(study::all_render_modes().size(), kRenderModeNames.size());
    auto named = kRenderModeNames.begin();
    for (study::RenderMode mode : study::all_render_modes()) {
        EXPECT_EQ(study::render_mode_name(mode), named->second);
        const Result<study::RenderMode> parsed = study::parse_render_mode(named->second);
        ASSERT_TRUE(parsed.ok()) << parsed.error().message;
        EXPECT_EQ(*parsed, mode);
        ++named;
    }
}

// Every renderer choice has a named mode, and every named mode but the study's hybrid-auto is a
// renderer choice; the hybrid modes' stereo pass is not part of their name.
TEST(RenderModeNames, TheRenderersChoicesAreTheNamedModes) {
    using namespace plan;
    const RenderModeChoice stereo_gs{Mode::kStereo, StereoPass::kGeometryShader};
    EXPECT_EQ(render_mode_name(stereo_gs), "stereo-gs");
    EXPECT_EQ(render_mode_name({Mode::kStereo, StereoPass::kMultiview}), "stereo-multiview");
    EXPECT_EQ(render_mode_name({Mode::kStereo, StereoPass::kInstanced}), "stereo-instanced");
    EXPECT_EQ(render_mode_name({Mode::kHybrid, StereoPass::kInstanced}), "hybrid");
    EXPECT_EQ(render_mode_name({Mode::kHybrid, StereoPass::kMultiview}), "hybrid");
    EXPECT_EQ(render_mode_name({Mode::kHybridFarfield, StereoPass::kTwoPasses}), "hybrid-farfield");
    for (const auto& [named, name] : kRenderModeNames) {
        const auto choice = parse_render_mode(name);
        if (named == NamedRenderMode::HybridAuto) {
            EXPECT_FALSE(choice.has_value());
            continue;
        }
        ASSERT_TRUE(choice.has_value()) << name;
        EXPECT_EQ(render_mode_name(*choice), name);
    }
    for (Mode mode : {Mode::kStereo, Mode::kHybrid, Mode::kHybridFarfield}) {
        for (StereoPass pass : {StereoPass::kTwoPasses, StereoPass::kMultiview,
                                StereoPass::kGeometryShader, StereoPass::kInstanced}) {
            const std::string name = render_mode_name({mode, pass});
            EXPECT_TRUE(parse_name(kRenderModeNames, name).has_value()) << name;
            EXPECT_EQ(parse_render_mode(name)->mode, mode) << name;
        }
        EXPECT_EQ(parse_mode(mode_name(mode)), mode);
    }
    EXPECT_EQ(mode_name(Mode::kHybridFarfield), "hybrid-farfield");
    EXPECT_EQ(parse_mode("stereo-gs"), std::nullopt);  // a render mode, not a Mode
    EXPECT_EQ(parse_mode("stereo-instanced"), std::nullopt);
    const auto instanced = parse_render_mode("stereo-instanced");
    ASSERT_TRUE(instanced.has_value());
    EXPECT_EQ(instanced->mode, Mode::kStereo);
    EXPECT_EQ(instanced->stereo_pass, StereoPass::kInstanced);
    EXPECT_EQ(parse_mode("hybrid-auto"), std::nullopt);
    EXPECT_EQ(parse_render_mode("Stereo"), std::nullopt);
}

TEST(RenderModeNames, AntiAliasingRoundTripsThroughTheSharedTable) {
    using namespace plan;
    for (AntiAliasing aa : {AntiAliasing::kNone, AntiAliasing::kTaa, AntiAliasing::kMsaa2,
                            AntiAliasing::kMsaa4, AntiAliasing::kMsaa8}) {
        EXPECT_EQ(parse_anti_aliasing(anti_aliasing_name(aa)), aa) << anti_aliasing_name(aa);
    }
    EXPECT_EQ(anti_aliasing_name(AntiAliasing::kMsaa4), "msaa4");
    EXPECT_EQ(parse_anti_aliasing("taa"), AntiAliasing::kTaa);
    EXPECT_EQ(parse_anti_aliasing("msaa16"), std::nullopt);
    EXPECT_EQ(mono_culling_name(MonoCulling::kOcclusionCull), "occlusion-cull");
    EXPECT_EQ(parse_stereo_pass("gs"), StereoPass::kGeometryShader);
    EXPECT_EQ(parse_stereo_pass("instanced"), StereoPass::kInstanced);
    EXPECT_EQ(stereo_pass_name(StereoPass::kInstanced), "instanced");
    EXPECT_EQ(parse_stereo_pass("Instanced"), std::nullopt);
}

// The stored event names: one per kind, each read back as its kind; screen kinds after trial kinds.
TEST(EventKindNames, EveryKindRoundTrips) {
    using study::EventKind;
    const int count = static_cast<int>(EventKind::RunStarted) + 1;
    EXPECT_EQ(count, 18);
    std::set<std::string_view> names;
    for (int k = 0; k < count; ++k) {
        const auto kind = static_cast<EventKind>(k);
        const std::string_view name = study::event_kind_name(kind);
        EXPECT_NE(name, "unknown") << k;
        EXPECT_EQ(study::parse_event_kind(name), kind) << name;
        names.insert(name);
    }
    EXPECT_EQ(names.size(), static_cast<std::size_t>(count));
    EXPECT_EQ(study::event_kind_name(EventKind::InstructionsConfirmed), "instructions_confirmed");
    EXPECT_EQ(study::event_kind_name(EventKind::BreakStarted), "break_started");
    EXPECT_EQ(study::event_kind_name(EventKind::EndShown), "end_shown");
    EXPECT_EQ(study::event_kind_name(EventKind::SessionAbandoned), "session_abandoned");
    EXPECT_EQ(study::event_kind_name(EventKind::ProtocolTextChanged), "protocol_text_changed");
    EXPECT_EQ(study::event_kind_name(static_cast<EventKind>(count)), "unknown");
    EXPECT_EQ(study::parse_event_kind("Shown"), std::nullopt);
    EXPECT_EQ(study::parse_event_kind("unknown"), std::nullopt);
    EXPECT_EQ(study::parse_event_kind(""), std::nullopt);
}

}  // namespace
}  // namespace monoplane
