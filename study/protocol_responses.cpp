#include "study/protocol_responses.h"

#include <algorithm>
#include <filesystem>

#include "common/quoted.h"
#include "study/response_keys.h"

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 2> kResponsesKeys = {"keys", "device"};
constexpr std::array<std::string_view, 2> kActionNames = {"switch", "confirm"};

// The window's own key commands (app/window/key_commands.cpp).
constexpr WindowKey kWindowKeys[] = {
    {"space", ResponseAction::Switch, "switch"},
    {"Tab", ResponseAction::Switch, "switch"},
    {"Return", ResponseAction::Confirm, "confirm"},
    {"KP_Enter", ResponseAction::Confirm, "confirm"},
    {"p", std::nullopt, "pause/resume"},
};

std::vector<std::string> to_strings(std::span<const std::string_view> names) {
    return {names.begin(), names.end()};
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
    return out;
}

void name_problems(const std::vector<std::string>& keys, std::vector<std::string>& problems) {
    for (const std::string& key : keys) {
        if (find_response_key(key)) continue;
        std::string problem = in_quotes(key) + " is no key name monoplane knows";
        const std::string_view close = closest_response_key(key);
        if (!close.empty()) problem += " (did you mean " + in_quotes(close) + "?)";
        problems.push_back(problem + "; docs/protocols.md lists the names");
    }
}

void window_clashes(const ResponseSettings& r, std::vector<std::string>& problems) {
    for (const WindowKey& reserved : kWindowKeys) {
        const std::optional<ResponseAction> action = r.action_of(reserved.name);
        if (!action || action == reserved.action) continue;
        problems.push_back(in_quotes(reserved.name) + " is the experimenter window's " +
                           std::string(reserved.command) + " key and cannot also " +
                           std::string(response_action_name(*action)) +
                           "; choose another key, or read the keys from a device");
    }
}

// A key name or a list of them, into `keys`.
void read_key_names(const toml::node& node, const std::string& qualified,
                    std::vector<std::string>& keys, TomlProblems& problems) {
    constexpr std::string_view kExpected = "a key name or a list of key names";
    if (const auto* name = node.as_string()) {
        keys = {name->get()};
        return;
    }
    const toml::array* array = node.as_array();
    if (array == nullptr) return report_wrong_type(node, qualified, kExpected, problems);
    if (array->empty()) {
        problems.add(node.source(), toml_key_prefix(qualified) + "must name at least one key");
        return;
    }
    keys.clear();
    for (const toml::node& element : *array) {
        if (const auto* name = element.as_string()) {
            keys.push_back(name->get());
        } else {
            report_wrong_type(element, qualified, "a key name", problems);
        }
    }
}

void read_keys_table(const toml::node& node, ResponseSettings& r, TomlProblems& problems) {
    const toml::table* table = node.as_table();
    if (table == nullptr) {
        return report_wrong_type(node, "responses.keys",
                                 "a table such as { switch = \"Left\", confirm = \"Return\" }",
                                 problems);
    }
    const TomlScope scope{*table, "responses.keys"};
    report_unknown_keys(scope, kActionNames, problems);
    if (const toml::node* keys = table->get("switch")) {
        read_key_names(*keys, scope.qualified("switch"), r.switch_keys, problems);
    }
    if (const toml::node* keys = table->get("confirm")) {
        read_key_names(*keys, scope.qualified("confirm"), r.confirm_keys, problems);
    }
}

}  // namespace

std::string_view response_action_name(ResponseAction action) {
    return action == ResponseAction::Switch ? "switch" : "confirm";
}

std::optional<ResponseAction> ResponseSettings::action_of(std::string_view key) const {
    if (std::ranges::find(switch_keys, key) != switch_keys.end()) return ResponseAction::Switch;
    if (std::ranges::find(confirm_keys, key) != confirm_keys.end()) return ResponseAction::Confirm;
    return std::nullopt;
}

ResponseSettings default_responses() {
    ResponseSettings r;
    r.enabled = true;
    r.switch_keys = to_strings(kDefaultSwitchKeys);
    r.confirm_keys = to_strings(kDefaultConfirmKeys);
    return r;
}

std::span<const WindowKey> experimenter_window_keys() {
    return kWindowKeys;
}

std::vector<std::string> response_problems(const ResponseSettings& r) {
    std::vector<std::string> problems;
    if (!r.enabled) return problems;
    if (r.switch_keys.empty()) problems.push_back("no key switches");
    if (r.confirm_keys.empty()) problems.push_back("no key confirms");
    name_problems(r.switch_keys, problems);
    name_problems(r.confirm_keys, problems);
    for (const std::string& key : r.switch_keys) {
        if (std::ranges::find(r.confirm_keys, key) != r.confirm_keys.end()) {
            problems.push_back(in_quotes(key) +
                               " both switches and confirms; give each action its own key");
        }
    }
    if (r.device.empty()) window_clashes(r, problems);
    return problems;
}

void read_responses(const TomlScope& root, ResponseSettings& r, TomlProblems& problems) {
    const toml::node* node = root.table.get("responses");
    if (node == nullptr) return;
    const toml::table* table = node->as_table();
    if (table == nullptr) return report_wrong_type(*node, "responses", "a table", problems);
    const TomlScope scope{*table, "responses"};
    report_unknown_keys(scope, kResponsesKeys, problems);
    r = default_responses();
    if (const toml::node* keys = table->get("keys")) read_keys_table(*keys, r, problems);
    if (const toml::node* device = table->get("device")) {
        if (const auto* path = device->as_string()) {
            r.device = path->get();
            if (!std::filesystem::path(r.device).is_absolute()) {
                problems.add(device->source(), toml_key_prefix("responses.device") +
                                                   "must be an absolute path such as "
                                                   "/dev/input/by-id/usb-...-event-kbd, but is '" +
                                                   r.device + "'");
            }
        } else {
            report_wrong_type(*device, "responses.device", "a path", problems);
        }
    }
    // At the keys' line where they were written, else at the table's (the defaults are fine).
    const toml::node* keys = table->get("keys");
    for (const std::string& problem : response_problems(r)) {
        problems.add(keys ? keys->source() : table->source(),
                     toml_key_prefix("responses.keys") + problem);
    }
}

Result<ResponseSettings> parse_keys_option(std::string_view spec, const ResponseSettings& base) {
    ResponseSettings r = base;
    if (spec == "none") {
        r = {};
        return r;
    }
    const ResponseSettings defaults = default_responses();
    r.enabled = true;
    r.switch_keys = defaults.switch_keys;
    r.confirm_keys = defaults.confirm_keys;
    if (spec != "default") {
        bool switch_named = false, confirm_named = false;
        std::size_t start = 0;
        while (start <= spec.size()) {
            const std::size_t comma = std::min(spec.find(',', start), spec.size());
            const std::string_view item = spec.substr(start, comma - start);
            start = comma + 1;
            const std::size_t equals = item.find('=');
            const std::string_view action = item.substr(0, equals);
            const bool is_switch = action == "switch", is_confirm = action == "confirm";
            if (equals == std::string_view::npos || (!is_switch && !is_confirm) ||
                equals + 1 == item.size()) {
                return Error{"--keys " + std::string(spec) + ": '" + std::string(item) +
                             "' is not ACTION=KEY; write e.g. --keys switch=Left,confirm=Return, "
                             "--keys default or --keys none"};
            }
            bool& named = is_switch ? switch_named : confirm_named;
            std::vector<std::string>& keys = is_switch ? r.switch_keys : r.confirm_keys;
            if (!named) keys.clear();
            named = true;
            keys.emplace_back(item.substr(equals + 1));
        }
    }
    const std::vector<std::string> problems = response_problems(r);
    if (!problems.empty()) return Error{"--keys " + std::string(spec) + ": " + problems.front()};
    return r;
}

Result<ResponseSettings> with_response_device(std::string_view path, const ResponseSettings& base) {
    if (!std::filesystem::path(path).is_absolute()) {
        return Error{"--response-device " + std::string(path) +
                     ": give the device's absolute path, e.g. /dev/input/by-id/usb-...-event-kbd"};
    }
    ResponseSettings r = base.enabled ? base : default_responses();
    r.device = std::string(path);
    const std::vector<std::string> problems = response_problems(r);
    if (!problems.empty()) return Error{"--response-device: " + problems.front()};
    return r;
}

std::string describe_responses(const ResponseSettings& r) {
    if (!r.enabled) return "no keys";
    return "keys " + joined(r.switch_keys) + " switch; " + joined(r.confirm_keys) + " confirm" +
           (r.device.empty() ? " (experimenter window)" : " (device " + r.device + ")");
}

}  // namespace monoplane::study
