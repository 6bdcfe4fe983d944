// The parts of a protocol that make a study day of sessions (docs/protocols.md, "A study day"):
// repetitions and blocking of the constant procedure, sessions per participant, the screens the
// participant reads in the headset (instructions, ready, breaks, end) and the participant
// variables the experimenter records before the first session. All optional: a protocol without
// them behaves as one session of one repetition, no screens, no variables.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/headset_prompts.h"
#include "text/font.h"

namespace monoplane::study {

// How the data trials of a constant-procedure session are grouped.
enum class Blocking {
    Scene,  // one block per scene, blocks in the counterbalanced order (the default)
    None,   // all scenes' trials interleaved in one block
};

// A page of text shown in the headset (and mirrored in the experimenter's window). The
// participant advances with confirm; on instruction pages, switch goes back one page.
struct ScreenPage {
    std::string text;  // may contain line breaks; wrapped to the panel's width when shown

    bool operator==(const ScreenPage&) const = default;
};

// Rests in a long session. Either trigger may be used, or both; a break is never shown before
// the first data trial or after the last.
struct BreakSettings {
    int every_trials = 0;         // a break after every N data trials; 0: none by count
    bool between_blocks = false;  // a break between scene blocks (blocking = "scene")
    double min_s = 30.0;          // the countdown before confirm continues, seconds
    std::string text = "Take a short break. Remove the headset if you like.";

    bool enabled() const { return every_trials > 0 || between_blocks; }
    bool operator==(const BreakSettings&) const = default;
};

enum class VariableType { Integer, Number, Choice, Text };

// A participant variable, recorded with the participant before the first session and exported
// as column var_<name> on every trial row.
struct ParticipantVariable {
    std::string name;  // [a-z][a-z0-9_]*, at most 32 characters, unique in the protocol
    VariableType type = VariableType::Text;
    std::optional<double> min;  // integer and number: the inclusive range, if any
    std::optional<double> max;
    std::vector<std::string> choices;  // choice: the allowed values (non-empty, unique)
    bool required = false;
    std::string help;  // one line for the form and the error messages

    bool operator==(const ParticipantVariable&) const = default;
};

struct StudyDaySettings {
    int sessions = 1;     // sessions per participant: the block order rotates
    int repetitions = 1;  // constant procedure: each condition this many times
    Blocking blocking = Blocking::Scene;
    std::vector<ScreenPage> instructions;  // before the first trial (practice included)
    std::optional<ScreenPage> ready;       // after practice, before the first data trial
    std::optional<BreakSettings> breaks;
    std::optional<ScreenPage> end;  // after the last trial and the questionnaire
    std::vector<ParticipantVariable> variables;
    // The height of a capital letter on the screens, degrees of visual angle.
    double text_height_deg = 1.0;
    // [text] font: the font file the screens and questionnaire are drawn with in the headset
    // (docs/protocols.md, "Languages"); an absolute path.
    std::string font = text::kDefaultFontPath;
    // [text.prompts]: the headset's own words (page footers, the break countdown, the
    // questionnaire's scale), in the participant's language.
    HeadsetPrompts prompts;

    bool has_screens() const {
        return !instructions.empty() || ready || (breaks && breaks->enabled()) || end;
    }
};

// Names as protocols and messages spell them.
std::string_view variable_type_name(VariableType type);
std::optional<VariableType> parse_variable_type(std::string_view name);
std::vector<std::string_view> variable_type_names();  // every type's, in order
std::string_view blocking_name(Blocking blocking);

inline constexpr std::size_t kMaxVariableName = 32;

// A participant variable's name: `[a-z][a-z0-9_]*`, at most 32 characters, since it becomes an
// export column (var_<name>) and a --var NAME=VALUE argument. The one rule for names, whether a
// protocol declares one or the store is given one; the message names it and says what a name may
// hold. Pure; any time.
Result<void> check_variable_name(std::string_view name);

}  // namespace monoplane::study
