// What `study run` (and the launcher) decide before a session's first row is written: the
// participant's session number, their number in the study (the Latin-square row), their
// variables, the seed and the schedule. Every rule about starting a session lives here, so a
// session started from the command line and one started from the launcher are the same.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/participant_code.h"  // check_participant_code, which plan_session applies
#include "study/protocol.h"
#include "study/request_names.h"
#include "study/schedule.h"
#include "study/study_store.h"

namespace monoplane::study {

struct SessionRequest {
    std::string participant_code;
    std::optional<int> session_number;      // default: the participant's next
    std::optional<int> participant_number;  // 1-based, as people count
    std::vector<std::string> variables;     // NAME=VALUE, as given
    std::uint64_t seed = 0;
    StartDecisions decisions;  // --abandon, --protocol-changed
};

// A session ready to begin: begin_session(info, schedule) with info's runtime and device set.
struct SessionStart {
    SessionInfo info;
    Schedule schedule;
    bool new_participant = true;
};

// Checks a request against the protocol and what the database holds (`store` may be null for a
// database that does not exist yet: every participant is new) and plans the session. All
// problems are reported at once, one per line: a participant code that is not 1-64 of
// [A-Za-z0-9_-]; a session number that exists ("use study resume ...") or skips ahead, or is
// beyond the protocol's `sessions`; a participant number below 1, taken by another participant,
// or different from the one a returning participant has; variables (check_variables: unknown,
// out of range, not a choice, required but missing) for a new participant, and for a returning
// one any value that differs from the recorded one; an earlier session of theirs that is running
// or interrupted, or a change of design without a reason (admit_session). The messages name the
// request's inputs as `names` says them. Writes nothing. Any time.
Result<SessionStart> plan_session(const StudyStore* store, const Protocol& protocol,
                                  const SessionRequest& request,
                                  const RequestNames& names = study_request_names());

}  // namespace monoplane::study
