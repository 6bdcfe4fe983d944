// Fuzz target: study protocols (study/protocol.h), the TOML files experimenters write.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "study/condition.h"
#include "study/protocol.h"
#include "tests/fuzz/fuzz_runner.h"
#include "tests/fuzz/mutator.h"

namespace monoplane {
namespace {

// What parse_protocol promises about a protocol it accepts (study/protocol.h).
std::string broken_promise(const study::Protocol& p) {
    if (p.name.empty()) return "an empty name";
    if (p.scenes.empty() || p.mono_planes.empty()) return "no scenes or no distances";
    const auto scenes = study::study_scene_names();
    for (const std::string& scene : p.scenes) {
        if (std::ranges::find(scenes, scene) == scenes.end()) return "unknown scene " + scene;
        if (std::ranges::count(p.scenes, scene) != 1) return "duplicate scene " + scene;
    }
    if (!(std::isfinite(p.near) && std::isfinite(p.far) && 0.0 < p.near && p.near < p.far))
        return "a bad clip range";
    for (const double m : p.mono_planes) {
        if (!(p.near < m && m < p.far)) return "a distance outside (near, far)";
        if (std::ranges::count(p.mono_planes, m) != 1) return "a duplicate distance";
    }
    if (p.alternatives[0] == p.alternatives[1]) return "two equal alternatives";
    if (p.practice_trials < 0 || p.practice_trials > 50) return "practice_trials out of range";
    if (p.questionnaire.scale_points < 2 || p.questionnaire.scale_points > 11)
        return "scale_points out of range";
    if (!(p.missed_frame_threshold >= 0.0 && p.missed_frame_threshold <= 1.0))
        return "missed_frame_threshold out of range";
    return {};
}

TEST(Fuzz, Protocol) {
    std::vector<std::string> dictionary = fuzz::split_words(R"(
name scenes mono_planes alternatives order first_scene require_both_viewed
practice_trials near far missed_frame_threshold [questionnaire] [render] items
scale_points anti_aliasing ssao detail questionnaire.items render.ssao "randomized"
"fixed" "latin-square" "random" "none" "taa" "msaa2" "msaa8" "off" "per-eye" "stereo"
"high" "medium"
)");
    for (const study::RenderMode mode : study::all_render_modes())
        dictionary.push_back("\"" + std::string(study::render_mode_name(mode)) + "\"");
    for (const std::string_view scene : study::study_scene_names())
        dictionary.push_back("\"" + std::string(scene) + "\"");

    const fuzz::FuzzTarget target{
        .name = "protocol",
        .seeds = {fuzz::source_path("protocols"), fuzz::corpus_path("protocol")},
        .dictionary = dictionary,
        .file_extension = ".toml",
        .iterations = 15000,
        .run = [](const fuzz::FuzzInput& input) {
            const Result<study::Protocol> protocol =
                study::parse_protocol(input.bytes, input.file.string());
            if (!protocol) return fuzz::rejected(protocol.error(), input);
            if (std::string broken = broken_promise(*protocol); !broken.empty())
                return fuzz::violation("accepted a protocol with " + broken);
            return fuzz::accepted();
        }};
    fuzz::expect_clean(fuzz::run_fuzz_target(target));
}

}  // namespace
}  // namespace monoplane
