// A study protocol (DESIGN.md section 7): which scenes, distances and alternatives, in what order,
// with how many practice trials and which questionnaire. Parsed from TOML and validated before
// anything runs; every problem names the file, the line and the key.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/render_mode.h"

namespace monoplane::study {

enum class TrialOrder {
    Randomized,  // distances shuffled within each scene block; the seed is drawn and recorded
    Fixed,       // as listed in the protocol
};

enum class FirstSceneBalance {
    LatinSquare,  // block (scene) order from a balanced Latin square row: participant index
    Random,       // block order shuffled with the session's seed
    Fixed,        // scenes in the order listed
};

struct Questionnaire {
    std::vector<std::string> items;  // Likert statements asked after the last trial
    int scale_points = 7;            // answers 1..scale_points
};

// How every trial is rendered (the protocol's [render] table, DESIGN.md section 7): part of the
// protocol because participants compare images, and papers/000 rendered its study with TAA, so
// aliasing that differs between the alternatives would confound the choices. Names as the render
// command takes them; study/ stays free of renderer types.
struct RenderSettings {
    std::string anti_aliasing = "none";  // none | taa | msaa2 | msaa4 | msaa8 (stereo forms only)
    std::string ssao = "off";            // off | per-eye | stereo
    std::string detail = "low";          // test | low | medium | high | ultra

    bool operator==(const RenderSettings&) const = default;
};

struct Protocol {
    std::string name;
    std::vector<std::string> scenes;  // study_scene_names(), no duplicates, not empty
    std::vector<double> mono_planes;  // metres, strictly inside (near, far), no duplicates
    std::array<RenderMode, 2> alternatives{RenderMode::Stereo, RenderMode::Hybrid};
    TrialOrder order = TrialOrder::Randomized;
    FirstSceneBalance first_scene = FirstSceneBalance::LatinSquare;
    bool require_both_viewed = true;
    int practice_trials = 2;
    double near = 0.1;  // clip range the conditions are rendered with (DESIGN.md section 2)
    double far = 1000.0;
    Questionnaire questionnaire;
    RenderSettings render;
    // A trial whose frame log shows more than this share of its displayed frames missing their
    // display slot is flagged by `analyze` (a stutter participants may have noticed).
    double missed_frame_threshold = 0.05;
    std::string source;           // file path or "<text>"
    std::string text;             // the file's text, stored with every session
    std::uint64_t text_hash = 0;  // FNV-1a 64 of text: identifies the protocol version

    std::size_t trials_per_session() const { return scenes.size() * mono_planes.size(); }
};

// Parses and validates; all problems are reported, one per line, as "FILE:LINE:COL: key 'K': ..."
// (unknown keys, wrong types, unknown scenes or modes, distances outside (near, far), empty or
// duplicate lists, bad enum values, MSAA with a hybrid alternative). source_name appears in the
// messages.
Result<Protocol> parse_protocol(std::string_view toml_text, std::string_view source_name);

// Reads a file and parses it; an unreadable file is an error naming it.
Result<Protocol> load_protocol(const std::filesystem::path& path);

}  // namespace monoplane::study
