#include "study/staircase_estimates.h"

#include <algorithm>

#include "study/protocol.h"
#include "study/staircases.h"

namespace monoplane::study {
namespace {

// The session's decided adaptive trials in trial order.
std::vector<const TrialRecord*> decided_adaptive(const SessionInfo& session,
                                                 const std::vector<TrialRecord>& trials) {
    std::vector<const TrialRecord*> decided;
    for (const TrialRecord& r : trials) {
        if (r.session_id == session.id && r.decided && r.trial.adaptive) decided.push_back(&r);
    }
    std::ranges::sort(decided, {}, [](const TrialRecord* r) { return r->trial.index; });
    return decided;
}

}  // namespace

// The session's staircases rebuilt from its stored protocol text, each decided adaptive trial
// recorded in trial order, `after(trial, staircases)` called after each and `at_end(staircases)`
// once after the last.
template <class After, class AtEnd>
Result<void> replay(const SessionInfo& session, const std::vector<TrialRecord>& trials, After after,
                    AtEnd at_end) {
    if (session.procedure != Procedure::Staircase) return Ok{};
    const std::string name = "session " + std::to_string(session.id) + "'s protocol";
    Result<Protocol> protocol = parse_protocol(session.protocol_text, name);
    MONOPLANE_TRY(protocol);
    if (protocol->procedure != Procedure::Staircase) {
        return Error{name + " is not a staircase protocol, but the session is a staircase's"};
    }
    Staircases staircases(*protocol);
    for (const TrialRecord* r : decided_adaptive(session, trials)) {
        staircases.record(r->trial, r->outcome);
        after(r->trial, staircases);
    }
    at_end(staircases);
    return Ok{};
}

Result<std::map<int, ThresholdEstimate>> replay_staircase_estimates(
    const SessionInfo& session, const std::vector<TrialRecord>& trials) {
    std::map<int, ThresholdEstimate> estimates;
    MONOPLANE_TRY(replay(
        session, trials,
        [&](const ScheduledTrial& trial, const Staircases& staircases) {
            estimates[trial.index] = staircases.estimate(trial.scene);
        },
        [](const Staircases&) {}));
    return estimates;
}

Result<std::map<std::string, ThresholdEstimate>> final_staircase_estimates(
    const SessionInfo& session, const std::vector<TrialRecord>& trials) {
    // Each scene's estimate once, after its last decision (QUEST+'s estimate marginalises the
    // whole posterior: not worth computing after every trial here).
    std::map<std::string, ThresholdEstimate> last;
    MONOPLANE_TRY(replay(
        session, trials,
        [&](const ScheduledTrial& trial, const Staircases&) { last[trial.scene] = {}; },
        [&](const Staircases& staircases) {
            for (auto& [scene, estimate] : last) estimate = staircases.estimate(scene);
        }));
    return last;
}

}  // namespace monoplane::study
