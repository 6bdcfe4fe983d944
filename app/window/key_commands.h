// The keyboard of a desktop dry run: the experimenter (or a developer) plays the participant.
#pragma once

#include <optional>

#include "app/window/experimenter_view.h"

namespace monoplane::window {

// Space or Tab -> Switch and Enter / keypad Enter -> Confirm, during a trial; on the protocol's
// pages as the controller's buttons work there (Confirm on instructions, ready and break; Switch,
// back a page, on instructions); P -> Pause while a trial or the pause between trials runs,
// Resume while paused. Nothing else: Abort is only offered as a button with a confirmation, so
// that no stray key ends a session. Keys typed into the note field are not commands (the window
// drops them). Pure.
std::optional<Command> command_for_key(int glfw_key, Phase phase);

}  // namespace monoplane::window
