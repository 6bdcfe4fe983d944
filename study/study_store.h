// The study database (docs/data.md): SQLite in WAL mode, schema version with migrations in
// code, every event committed before the next frame starts, unique pseudonymous participant
// codes, sessions with status, resumable. Nothing is written at the end only: a killed process
// loses no confirmed decision and no switch.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/result.h"
#include "study/frame_record.h"
#include "study/participant_variables.h"
#include "study/protocol.h"
#include "study/scene_files.h"
#include "study/session_admission.h"
#include "study/schedule.h"
#include "study/session_log.h"
#include "study/session_note.h"
#include "study/trial_events.h"
#include "study/trial_state_machine.h"

namespace monoplane::study {

// Something the software recorded about a session for whoever reviews its data, e.g. that a
// resume went ahead with changed scene files (`study resume --accept-changed-scenes`).
struct SessionInfo {
    std::int64_t id = 0;
    // Globally unique, made when the session starts (begin_session makes a random version-4
    // UUID when empty), so the session is known as one wherever its rows are copied. Sessions
    // of schema versions before 8 carry one derived from what identifies them.
    std::string session_uuid;
    std::string participant_code;
    int participant_index = 0;  // 0-based order of the participant's first session in this file
    // 0-based: the participant's number in the whole study, which picks the Latin square row
    // (`--participant-number`); by default participant_index. Fixed at the first session: a
    // later session's begin_session takes the stored one. Before schema 7: participant_index.
    int participant_number = 0;
    int session_number = 1;  // 1-based: the participant's session (`--session N`)
    // The participant's variables (protocol [[variables]]), in declaration order: begin_session
    // stores them with a new participant; a later session passes none (or the same values).
    std::vector<VariableValue> variables;
    std::string ended_utc;  // read back; empty while the session has not ended
    std::string protocol_name;
    std::uint64_t protocol_hash = 0;
    std::string protocol_text;
    std::uint64_t seed = 0;
    std::string software_version;
    std::string hmd;
    std::string runtime;  // "none", "simulated", or the OpenXR runtime's name
    std::string device;
    std::string observer;     // simulated observer's name, "" for a person
    std::string started_utc;  // ISO 8601 UTC; empty: begin_session stamps the current time
    SessionStatus status = SessionStatus::Running;
    // What the session rendered with: the protocol's [render] table with the command line's
    // overrides. Sessions from schema version 1 read as none / off / "" (detail not recorded).
    RenderSettings render;
    // Every file each imported (glTF) scene was read from when the session began, with its size
    // and SHA-256: begin_session requires the record of each such scene's own file (file 0).
    // Empty for sessions of built-in scenes only (and all sessions before schema version 3).
    std::vector<SceneFileRecord> scene_files;
    // Read back by session(); begin_session ignores them (add_session_note adds one).
    std::vector<SessionNote> notes;
    // Read back by session(); begin_session records the procedure its schedule was made for
    // (staircase when it has adaptive trials). Sessions before schema version 5: constant.
    Procedure procedure = Procedure::Constant;
    // begin_session only: the experimenter's decisions at the start (an interrupted session
    // to abandon, the reason for a change of design), judged by admit_session.
    StartDecisions decisions;
    // Read back by session(): the session's session_abandoned, protocol_changed and
    // protocol_text_changed events, in order, with their reasons (schema 8; none before).
    std::vector<TrialEvent> recorded_decisions;
};

// One row of the export: a trial with its outcome (docs/data.md).
struct TrialRecord {
    std::int64_t session_id = 0;
    std::string participant_code;
    int session_number = 1;  // the participant's session, 1-based
    ScheduledTrial trial;    // trial.repetition: which showing of its condition
    bool decided = false;
    TrialOutcome outcome;
};

// One recorded Likert answer (record_answer).
struct QuestionnaireAnswer {
    int item = 0;
    std::string text;
    int answer = 0;
};

// One line of the roster (`study list`): a session and where it stands.
struct RosterRow {
    std::string participant_code;
    int participant_number = 0;
    int session_number = 1;
    std::int64_t session_id = 0;
    SessionStatus status = SessionStatus::Running;
    int trials_decided = 0;  // data trials decided
    int trials_planned = 0;  // data trials in the schedule (a staircase's: its most)
    std::string started_utc;
    std::string ended_utc;  // empty while not ended
    std::string device;
    std::string runtime;
    std::uint64_t protocol_hash = 0;
    std::string protocol_name;
    std::string session_uuid;
    // The reason given when the session was abandoned (`study run --abandon`), or none.
    std::optional<std::string> abandoned_reason;
    // Its frames hold eye gaze samples (valid or not): personal data (docs/data.md, "Privacy").
    bool gaze = false;
};

// The participant as the database knows them (for --session's default, the launcher's form and
// `study note`).
struct ParticipantRecord {
    std::string code;
    int participant_index = 0;
    int participant_number = 0;
    std::vector<VariableValue> variables;
    std::vector<std::pair<int, std::int64_t>> sessions;  // (session number, session id), in order
    int next_session_number() const { return static_cast<int>(sessions.size()) + 1; }
};

struct StoreOptions {
    // How long a call waits for another connection's lock before it fails with an error that
    // names the file.
    int busy_timeout_ms = 2000;
    // Test hook: when > 0, the database may not grow beyond this many pages (SQLite clamps it to
    // the current size), so writes fail as on a full disk. 0: no limit.
    std::int64_t max_page_count = 0;
};

class StudyStore final : public SessionLog {
  public:
    // Three ways to open a study database, one per kind of command (docs/data.md, "Which
    // commands write"). Each refuses, with one line naming the file and nothing written: a
    // 0-byte, truncated or non-SQLite file (study_file_check.h), another program's SQLite
    // database, a schema newer than this build knows, a damaged page (quick_check), a locked
    // file (after StoreOptions::busy_timeout_ms).
    //
    // `study run`, the launcher's Create: opens or creates the database, creating it readable
    // by its owner only (0600); a new file that fails to open is removed again. An older schema
    // is migrated in place after a copy of the file is kept (schema_backup()). Refuses a file
    // the user may not write.
    static Result<std::unique_ptr<StudyStore>> open(const std::filesystem::path& path);
    static Result<std::unique_ptr<StudyStore>> open(const std::filesystem::path& path,
                                                    const StoreOptions& options);
    // `study resume`, `study note`, `study migrate`: as open(), but a missing file or an empty
    // SQLite file is refused rather than made a study.
    static Result<std::unique_ptr<StudyStore>> open_existing(const std::filesystem::path& path,
                                                             const StoreOptions& options = {});
    // `study list`, `study export`, `analyze`, the launcher's roster: reads a private snapshot
    // of the file (store_snapshot.h), so not one byte of it, its -wal or its -shm changes, a
    // file of mode 0444 or on a read-only mount reads as any other, and an older schema is read
    // as it is (migrated in the copy only). Every write through this store fails.
    static Result<std::unique_ptr<StudyStore>> open_read_only(const std::filesystem::path& path,
                                                              const StoreOptions& options = {});
    ~StudyStore();

    // The schema version the file had when opened (0: a new file), before any migration.
    int found_schema_version() const;
    // The copy this open kept before migrating the file's older schema (FILE.schema<N>.bak),
    // or none.
    const std::optional<std::filesystem::path>& schema_backup() const;
    // Opened with open_read_only.
    bool read_only() const;

    static constexpr int kSchemaVersion = 10;

    // The file this store was opened from (session holds lie beside it).
    const std::filesystem::path& path() const;

    // Starts a session: info.session_number must be the participant's next (1 for a new code)
    // and the schedule's: one that exists is refused (use resume), one that skips ahead too. A
    // new participant is stored with the participant number the schedule was made for (its
    // Latin-square row; info.participant_number must be the same, or 0 for "the schedule's"),
    // refused when another participant of this file has it, and with info.variables; a known
    // one keeps theirs (the schedule must be made for their number; info.variables must be
    // empty or equal).
    // Stores the protocol text and hash, the seed, the whole schedule and the scene files'
    // digests (info.scene_files, checked by validate_scene_files: each imported scene of the
    // schedule needs its record) in one transaction, before the first trial. A staircase's
    // adaptive trials are stored as plans without a mono plane (record_stimulus adds it).
    // Judges info.decisions and the participant's earlier sessions with admit_session inside the
    // transaction (so of two processes starting the same participant at once one is refused),
    // then ends the session info.decisions abandons (status aborted, a session_abandoned event
    // with the reason) and records a change of protocol as an event of the new session.
    // before_commit (optional): called with the new session's id inside the transaction, before
    // it commits; its error rolls the session back. `study run` takes the session's hold there,
    // so no other process can see the session running without a holder.
    Result<std::int64_t> begin_session(
        const SessionInfo& info, const Schedule& schedule,
        const std::function<Result<void>(std::int64_t)>& before_commit = {});

    // The schedule stored for a session (adaptive trials not started yet with a NaN mono
    // plane), and where to continue: the first undecided trial or unstarted slot.
    Result<Schedule> load_schedule(std::int64_t session_id) const;
    Result<int> first_undecided_trial(std::int64_t session_id) const;
    Result<SessionInfo> session(std::int64_t session_id) const;
    // The latest session that is not completed (for `study resume` without --session).
    Result<std::optional<std::int64_t>> latest_unfinished_session() const;
    // The number of participants so far: the next participant's index (and default number).
    Result<int> participant_count() const;
    // The participant with this code, or none.
    Result<std::optional<ParticipantRecord>> participant(const std::string& code) const;
    // The id of the participant's session `session_number`, or none.
    Result<std::optional<std::int64_t>> find_session(const std::string& code,
                                                     int session_number) const;
    // Every session, by participant code and session number (`study list`).
    Result<std::vector<RosterRow>> roster() const;
    // The participant's sessions in this file, by session number, with who runs each unfinished
    // one now (session holds beside the file): what admit_session judges.
    Result<std::vector<EarlierSession>> earlier_sessions(const std::string& code) const;

    // The frame log: rows are queued in memory and written in the transaction of the next
    // durable write below (or of flush_frames), so every committed event has every frame
    // queued before it committed with it. A frame's GPU time, known frames later, is queued
    // the same way and fills the stored row.
    void queue_frame(std::int64_t session_id, const FrameRecord& frame);
    void queue_frame_gpu_ms(std::int64_t session_id, std::int64_t frame, double gpu_ms,
                            std::optional<double> mono_plane = std::nullopt);
    Result<void> flush_frames();
    Result<std::vector<FrameRecord>> frames(std::int64_t session_id) const;
    // One past the highest frame number the session's frame log or events use (0 for none):
    // where a resumed run's frames continue, so no two runs share a number.
    Result<std::int64_t> next_frame_number(std::int64_t session_id) const;

    // Durable when it returns (one transaction each).
    Result<void> append_event(std::int64_t session_id, const TrialEvent& event) override;
    Result<void> record_outcome(std::int64_t session_id, int trial_index,
                                const TrialOutcome& outcome) override;
    Result<void> set_status(std::int64_t session_id, SessionStatus status) override;
    Result<void> record_answer(std::int64_t session_id, int item, const std::string& text,
                               int answer) override;
    // The started adaptive trial becomes a row of the trials table with its m.
    Result<void> record_stimulus(std::int64_t session_id, const ScheduledTrial& trial) override;
    // Appends a note to a session (stamped with the current UTC time unless note.noted_utc is
    // set), durable when it returns. Refuses an empty or blank note, one over 10,000 characters
    // and an unknown session.
    Result<void> add_note(std::int64_t session_id, const SessionNote& note);
    // add_note's refusals without writing (also through a read-only store).
    Result<void> check_note(std::int64_t session_id, const SessionNote& note) const;
    // A note from the software (NoteSource::Software, no session time).
    Result<void> add_session_note(std::int64_t session_id, const std::string& text);
    // A run of the session begins (SessionLog::begin_run): its row in session_runs, stamped with
    // this process's host and pid and the UTC time, and its run_started event, in one
    // transaction with the queued frames. Once per process that runs the session, before its
    // first event (LiveSession::begin_run). Refuses an unknown session.
    Result<RunStart> begin_run(std::int64_t session_id, const RunInfo& info) override;
    // The press into table `presses` (schema 9) with the queued frames, durable on return
    // (SessionLog::record_press; study/press_store.cpp). Refuses an unknown session.
    Result<void> record_press(std::int64_t session_id, const ResponsePress& press) override;
    // The session's presses in the order logged (none for sessions before schema 9). Any time.
    Result<std::vector<ResponsePress>> presses(std::int64_t session_id) const;
    // The session's runs (table session_runs), by run number. Sessions of schema 7 and before
    // have none for their runs then. Any time.
    Result<std::vector<RunRecord>> runs(std::int64_t session_id) const;

    // The trials shown or being shown (a staircase's slots once started), by session and index.
    Result<std::vector<TrialRecord>> trials(std::optional<std::int64_t> session_id = {}) const;
    Result<std::vector<TrialEvent>> events(std::int64_t session_id) const;
    // The questionnaire answers of a session, by item (the latest answer to each item).
    Result<std::vector<QuestionnaireAnswer>> answers(std::int64_t session_id) const;

    // The store's state, defined in store_impl.h for the store's own files only (named here so
    // that the file that opens stores can build one).
    struct Impl;

  private:
    explicit StudyStore(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace monoplane::study
