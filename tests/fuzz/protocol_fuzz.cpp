// Fuzz target: study protocols (study/protocol.h), the TOML files experimenters write.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "study/condition.h"
#include "study/protocol.h"
#include "study/protocol_study_day_parse.h"
#include "tests/fuzz/fuzz_runner.h"
#include "tests/fuzz/mutator.h"

namespace monoplane {
namespace {

// A screen's text: not blank, at most kMaxPageCharacters (UTF-8: at most 4 bytes each).
bool page_ok(const std::string& text) {
    return !text.empty() && text.find_first_not_of(" \t\n") != std::string::npos &&
           text.size() <= 4 * study::kMaxPageCharacters;
}

bool variable_ok(const study::ParticipantVariable& v) {
    const bool numeric =
        v.type == study::VariableType::Integer || v.type == study::VariableType::Number;
    if (v.name.empty() || v.name.size() > study::kMaxVariableName) return false;
    if (!(v.name[0] >= 'a' && v.name[0] <= 'z')) return false;
    if (!numeric && (v.min || v.max)) return false;
    if (v.min && v.max && *v.min > *v.max) return false;
    if ((v.type == study::VariableType::Choice) == v.choices.empty()) return false;
    for (const std::string& choice : v.choices) {
        if (choice.empty() || std::ranges::count(v.choices, choice) != 1) return false;
    }
    return v.help.find('\n') == std::string::npos;
}

// What the study-day readers promise (study/protocol_study_day_parse.h).
std::string broken_day_promise(const study::Protocol& p) {
    const study::StudyDaySettings& day = p.day;
    if (day.sessions < 1 || day.sessions > study::kMaxSessions) return "sessions out of range";
    if (day.repetitions < 1 || day.repetitions > study::kMaxRepetitions)
        return "repetitions out of range";
    if (p.procedure == study::Procedure::Staircase &&
        (day.repetitions != 1 || day.blocking != study::Blocking::Scene))
        return "a staircase with repetitions or blocking";
    if (!(day.text_height_deg >= study::kMinTextHeightDeg &&
          day.text_height_deg <= study::kMaxTextHeightDeg))
        return "text_height_deg out of range";
    if (day.instructions.size() > study::kMaxInstructionPages) return "too many pages";
    for (const study::ScreenPage& page : day.instructions)
        if (!page_ok(page.text)) return "a bad instruction page";
    if ((day.ready && !page_ok(day.ready->text)) || (day.end && !page_ok(day.end->text)))
        return "a bad ready or end page";
    if (day.breaks) {
        const study::BreakSettings& b = *day.breaks;
        if (!b.enabled() || b.every_trials < 0 || b.every_trials > study::kMaxBreakInterval ||
            !(b.min_s >= 0.0 && b.min_s <= study::kMaxBreakSeconds) || !page_ok(b.text))
            return "bad breaks";
        if (b.between_blocks &&
            (day.blocking == study::Blocking::None || p.procedure == study::Procedure::Staircase))
            return "breaks between blocks without blocks";
    }
    if (day.font.find_first_not_of(" \t\n") == std::string::npos) return "a blank [text] font";
    if (day.variables.size() > study::kMaxVariables) return "too many variables";
    for (const study::ParticipantVariable& v : day.variables) {
        if (!variable_ok(v)) return "a bad variable " + v.name;
        if (std::ranges::count(day.variables, v.name, &study::ParticipantVariable::name) != 1)
            return "a duplicate variable " + v.name;
    }
    return {};
}

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
    return broken_day_promise(p);
}

TEST(Fuzz, Protocol) {
    std::vector<std::string> dictionary = fuzz::split_words(R"(
name scenes mono_planes alternatives order first_scene require_both_viewed
practice_trials near far missed_frame_threshold [questionnaire] [render] items
scale_points anti_aliasing ssao detail questionnaire.items render.ssao "randomized"
"fixed" "latin-square" "random" "none" "taa" "msaa2" "msaa8" "off" "per-eye" "stereo"
"high" "medium"
sessions repetitions blocking text_height_deg [[instructions]] [ready] [breaks] [end]
[[variables]] text every_trials between_blocks min_s name type min max choices required help
"scene" "integer" "number" "choice" "text" true false 0 1 1800 1801 -1 0.4 50 51 ["a","a"]
"""multi
line""" "\u00fc" "\u2013" "\u4e2d\u3002" "\u05e9" "e\u0301" "\U0001F600" [text] font
"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
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
