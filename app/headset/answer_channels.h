// Whether the participant can answer at all: a session needs at least one way to switch and
// confirm. The headset's controller counts once the runtime bound an interaction profile to it
// (OpenXrHeadset::interaction_profile(), known after the running session's first xrSyncActions);
// [responses] keys count from the start (study/protocol_responses.h), and so does a simulated
// observer. Many lab set-ups (Monado's simulated HMD among them) bind no controller: without keys
// such a session would wait on its first page forever, so the experimenter window and the
// launcher say so at once. Pure; any time.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace monoplane::headset {

// What the experimenter reads in the window (and on stderr) when nobody can answer.
inline constexpr std::string_view kNoControllerMessage =
    "no controller bound: the participant cannot answer; connect one or enable keys";

// Syncs of a focused session after which a profile still unbound counts as none: runtimes bind
// in xrSyncActions (the spec lets them take a few), simxr and Monado in the first.
inline constexpr int kSyncsBeforeUnbound = 3;

struct AnswerChannels {
    // The runtime's current interaction profile ("" while none is bound), and how many
    // xrSyncActions calls of the focused session have passed; before kSyncsBeforeUnbound the
    // controller is not judged yet.
    std::string interaction_profile;
    int focused_syncs = 0;
    bool keys = false;      // [responses] keys (from the window or a device) are enabled
    bool observer = false;  // a simulated observer answers for the participant
};

// Whether the controller is known to be unbound: enough syncs and no profile.
bool controller_unbound(const AnswerChannels& channels);

// kNoControllerMessage when the controller is unbound and neither keys nor an observer answer;
// none otherwise (also while it is too early to tell).
std::optional<std::string> cannot_answer_message(const AnswerChannels& channels);

}  // namespace monoplane::headset
