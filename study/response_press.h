// One press of a button or key the participant answers with, as logged in the study database
// (table `presses`, docs/data.md): which channel it came from, what it asked for, and when, on the
// session's time axis. Presses are logged whether or not they changed anything (a switch on the
// neutral screen is a press too); what they changed is in the events.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.h"

namespace monoplane::study {

// controller: the headset's controller (OpenXR actions); keyboard: a key in the experimenter
// window's focus ([responses] keys); device: a key of an evdev device ([responses] device).
enum class PressSource { Controller, Keyboard, Device };
std::string_view press_source_name(PressSource source);
std::optional<PressSource> parse_press_source(std::string_view name);

// What the press asked for: the controller's three buttons; keys switch and confirm only.
enum class PressAction { Switch, Confirm, Pause };
std::string_view press_action_name(PressAction action);
std::optional<PressAction> parse_press_action(std::string_view name);

struct ResponsePress {
    PressSource source = PressSource::Controller;
    PressAction action = PressAction::Switch;
    std::string key;           // keyboard and device: the X key name; controller: empty
    std::string screen;        // what the participant saw: screen_kind_name() ("trial", ...)
    int trial_index = -1;      // the trial on screen (also while paused); -1: none
    std::int64_t time_ns = 0;  // on the session's time axis (as events.time_ns)
};

// What every log refuses: a key press without its key name, a controller press with one, a press
// without its screen. Pure.
Result<void> check_press(const ResponsePress& press);

}  // namespace monoplane::study
