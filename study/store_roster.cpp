// StudyStore's views over sessions: the roster of every session in the file (`study list`, with
// which sessions hold eye gaze) and a participant's earlier sessions with who holds them (the rule
// of one live session, session_admission.h). Both count a session's trials the same way.
#include "study/study_store.h"

#include <string>

#include "study/session_hold.h"
#include "study/store_impl.h"
#include "study/store_values.h"

namespace monoplane::study {
namespace {

using sqlite::Connection;
using sqlite::Statement;

// A session's data trials decided, and planned (a staircase's slots not started yet counted):
// what the roster and the rule of one live session (kEarlierSessionsQuery) show.
constexpr std::string_view kTrialCounts =
    "(SELECT count(*) FROM trials t WHERE t.session_id = s.id AND t.practice = 0 AND "
    "t.decided = 1), "
    "(SELECT count(*) FROM trials t WHERE t.session_id = s.id AND t.practice = 0) + "
    "(SELECT count(*) FROM planned_trials pt WHERE pt.session_id = s.id AND NOT EXISTS "
    "(SELECT 1 FROM trials t WHERE t.session_id = pt.session_id AND "
    "t.trial_index = pt.trial_index))";

// Whether a session's frames hold gaze samples (personal data, docs/data.md): a valid or invalid
// sample makes gaze_valid non-NULL. The partial index frames_with_gaze holds only such rows, so a
// session without gaze costs one index probe, not a pass over its frame log.
constexpr std::string_view kHoldsGaze =
    "EXISTS (SELECT 1 FROM frames f WHERE f.session_id = s.id AND f.gaze_valid IS NOT NULL)";

const std::string kRosterQuery =
    "SELECT p.code, p.participant_number, s.session_number, s.id, s.status, " +
    std::string(kTrialCounts) +
    ", s.started_utc, s.ended_utc, s.device, s.runtime, s.protocol_hash, s.protocol_name, "
    "s.session_uuid, (SELECT e.detail FROM events e WHERE e.session_id = s.id AND "
    "e.kind = 'session_abandoned' ORDER BY e.id DESC LIMIT 1), " +
    std::string(kHoldsGaze) +
    " FROM sessions s JOIN participants p ON p.id = s.participant_id "
    "ORDER BY p.code, s.session_number";

// A participant's sessions with the counts the roster shows (kRosterQuery's planned count).
const std::string kEarlierSessionsQuery =
    "SELECT s.id, s.session_number, s.status, EXISTS (SELECT 1 FROM events e WHERE "
    "e.session_id = s.id AND e.kind = 'session_abandoned'), " +
    std::string(kTrialCounts) +
    ", s.protocol_text, s.protocol_hash "
    "FROM sessions s JOIN participants p ON p.id = s.participant_id WHERE p.code = ? "
    "ORDER BY s.session_number";

// Where a query's row has a session's id, status and protocol hash.
struct SessionColumns {
    int id = 0;
    int status = 0;
    int hash = 0;
};

struct StatusAndHash {
    SessionStatus status = SessionStatus::Running;
    std::uint64_t hash = 0;
};

// The row's status and protocol hash, or an error naming the session whose row holds bad ones.
Result<StatusAndHash> status_and_hash(const Connection& db, const Statement& s,
                                      SessionColumns columns) {
    const std::optional<SessionStatus> status = parse_session_status(s.text(columns.status));
    const std::optional<std::uint64_t> hash = parse_stored_u64(s.text(columns.hash), 16);
    if (!status || !hash)
        return Error{"study database '" + db.path() + "' holds a bad status or hash in session " +
                     std::to_string(s.int64(columns.id))};
    return StatusAndHash{*status, *hash};
}

}  // namespace

Result<std::vector<RosterRow>> StudyStore::roster() const {
    const Connection& db = impl_->db;
    Result<Statement> stmt = Statement::prepare(db, kRosterQuery);
    MONOPLANE_TRY(stmt);
    std::vector<RosterRow> rows;
    for (;;) {
        Result<bool> row = stmt.value().step("reading the roster");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        Result<StatusAndHash> checked = status_and_hash(db, s, {.id = 3, .status = 4, .hash = 11});
        MONOPLANE_TRY(checked);
        const std::optional<SessionStatus> status = checked->status;
        const std::optional<std::uint64_t> hash = checked->hash;
        rows.push_back(RosterRow{.participant_code = s.text(0),
                                 .participant_number = s.int32(1),
                                 .session_number = s.int32(2),
                                 .session_id = s.int64(3),
                                 .status = *status,
                                 .trials_decided = s.int32(5),
                                 .trials_planned = s.int32(6),
                                 .started_utc = s.text(7),
                                 .ended_utc = s.is_null(8) ? "" : s.text(8),
                                 .device = s.text(9),
                                 .runtime = s.text(10),
                                 .protocol_hash = *hash,
                                 .protocol_name = s.text(12),
                                 .session_uuid = s.text(13),
                                 .abandoned_reason = s.is_null(14)
                                                         ? std::nullopt
                                                         : std::optional<std::string>(s.text(14)),
                                 .gaze = s.int64(15) != 0});
    }
    return rows;
}

Result<std::vector<EarlierSession>> StudyStore::earlier_sessions(const std::string& code) const {
    const Connection& db = impl_->db;
    Result<Statement> stmt = Statement::prepare(db, kEarlierSessionsQuery);
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, code);
    std::vector<EarlierSession> sessions;
    for (;;) {
        Result<bool> row = stmt.value().step("reading participant '" + code + "''s sessions");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        Result<StatusAndHash> checked = status_and_hash(db, s, {.id = 0, .status = 2, .hash = 7});
        MONOPLANE_TRY(checked);
        const std::optional<SessionStatus> status = checked->status;
        const std::optional<std::uint64_t> hash = checked->hash;
        EarlierSession earlier{.id = s.int64(0),
                               .session_number = s.int32(1),
                               .status = *status,
                               .abandoned = s.int64(3) != 0,
                               .holder = std::nullopt,
                               .trials_decided = s.int32(4),
                               .trials_planned = s.int32(5),
                               .protocol_text = s.text(6),
                               .protocol_hash = *hash};
        if (*status == SessionStatus::Running || *status == SessionStatus::Paused) {
            Result<std::optional<SessionHolder>> holder =
                SessionHold::holder(impl_->file, earlier.id);
            MONOPLANE_TRY(holder);
            earlier.holder = *holder;
        }
        sessions.push_back(std::move(earlier));
    }
    return sessions;
}

}  // namespace monoplane::study
