// Reading the study-day keys (protocol_study_day_parse.h). The limits are generous for any real
// study and tight enough that a typo (sessions = 200, min_s = 3000) is caught before a
// participant sits in the headset.
#include "study/protocol_study_day_parse.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "common/quoted.h"
#include "text/complex_scripts.h"
#include "text/utf8.h"

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 1> kPageKeys = {"text"};
constexpr std::array<std::string_view, 2> kTextKeys = {"font", "prompts"};
constexpr std::array<std::string_view, 4> kBreakKeys = {"every_trials", "between_blocks", "min_s",
                                                        "text"};
constexpr std::array<std::string_view, 7> kVariableKeys = {"name",    "type",     "min", "max",
                                                           "choices", "required", "help"};
constexpr std::array<std::string_view, 2> kBlockings = {"scene", "none"};

bool is_blank(std::string_view text) {
    return std::ranges::all_of(text, [](char c) { return c == ' ' || c == '\t' || c == '\n'; });
}

// One of `names`, or nothing after a problem that lists them and suggests the closest.
std::optional<std::string_view> read_one_of(const toml::node& node, std::string_view key,
                                            std::span<const std::string_view> names,
                                            TomlProblems& problems) {
    const auto* text = node.as_string();
    if (text == nullptr) {
        report_wrong_type(node, key, "a string, one of " + join(names), problems);
        return std::nullopt;
    }
    const auto found = std::ranges::find(names, text->get());
    if (found != names.end()) return *found;
    std::string message = toml_key_prefix(key) + "unknown value " + in_quotes(text->get()) +
                          " (allowed: " + join(names) + ")";
    const std::string_view closest = closest_match(text->get(), names);
    if (!closest.empty()) message += "; did you mean " + in_quotes(closest) + "?";
    problems.add(node.source(), message);
    return std::nullopt;
}

std::optional<bool> read_flag(const toml::node& node, std::string_view key,
                              TomlProblems& problems) {
    if (const auto* flag = node.as_boolean()) return flag->get();
    report_wrong_type(node, key, "a boolean (true or false)", problems);
    return std::nullopt;
}

// The table at `key` of the root, or nullptr (absent, or reported as the wrong type).
const toml::table* find_table(const TomlScope& root, std::string_view key,
                              std::string_view expected, TomlProblems& problems) {
    const toml::node* node = root.table.get(key);
    if (node == nullptr) return nullptr;
    const toml::table* table = node->as_table();
    if (table == nullptr) report_wrong_type(*node, key, expected, problems);
    return table;
}

// The problem with a screen's text, or nothing: blank, too long, not UTF-8, a control
// character, or one the headset cannot draw whatever the font (it draws one glyph per
// character, left to right: no text shaping); named with its position and the text before it.
std::optional<std::string> screen_text_problem(std::string_view text) {
    if (is_blank(text)) return "is empty; a screen needs text to read";
    if (const std::optional<std::size_t> invalid = text::first_invalid_utf8(text)) {
        return "is not UTF-8 text (byte " + std::to_string(*invalid + 1) +
               "); save the protocol as UTF-8";
    }
    const std::u32string characters = text::decode_utf8_lenient(text);
    for (std::size_t i = 0; i < characters.size(); ++i) {
        const char32_t c = characters[i];
        const bool control = (c < 0x20 && c != U'\n' && c != U'\t') || (c >= 0x7F && c < 0xA0);
        std::optional<std::string> reason = text::needs_shaping(c);
        if (!control && !reason) continue;
        const std::size_t from = i > 12 ? i - 12 : 0;
        const std::string what =
            control ? "a control character"
                    : in_quotes(text::encode_utf8(c)) + " " + text::code_point_label(c);
        return "character " + std::to_string(i + 1) + " (" + what + ", after " +
               in_quotes(text::encode_utf8(characters.substr(from, i - from))) +
               ") cannot be shown in the headset: " +
               (control ? std::string("remove it")
                        : "it is " + *reason +
                              "; the headset draws one glyph per character, left to right");
    }
    if (characters.size() > kMaxPageCharacters) {
        return "has " + std::to_string(characters.size()) + " characters; a page holds at most " +
               std::to_string(kMaxPageCharacters) + " (split it into pages)";
    }
    return std::nullopt;
}

// Text for the headset. Line breaks are kept; long lines are wrapped when shown.
std::optional<std::string> read_screen_text(const toml::node& node, std::string_view key,
                                            TomlProblems& problems) {
    const auto* value = node.as_string();
    if (value == nullptr) {
        report_wrong_type(node, key, "a string, the text shown to the participant", problems);
        return std::nullopt;
    }
    if (std::optional<std::string> problem = screen_text_problem(value->get())) {
        problems.add(node.source(), toml_key_prefix(key) + *problem);
        return std::nullopt;
    }
    return value->get();
}

// A table with one key, text: [ready], [end] and each [[instructions]] page.
std::optional<ScreenPage> read_page(const toml::table& table, std::string_view name,
                                    TomlProblems& problems) {
    const TomlScope scope{table, std::string(name)};
    report_unknown_keys(scope, kPageKeys, problems);
    const toml::node* node = find_required(scope, "text", "a string, the page's text", problems);
    if (node == nullptr) return std::nullopt;
    std::optional<std::string> text = read_screen_text(*node, scope.qualified("text"), problems);
    if (!text) return std::nullopt;
    return ScreenPage{std::move(*text)};
}

void read_instructions(const TomlScope& root, StudyDaySettings& day, TomlProblems& problems) {
    const toml::node* node = root.table.get("instructions");
    if (node == nullptr) return;
    constexpr std::string_view kExpected = "an array of tables ([[instructions]], each with text)";
    const toml::array* pages = node->as_array();
    if (pages == nullptr) {
        report_wrong_type(*node, "instructions", kExpected, problems);
        return;
    }
    if (pages->size() > kMaxInstructionPages) {
        problems.add(node->source(), toml_key_prefix("instructions") + "has " +
                                         std::to_string(pages->size()) + " pages; at most " +
                                         std::to_string(kMaxInstructionPages));
        return;
    }
    for (std::size_t i = 0; i < pages->size(); ++i) {
        const toml::node& element = (*pages)[i];
        if (const toml::table* table = element.as_table()) {
            if (auto page = read_page(*table, "instructions", problems)) {
                day.instructions.push_back(std::move(*page));
            }
        } else {
            problems.add(element.source(), toml_key_prefix("instructions") + "page " +
                                               std::to_string(i + 1) +
                                               " must be a table ([[instructions]] with text), "
                                               "but is " +
                                               std::string(toml_type_phrase(element.type())));
        }
    }
}

void read_single_page(const TomlScope& root, std::string_view key, std::optional<ScreenPage>& page,
                      TomlProblems& problems) {
    const std::string expected = "a table ([" + std::string(key) + "] with text)";
    if (const toml::table* table = find_table(root, key, expected, problems)) {
        page = read_page(*table, key, problems);
    }
}

void read_counts(const TomlScope& root, Procedure procedure, StudyDaySettings& day,
                 TomlProblems& problems) {
    if (const toml::node* node = root.table.get("sessions")) {
        if (auto n = read_integer_in(*node, "sessions", 1, kMaxSessions, problems)) {
            day.sessions = static_cast<int>(*n);
        }
    }
    if (const toml::node* node = root.table.get("repetitions")) {
        if (auto n = read_integer_in(*node, "repetitions", 1, kMaxRepetitions, problems)) {
            if (procedure == Procedure::Staircase && *n != 1) {
                problems.add(node->source(), toml_key_prefix("repetitions") +
                                                 "staircases choose their own trials (each "
                                                 "scene's up to staircase.trials_per_scene); "
                                                 "repetitions applies to procedure = 'constant'");
            } else {
                day.repetitions = static_cast<int>(*n);
            }
        }
    }
}

void read_layout(const TomlScope& root, Procedure procedure, StudyDaySettings& day,
                 TomlProblems& problems) {
    if (const toml::node* node = root.table.get("blocking")) {
        if (auto name = read_one_of(*node, "blocking", kBlockings, problems)) {
            if (procedure == Procedure::Staircase) {
                problems.add(node->source(), toml_key_prefix("blocking") +
                                                 "staircases interleave their scenes' trials in "
                                                 "rounds; blocking applies to procedure = "
                                                 "'constant'");
            } else {
                day.blocking = *name == "none" ? Blocking::None : Blocking::Scene;
            }
        }
    }
    if (const toml::node* node = root.table.get("text_height_deg")) {
        const std::string range =
            "from " + format_number(kMinTextHeightDeg) + " to " + format_number(kMaxTextHeightDeg);
        const std::optional<double> height = read_number(
            *node, "text_height_deg", "a number of degrees of visual angle, " + range, problems);
        if (!height) return;
        if (!(*height >= kMinTextHeightDeg && *height <= kMaxTextHeightDeg)) {
            problems.add(node->source(), toml_key_prefix("text_height_deg") +
                                             format_number(*height) + " degrees is outside " +
                                             range + " (1 degree reads well in a headset)");
        } else {
            day.text_height_deg = *height;
        }
    }
}

void read_break_duration(const toml::table& table, BreakSettings& breaks, TomlProblems& problems) {
    const toml::node* node = table.get("min_s");
    if (node == nullptr) return;
    const std::optional<double> seconds =
        read_number(*node, "breaks.min_s", "a number of seconds, 0 to 1800", problems);
    if (!seconds) return;
    if (!(*seconds >= 0.0)) {
        problems.add(node->source(), toml_key_prefix("breaks.min_s") + format_number(*seconds) +
                                         " is not a number of seconds >= 0");
    } else if (*seconds > kMaxBreakSeconds) {
        problems.add(node->source(), toml_key_prefix("breaks.min_s") + format_number(*seconds) +
                                         " s: a break longer than 30 minutes is not a break "
                                         "(at most 1800; end the session instead)");
    } else {
        breaks.min_s = *seconds;
    }
}

// The triggers, after the blocking they depend on has been read; false when one was reported.
bool read_break_triggers(const toml::table& table, Procedure procedure, Blocking blocking,
                         BreakSettings& breaks, TomlProblems& problems) {
    bool clean = true;
    if (const toml::node* node = table.get("every_trials")) {
        const auto n =
            read_integer_in(*node, "breaks.every_trials", 0, kMaxBreakInterval, problems);
        if (n) breaks.every_trials = static_cast<int>(*n);
        clean = n.has_value();
    }
    const toml::node* node = table.get("between_blocks");
    if (node == nullptr) return clean;
    const std::optional<bool> flag = read_flag(*node, "breaks.between_blocks", problems);
    if (!flag) return false;
    if (*flag && procedure == Procedure::Staircase) {
        problems.add(node->source(), toml_key_prefix("breaks.between_blocks") +
                                         "a staircase session has no scene blocks (its scenes' "
                                         "trials interleave); use every_trials");
        return false;
    }
    if (*flag && blocking == Blocking::None) {
        problems.add(node->source(), toml_key_prefix("breaks.between_blocks") +
                                         "blocking = 'none' puts every trial in one block, so "
                                         "there is no break between blocks; use every_trials "
                                         "or blocking = 'scene'");
        return false;
    }
    breaks.between_blocks = *flag;
    return clean;
}

void read_breaks(const TomlScope& root, Procedure procedure, StudyDaySettings& day,
                 TomlProblems& problems) {
    const toml::table* table = find_table(
        root, "breaks", "a table ([breaks] with every_trials and/or between_blocks)", problems);
    if (table == nullptr) return;
    const TomlScope scope{*table, "breaks"};
    report_unknown_keys(scope, kBreakKeys, problems);
    BreakSettings breaks;
    const bool triggers_read =
        read_break_triggers(*table, procedure, day.blocking, breaks, problems);
    read_break_duration(*table, breaks, problems);
    if (const toml::node* node = table->get("text")) {
        if (auto text = read_screen_text(*node, "breaks.text", problems)) breaks.text = *text;
    }
    // Only when the triggers read cleanly: a wrong one was reported already.
    if (triggers_read && !breaks.enabled()) {
        problems.add(table->source(), toml_key_prefix("breaks") +
                                          "shows no break: give every_trials = N (N > 0) or "
                                          "between_blocks = true, or remove [breaks]");
    }
    day.breaks = std::move(breaks);
}

// "'age'", or "this variable" when its name was wrong (and reported).
std::string variable_label(const ParticipantVariable& variable) {
    return variable.name.empty() ? "this variable" : in_quotes(variable.name);
}

// Names become export columns (var_<name>) and --var NAME=VALUE arguments: lower case, unique.
void read_variable_name(const TomlScope& scope, const std::vector<ParticipantVariable>& earlier,
                        ParticipantVariable& variable, TomlProblems& problems) {
    const toml::node* node = find_required(scope, "name", "a name, e.g. \"age\"", problems);
    if (node == nullptr) return;
    const auto* name = node->as_string();
    if (name == nullptr) {
        report_wrong_type(*node, "variables.name", "a string, e.g. \"age\"", problems);
    } else if (Result<void> valid = check_variable_name(name->get()); !valid) {
        problems.add(node->source(), toml_key_prefix("variables.name") + valid.error().message);
    } else if (std::ranges::find(earlier, name->get(), &ParticipantVariable::name) !=
               earlier.end()) {
        problems.add(node->source(), toml_key_prefix("variables.name") + "variable " +
                                         in_quotes(name->get()) +
                                         " is declared twice; each name is one export column "
                                         "(var_" +
                                         name->get() + ")");
    } else {
        variable.name = name->get();
    }
}

std::optional<VariableType> read_variable_type(const TomlScope& scope, TomlProblems& problems) {
    const std::vector<std::string_view> types = variable_type_names();
    const toml::node* node = find_required(scope, "type", "one of " + join(types), problems);
    if (node == nullptr) return std::nullopt;
    const auto name = read_one_of(*node, "variables.type", types, problems);
    if (!name) return std::nullopt;
    return parse_variable_type(*name);
}

// One end of an integer or number variable's range; integers only for an integer variable.
std::optional<double> read_bound(const toml::node& node, std::string_view key, VariableType type,
                                 TomlProblems& problems) {
    if (type == VariableType::Integer) {
        const auto* integer = node.as_integer();
        if (integer == nullptr) {
            report_wrong_type(node, key, "an integer (the variable is an integer)", problems);
            return std::nullopt;
        }
        return static_cast<double>(integer->get());
    }
    const std::optional<double> value = read_number(node, key, "a number", problems);
    if (value && !std::isfinite(*value)) {
        problems.add(node.source(), toml_key_prefix(key) + "must be a finite number");
        return std::nullopt;
    }
    return value;
}

void read_variable_range(const toml::table& table, ParticipantVariable& variable,
                         TomlProblems& problems) {
    const bool numeric =
        variable.type == VariableType::Integer || variable.type == VariableType::Number;
    for (auto [key, field] : {std::pair{"min", &ParticipantVariable::min},
                              std::pair{"max", &ParticipantVariable::max}}) {
        const toml::node* node = table.get(key);
        if (node == nullptr) continue;
        const std::string qualified = "variables." + std::string(key);
        if (!numeric) {
            problems.add(node->source(), toml_key_prefix(qualified) +
                                             "applies to integer and number variables, but " +
                                             variable_label(variable) + " is of type " +
                                             in_quotes(variable_type_name(variable.type)));
            continue;
        }
        variable.*field = read_bound(*node, qualified, variable.type, problems);
    }
    if (variable.min && variable.max && *variable.min > *variable.max) {
        problems.add(table.get("max")->source(),
                     toml_key_prefix("variables.max") + format_number(*variable.max) +
                         " is below min = " + format_number(*variable.min));
    }
}

// A choice is typed as --var NAME=CHOICE: printable, not blank, each once.
bool accept_choice(const std::string& choice, const toml::node& element,
                   const std::vector<std::string>& earlier, TomlProblems& problems) {
    const std::string prefix = toml_key_prefix("variables.choices");
    const bool control = std::ranges::any_of(
        choice, [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
    std::string problem;
    if (is_blank(choice)) {
        problem = "a choice is empty";
    } else if (control) {
        problem = "choice " + in_quotes(choice) + " has a control character";
    } else if (std::ranges::find(earlier, choice) != earlier.end()) {
        problem = "duplicate choice " + in_quotes(choice) + "; list each once";
    }
    if (!problem.empty()) problems.add(element.source(), prefix + problem);
    return problem.empty();
}

void read_variable_choices(const toml::table& table, ParticipantVariable& variable,
                           TomlProblems& problems) {
    const toml::node* node = table.get("choices");
    if (variable.type != VariableType::Choice) {
        if (node != nullptr) {
            problems.add(node->source(), toml_key_prefix("variables.choices") +
                                             "applies to choice variables, but " +
                                             variable_label(variable) + " is of type " +
                                             in_quotes(variable_type_name(variable.type)));
        }
        return;
    }
    const TomlScope scope{table, "variables"};
    constexpr std::string_view kExpected = "an array of strings, e.g. [\"normal\", \"corrected\"]";
    if (node == nullptr) node = find_required(scope, "choices", kExpected, problems);
    if (node == nullptr) return;
    const toml::array* array = node->as_array();
    if (array == nullptr || array->empty()) {
        if (array == nullptr)
            report_wrong_type(*node, "variables.choices", kExpected, problems);
        else
            problems.add(node->source(), toml_key_prefix("variables.choices") + "is empty");
        return;
    }
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& element = (*array)[i];
        const auto* choice = element.as_string();
        if (choice == nullptr) {
            report_wrong_type(element, "variables.choices element " + std::to_string(i + 1),
                              "a string", problems);
        } else if (accept_choice(choice->get(), element, variable.choices, problems)) {
            variable.choices.push_back(choice->get());
        }
    }
}

void read_variable_help(const toml::table& table, ParticipantVariable& variable,
                        TomlProblems& problems) {
    if (const toml::node* node = table.get("required")) {
        if (auto flag = read_flag(*node, "variables.required", problems)) variable.required = *flag;
    }
    const toml::node* node = table.get("help");
    if (node == nullptr) return;
    const auto* help = node->as_string();
    if (help == nullptr) {
        report_wrong_type(*node, "variables.help", "a string, one line", problems);
        return;
    }
    const bool control = std::ranges::any_of(
        help->get(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
    if (control || help->get().size() > kMaxVariableHelp) {
        problems.add(node->source(), toml_key_prefix("variables.help") +
                                         "must be one line of at most " +
                                         std::to_string(kMaxVariableHelp) +
                                         " characters (it is shown in forms and messages)");
        return;
    }
    variable.help = help->get();
}

// One [[variables]] table; nothing when it has a problem.
std::optional<ParticipantVariable> read_variable(const toml::table& table,
                                                 const std::vector<ParticipantVariable>& earlier,
                                                 TomlProblems& problems) {
    const TomlScope scope{table, "variables"};
    report_unknown_keys(scope, kVariableKeys, problems);
    ParticipantVariable variable;
    read_variable_name(scope, earlier, variable, problems);
    const std::optional<VariableType> type = read_variable_type(scope, problems);
    read_variable_help(table, variable, problems);
    if (!type) return std::nullopt;  // the range and choices depend on it
    variable.type = *type;
    read_variable_range(table, variable, problems);
    read_variable_choices(table, variable, problems);
    if (variable.name.empty()) return std::nullopt;
    return variable;
}

void read_variables(const TomlScope& root, StudyDaySettings& day, TomlProblems& problems) {
    const toml::node* node = root.table.get("variables");
    if (node == nullptr) return;
    constexpr std::string_view kExpected =
        "an array of tables ([[variables]], each with name and type)";
    const toml::array* array = node->as_array();
    if (array == nullptr) {
        report_wrong_type(*node, "variables", kExpected, problems);
        return;
    }
    if (array->size() > kMaxVariables) {
        problems.add(node->source(), toml_key_prefix("variables") + "declares " +
                                         std::to_string(array->size()) + " variables; at most " +
                                         std::to_string(kMaxVariables));
        return;
    }
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& element = (*array)[i];
        const toml::table* table = element.as_table();
        if (table == nullptr) {
            problems.add(element.source(), toml_key_prefix("variables") + "element " +
                                               std::to_string(i + 1) +
                                               " must be a table ([[variables]] with name and "
                                               "type), but is " +
                                               std::string(toml_type_phrase(element.type())));
        } else if (auto variable = read_variable(*table, day.variables, problems)) {
            day.variables.push_back(std::move(*variable));
        }
    }
}

// [text.prompts]: each given prompt replaces the English one; empty leaves that part out. The
// characters are judged as a page's (screen_text_problem), the placeholders against the
// prompt's own.
void read_prompts(const toml::table& text, HeadsetPrompts& prompts, TomlProblems& problems) {
    const toml::node* node = text.get("prompts");
    if (node == nullptr) return;
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        report_wrong_type(*node, "text.prompts",
                          "a table ([text.prompts] with page = \"...\", next = \"...\", ...)",
                          problems);
        return;
    }
    const TomlScope scope{*table, "text.prompts"};
    std::vector<std::string_view> known;
    for (const PromptKey& key : prompt_keys()) known.push_back(key.key);
    report_unknown_keys(scope, known, problems);
    for (const PromptKey& key : prompt_keys()) {
        const toml::node* value = table->get(key.key);
        if (value == nullptr) continue;
        const std::string qualified = scope.qualified(key.key);
        const auto* text_value = value->as_string();
        if (text_value == nullptr) {
            report_wrong_type(*value, qualified, "a string, the prompt as the participant reads it",
                              problems);
            continue;
        }
        const std::string& prompt = text_value->get();
        std::optional<std::string> problem =
            is_blank(prompt) ? std::nullopt : screen_text_problem(prompt);
        if (!problem) problem = prompt_placeholder_problem(prompt, key.placeholders);
        if (problem) {
            problems.add(value->source(), toml_key_prefix(qualified) + *problem);
            continue;
        }
        prompts.*key.member = is_blank(prompt) ? std::string() : prompt;
    }
}

// [text]: the font the screens are drawn with. Whether it opens and has the screens'
// characters is checked when the file is loaded (protocol_font.h).
void read_text(const TomlScope& root, StudyDaySettings& day, TomlProblems& problems) {
    const toml::table* table = find_table(
        root, "text", "a table ([text] with font = \"/path/to/font.ttf\" and [text.prompts])",
        problems);
    if (table == nullptr) return;
    const TomlScope scope{*table, "text"};
    report_unknown_keys(scope, kTextKeys, problems);
    read_prompts(*table, day.prompts, problems);
    const toml::node* node = table->get("font");
    if (node == nullptr) return;
    const auto* font = node->as_string();
    if (font == nullptr) {
        report_wrong_type(*node, "text.font",
                          "a string, the path of a TrueType or OpenType font file", problems);
        return;
    }
    if (is_blank(font->get())) {
        problems.add(node->source(), toml_key_prefix("text.font") +
                                         "is empty; give the path of a font file, or leave the "
                                         "key out for the default (" +
                                         std::string(text::kDefaultFontPath) + ")");
        return;
    }
    // Absolute: a resumed session reads its stored protocol text, away from the file's folder.
    if (!std::filesystem::path(font->get()).is_absolute()) {
        problems.add(node->source(), toml_key_prefix("text.font") + in_quotes(font->get()) +
                                         " is a relative path; give the font file's absolute "
                                         "path (fc-list lists them), so that a resumed session "
                                         "finds it too");
        return;
    }
    day.font = font->get();
}

}  // namespace

void read_study_day(const TomlScope& root, Procedure procedure, StudyDaySettings& day,
                    TomlProblems& problems) {
    read_counts(root, procedure, day, problems);
    read_layout(root, procedure, day, problems);  // blocking before [breaks]: they depend on it
    read_instructions(root, day, problems);
    read_single_page(root, "ready", day.ready, problems);
    read_breaks(root, procedure, day, problems);
    read_single_page(root, "end", day.end, problems);
    read_variables(root, day, problems);
    read_text(root, day, problems);
}

void check_break_interval(const TomlScope& root, const StudyDaySettings& day,
                          std::size_t data_trials, TomlProblems& problems) {
    if (!day.breaks || day.breaks->every_trials <= 0 || data_trials == 0) return;
    const auto every = static_cast<std::size_t>(day.breaks->every_trials);
    if (every < data_trials) return;
    const toml::node* node = root.table.at_path("breaks.every_trials").node();
    if (node == nullptr) return;
    problems.add(node->source(), toml_key_prefix("breaks.every_trials") + std::to_string(every) +
                                     ", but a session has " + std::to_string(data_trials) +
                                     " data trials, so this break would never be shown; use a "
                                     "smaller number");
}

}  // namespace monoplane::study
