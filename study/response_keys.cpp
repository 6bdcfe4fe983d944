#include "study/response_keys.h"

#include <linux/input-event-codes.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "common/toml/toml_problems.h"

namespace monoplane::study {
namespace {

constexpr ResponseKey kKeys[] = {
    // What response boxes send most (arrows and Enter), then the rest of a keyboard.
    {"Left", KEY_LEFT},
    {"Right", KEY_RIGHT},
    {"Up", KEY_UP},
    {"Down", KEY_DOWN},
    {"Return", KEY_ENTER},
    {"KP_Enter", KEY_KPENTER},
    {"space", KEY_SPACE},
    {"Tab", KEY_TAB},
    {"BackSpace", KEY_BACKSPACE},
    {"Home", KEY_HOME},
    {"End", KEY_END},
    {"Prior", KEY_PAGEUP},
    {"Next", KEY_PAGEDOWN},
    {"Insert", KEY_INSERT},
    {"Delete", KEY_DELETE},
    {"F1", KEY_F1},
    {"F2", KEY_F2},
    {"F3", KEY_F3},
    {"F4", KEY_F4},
    {"F5", KEY_F5},
    {"F6", KEY_F6},
    {"F7", KEY_F7},
    {"F8", KEY_F8},
    {"F9", KEY_F9},
    {"F10", KEY_F10},
    {"F11", KEY_F11},
    {"F12", KEY_F12},
    {"a", KEY_A},
    {"b", KEY_B},
    {"c", KEY_C},
    {"d", KEY_D},
    {"e", KEY_E},
    {"f", KEY_F},
    {"g", KEY_G},
    {"h", KEY_H},
    {"i", KEY_I},
    {"j", KEY_J},
    {"k", KEY_K},
    {"l", KEY_L},
    {"m", KEY_M},
    {"n", KEY_N},
    {"o", KEY_O},
    {"p", KEY_P},
    {"q", KEY_Q},
    {"r", KEY_R},
    {"s", KEY_S},
    {"t", KEY_T},
    {"u", KEY_U},
    {"v", KEY_V},
    {"w", KEY_W},
    {"x", KEY_X},
    {"y", KEY_Y},
    {"z", KEY_Z},
    {"0", KEY_0},
    {"1", KEY_1},
    {"2", KEY_2},
    {"3", KEY_3},
    {"4", KEY_4},
    {"5", KEY_5},
    {"6", KEY_6},
    {"7", KEY_7},
    {"8", KEY_8},
    {"9", KEY_9},
    {"KP_0", KEY_KP0},
    {"KP_1", KEY_KP1},
    {"KP_2", KEY_KP2},
    {"KP_3", KEY_KP3},
    {"KP_4", KEY_KP4},
    {"KP_5", KEY_KP5},
    {"KP_6", KEY_KP6},
    {"KP_7", KEY_KP7},
    {"KP_8", KEY_KP8},
    {"KP_9", KEY_KP9},
    {"KP_Add", KEY_KPPLUS},
    {"KP_Subtract", KEY_KPMINUS},
    {"KP_Multiply", KEY_KPASTERISK},
    {"KP_Divide", KEY_KPSLASH},
    {"KP_Decimal", KEY_KPDOT},
    {"comma", KEY_COMMA},
    {"period", KEY_DOT},
    {"slash", KEY_SLASH},
    {"semicolon", KEY_SEMICOLON},
    {"minus", KEY_MINUS},
    {"equal", KEY_EQUAL},
    {"Shift_L", KEY_LEFTSHIFT},
    {"Shift_R", KEY_RIGHTSHIFT},
    {"Control_L", KEY_LEFTCTRL},
    {"Control_R", KEY_RIGHTCTRL},
    {"Alt_L", KEY_LEFTALT},
    {"Alt_R", KEY_RIGHTALT},
};

}  // namespace

std::span<const ResponseKey> response_keys() {
    return kKeys;
}

std::optional<ResponseKey> find_response_key(std::string_view name) {
    for (const ResponseKey& key : kKeys)
        if (key.name == name) return key;
    return std::nullopt;
}

std::string_view closest_response_key(std::string_view name) {
    // A name in the wrong case ("return", "LEFT") is the likeliest slip: matched first.
    const auto lower = [](std::string_view text) {
        std::string out(text);
        for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return out;
    };
    for (const ResponseKey& key : kKeys)
        if (lower(key.name) == lower(name)) return key.name;
    std::vector<std::string_view> names;
    for (const ResponseKey& key : kKeys) names.push_back(key.name);
    return closest_match(name, names);
}

std::optional<std::string_view> response_key_name(int evdev_code) {
    for (const ResponseKey& key : kKeys)
        if (key.evdev_code == evdev_code) return key.name;
    return std::nullopt;
}

}  // namespace monoplane::study
