// Parsing and validation of simxr scripts (docs/simxr.md). Every problem is reported with file,
// line and key, all at once, like HMD profiles and study protocols (common/toml).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "common/toml/toml_keys.h"
#include "common/toml/toml_problems.h"
#include "simxr/interaction_profiles.h"
#include "simxr/script.h"

namespace monoplane::simxr {
namespace {

constexpr std::array<std::string_view, 16> kTopLevelKeys = {"hmd",
                                                            "display_rate_hz",
                                                            "missed_slot_every",
                                                            "physical_device",
                                                            "interaction_profile",
                                                            "dump_dir",
                                                            "dump_every",
                                                            "exit_after_s",
                                                            "lose_session_at_s",
                                                            "lose_instance_at_s",
                                                            "pose",
                                                            "input",
                                                            "head_motion",
                                                            "gaze",
                                                            "fixation",
                                                            "blink"};
constexpr std::array<std::string_view, 7> kGazeKeys = {
    "tracker", "saccades_per_s", "spread_deg", "seed", "saccade_s", "blink_every_s", "blink_s"};
constexpr std::array<std::string_view, 4> kFixationKeys = {"t", "duration", "target",
                                                           "yaw_pitch_deg"};
constexpr std::array<std::string_view, 2> kBlinkKeys = {"t", "duration"};
constexpr std::array<std::string_view, 3> kPoseKeys = {"t", "position", "yaw_pitch_roll_deg"};
constexpr std::array<std::string_view, 3> kInputKeys = {"t", "path", "duration"};
// Above this a frame period is shorter than any display and the rate is a typo (kHz for Hz);
// below the minimum no display refreshes, and 1e9 / rate ns would leave the int64 clock.
constexpr double kMinDisplayRateHz = 1.0;
constexpr double kMaxDisplayRateHz = 1000.0;
// Script times become int64 nanoseconds on the virtual clock (XrTime): beyond about 9.2e9 s they
// do not fit, and sums of two (a press's start and duration) overflow sooner. A simulated session
// lasts minutes; 1e6 s (11.6 days) keeps every sum far inside the range.
constexpr double kMaxScriptTimeS = 1e6;

// A key's value read from a scope; each reader reports a wrong type or range and returns nullopt.
class Reader {
  public:
    Reader(const TomlScope& scope, TomlProblems& problems) : scope_(scope), problems_(problems) {}

    std::optional<double> number(std::string_view key) const {
        const toml::node* node = scope_.table.get(key);
        if (node == nullptr) return std::nullopt;
        return number_of(*node, scope_.qualified(key));
    }

    std::optional<std::string> string(std::string_view key) const {
        const toml::node* node = scope_.table.get(key);
        if (node == nullptr) return std::nullopt;
        if (const auto* text = node->as_string()) return text->get();
        report_wrong_type(*node, scope_.qualified(key), "a string", problems_);
        return std::nullopt;
    }

    std::optional<std::int64_t> integer(std::string_view key) const {
        const toml::node* node = scope_.table.get(key);
        if (node == nullptr) return std::nullopt;
        if (const auto* value = node->as_integer()) return value->get();
        report_wrong_type(*node, scope_.qualified(key), "an integer", problems_);
        return std::nullopt;
    }

    std::optional<bool> boolean(std::string_view key) const {
        const toml::node* node = scope_.table.get(key);
        if (node == nullptr) return std::nullopt;
        if (const auto* value = node->as_boolean()) return value->get();
        report_wrong_type(*node, scope_.qualified(key), "true or false", problems_);
        return std::nullopt;
    }

    std::optional<glm::dvec3> vec3(std::string_view key) const { return vec<3>(key); }
    std::optional<glm::dvec2> vec2(std::string_view key) const { return vec<2>(key); }

    template <glm::length_t N>
    std::optional<glm::vec<N, double>> vec(std::string_view key) const {
        const toml::node* node = scope_.table.get(key);
        if (node == nullptr) return std::nullopt;
        const std::string qualified = scope_.qualified(key);
        const auto* array = node->as_array();
        if (array == nullptr || array->size() != N) {
            problems_.add(node->source(), toml_key_prefix(qualified) + "must be an array of " +
                                              std::to_string(N) + " numbers");
            return std::nullopt;
        }
        glm::vec<N, double> value{0.0};
        for (glm::length_t i = 0; i < N; ++i) {
            const auto component = number_of(*array->get(static_cast<std::size_t>(i)), qualified);
            if (!component) return std::nullopt;
            value[i] = *component;
        }
        return value;
    }

    void problem(std::string_view key, std::string_view message) const {
        const toml::node* node = scope_.table.get(key);
        const std::string text = toml_key_prefix(scope_.qualified(key)) + std::string(message);
        if (node != nullptr) {
            problems_.add(node->source(), text);
        } else {
            problems_.add(scope_.table.source(), text);
        }
    }

  private:
    // Integers are accepted where a real number is expected: `t = 1` means 1.0.
    std::optional<double> number_of(const toml::node& node, const std::string& qualified) const {
        double value = 0.0;
        if (const auto* integer = node.as_integer()) {
            value = static_cast<double>(integer->get());
        } else if (const auto* real = node.as_floating_point()) {
            value = real->get();
        } else {
            report_wrong_type(node, qualified, "a number", problems_);
            return std::nullopt;
        }
        if (!std::isfinite(value)) {
            problems_.add(node.source(), toml_key_prefix(qualified) + "must be a finite number");
            return std::nullopt;
        }
        return value;
    }

    const TomlScope& scope_;
    TomlProblems& problems_;
};

bool is_builtin_hmd(std::string_view name) {
    const std::vector<std::string> names = hmd::builtin_hmd_names();
    return std::ranges::find(names, name) != names.end();
}

void read_hmd(const Reader& root, const std::filesystem::path& folder, Script& script) {
    const auto name = root.string("hmd");
    if (!name) return;
    std::string resolved = *name;
    if (!is_builtin_hmd(resolved) && std::filesystem::path(resolved).is_relative()) {
        resolved = (folder / resolved).lexically_normal().string();
    }
    auto profile = hmd::load_hmd_profile(resolved);
    if (!profile) {
        root.problem("hmd", profile.error().message);
        return;
    }
    script.hmd_name = resolved;
    script.hmd = std::move(profile).value();
}

void read_settings(const Reader& root, const std::filesystem::path& folder, Script& script) {
    read_hmd(root, folder, script);
    if (const auto rate = root.number("display_rate_hz")) {
        if (*rate < kMinDisplayRateHz || *rate > kMaxDisplayRateHz) {
            root.problem("display_rate_hz", "must lie in [1, 1000] Hz");
        } else {
            script.display_rate_hz = *rate;
        }
    }
    if (const auto device = root.string("physical_device")) script.physical_device = *device;
    if (const auto profile = root.string("interaction_profile")) {
        if (find_interaction_profile(*profile) == nullptr) {
            std::string known;
            for (const InteractionProfile& p : interaction_profiles()) {
                known += (known.empty() ? "" : ", ") + p.path;
            }
            root.problem("interaction_profile",
                         "unknown interaction profile (known: " + known + ")");
        } else {
            script.interaction_profile = *profile;
        }
    }
    if (const auto dir = root.string("dump_dir"); dir && !dir->empty()) {
        script.dump_dir = std::filesystem::path(*dir).is_relative()
                              ? (folder / *dir).lexically_normal()
                              : std::filesystem::path(*dir);
    }
    if (const auto every = root.integer("missed_slot_every")) {
        if (*every < 0 || *every == 1) {
            root.problem("missed_slot_every", "must be 0 (never) or at least 2 frames");
        } else {
            script.missed_slot_every = *every;
        }
    }
    if (const auto motion = root.string("head_motion")) {
        if (*motion == "still") {
            script.head_motion = HeadMotion::kStill;
        } else if (*motion == "seated") {
            script.head_motion = HeadMotion::kSeated;
        } else {
            root.problem("head_motion", "must be \"still\" or \"seated\"");
        }
    }
    if (const auto every = root.integer("dump_every")) {
        if (*every < 1) {
            root.problem("dump_every", "must be at least 1");
        } else {
            script.dump_every = *every;
        }
    }
    for (auto [key, field] : {std::pair{"exit_after_s", &Script::exit_after_s},
                              std::pair{"lose_session_at_s", &Script::lose_session_at_s},
                              std::pair{"lose_instance_at_s", &Script::lose_instance_at_s}}) {
        if (const auto seconds = root.number(key)) {
            if (*seconds < 0.0) {
                root.problem(key, "must be 0 (never) or a positive time in seconds");
            } else if (*seconds > kMaxScriptTimeS) {
                root.problem(key, "must be at most 1e6 s (the virtual clock counts nanoseconds)");
            } else {
                script.*field = *seconds;
            }
        }
    }
}

// [[pose]] and [[input]] are arrays of tables; a single [pose] table is a likely slip.
const toml::array* table_array(const toml::table& root, std::string_view key,
                               TomlProblems& problems) {
    const toml::node* node = root.get(key);
    if (node == nullptr) return nullptr;
    const toml::array* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
        problems.add(node->source(), toml_key_prefix(key) + "must be an array of tables ([[" +
                                         std::string(key) + "]])");
        return nullptr;
    }
    return array;
}

void read_poses(const toml::table& root, TomlProblems& problems, Script& script) {
    const toml::array* array = table_array(root, "pose", problems);
    if (array == nullptr) return;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const TomlScope scope{*array->get(i)->as_table(), "pose[" + std::to_string(i) + "]"};
        report_unknown_keys(scope, kPoseKeys, problems);
        const Reader reader(scope, problems);
        PoseKeyframe keyframe;
        if (find_required(scope, "t", "a time in seconds", problems) == nullptr) continue;
        const auto t = reader.number("t");
        if (!t) continue;
        if (*t < 0.0) reader.problem("t", "must not be negative");
        if (*t > kMaxScriptTimeS) reader.problem("t", "must be at most 1e6 s");
        if (!script.poses.empty() && *t <= script.poses.back().t) {
            reader.problem("t", "keyframes must be in ascending order of t");
        }
        keyframe.t = *t;
        if (const auto position = reader.vec3("position")) keyframe.position = *position;
        if (const auto angles = reader.vec3("yaw_pitch_roll_deg")) {
            keyframe.yaw_pitch_roll_deg = *angles;
        }
        script.poses.push_back(keyframe);
    }
}

void read_inputs(const toml::table& root, TomlProblems& problems, Script& script) {
    const toml::array* array = table_array(root, "input", problems);
    if (array == nullptr) return;
    const InteractionProfile* profile = find_interaction_profile(script.interaction_profile);
    for (std::size_t i = 0; i < array->size(); ++i) {
        const TomlScope scope{*array->get(i)->as_table(), "input[" + std::to_string(i) + "]"};
        report_unknown_keys(scope, kInputKeys, problems);
        const Reader reader(scope, problems);
        InputPress press;
        const bool has_t = find_required(scope, "t", "a time in seconds", problems) != nullptr;
        const bool has_path = find_required(scope, "path", "a component path", problems) != nullptr;
        if (!has_t || !has_path) continue;
        const auto t = reader.number("t");
        const auto path = reader.string("path");
        if (!t || !path) continue;
        if (*t < 0.0) reader.problem("t", "must not be negative");
        if (*t > kMaxScriptTimeS) reader.problem("t", "must be at most 1e6 s");
        press.t = *t;
        const Component* component = nullptr;
        for (const Component& c : profile->components) {
            if (c.path == *path) component = &c;
        }
        if (component == nullptr || component->kind == ComponentKind::pose ||
            component->kind == ComponentKind::haptic) {
            // The example is one of this profile's own buttons (an Xbox controller has no hands).
            std::string example;
            for (const Component& c : profile->components) {
                if (example.empty() && c.kind == ComponentKind::boolean) example = c.path;
            }
            reader.problem("path", "'" + *path + "' is no button or axis of " + profile->path +
                                       " (e.g. " + example + ")");
            continue;
        }
        press.path = *path;
        if (const auto duration = reader.number("duration")) {
            if (*duration <= 0.0) {
                reader.problem("duration", "must be positive (leave it out for one frame)");
            } else if (*duration > kMaxScriptTimeS) {
                reader.problem("duration", "must be at most 1e6 s");
            }
            press.duration = *duration;
        }
        if (press.duration <= 0.0) press.duration = 1.0 / script.display_rate_hz;
        script.inputs.push_back(press);
    }
}

// [gaze]: the tracker and the default's rates. Rates and durations must be positive where they
// divide or bound a time; 0 turns the default's blinks off.
void read_gaze_settings(const toml::table& root, TomlProblems& problems, GazeScript& gaze) {
    const toml::node* node = root.get("gaze");
    if (node == nullptr) return;
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        problems.add(node->source(), toml_key_prefix("gaze") + "must be a table ([gaze])");
        return;
    }
    const TomlScope scope{*table, "gaze"};
    report_unknown_keys(scope, kGazeKeys, problems);
    const Reader reader(scope, problems);
    if (const auto tracker = reader.boolean("tracker")) gaze.tracker = *tracker;
    if (const auto seed = reader.integer("seed")) gaze.seed = static_cast<std::uint64_t>(*seed);
    struct Bounded {
        const char* key;
        double GazeScript::*field;
        bool zero_allowed;
        double max;
        const char* range;  // as the message gives it
    };
    for (const Bounded& b :
         {Bounded{"saccades_per_s", &GazeScript::saccades_per_s, false, 20.0, "(0, 20]"},
          Bounded{"spread_deg", &GazeScript::spread_deg, true, 60.0, "[0, 60]"},
          Bounded{"saccade_s", &GazeScript::saccade_s, false, 1.0, "(0, 1]"},
          Bounded{"blink_every_s", &GazeScript::blink_every_s, true, 1e6, "[0, 1e6]"},
          Bounded{"blink_s", &GazeScript::blink_s, false, 1.0, "(0, 1]"}}) {
        const auto value = reader.number(b.key);
        if (!value) continue;
        const bool low = b.zero_allowed ? *value < 0.0 : *value <= 0.0;
        if (low || *value > b.max) {
            reader.problem(b.key, std::string("must lie in ") + b.range);
            continue;
        }
        gaze.*b.field = *value;
    }
    if (gaze.blink_every_s > 0.0 && gaze.blink_s >= gaze.blink_every_s) {
        reader.problem("blink_s", "must be shorter than blink_every_s");
    }
}

// A [[fixation]] or [[blink]]'s time and duration; false when either is missing or wrong.
bool read_interval(const Reader& reader, const TomlScope& scope, TomlProblems& problems, double& t,
                   double& duration) {
    if (find_required(scope, "t", "a time in seconds", problems) == nullptr) return false;
    const auto start = reader.number("t");
    if (!start) return false;
    if (*start < 0.0 || *start > kMaxScriptTimeS) {
        reader.problem("t", "must lie in [0, 1e6] s");
        return false;
    }
    t = *start;
    if (const auto length = reader.number("duration")) {
        if (*length <= 0.0 || *length > kMaxScriptTimeS) {
            reader.problem("duration", "must lie in (0, 1e6] s");
            return false;
        }
        duration = *length;
    }
    return true;
}

void read_gaze(const toml::table& root, TomlProblems& problems, GazeScript& gaze) {
    read_gaze_settings(root, problems, gaze);
    if (const toml::array* array = table_array(root, "fixation", problems)) {
        for (std::size_t i = 0; i < array->size(); ++i) {
            const TomlScope scope{*array->get(i)->as_table(),
                                  "fixation[" + std::to_string(i) + "]"};
            report_unknown_keys(scope, kFixationKeys, problems);
            const Reader reader(scope, problems);
            GazeFixation fixation;
            if (!read_interval(reader, scope, problems, fixation.t, fixation.duration)) continue;
            if (!gaze.fixations.empty() && fixation.t <= gaze.fixations.back().t) {
                reader.problem("t", "fixations must be in ascending order of t");
            }
            fixation.target = reader.vec3("target");
            if (const auto angles = reader.vec2("yaw_pitch_deg")) {
                if (fixation.target)
                    reader.problem("yaw_pitch_deg", "give target or this, not both");
                fixation.yaw_pitch_deg = *angles;
            }
            gaze.fixations.push_back(fixation);
        }
    }
    if (const toml::array* array = table_array(root, "blink", problems)) {
        for (std::size_t i = 0; i < array->size(); ++i) {
            const TomlScope scope{*array->get(i)->as_table(), "blink[" + std::to_string(i) + "]"};
            report_unknown_keys(scope, kBlinkKeys, problems);
            const Reader reader(scope, problems);
            GazeBlink blink;
            if (read_interval(reader, scope, problems, blink.t, blink.duration)) {
                gaze.blinks.push_back(blink);
            }
        }
    }
}

Result<Script> default_script() {
    Script script;
    auto profile = hmd::load_hmd_profile(script.hmd_name);
    MONOPLANE_TRY(profile);
    script.hmd = std::move(profile).value();
    return script;
}

}  // namespace

std::int64_t Script::frame_period_ns() const {
    return std::llround(1e9 / display_rate_hz);
}

Result<Script> parse_script(std::string_view toml_text, const std::filesystem::path& source_path) {
    const std::string source = source_path.string();
    auto parsed = parse_toml(toml_text, source);
    MONOPLANE_TRY(parsed);
    auto defaults = default_script();
    MONOPLANE_TRY(defaults);
    Script script = std::move(defaults).value();
    script.source = source;

    TomlProblems problems(source);
    const TomlScope root{parsed.value(), ""};
    report_unknown_keys(root, kTopLevelKeys, problems);
    const std::filesystem::path folder = source_path.parent_path();
    read_settings(Reader(root, problems), folder, script);
    read_poses(root.table, problems, script);
    read_inputs(root.table, problems, script);
    read_gaze(root.table, problems, script.gaze);
    if (!problems.empty()) return problems.error();
    return script;
}

Result<Script> load_script(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return Error{path.string() + ": cannot open the simxr script"};
    std::ostringstream text;
    text << file.rdbuf();
    return parse_script(text.str(), path);
}

Result<Script> load_script_from_environment() {
    const char* path = std::getenv("SIMXR_SCRIPT");
    if (path == nullptr || *path == '\0') return default_script();
    return load_script(path);
}

}  // namespace monoplane::simxr
