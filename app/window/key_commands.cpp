#include "app/window/key_commands.h"

#include <GLFW/glfw3.h>

namespace monoplane::window {

std::optional<Command> command_for_key(int glfw_key, Phase phase) {
    switch (glfw_key) {
        case GLFW_KEY_SPACE:
        case GLFW_KEY_TAB:
            // On an instruction page, switch goes back a page.
            if (phase == Phase::Trial || phase == Phase::Instructions) {
                return Command{Command::Kind::Switch};
            }
            return std::nullopt;
        case GLFW_KEY_ENTER:
        case GLFW_KEY_KP_ENTER:
            if (phase == Phase::Trial || phase == Phase::Instructions || phase == Phase::Ready ||
                phase == Phase::Break) {
                return Command{Command::Kind::Confirm};
            }
            return std::nullopt;
        case GLFW_KEY_P:
            if (phase == Phase::Trial || phase == Phase::Neutral) {
                return Command{Command::Kind::Pause};
            }
            if (phase == Phase::Paused) return Command{Command::Kind::Resume};
            return std::nullopt;
        default:
            return std::nullopt;
    }
}

}  // namespace monoplane::window
