// Whether a participant's next session may begin, given their earlier sessions in the file: one
// live session per participant, and no silent change of design. plan_session (before anything
// is written, so the launcher's Start says why it is off) and begin_session (again inside its
// write transaction, so two processes starting the same participant at once cannot both pass)
// ask the same function.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/protocol.h"
#include "study/session_hold.h"
#include "study/session_log.h"
#include "study/trial_events.h"

namespace monoplane::study {

// One of the participant's earlier sessions as the rules need it (StudyStore::earlier_sessions).
struct EarlierSession {
    std::int64_t id = 0;
    int session_number = 1;
    SessionStatus status = SessionStatus::Running;
    bool abandoned = false;               // ended with `--abandon`
    std::optional<SessionHolder> holder;  // the process running it now, if any
    int trials_decided = 0;
    int trials_planned = 0;
    std::string protocol_text;
    std::uint64_t protocol_hash = 0;
};

// What the experimenter decided when starting (`study run --abandon N "reason"`,
// `--protocol-changed "reason"`; the launcher's same fields).
struct StartDecisions {
    std::optional<int> abandon_session;  // the participant's interrupted session to end first
    std::string abandon_reason;
    std::string protocol_change_reason;  // empty: none given
};

// What starting the session records besides it.
struct Admission {
    std::optional<std::int64_t> abandon_id;    // ends as abandoned (status aborted + event)
    std::optional<TrialEvent> protocol_event;  // for the new session: changed or text changed
};

// The new session's protocol as stored with it: parsed only when a comparison needs it.
struct ProtocolVersion {
    std::string name;
    std::string text;
    std::uint64_t hash = 0;
};

// Where the messages point the experimenter: the database as given and the participant.
struct AdmissionContext {
    std::string database;
    std::string participant_code;
};

// Refuses, naming the session, while one of the participant's earlier sessions is running in
// a process (which, where, since when) or interrupted (with the resume command and the
// --abandon way out) unless `decisions` abandons exactly that one; refuses --abandon of a
// session that is not interrupted. Refuses a protocol whose design (protocol_design.h) differs
// from an earlier, not abandoned session's unless a reason is given, and a reason when the
// design is the same; records a text-only change. `protocol`: the new session's. Pure; any
// time.
Result<Admission> admit_session(const AdmissionContext& context,
                                const std::vector<EarlierSession>& earlier,
                                const ProtocolVersion& protocol, const StartDecisions& decisions);

}  // namespace monoplane::study
