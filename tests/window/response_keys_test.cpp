// The participant's answer keys in the experimenter window and from a response device: every key
// name has its GLFW key, the window's own keys agree with the list the protocol check refuses, key
// presses become presses of the right action and source, a device's EV_KEY presses are read, and
// nobody-can-answer is told exactly when no controller is bound and no keys or observer answer.
#include <GLFW/glfw3.h>
#include <fcntl.h>
#include <linux/input.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <set>

#include "app/commands/participant_answers.h"
#include "app/headset/answer_channels.h"
#include "app/headset/response_device.h"
#include "app/window/key_commands.h"
#include "app/window/response_key_input.h"
#include "study/protocol_responses.h"
#include "study/response_keys.h"

namespace monoplane {
namespace {

using window::Command;
using window::Phase;

TEST(ResponseKeyInput, EveryKeyNameHasItsOwnGlfwKey) {
    std::set<int> seen;
    for (const study::ResponseKey& key : study::response_keys()) {
        const std::optional<int> glfw = window::glfw_key_for(key.name);
        ASSERT_TRUE(glfw) << key.name;
        EXPECT_TRUE(seen.insert(*glfw).second) << key.name << " shares its GLFW key";
    }
    EXPECT_EQ(window::glfw_key_for("Left"), GLFW_KEY_LEFT);
    EXPECT_EQ(window::glfw_key_for("Return"), GLFW_KEY_ENTER);
    EXPECT_EQ(window::glfw_key_for("q"), GLFW_KEY_Q);
    EXPECT_EQ(window::glfw_key_for("7"), GLFW_KEY_7);
    EXPECT_EQ(window::glfw_key_for("KP_3"), GLFW_KEY_KP_3);
    EXPECT_EQ(window::glfw_key_for("F10"), GLFW_KEY_F10);
    EXPECT_FALSE(window::glfw_key_for("F0"));
    EXPECT_FALSE(window::glfw_key_for("F13"));
    EXPECT_FALSE(window::glfw_key_for("Q"));
}

// The protocol check refuses a response key that the window uses otherwise: its list must be the
// window's own keys, each with what it does there.
TEST(ResponseKeyInput, TheWindowsOwnKeysAreTheOnesTheProtocolCheckKnows) {
    const Phase phases[] = {
        Phase::Starting,      Phase::Trial,    Phase::Neutral, Phase::Paused,
        Phase::Questionnaire, Phase::Finished, Phase::Aborted, Phase::Instructions,
        Phase::Ready,         Phase::Break,    Phase::End};
    for (const study::ResponseKey& key : study::response_keys()) {
        std::set<Command::Kind> kinds;
        for (const Phase phase : phases) {
            if (auto command = window::command_for_key(*window::glfw_key_for(key.name), phase))
                kinds.insert(command->kind);
        }
        const study::WindowKey* reserved = nullptr;
        for (const study::WindowKey& w : study::experimenter_window_keys())
            if (w.name == key.name) reserved = &w;
        ASSERT_EQ(reserved != nullptr, !kinds.empty()) << key.name;
        if (!reserved) continue;
        if (reserved->action == study::ResponseAction::Switch) {
            EXPECT_EQ(kinds, std::set<Command::Kind>{Command::Kind::Switch}) << key.name;
        } else if (reserved->action == study::ResponseAction::Confirm) {
            EXPECT_EQ(kinds, std::set<Command::Kind>{Command::Kind::Confirm}) << key.name;
        } else {
            EXPECT_EQ(kinds, (std::set<Command::Kind>{Command::Kind::Pause, Command::Kind::Resume}))
                << key.name;
        }
    }
}

TEST(ParticipantAnswers, WindowBindingsOfTheKeys) {
    const auto bindings = app::window_bindings(study::default_responses());
    ASSERT_EQ(bindings.size(), 3u);
    EXPECT_EQ(window::find_binding(bindings, GLFW_KEY_LEFT)->kind, Command::Kind::Switch);
    EXPECT_EQ(window::find_binding(bindings, GLFW_KEY_RIGHT)->name, "Right");
    EXPECT_EQ(window::find_binding(bindings, GLFW_KEY_ENTER)->kind, Command::Kind::Confirm);
    EXPECT_EQ(window::find_binding(bindings, GLFW_KEY_SPACE), nullptr);
    // Read from a device, or disabled: the window binds nothing.
    study::ResponseSettings device = study::default_responses();
    device.device = "/dev/input/event3";
    EXPECT_TRUE(app::window_bindings(device).empty());
    EXPECT_TRUE(app::window_bindings({}).empty());
}

TEST(ParticipantAnswers, OnlyAnswerKeysArePresses) {
    const auto press =
        app::keyboard_press(Command{.kind = Command::Kind::Confirm, .key = "Return"});
    ASSERT_TRUE(press);
    EXPECT_EQ(press->source, study::PressSource::Keyboard);
    EXPECT_EQ(press->action, study::PressAction::Confirm);
    EXPECT_EQ(press->key, "Return");
    EXPECT_FALSE(press->monotonic);  // no read time given
    const timespec read{5, 6};
    EXPECT_EQ(app::keyboard_press(Command{.kind = Command::Kind::Switch, .key = "Left"}, read)
                  ->monotonic->tv_nsec,
              6);
    // The experimenter's Enter, and a pause, are the experimenter's commands.
    EXPECT_FALSE(app::keyboard_press(Command{Command::Kind::Confirm}));
    EXPECT_FALSE(app::keyboard_press(Command{.kind = Command::Kind::Pause, .key = "p"}));
    EXPECT_EQ(app::controller_press(headset::Control::Pause).action, study::PressAction::Pause);
    EXPECT_EQ(app::controller_press(headset::Control::Switch).source,
              study::PressSource::Controller);
}

TEST(ParticipantAnswers, OptionsOverTheProtocol) {
    const study::ResponseSettings protocol;  // no [responses]
    EXPECT_FALSE(app::resolve_responses(protocol, "", "").enabled);
    EXPECT_EQ(app::resolve_responses(protocol, "default", ""), study::default_responses());
    const study::ResponseSettings device =
        app::resolve_responses(protocol, "switch=a,confirm=b", "/dev/input/event4");
    EXPECT_EQ(device.switch_keys, std::vector<std::string>{"a"});
    EXPECT_EQ(device.device, "/dev/input/event4");
    EXPECT_THROW(app::resolve_responses(protocol, "none", "/dev/input/event4"), UserError);
    EXPECT_THROW(app::resolve_responses(protocol, "switch=p", ""), UserError);
}

TEST(AnswerChannels, NobodyCanAnswerOnlyWithoutControllerKeysAndObserver) {
    headset::AnswerChannels channels;
    EXPECT_FALSE(headset::cannot_answer_message(channels));  // too early to tell
    channels.focused_syncs = headset::kSyncsBeforeUnbound;
    EXPECT_EQ(headset::cannot_answer_message(channels),
              "no controller bound: the participant cannot answer; connect one or enable keys");
    channels.keys = true;
    EXPECT_FALSE(headset::cannot_answer_message(channels));
    channels.keys = false;
    channels.observer = true;
    EXPECT_FALSE(headset::cannot_answer_message(channels));
    channels.observer = false;
    channels.interaction_profile = "/interaction_profiles/khr/simple_controller";
    EXPECT_FALSE(headset::cannot_answer_message(channels));
    EXPECT_FALSE(headset::controller_unbound(channels));
}

// A response device's events through a pipe: presses (value 1) only, in order.
TEST(ResponseDevice, ReadsKeyPressesAndNothingElse) {
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    headset::ResponseDevice device = headset::ResponseDevice::adopt(fds[0], "pipe");
    EXPECT_TRUE(device.take_presses()->empty());  // nothing yet, and no wait
    const auto send = [&](int type, int code, int value) {
        input_event event{};
        event.input_event_sec = 12;
        event.input_event_usec = 345 + code;
        event.type = static_cast<__u16>(type);
        event.code = static_cast<__u16>(code);
        event.value = value;
        ASSERT_EQ(write(fds[1], &event, sizeof event), static_cast<ssize_t>(sizeof event));
    };
    send(EV_MSC, MSC_SCAN, 458832);
    send(EV_KEY, KEY_LEFT, 1);
    send(EV_SYN, SYN_REPORT, 0);
    send(EV_KEY, KEY_LEFT, 2);  // autorepeat
    send(EV_KEY, KEY_LEFT, 0);  // release
    send(EV_KEY, KEY_ENTER, 1);
    const auto presses = device.take_presses();
    ASSERT_TRUE(presses) << presses.error().message;
    ASSERT_EQ(presses->size(), 2u);
    EXPECT_EQ((*presses)[0].code, KEY_LEFT);
    EXPECT_EQ((*presses)[1].code, KEY_ENTER);
    // The event's own time, to the microsecond, for the runtime to convert.
    EXPECT_EQ((*presses)[1].time.tv_sec, 12);
    EXPECT_EQ((*presses)[1].time.tv_nsec, (345 + KEY_ENTER) * 1000);
    EXPECT_TRUE(device.take_presses()->empty());
    close(fds[1]);
}

TEST(ResponseDevice, AnUnreadableDeviceNamesThePathAndTheFix) {
    EXPECT_EQ(headset::response_device_error("/dev/input/event9", EACCES),
              "cannot read the response device /dev/input/event9: permission denied; add your "
              "user to the device's group (usually 'input': sudo usermod -aG input $USER, then "
              "log in again) or give it a udev rule");
    const auto missing = headset::ResponseDevice::open("/nonexistent/monoplane-event-kbd");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().message,
              "cannot read the response device /nonexistent/monoplane-event-kbd: no such device; "
              "is it plugged in? (ls -l /dev/input/by-id)");
}

}  // namespace
}  // namespace monoplane
