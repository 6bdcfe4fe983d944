// Private to the study store: participants in the database. Each is a pseudonymous code with a
// row id, an order in the file, a number in the whole study (the Latin-square row) and the
// variables recorded at their first session, which never change.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/participant_variables.h"
#include "study/schedule.h"
#include "study/store_sqlite.h"
#include "study/study_store.h"

namespace monoplane::study {

// What the database knows of a participant, with the row id the session rows refer to.
struct StoredParticipant {
    std::int64_t id = 0;
    ParticipantRecord record;
};

// "session 3", as messages name a session of a participant.
inline std::string numbered_session(int session_number) {
    return "session " + std::to_string(session_number);
}

// The participant's variables in the order begin_session wrote them (the protocol's declaration
// order). Any time the connection is open.
Result<std::vector<VariableValue>> read_participant_variables(const sqlite::Connection& db,
                                                              std::int64_t participant_id);

// The participant with `code` and their sessions, or none. Any time the connection is open.
Result<std::optional<StoredParticipant>> find_participant(const sqlite::Connection& db,
                                                          const std::string& code);

// The participant row a session belongs to: the known one, if the session is their next and
// agrees with what their first recorded, or a new one with a study-wide number no one else in the
// file has, and its variables. Inside begin_session's transaction.
Result<std::int64_t> admit_participant(const sqlite::Connection& db, const SessionInfo& info,
                                       const Schedule& schedule);

}  // namespace monoplane::study
