// The participant's answer channels in a headset session besides the controller: the [responses]
// keys from the experimenter window or from an evdev device (study/protocol_responses.h), each key
// press turned into the action it stands for; and the watch on the controller's binding, which
// tells the experimenter at once when nobody can answer (app/headset/answer_channels.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/headset/answer_channels.h"
#include "app/headset/openxr_headset.h"
#include "app/headset/response_device.h"
#include "app/window/experimenter_view.h"
#include "app/window/response_key_input.h"
#include "study/protocol_responses.h"
#include "study/response_press.h"

namespace monoplane::app {

// One press of an answer key, or of a controller button.
struct AnswerPress {
    study::PressSource source = study::PressSource::Keyboard;
    study::PressAction action = study::PressAction::Switch;
    std::string key;  // the X key name; empty for the controller
    // Keys: when the key went down (a device's event) or was read (the window's poll), on
    // CLOCK_MONOTONIC, for the runtime to convert; none for the controller (its time is the
    // runtime's own).
    std::optional<timespec> monotonic;
};

// CLOCK_MONOTONIC now. Any time.
timespec monotonic_now();

// The protocol's [responses] with `study run|resume --keys` and `--response-device` over it
// (empty: not given). Throws UserError with the option's message. Pure.
study::ResponseSettings resolve_responses(const study::ResponseSettings& protocol,
                                          const std::string& keys_option,
                                          const std::string& device_option);

// The window's bindings of the keys (none when the keys are read from a device or disabled).
// Every name of study/response_keys.h has a GLFW key (tested). Pure.
std::vector<window::ResponseKeyBinding> window_bindings(const study::ResponseSettings& responses);

// A Switch or Confirm the window read from an answer key (Command::key set) as a press, read at
// `read` (CLOCK_MONOTONIC); none for the experimenter's own commands. Pure.
std::optional<AnswerPress> keyboard_press(const window::Command& command,
                                          std::optional<timespec> read = std::nullopt);

// The controller's press as one of the participant's.
AnswerPress controller_press(headset::Control control);

class ParticipantAnswers {
  public:
    // Opens the device when `responses` name one: a UserError naming the path and the fix when it
    // cannot be read. `window`: the experimenter window is shown (keys from the window need it);
    // `observer`: a simulated observer answers. Before the session's first frame.
    ParticipantAnswers(const study::ResponseSettings& responses, bool window, bool observer);

    // The device's presses since the last call, of the mapped keys only. Once a frame; a device
    // gone (unplugged) is a UserError naming it.
    std::vector<AnswerPress> device_presses();

    // After each xrSyncActions: looks at the runtime's binding when it can be judged (a few syncs
    // of the focused session, then now and then while none is bound). Returns a line for the log
    // when whether anyone can answer changed: the message, or that a controller is now bound.
    std::optional<std::string> after_sync(const headset::OpenXrHeadset& headset, bool focused);

    // kNoControllerMessage while nobody can answer, else none.
    const std::optional<std::string>& cannot_answer() const { return cannot_answer_; }

  private:
    study::ResponseSettings responses_;
    std::optional<headset::ResponseDevice> device_;
    headset::AnswerChannels channels_;
    std::optional<std::string> cannot_answer_;
};

}  // namespace monoplane::app
