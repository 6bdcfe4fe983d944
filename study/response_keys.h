// The keys a participant may answer with (a keyboard, or a response box that the computer sees as
// a keyboard): X key names, as `xev` and `xdotool` print and send them ("Left", "Return", "a",
// "KP_1"), each with the Linux input event code (linux/input-event-codes.h) an evdev device
// reports for that key. One table, so the protocol's check, the experimenter window and a
// response device agree on what a name means. Pure data; any time.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace monoplane::study {

struct ResponseKey {
    std::string_view name;  // the X keysym name
    int evdev_code;         // KEY_* of linux/input-event-codes.h
};

// Every key name a protocol or --keys may use, in the table's order: arrows, Return and
// KP_Enter, space, Tab, BackSpace, Home/End/Prior/Next/Insert/Delete, F1-F12, a-z, 0-9, the
// keypad's digits and operators, a few punctuation keys, and Shift/Control/Alt left and right.
// Escape is left out: the window's text fields use it.
std::span<const ResponseKey> response_keys();

// The key named `name` (case-sensitive, as X names are), or none.
std::optional<ResponseKey> find_response_key(std::string_view name);

// The key name closest to a name that is not one (for "did you mean 'Return'?"), or empty.
std::string_view closest_response_key(std::string_view name);

// The name of the key an evdev device reports as `code`, or none for a key outside the table.
std::optional<std::string_view> response_key_name(int evdev_code);

}  // namespace monoplane::study
