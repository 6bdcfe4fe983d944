// The analysis's input: plain rows, one per trial and one per questionnaire answer, whatever file
// they came from. The app converts a study database into these rows; read_export_csv() reads the
// CSV of `monoplane study export`. Keeping the rows plain keeps analysis/ free of the study
// library, SQLite and the renderer (docs/architecture.md).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/result.h"

namespace monoplane::analysis {

struct TrialRow {
    std::string source;  // the file it came from (database or CSV path)
    std::int64_t session_id = 0;
    // The session's globally unique id (the export's `session_uuid`): the same session found in
    // two inputs (a copy, a backup) has the same one. "" when the input does not record it (an
    // export of a monoplane from before the column).
    std::string session_uuid;
    std::string participant;  // pseudonymous code: the cluster for repeated measures
    int session_number = 1;   // the participant's session, 1-based (the export's `session`)
    std::string protocol;
    int trial_index = 0;
    // Which showing of its scene x distance condition (protocol `repetitions`), 1-based: every
    // repetition is a trial of its own in every statistic.
    int repetition = 1;
    bool practice = false;
    int block = -1;  // -1 for practice trials
    std::string scene;
    double mono_plane = 0.0;  // metres
    std::string label1_mode, label2_mode;
    std::string reference_mode;  // the protocol's first alternative (e.g. "stereo")
    std::string test_mode;       // the other one (e.g. "hybrid")
    bool decided = false;
    bool valid = false;
    std::string chosen_mode;  // "" if undecided
    bool chose_test = false;  // chosen_mode == test_mode
    int switches = 0;
    double decision_time_s = 0.0;
    std::string first_scene;  // scene of the session's first data block (order effects)
    // Headset sessions' frame log (database input only; 0 without one): frames the trial showed
    // and how many of them missed their display slot; the protocol's threshold for flagging.
    int frames_shown = 0;
    int frames_missed = 0;
    double missed_frame_threshold = 0.05;
    // Eye gaze, where the session recorded it (docs/gaze.md); none otherwise. Hybrid's error at
    // the gaze point, arcmin, averaged over the frames that showed the test alternative (the
    // stimulus where the participant looked), and the share of the trial's gaze points that lay
    // beyond the mono plane.
    std::optional<double> gaze_error_test_arcmin;
    std::optional<double> gaze_share_beyond_m;
    std::optional<int> gaze_fixations;  // I-DT fixations over the frames showing a label
};

// One valid gaze sample of a frame that showed a trial's scene (database input only), for the
// report's gaze density over each scene's left-eye image: the head relative to the seat and the
// gaze in the head's frame, and the depth of the point the gaze met (none: the sky).
struct GazeSampleRow {
    std::string source = {};  // the database it came from, and its session there
    std::int64_t session_id = 0;
    std::string participant;
    std::string scene;
    double mono_plane = 0.0;                       // the trial's m
    std::array<double, 7> head{};                  // x, y, z, qw, qx, qy, qz
    std::array<double, 3> direction{0, 0, -1};     // unit, head frame, -z ahead
    std::optional<double> depth_m = std::nullopt;  // in front of the eyes' plane
};

struct AnswerRow {
    std::string source;
    std::int64_t session_id = 0;
    std::string participant;
    int item = 0;  // 0-based position in the protocol's questionnaire
    std::string text;
    int answer = 0;  // 1 .. scale_points
    int scale_points = 7;
};

// A note on a session (the experimenter's window, `monoplane study note`, or the software).
struct NoteRow {
    std::string noted_utc;  // ISO 8601 UTC
    std::optional<int> trial_index;
    std::string written_by;  // "window", "command" or "software"
    std::string text;        // as typed
};

// What an input knows about a session beyond its trial rows: who and which of their sessions,
// the Latin-square row selector, the participant's variables and the notes. Readers fill what
// their input holds (a CSV export has no notes and does not say how its protocol orders scenes).
struct SessionRow {
    std::string source;
    std::int64_t session_id = 0;
    std::string participant;
    int session_number = 1;
    // The participant's position in the whole study, which picked the Latin-square row of their
    // block order, 0-based (`study run --participant-number N` and the export's column count from
    // 1: this is N - 1; exports without it: the participant's index within their database).
    int participant_number = 0;
    std::string protocol;
    std::string session_uuid;  // as TrialRow::session_uuid
    // The protocol version the session ran: its hash as the export writes it ("fnv1a64:" and 16
    // hex digits; "" when the input does not record it) and its whole text (databases only: a
    // CSV export does not hold it, so its design cannot be compared).
    std::string protocol_hash;
    std::string protocol_text;
    // The monoplane that ran the session, as the database and the export record it ("monoplane
    // 0.1.0 (806fb8622b5b)"); "unknown" where the input does not say (an older export).
    std::string software_version;
    std::string started_utc;  // "" when unknown (CSV)
    // The protocol's `first_scene`: "latin-square", "random" or "fixed"; "" when the input does
    // not say (a CSV export).
    std::string first_scene_order;
    int scenes = 0;  // scenes in the protocol (CSV: distinct scenes of the session's data trials)
    // Rows of the protocol's balanced Latin square; 0 when not known or not a Latin square. The
    // reader of the input fills it (analysis/ does not know the schedule's design).
    int latin_square_rows = 0;
    // The participant's variables (protocol [[variables]]) as (name, value), in declaration
    // order; variables not given are left out.
    std::vector<std::pair<std::string, std::string>> variables;
    // The variables' types where the input records them (a database: the protocol's
    // declarations; a CSV export does not): true for integer and number, false for choice and
    // text. summary.json writes a variable as a JSON number when no session records another type
    // for it and every value is a number.
    std::map<std::string, bool> variable_is_number;
    std::vector<NoteRow> notes;
};

// How participant codes found in more than one input are joined (`analyze --codes`).
enum class SharedCodes {
    Refuse,       // a shared code is an error (the default): no silent merge
    SamePerson,   // one person: their sessions from every input form one cluster
    PerDatabase,  // each input's codes are its own: every code gets its file's stem as prefix
};

// One protocol version the sessions ran, as list_protocol_versions() (protocol_versions.h) finds
// it: versions are told apart by hash, their designs (scenes, distances, alternatives,
// procedure, ...; not comments or wording) compared where the inputs hold the text.
struct ProtocolVersion {
    std::string name;
    std::string hash;  // "" when the input did not record it (an older CSV export)
    int sessions = 0;
    std::vector<std::string> sources = {};  // the files its sessions came from, in reading order
    // 1, 2, ...: versions with the same number share a design (design 1 is the first version's);
    // 0: not known (no input holds the protocol's text: CSV exports only, or a text that no
    // longer reads).
    int design = 0;
    // How the design differs from design 1, one line per field ("mono_planes: 3, 8 -> 2, 6");
    // empty for design 1 and for a design not known.
    std::vector<std::string> design_differences = {};
};

// A session that more than one input holds (the same session_uuid), counted once on request
// (drop_duplicate_sessions, duplicate_sessions.h): the copies were identical.
struct DroppedCopy {
    std::string session_uuid;
    std::string participant;  // the code as the inputs hold it (before any --codes prefix)
    int session_number = 1;
    std::string kept;                  // the input whose copy was counted (read first)
    std::vector<std::string> dropped;  // the inputs whose copies were left out
};

struct Dataset {
    std::vector<TrialRow> trials;
    std::vector<AnswerRow> answers;
    std::vector<SessionRow> sessions;  // may be empty (hand-built data): nothing beyond trials
    std::vector<GazeSampleRow> gaze_samples;  // headset sessions that recorded gaze
    std::vector<std::string> sources;         // in the order they were read
    // Set by join_participant_codes(): the rule applied and the codes more than one input held.
    SharedCodes codes = SharedCodes::Refuse;
    std::vector<std::string> shared_codes;
    // Set by the checks of protocol_versions.h: every version the sessions ran, and whether
    // sessions of different (or unknown) designs were pooled because the user asked.
    std::vector<ProtocolVersion> protocol_versions;
    bool pooled_protocols = false;
    // Set by drop_duplicate_sessions(): the sessions several inputs held, counted once.
    std::vector<DroppedCopy> dropped_copies;
};

// Reads the CSV of `monoplane study export --format csv` (columns: study/export.cpp
// export_columns() and docs/data.md). Columns are found by header name, so later versions may
// add columns at the end. Practice and undecided trials are kept (analysable_trials() drops and
// counts them); the export has no questionnaire answers, so `answers` stays empty.
// reference_mode / test_mode / first_scene / chose_test come from derive_session_fields().
// Sessions: with a `session_id` column, `session` is the participant's session number; without
// one, an export that has `repetition` numbers sessions in `session` too (sessions are then told
// apart by participant and number), and an older export has the session id in `session` (one
// session per participant). `sessions` gets one row per session, its variables from the
// `var_<name>` columns, its session_uuid and protocol_hash (when the export has them; the
// protocol's text is not in the export). Text cells that the export guarded against spreadsheet
// formulas (a leading apostrophe before =, +, -, @, tab or CR) come back as typed.
// Errors (a file that cannot be read, a missing column, a malformed field or record) name the
// file, the line and, for a field, the column.
Result<Dataset> read_export_csv(const std::filesystem::path& path);

// A CSV text cell without the apostrophe the export puts before text that begins with =, +, -,
// @, tab or CR after any apostrophes (so that a spreadsheet shows it as text): "'=1+2" -> "=1+2",
// "''=x" -> "'=x"; anything else unchanged.
std::string unguarded_cell(std::string text);

// Appends another source. Sessions stay apart by (source, session_id): two databases may both
// have a session 1. Participants are not kept apart here: join_participant_codes() decides what
// a code that several sources hold means.
void merge(Dataset& into, Dataset from);

// How join_participant_codes' messages name the rules and ask for one. The analysis' own words
// name the rules ("same-person"); `analyze` names its option instead ("--codes same-person") and
// says to run it again.
struct SharedCodesNames {
    std::function<std::string(SharedCodes rule)> rule;
    std::string choose;  // the sentence before the list of the two ways on
};
// "same-person", "per-database"; "... choose one of:".
const SharedCodesNames& analysis_codes_names();

// Applies `rule` to the codes found in more than one source of `data` (trials, answers and
// sessions alike): Refuse fails with a message that names the codes, their files and the two
// ways on (SamePerson, PerDatabase, as `names` says them); SamePerson keeps the codes (one
// person, one cluster); PerDatabase prefixes every code with its source's file stem and "/"
// ("site-a.sqlite" -> "site-a/a1"), and fails when two sources share a stem. Records the rule
// and the shared codes in data.codes and data.shared_codes.
Result<void> join_participant_codes(Dataset& data, SharedCodes rule,
                                    const SharedCodesNames& names = analysis_codes_names());
// "same-person" / "per-database" (the values of `analyze --codes` too); "refuse" for the default.
std::string_view shared_codes_name(SharedCodes rule);

// Fills, per session (source, session_id): first_scene = scene of the session's data trial in
// block 0; reference_mode = the one already set on any of the session's rows (a database
// reader knows the protocol's first alternative), else "stereo" when the session shows it,
// else the alphabetically first mode shown; test_mode = the other mode shown; chose_test =
// decided && chosen_mode == test_mode. Used by both readers. May be called more than once.
void derive_session_fields(std::vector<TrialRow>& trials);

}  // namespace monoplane::analysis
