// The participant's answer keys as the experimenter window reads them ([responses] keys,
// study/protocol_responses.h): X key names turned into GLFW keys, and the window's bindings of
// those keys to switch and confirm. Kept apart from key_commands.h, the experimenter's own keys:
// a response key is the participant's press (logged with source "keyboard"), never the
// experimenter's command.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/window/experimenter_view.h"

namespace monoplane::window {

// The GLFW key (GLFW_KEY_*) of an X key name ("Left" -> GLFW_KEY_LEFT, "a" -> GLFW_KEY_A), or
// none for a name GLFW has no key for. GLFW names keys by their US-layout position; X names by
// the symbol: on another layout a letter key may sit elsewhere (docs/protocols.md). Pure.
std::optional<int> glfw_key_for(std::string_view x_key_name);

// One answer key of the window: pressing `glfw_key` asks for `kind` (Switch or Confirm).
struct ResponseKeyBinding {
    int glfw_key = 0;
    Command::Kind kind = Command::Kind::Switch;
    std::string name;  // the X key name, logged with the press
};

// The binding of `glfw_key` among `bindings`, or null. Pure.
const ResponseKeyBinding* find_binding(const std::vector<ResponseKeyBinding>& bindings,
                                       int glfw_key);

}  // namespace monoplane::window
