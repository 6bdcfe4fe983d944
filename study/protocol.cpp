// Parsing and validation of study protocols. Everything a session will rely
// on is checked here, before the first trial: a mistake found halfway through a participant's
// session costs the participant. Every reader records its problems and goes on, so the user sees
// all of them at once, each with file, line, column and key.
#include "study/protocol.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "common/quoted.h"
#include "common/toml/toml_keys.h"
#include "common/toml/toml_problems.h"
#include "study/condition.h"
#include "study/protocol_font.h"
#include "study/protocol_study_day_parse.h"
#include "study/scene_files.h"

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 28> kTopLevelKeys = {
    "name", "scenes", "mono_planes", "alternatives", "order", "first_scene", "require_both_viewed",
    "practice_trials", "near", "far", "questionnaire", "render", "missed_frame_threshold", "auto",
    "procedure", "staircase", "responses", "gaze",
    // A study day (protocol_study_day_parse.h).
    "sessions", "repetitions", "blocking", "text_height_deg", "instructions", "ready", "breaks",
    "end", "variables", "text"};
static_assert(std::ranges::all_of(kStudyDayKeys, [](std::string_view key) {
    return std::ranges::find(kTopLevelKeys, key) != kTopLevelKeys.end();
}));
constexpr std::array<std::string_view, 2> kQuestionnaireKeys = {"items", "scale_points"};
constexpr std::array<std::string_view, 3> kRenderKeys = {"anti_aliasing", "ssao", "detail"};
// The render command's names (renderer/plan/render_choices.h, scenes/generate.h).
constexpr std::array<std::string_view, 5> kAntiAliasing = {"none", "taa", "msaa2", "msaa4",
                                                           "msaa8"};
constexpr std::array<std::string_view, 3> kSsao = {"off", "per-eye", "stereo"};
constexpr std::array<std::string_view, 5> kDetails = {"test", "low", "medium", "high", "ultra"};

// Practice trials precede every session; more than 50 is a typo, not a warm-up.
constexpr std::int64_t kMaxPracticeTrials = 50;
// Likert scales in use run from 2 (yes/no) to 11 (0..10) points.
constexpr std::int64_t kMinScalePoints = 2;
constexpr std::int64_t kMaxScalePoints = 11;

template <class T>
struct NamedValue {
    std::string_view name;
    T value;
};

constexpr std::array<NamedValue<TrialOrder>, 2> kOrders = {{
    {"randomized", TrialOrder::Randomized},
    {"fixed", TrialOrder::Fixed},
}};
constexpr std::array<NamedValue<FirstSceneBalance>, 3> kFirstScenes = {{
    {"latin-square", FirstSceneBalance::LatinSquare},
    {"random", FirstSceneBalance::Random},
    {"fixed", FirstSceneBalance::Fixed},
}};

std::string known_scenes() {
    return join(study_scene_names());
}

bool is_blank(std::string_view text) {
    return std::ranges::all_of(text, [](char c) { return c == ' ' || c == '\t' || c == '\n'; });
}

std::optional<std::string> read_string(const toml::node& node, std::string_view key,
                                       std::string_view expected, TomlProblems& problems) {
    const auto* text = node.as_string();
    if (text == nullptr) {
        report_wrong_type(node, key, expected, problems);
        return std::nullopt;
    }
    return text->get();
}

// An array whose elements all have a type, or nullopt after reporting what is wrong. An empty
// array is a problem: every list in a protocol must name at least one thing.
const toml::array* read_nonempty_array(const toml::node& node, std::string_view key,
                                       std::string_view expected, TomlProblems& problems) {
    const toml::array* array = node.as_array();
    if (array == nullptr) {
        report_wrong_type(node, key, expected, problems);
        return nullptr;
    }
    if (array->empty()) {
        problems.add(node.source(),
                     toml_key_prefix(key) + "must not be empty; expected " + std::string(expected));
        return nullptr;
    }
    return array;
}

// A string element of an array, with its node (for the place of a later problem) and its
// 1-based position in the array (for the message).
struct StringElement {
    std::string text;
    const toml::node* node;
    std::size_t position;
};

// The strings of an array; elements that are not strings are reported and left out.
std::vector<StringElement> read_strings(const toml::array& array, std::string_view key,
                                        TomlProblems& problems) {
    std::vector<StringElement> strings;
    for (std::size_t i = 0; i < array.size(); ++i) {
        const toml::node& element = array[i];
        if (const auto* text = element.as_string()) {
            strings.push_back({text->get(), &element, i + 1});
        } else {
            problems.add(element.source(), toml_key_prefix(key) + "element " +
                                               std::to_string(i + 1) +
                                               " must be a string, but is " +
                                               std::string(toml_type_phrase(element.type())));
        }
    }
    return strings;
}

template <class T, std::size_t N>
std::optional<T> read_choice(const toml::node& node, std::string_view key,
                             const std::array<NamedValue<T>, N>& choices, TomlProblems& problems) {
    std::array<std::string_view, N> names;
    std::ranges::transform(choices, names.begin(), &NamedValue<T>::name);
    const std::string allowed = "one of " + join(names);
    const std::optional<std::string> text =
        read_string(node, key, "a string, " + allowed, problems);
    if (!text) return std::nullopt;
    for (const NamedValue<T>& choice : choices) {
        if (choice.name == *text) return choice.value;
    }
    std::string message = toml_key_prefix(key) + "unknown value " + in_quotes(*text) +
                          " (allowed: " + join(names) + ")";
    const std::string_view closest = closest_match(*text, names);
    if (!closest.empty()) message += "; did you mean " + in_quotes(closest) + "?";
    problems.add(node.source(), message);
    return std::nullopt;
}

void read_name(const TomlScope& root, Protocol& protocol, TomlProblems& problems) {
    constexpr std::string_view kExpected = "a non-empty string";
    const toml::node* node = find_required(root, "name", kExpected, problems);
    if (node == nullptr) return;
    std::optional<std::string> name = read_string(*node, "name", kExpected, problems);
    if (!name) return;
    if (is_blank(*name)) {
        problems.add(node->source(), toml_key_prefix("name") + "must not be empty");
        return;
    }
    protocol.name = std::move(*name);
}

// A scenes entry that names a glTF file. No comma: the database keeps the block order
// comma-separated. With a folder to resolve it against, the file must exist and not be listed
// already under another name (that would double its block, as a repeated name would).
bool accept_scene_file(const std::string& scene, const toml::node& element,
                       const std::filesystem::path* directory, Protocol& protocol,
                       TomlProblems& problems) {
    const std::string prefix = toml_key_prefix("scenes") + "scene file " + in_quotes(scene);
    if (scene.find(',') != std::string::npos) {
        problems.add(element.source(), prefix +
                                           " has a comma in its name, which the database's "
                                           "comma-separated block order cannot hold; "
                                           "rename the file");
        return false;
    }
    if (directory == nullptr) return true;
    const std::filesystem::path path = resolve_scene_file(scene, *directory);
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (!std::filesystem::is_regular_file(status)) {
        const std::string what = std::filesystem::exists(status) ? " is not a regular file ("
                                                                 : " not found (looked for ";
        problems.add(element.source(), prefix + what + path.string() +
                                           "; relative paths start at the protocol "
                                           "file's folder)");
        return false;
    }
    for (const auto& [label, other] : protocol.scene_files) {
        if (other == path) {
            problems.add(element.source(), prefix + " is the same file as " + in_quotes(label) +
                                               "; list each scene once");
            return false;
        }
    }
    protocol.scene_files[scene] = path;
    return true;
}

void read_scenes(const TomlScope& root, const std::filesystem::path* scene_directory,
                 Protocol& protocol, TomlProblems& problems) {
    const std::string expected = "an array of scene names (known scenes: " + known_scenes() +
                                 ") or glTF files (.gltf, .glb)";
    const toml::node* node = find_required(root, "scenes", expected, problems);
    if (node == nullptr) return;
    const toml::array* array = read_nonempty_array(*node, "scenes", expected, problems);
    if (array == nullptr) return;
    const std::span<const std::string_view> known = study_scene_names();
    for (auto& [scene, element, position] : read_strings(*array, "scenes", problems)) {
        if (std::ranges::find(protocol.scenes, scene) != protocol.scenes.end()) {
            // A scene listed twice would double its block and unbalance the Latin square.
            problems.add(element->source(), toml_key_prefix("scenes") + "duplicate scene " +
                                                in_quotes(scene) + "; list each scene once");
        } else if (names_scene_file(scene)) {
            if (accept_scene_file(scene, *element, scene_directory, protocol, problems)) {
                protocol.scenes.push_back(std::move(scene));
            }
        } else if (std::ranges::find(known, scene) == known.end()) {
            std::string message = toml_key_prefix("scenes") + "unknown scene " + in_quotes(scene) +
                                  " (known scenes: " + known_scenes() +
                                  "; or a glTF file ending in .gltf or .glb)";
            const std::string_view closest = closest_match(scene, known);
            if (!closest.empty()) message += "; did you mean " + in_quotes(closest) + "?";
            problems.add(element->source(), message);
        } else {
            protocol.scenes.push_back(std::move(scene));
        }
    }
}

// Near and far come first: the mono planes are checked against them.
bool read_clip_range(const TomlScope& root, Protocol& protocol, TomlProblems& problems) {
    constexpr std::string_view kExpected = "a number of metres";
    const toml::node* near_node = root.table.get("near");
    const toml::node* far_node = root.table.get("far");
    bool valid = true;
    for (auto [key, node, field] : {std::tuple{"near", near_node, &Protocol::near},
                                    std::tuple{"far", far_node, &Protocol::far}}) {
        if (node == nullptr) continue;
        const std::optional<double> value = read_number(*node, key, kExpected, problems);
        if (!value) {
            valid = false;
        } else if (!std::isfinite(*value) || *value <= 0.0) {
            problems.add(node->source(), toml_key_prefix(key) +
                                             "must be a finite number of metres > 0, got " +
                                             format_number(*value));
            valid = false;
        } else {
            protocol.*field = *value;
        }
    }
    if (valid && !(protocol.near < protocol.far)) {
        const toml::node* node = far_node != nullptr ? far_node : near_node;
        problems.add(node->source(), toml_key_prefix(node == far_node ? "far" : "near") +
                                         "the clip range needs near < far, got near = " +
                                         format_number(protocol.near) +
                                         " m, far = " + format_number(protocol.far) + " m");
        valid = false;
    }
    return valid;
}

void read_mono_planes(const TomlScope& root, bool clip_range_valid, Protocol& protocol,
                      TomlProblems& problems) {
    constexpr std::string_view kExpected = "an array of distances in metres, e.g. [3, 8]";
    const toml::node* node = find_required(root, "mono_planes", kExpected, problems);
    if (node == nullptr) return;
    const toml::array* array = read_nonempty_array(*node, "mono_planes", kExpected, problems);
    if (array == nullptr) return;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& element = (*array)[i];
        const std::string position = "element " + std::to_string(i + 1);
        std::optional<double> m;
        if (const auto* integer = element.as_integer()) {
            m = static_cast<double>(integer->get());
        } else if (const auto* real = element.as_floating_point()) {
            m = real->get();
        } else {
            problems.add(element.source(), toml_key_prefix("mono_planes") + position +
                                               " must be a number of metres, but is " +
                                               std::string(toml_type_phrase(element.type())));
        }
        if (!m) continue;
        const std::string value = format_number(*m);
        if (!std::isfinite(*m) || *m <= 0.0) {
            problems.add(element.source(), toml_key_prefix("mono_planes") + position + " = " +
                                               value +
                                               " must be a finite, positive distance in metres");
            continue;
        }
        // At or beyond either end of the clip range hybrid rendering degenerates (section 3).
        if (clip_range_valid && !(protocol.near < *m && *m < protocol.far)) {
            problems.add(element.source(), toml_key_prefix("mono_planes") + position + " = " +
                                               value + " m is not strictly inside (near, far) = (" +
                                               format_number(protocol.near) + ", " +
                                               format_number(protocol.far) + ") m");
            continue;
        }
        const auto previous = std::ranges::find(protocol.mono_planes, *m);
        if (previous != protocol.mono_planes.end()) {
            // Each distance is one trial per scene; a repeat is almost always a typo.
            problems.add(element.source(), toml_key_prefix("mono_planes") + "duplicate distance " +
                                               value + " m; list each distance once");
            continue;
        }
        protocol.mono_planes.push_back(*m);
    }
}

void read_alternatives(const TomlScope& root, Protocol& protocol, TomlProblems& problems) {
    const std::string expected =
        "an array of two render modes, the reference first, e.g. [\"stereo\", \"hybrid\"]";
    const toml::node* node = find_required(root, "alternatives", expected, problems);
    if (node == nullptr) return;
    const toml::array* array = read_nonempty_array(*node, "alternatives", expected, problems);
    if (array == nullptr) return;
    if (array->size() != 2) {
        // 2AFC: exactly two alternatives per trial.
        problems.add(node->source(), toml_key_prefix("alternatives") +
                                         "must list exactly two render " +
                                         "modes (a two-alternative forced choice), but lists " +
                                         std::to_string(array->size()));
        return;
    }
    std::vector<RenderMode> modes;
    for (const auto& [name, element, position] : read_strings(*array, "alternatives", problems)) {
        const Result<RenderMode> mode = parse_render_mode(name);
        if (mode) {
            modes.push_back(*mode);
        } else {
            problems.add(element->source(), toml_key_prefix("alternatives") + mode.error().message);
        }
    }
    if (modes.size() != 2) return;
    if (modes[0] == modes[1]) {
        problems.add(node->source(), toml_key_prefix("alternatives") + "both alternatives are " +
                                         in_quotes(render_mode_name(modes[0])) +
                                         "; a trial must compare two different render modes");
        return;
    }
    protocol.alternatives = {modes[0], modes[1]};
}

void read_session_options(const TomlScope& root, Protocol& protocol, TomlProblems& problems) {
    if (const toml::node* node = root.table.get("order")) {
        if (auto order = read_choice(*node, "order", kOrders, problems)) protocol.order = *order;
    }
    if (const toml::node* node = root.table.get("first_scene")) {
        if (auto first = read_choice(*node, "first_scene", kFirstScenes, problems)) {
            protocol.first_scene = *first;
        }
    }
    if (const toml::node* node = root.table.get("require_both_viewed")) {
        if (const auto* flag = node->as_boolean()) {
            protocol.require_both_viewed = flag->get();
        } else {
            report_wrong_type(*node, "require_both_viewed", "a boolean (true or false)", problems);
        }
    }
    if (const toml::node* node = root.table.get("missed_frame_threshold")) {
        const std::optional<double> share = node->value<double>();
        if (!share || node->is_boolean() || node->is_string()) {
            report_wrong_type(*node, "missed_frame_threshold",
                              "a number, the share of a trial's frames (e.g. 0.05)", problems);
        } else if (!(*share >= 0.0 && *share <= 1.0)) {
            problems.add(node->source(), toml_key_prefix("missed_frame_threshold") + "is " +
                                             format_number(*share) +
                                             "; a share of frames lies in [0, 1]");
        } else {
            protocol.missed_frame_threshold = *share;
        }
    }
    if (const toml::node* node = root.table.get("practice_trials")) {
        if (auto count =
                read_integer_in(*node, "practice_trials", 0, kMaxPracticeTrials, problems)) {
            protocol.practice_trials = static_cast<int>(*count);
        }
    }
}

void read_questionnaire(const TomlScope& root, Protocol& protocol, TomlProblems& problems) {
    const toml::node* node = root.table.get("questionnaire");
    if (node == nullptr) return;  // no questionnaire: the session ends after the last trial
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        report_wrong_type(*node, "questionnaire",
                          "a table ([questionnaire] with items and optional scale_points)",
                          problems);
        return;
    }
    const TomlScope scope{*table, "questionnaire"};
    report_unknown_keys(scope, kQuestionnaireKeys, problems);
    if (const toml::node* points = table->get("scale_points")) {
        if (auto count = read_integer_in(*points, "questionnaire.scale_points", kMinScalePoints,
                                         kMaxScalePoints, problems)) {
            protocol.questionnaire.scale_points = static_cast<int>(*count);
        }
    }
    constexpr std::string_view kExpected = "an array of Likert statements (strings)";
    const toml::node* items_node = find_required(scope, "items", kExpected, problems);
    if (items_node == nullptr) return;
    const toml::array* items =
        read_nonempty_array(*items_node, "questionnaire.items", kExpected, problems);
    if (items == nullptr) return;
    for (auto& [item, element, position] : read_strings(*items, "questionnaire.items", problems)) {
        if (is_blank(item)) {
            problems.add(element->source(), toml_key_prefix("questionnaire.items") + "item " +
                                                std::to_string(position) +
                                                " is empty; each item is a statement to rate");
            continue;
        }
        protocol.questionnaire.items.push_back(std::move(item));
    }
}

// One of `names` at key, or nothing (with a problem naming the allowed values).
template <std::size_t N>
std::optional<std::string> read_name_choice(const toml::node& node, std::string_view key,
                                            const std::array<std::string_view, N>& names,
                                            TomlProblems& problems) {
    std::array<NamedValue<std::string_view>, N> choices;
    std::ranges::transform(names, choices.begin(), [](std::string_view name) {
        return NamedValue<std::string_view>{name, name};
    });
    const std::optional<std::string_view> chosen = read_choice(node, key, choices, problems);
    if (!chosen) return std::nullopt;
    return std::string(*chosen);
}

bool is_hybrid(RenderMode mode) {
    return mode == RenderMode::Hybrid || mode == RenderMode::HybridFarfield ||
           mode == RenderMode::HybridAuto;
}

void read_render(const TomlScope& root, Protocol& protocol, TomlProblems& problems) {
    const toml::node* node = root.table.get("render");
    if (node == nullptr) return;  // the defaults: no anti-aliasing, no SSAO, detail low
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        report_wrong_type(*node, "render", "a table ([render] with anti_aliasing, ssao and detail)",
                          problems);
        return;
    }
    const TomlScope scope{*table, "render"};
    report_unknown_keys(scope, kRenderKeys, problems);
    RenderSettings& render = protocol.render;
    if (const toml::node* aa = table->get("anti_aliasing")) {
        if (auto name = read_name_choice(*aa, "render.anti_aliasing", kAntiAliasing, problems)) {
            render.anti_aliasing = *name;
            // MSAA resolves before hybrid's composite could map C's image in (papers/000 Sect.
            // 4.5; docs/hybrid.md): the renderer refuses it for the hybrid modes.
            const bool hybrid = std::ranges::any_of(protocol.alternatives, is_hybrid);
            if (name->starts_with("msaa") && hybrid) {
                problems.add(aa->source(), toml_key_prefix("render.anti_aliasing") +
                                               in_quotes(*name) +
                                               " needs both alternatives to be stereo forms, but "
                                               "one is a hybrid mode; use 'taa'");
            }
        }
    }
    if (const toml::node* ssao = table->get("ssao")) {
        if (auto name = read_name_choice(*ssao, "render.ssao", kSsao, problems))
            render.ssao = *name;
    }
    if (const toml::node* detail = table->get("detail")) {
        if (auto name = read_name_choice(*detail, "render.detail", kDetails, problems)) {
            render.detail = *name;
        }
    }
}

// FNV-1a, 64 bits: a stable, dependency-free fingerprint of the protocol text, stored with every
// session so analyses can tell protocol versions apart. Not a cryptographic hash.
std::uint64_t fnv1a64(std::string_view text) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (const char c : text) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

Result<std::string> read_text_file(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        return Error{"protocol '" + path.string() + "' is a directory; expected a TOML file"};
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return Error{"cannot open protocol file '" + path.string() + "': " + std::strerror(errno)};
    }
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) return Error{"cannot read protocol file '" + path.string() + "'"};
    return text.str();
}

Result<Protocol> parse(std::string_view toml_text, std::string_view source_name,
                       const std::filesystem::path* scene_directory) {
    Result<toml::table> document = parse_toml(toml_text, source_name);
    MONOPLANE_TRY(document);

    TomlProblems problems(source_name);
    Protocol protocol;
    const TomlScope root{*document, ""};
    report_unknown_keys(root, kTopLevelKeys, problems);
    read_name(root, protocol, problems);
    read_scenes(root, scene_directory, protocol, problems);
    const bool clip_range_valid = read_clip_range(root, protocol, problems);
    read_mono_planes(root, clip_range_valid, protocol, problems);
    read_procedure(root, protocol.mono_planes, protocol.procedure, protocol.staircase, problems);
    read_alternatives(root, protocol, problems);
    read_session_options(root, protocol, problems);
    read_questionnaire(root, protocol, problems);
    read_render(root, protocol, problems);  // after the alternatives: MSAA depends on them
    read_auto_plane(root, std::ranges::count(protocol.alternatives, RenderMode::HybridAuto) > 0,
                    protocol.auto_plane, problems);
    read_study_day(root, protocol.procedure, protocol.day, problems);  // after the procedure
    read_responses(root, protocol.responses, problems);
    read_gaze(root, protocol.gaze, problems);
    // Only for a protocol whose scenes and distances all read: the count is the session's.
    if (problems.empty()) {
        check_break_interval(root, protocol.day, protocol.trials_per_session(), problems);
    }
    if (!problems.empty()) return problems.error();

    protocol.source = std::string(source_name);
    protocol.text = std::string(toml_text);
    protocol.text_hash = fnv1a64(toml_text);
    return protocol;
}

}  // namespace

std::string_view trial_order_name(TrialOrder order) {
    for (const auto& [name, value] : kOrders)
        if (value == order) return name;
    return "?";
}

std::string_view first_scene_name(FirstSceneBalance balance) {
    for (const auto& [name, value] : kFirstScenes)
        if (value == balance) return name;
    return "?";
}

Result<Protocol> parse_protocol(std::string_view toml_text, std::string_view source_name) {
    return parse(toml_text, source_name, nullptr);
}

Result<Protocol> parse_protocol(std::string_view toml_text, std::string_view source_name,
                                const std::filesystem::path& scene_directory) {
    return parse(toml_text, source_name, &scene_directory);
}

Result<Protocol> load_protocol(const std::filesystem::path& path) {
    Result<std::string> text = read_text_file(path);
    MONOPLANE_TRY(text);
    // The two files most often given by mistake, named as what they are rather than as TOML
    // that lacks every key.
    if (text->empty())
        return Error{path.string() +
                     " is 0 bytes: not a protocol (a TOML file, docs/protocols.md)"};
    if (text->starts_with(std::string_view("SQLite format 3\0", 16)))
        return Error{path.string() +
                     " is a SQLite database (a study database?), not a protocol: give the "
                     "protocol's .toml file"};
    Result<Protocol> protocol = parse_protocol(*text, path.string(), path.parent_path());
    MONOPLANE_TRY(protocol);
    MONOPLANE_TRY(check_protocol_font(protocol.value()));
    return protocol;
}

}  // namespace monoplane::study
