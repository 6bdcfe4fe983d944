#include "study/response_press.h"

#include <array>

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 3> kSources = {"controller", "keyboard", "device"};
constexpr std::array<std::string_view, 3> kActions = {"switch", "confirm", "pause"};

template <class E, std::size_t N>
std::optional<E> parse(std::string_view name, const std::array<std::string_view, N>& names) {
    for (std::size_t i = 0; i < N; ++i)
        if (names[i] == name) return static_cast<E>(i);
    return std::nullopt;
}

}  // namespace

std::string_view press_source_name(PressSource source) {
    return kSources[static_cast<std::size_t>(source)];
}

std::optional<PressSource> parse_press_source(std::string_view name) {
    return parse<PressSource>(name, kSources);
}

std::string_view press_action_name(PressAction action) {
    return kActions[static_cast<std::size_t>(action)];
}

std::optional<PressAction> parse_press_action(std::string_view name) {
    return parse<PressAction>(name, kActions);
}

Result<void> check_press(const ResponsePress& press) {
    if ((press.source == PressSource::Controller) != press.key.empty()) {
        return Error{"a press of a key names its key, and one of the controller none"};
    }
    if (press.screen.empty()) return Error{"a press names the screen it was made on"};
    return Ok{};
}

}  // namespace monoplane::study
