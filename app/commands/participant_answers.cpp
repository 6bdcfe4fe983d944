#include "app/commands/participant_answers.h"

#include "common/result.h"
#include "study/response_keys.h"

namespace monoplane::app {
namespace {

// While no controller is bound, the binding is looked at again this often (focused syncs): a
// controller switched on later is noticed within a second at 90 Hz.
constexpr int kRecheckEvery = 45;

study::PressAction press_action(study::ResponseAction action) {
    return action == study::ResponseAction::Switch ? study::PressAction::Switch
                                                   : study::PressAction::Confirm;
}

}  // namespace

study::ResponseSettings resolve_responses(const study::ResponseSettings& protocol,
                                          const std::string& keys_option,
                                          const std::string& device_option) {
    study::ResponseSettings responses = protocol;
    if (!keys_option.empty()) {
        responses = study::parse_keys_option(keys_option, protocol).value_or_throw();
    }
    if (!device_option.empty()) {
        if (keys_option == "none") {
            throw UserError(
                "--keys none and --response-device contradict each other: a device "
                "answers with keys");
        }
        responses = study::with_response_device(device_option, responses).value_or_throw();
    }
    return responses;
}

std::vector<window::ResponseKeyBinding> window_bindings(const study::ResponseSettings& responses) {
    std::vector<window::ResponseKeyBinding> bindings;
    if (!responses.enabled || !responses.device.empty()) return bindings;
    const auto bind = [&](const std::vector<std::string>& keys, window::Command::Kind kind) {
        for (const std::string& key : keys) {
            // Checked when the protocol was read: every known name has a GLFW key.
            if (const std::optional<int> glfw = window::glfw_key_for(key)) {
                bindings.push_back({*glfw, kind, key});
            }
        }
    };
    bind(responses.switch_keys, window::Command::Kind::Switch);
    bind(responses.confirm_keys, window::Command::Kind::Confirm);
    return bindings;
}

timespec monotonic_now() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return now;
}

std::optional<AnswerPress> keyboard_press(const window::Command& command,
                                          std::optional<timespec> read) {
    if (command.key.empty()) return std::nullopt;
    AnswerPress press{study::PressSource::Keyboard, study::PressAction::Switch, command.key, read};
    if (command.kind == window::Command::Kind::Switch) return press;
    press.action = study::PressAction::Confirm;
    if (command.kind == window::Command::Kind::Confirm) return press;
    return std::nullopt;
}

AnswerPress controller_press(headset::Control control) {
    AnswerPress press{study::PressSource::Controller, study::PressAction::Switch, "", {}};
    if (control == headset::Control::Confirm) press.action = study::PressAction::Confirm;
    if (control == headset::Control::Pause) press.action = study::PressAction::Pause;
    return press;
}

ParticipantAnswers::ParticipantAnswers(const study::ResponseSettings& responses, bool window,
                                       bool observer)
    : responses_(responses) {
    if (responses.enabled && !responses.device.empty()) {
        device_.emplace(headset::ResponseDevice::open(responses.device).value_or_throw());
    }
    // Keys from the window answer only where there is a window to read them from.
    channels_.keys = responses.enabled && (device_ || window);
    channels_.observer = observer;
}

std::vector<AnswerPress> ParticipantAnswers::device_presses() {
    std::vector<AnswerPress> presses;
    if (!device_) return presses;
    for (const headset::DeviceKeyPress& down : device_->take_presses().value_or_throw()) {
        const std::optional<std::string_view> name = study::response_key_name(down.code);
        if (!name) continue;
        const std::optional<study::ResponseAction> action = responses_.action_of(*name);
        if (!action) continue;  // the device's other keys answer nothing
        presses.push_back(
            {study::PressSource::Device, press_action(*action), std::string(*name), down.time});
    }
    return presses;
}

std::optional<std::string> ParticipantAnswers::after_sync(const headset::OpenXrHeadset& headset,
                                                          bool focused) {
    if (!focused) return std::nullopt;
    const int syncs = ++channels_.focused_syncs;
    // Judged once enough syncs passed, then again now and then while nothing is bound.
    const bool look = syncs == headset::kSyncsBeforeUnbound ||
                      (syncs > headset::kSyncsBeforeUnbound &&
                       channels_.interaction_profile.empty() && syncs % kRecheckEvery == 0);
    if (!look) return std::nullopt;
    const Result<std::string> profile = headset.interaction_profile();
    if (!profile) return std::nullopt;  // a lost runtime: the session ends on its own
    channels_.interaction_profile = *profile;
    std::optional<std::string> message = headset::cannot_answer_message(channels_);
    if (message == cannot_answer_) return std::nullopt;
    const bool cleared = cannot_answer_.has_value() && !message;
    cannot_answer_ = std::move(message);
    if (cleared) return "controller bound: " + channels_.interaction_profile;
    return cannot_answer_;
}

}  // namespace monoplane::app
