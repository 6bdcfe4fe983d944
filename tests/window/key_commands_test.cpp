// The desktop dry run's keyboard: which key gives which command in which phase.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "app/window/key_commands.h"

namespace monoplane::window {
namespace {

using Kind = Command::Kind;

std::optional<Kind> kind_for(int key, Phase phase) {
    const auto command = command_for_key(key, phase);
    if (!command) return std::nullopt;
    return command->kind;
}

TEST(CommandForKey, SpaceAndTabSwitchDuringATrial) {
    EXPECT_EQ(kind_for(GLFW_KEY_SPACE, Phase::Trial), Kind::Switch);
    EXPECT_EQ(kind_for(GLFW_KEY_TAB, Phase::Trial), Kind::Switch);
}

TEST(CommandForKey, EnterAndKeypadEnterConfirmDuringATrial) {
    EXPECT_EQ(kind_for(GLFW_KEY_ENTER, Phase::Trial), Kind::Confirm);
    EXPECT_EQ(kind_for(GLFW_KEY_KP_ENTER, Phase::Trial), Kind::Confirm);
}

TEST(CommandForKey, PPausesARunningSessionAndResumesAPausedOne) {
    EXPECT_EQ(kind_for(GLFW_KEY_P, Phase::Trial), Kind::Pause);
    EXPECT_EQ(kind_for(GLFW_KEY_P, Phase::Neutral), Kind::Pause);
    EXPECT_EQ(kind_for(GLFW_KEY_P, Phase::Paused), Kind::Resume);
}

TEST(CommandForKey, SwitchAndConfirmOnlyDuringATrial) {
    for (const Phase phase : {Phase::Starting, Phase::Neutral, Phase::Paused, Phase::Questionnaire,
                              Phase::Finished, Phase::Aborted}) {
        EXPECT_FALSE(command_for_key(GLFW_KEY_SPACE, phase));
        EXPECT_FALSE(command_for_key(GLFW_KEY_TAB, phase));
        EXPECT_FALSE(command_for_key(GLFW_KEY_ENTER, phase));
        EXPECT_FALSE(command_for_key(GLFW_KEY_KP_ENTER, phase));
    }
}

TEST(CommandForKey, NoPauseBeforeTheFirstTrialOrAfterTheLast) {
    for (const Phase phase :
         {Phase::Starting, Phase::Questionnaire, Phase::Finished, Phase::Aborted}) {
        EXPECT_FALSE(command_for_key(GLFW_KEY_P, phase));
    }
}

TEST(CommandForKey, NoOtherKeyDoesAnything) {
    // Above all, no key aborts: Abort is a button with a confirmation.
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
        if (key == GLFW_KEY_SPACE || key == GLFW_KEY_TAB || key == GLFW_KEY_ENTER ||
            key == GLFW_KEY_KP_ENTER || key == GLFW_KEY_P) {
            continue;
        }
        for (const Phase phase : {Phase::Trial, Phase::Paused, Phase::Neutral}) {
            EXPECT_FALSE(command_for_key(key, phase)) << "key " << key;
        }
    }
    EXPECT_FALSE(command_for_key(GLFW_KEY_UNKNOWN, Phase::Trial));
}

}  // namespace
}  // namespace monoplane::window
