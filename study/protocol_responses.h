// Answers from a keyboard or a response box (docs/protocols.md, "[responses]"): which keys
// switch and confirm, as the controller's buttons do, and where they are read: the experimenter
// window's keyboard focus, or an evdev input device given by path (a response box the computer
// sees as a keyboard). The protocol's [responses] table sets it; `study run|resume --keys` and
// `--response-device` override it for one run (app/commands/study_options.h).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "common/toml/toml_keys.h"

namespace monoplane::study {

enum class ResponseAction { Switch, Confirm };
std::string_view response_action_name(ResponseAction action);  // "switch", "confirm"

struct ResponseSettings {
    bool enabled = false;                   // keys answer at all
    std::vector<std::string> switch_keys;   // X key names (study/response_keys.h)
    std::vector<std::string> confirm_keys;  // X key names
    std::string device;                     // an evdev device; empty: the experimenter window

    // The action `key` (an X key name) stands for, or none.
    std::optional<ResponseAction> action_of(std::string_view key) const;
    bool operator==(const ResponseSettings&) const = default;
};

// What response boxes send and what a keyboard offers at hand: either arrow key switches,
// Return confirms.
inline constexpr std::array<std::string_view, 2> kDefaultSwitchKeys = {"Left", "Right"};
inline constexpr std::array<std::string_view, 1> kDefaultConfirmKeys = {"Return"};
// Enabled, with the default keys, read from the window.
ResponseSettings default_responses();

// A key the experimenter window keeps for its own commands (app/window/key_commands.h; the window
// tests hold the two lists to agree): a response key may be one of them only where it does what
// the window's command does (space switching, Return confirming), so that the window never reads
// one key two ways.
struct WindowKey {
    std::string_view name;                 // X key name
    std::optional<ResponseAction> action;  // the window's command, if it is an answer
    std::string_view command;              // the window's command, in words
};
std::span<const WindowKey> experimenter_window_keys();

// What is wrong with a mapping, one sentence each (empty: nothing): a key name that is no key
// (with "did you mean"), a key for both actions, an action without a key, and, when read from the
// window (no device), a key the window keeps for another command. Pure; any time.
std::vector<std::string> response_problems(const ResponseSettings& responses);

// Reads the protocol's [responses] table: `keys = { switch = "Left", confirm = "Return" }` (each
// a key name or a list of them; an action left out keeps its default keys) and `device`, an
// absolute path. The table's presence enables keys. Reports, located: unknown keys, wrong types,
// an empty list, a relative device path, and response_problems(). Any time.
void read_responses(const TomlScope& root, ResponseSettings& responses, TomlProblems& problems);

// `--keys SPEC` over the protocol's settings `base`: "default" (the default keys), "none" (no
// keys; a --response-device is then refused), or "switch=KEY,confirm=KEY" (an action may be
// named again for a second key; one left out keeps its default keys). The mapping is checked
// with response_problems(); errors name the option. Pure.
Result<ResponseSettings> parse_keys_option(std::string_view spec, const ResponseSettings& base);

// `--response-device PATH` over `base`: enables keys (the protocol's, else the default) and reads
// them from the device; a relative path is refused. Pure: the device is opened when the session
// starts.
Result<ResponseSettings> with_response_device(std::string_view path, const ResponseSettings& base);

// "keys Left, Right switch; Return confirms (experimenter window)" or "... (device PATH)", or
// "no keys": for logs, the experimenter window and the launcher.
std::string describe_responses(const ResponseSettings& responses);

}  // namespace monoplane::study
