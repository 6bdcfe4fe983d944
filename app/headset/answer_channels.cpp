#include "app/headset/answer_channels.h"

namespace monoplane::headset {

bool controller_unbound(const AnswerChannels& channels) {
    return channels.focused_syncs >= kSyncsBeforeUnbound && channels.interaction_profile.empty();
}

std::optional<std::string> cannot_answer_message(const AnswerChannels& channels) {
    if (!controller_unbound(channels) || channels.keys || channels.observer) return std::nullopt;
    return std::string(kNoControllerMessage);
}

}  // namespace monoplane::headset
