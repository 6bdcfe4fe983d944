// A study protocol: which scenes, distances and alternatives, in what order,
// with how many practice trials and which questionnaire. Parsed from TOML and validated before
// anything runs; every problem names the file, the line and the key.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/protocol_auto.h"
#include "study/protocol_gaze.h"
#include "study/protocol_responses.h"
#include "study/protocol_staircase.h"
#include "study/protocol_study_day.h"
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

// The protocol's names for these values ("randomized", "latin-square", ...), as its `order` and
// `first_scene` keys take them.
std::string_view trial_order_name(TrialOrder order);
std::string_view first_scene_name(FirstSceneBalance balance);

struct Questionnaire {
    std::vector<std::string> items;  // Likert statements asked after the last trial
    int scale_points = 7;            // answers 1..scale_points
};

// How every trial is rendered (the protocol's [render] table, docs/headsets.md): part of the
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
    // Built-in scenes (study_scene_names()) and glTF files (names_scene_file(): ending in .gltf
    // or .glb), each as written in the protocol; no duplicates, not empty. These labels are what
    // the schedule, the database and the export carry.
    std::vector<std::string> scenes;
    // The absolute path of each entry that names a glTF file, by entry: resolved against the
    // protocol file's folder (absolute entries as they are). Empty for protocol text parsed
    // without a folder (a session's stored protocol: the database records the files it read).
    std::map<std::string, std::filesystem::path> scene_files;
    std::vector<double> mono_planes;  // metres, strictly inside (near, far), no duplicates
    std::array<RenderMode, 2> alternatives{RenderMode::Stereo, RenderMode::Hybrid};
    // Constant: every scene x distance once. Staircase: per scene, up to
    // staircase.trials_per_scene trials whose m an adaptive rule chooses within mono_planes'
    // range, the scenes' trials interleaved (study/schedule.h).
    Procedure procedure = Procedure::Constant;
    StaircaseSettings staircase;
    TrialOrder order = TrialOrder::Randomized;
    FirstSceneBalance first_scene = FirstSceneBalance::LatinSquare;
    bool require_both_viewed = true;
    int practice_trials = 2;
    double near = 0.1;  // clip range the conditions are rendered with (papers/000 Sect. 5.1)
    double far = 1000.0;
    Questionnaire questionnaire;
    RenderSettings render;
    AutoPlaneSettings auto_plane;  // [auto]: how hybrid-auto alternatives choose m
    // A trial whose frame log shows more than this share of its displayed frames missing their
    // display slot is flagged by `analyze` (a stutter participants may have noticed).
    double missed_frame_threshold = 0.05;
    // Sessions, repetitions, blocking, the participant's screens and variables
    // (study/protocol_study_day.h).
    StudyDaySettings day;
    // [responses]: answers from keys, besides the controller (study/protocol_responses.h).
    ResponseSettings responses;
    // [gaze]: eye gaze in the frame log (study/protocol_gaze.h).
    GazeSettings gaze;
    std::string source;           // file path or "<text>"
    std::string text;             // the file's text, stored with every session
    std::uint64_t text_hash = 0;  // FNV-1a 64 of text: identifies the protocol version

    // The data trials of a session; for a staircase the most (a posterior-width stopping rule
    // may end a scene's staircase sooner). The constant procedure shows every condition
    // day.repetitions times.
    std::size_t trials_per_session() const {
        const std::size_t per_scene =
            procedure == Procedure::Staircase
                ? static_cast<std::size_t>(staircase.trials_per_scene)
                : mono_planes.size() * static_cast<std::size_t>(day.repetitions);
        return scenes.size() * per_scene;
    }
};

// Parses and validates; all problems are reported, one per line, as "FILE:LINE:COL: key 'K': ..."
// (unknown keys, wrong types, unknown scenes or modes, a scene file name with a comma,
// distances outside (near, far), empty or duplicate lists, bad enum values, MSAA with a hybrid
// alternative). source_name appears in the messages. Scenes that name glTF files are checked for
// their form only and Protocol::scene_files stays empty: text alone has no folder to resolve
// them against. Any time.
Result<Protocol> parse_protocol(std::string_view toml_text, std::string_view source_name);

// As above, with every scene that names a glTF file resolved against scene_directory (see
// resolve_scene_file) into Protocol::scene_files; a file that does not exist or is no regular
// file is a located problem like the others, as is an entry that resolves to the same file as
// an earlier one. Touches the file system only to check that the files exist.
Result<Protocol> parse_protocol(std::string_view toml_text, std::string_view source_name,
                                const std::filesystem::path& scene_directory);

// Reads a file and parses it, scene files resolved against the file's folder; an unreadable
// file is an error naming it.
Result<Protocol> load_protocol(const std::filesystem::path& path);

}  // namespace monoplane::study
