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

Result<std::map<int, ThresholdEstimate>> replay_staircase_estimates(
    const SessionInfo& session, const std::vector<TrialRecord>& trials) {
    std::map<int, ThresholdEstimate> estimates;
    if (session.procedure != Procedure::Staircase) return estimates;
    const std::string name = "session " + std::to_string(session.id) + "'s protocol";
    Result<Protocol> protocol = parse_protocol(session.protocol_text, name);
    if (!protocol) return protocol.error();
    if (protocol->procedure != Procedure::Staircase) {
        return Error{name + " is not a staircase protocol, but the session is a staircase's"};
    }
    Staircases staircases(*protocol);
    for (const TrialRecord* r : decided_adaptive(session, trials)) {
        staircases.record(r->trial, r->outcome);
        estimates[r->trial.index] = staircases.estimate(r->trial.scene);
    }
    return estimates;
}

Result<std::map<std::string, ThresholdEstimate>> final_staircase_estimates(
    const SessionInfo& session, const std::vector<TrialRecord>& trials) {
    Result<std::map<int, ThresholdEstimate>> after = replay_staircase_estimates(session, trials);
    if (!after) return after.error();
    std::map<std::string, ThresholdEstimate> last;
    for (const TrialRecord* r : decided_adaptive(session, trials)) {
        last[r->trial.scene] = after->at(r->trial.index);
    }
    return last;
}

}  // namespace monoplane::study
