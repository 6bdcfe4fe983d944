// Export of the study database: one tidy row per trial, identity columns
// first, as CSV or JSON that pandas and R read without options, and the sessions' notes as CSV.
// docs/data.md lists every column with its type and unit.
//
// Every trial of every session is exported, practice trials too, flagged by the `practice`
// column, so an analysis filters them explicitly (and can check them); undecided trials appear
// with NA outcome columns (`decided` false). In CSV, booleans are TRUE / FALSE and NA is the
// unquoted field NA (as R writes them); in JSON they are true / false and null. A CSV text cell
// that begins with =, +, -, @, a tab or a carriage return gets a leading apostrophe, so a
// spreadsheet shows it as text instead of evaluating it (csv_text); JSON keeps text as typed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/adaptive_procedure.h"
#include "study/gaze_summary.h"
#include "study/output_file.h"
#include "study/study_store.h"

namespace monoplane::study {

// Csv and Json: the trials; FramesCsv: the frame and head log of every headset session;
// NotesCsv: the notes of every session; PressesCsv: every press of the participant's controller
// and keys, with its source (study/response_press.h); GazeCsv: every gaze sample of the sessions
// that recorded gaze (study/gaze_export.cpp).
enum class ExportFormat { Csv, Json, FramesCsv, NotesCsv, PressesCsv, GazeCsv };

// "csv", "json", "frames-csv", "notes-csv", "presses-csv" or "gaze-csv", as the CLI's --format
// takes them.
std::string_view export_format_name(ExportFormat format);
Result<ExportFormat> parse_export_format(std::string_view name);

// What an export holds: the trials and the sessions they belong to, keyed by session id.
struct ExportData {
    std::vector<TrialRecord> trials;
    // The trials' sessions; for NotesCsv and PressesCsv every session of the database.
    std::map<std::int64_t, SessionInfo> sessions;
    // The participant variables the sessions' protocols declare, in first-seen declaration order
    // (sessions in id order); variable_columns() adds any a session has a value for.
    std::vector<std::string> variable_names;
    // FramesCsv: every session's frame log; GazeCsv: the frame logs of the sessions holding gaze.
    std::map<std::int64_t, std::vector<FrameRecord>> frames;
    std::map<std::int64_t, std::vector<ResponsePress>> presses;  // PressesCsv only, per session
    // Staircase sessions: each scene's staircase estimate after each decided adaptive trial, by
    // session and trial index (replayed from the stored decisions; study/staircase_estimates.h).
    std::map<std::int64_t, std::map<int, ThresholdEstimate>> staircase_estimates;
    // Csv and Json: the sessions whose frames hold gaze, each trial's gaze by trial index
    // (summarize_trial_gaze); a session that recorded none is absent, its gaze columns NA.
    std::map<std::int64_t, std::map<int, TrialGaze>> trial_gaze;
};

// Reads every trial and its session (and, for FramesCsv, every session's frame log; for GazeCsv
// the frame logs of the sessions holding gaze; for Csv and Json their trials' gaze summaries; for
// NotesCsv only the sessions, every one), the variables the sessions' protocols declare, and
// replays each staircase session's decisions for its estimates; a staircase session whose stored
// protocol text does not parse is an error naming it. May be called while a study writes (WAL
// readers do not block the writer); the export is then a consistent snapshot of some moment per
// query.
Result<ExportData> collect_export(const StudyStore& store, ExportFormat format = ExportFormat::Csv);

// The export's fixed column names, in order (CSV header, JSON keys); one column
// "var_<name>" per participant variable follows them (variable_columns). JSON adds two keys
// after those: "scene_files" (the files the trial's scene was read from, with their SHA-256 and
// size; empty for a built-in scene) and "session_notes" (docs/data.md).
const std::vector<std::string_view>& export_columns();
// "var_<name>" for each of data.variable_names, then for each variable a session has a value
// for that is not among them (sessions in id order, values in declaration order).
std::vector<std::string> variable_columns(const ExportData& data);
// The frame log's columns (frames-csv), in order.
const std::vector<std::string_view>& frame_export_columns();
// The gaze samples' columns (gaze-csv), in order (study/gaze_export.cpp).
const std::vector<std::string_view>& gaze_export_columns();
// The notes' columns (notes-csv), in order.
const std::vector<std::string_view>& notes_export_columns();
// The presses' columns (presses-csv), in order (study/press_export.cpp).
const std::vector<std::string_view>& presses_export_columns();

// How an earlier export of `format` is recognised, for check_output (study/output_file.h): a
// CSV by the start of its header line, the JSON export by its shape (an array of objects whose
// first key is "participant"). Named "<format> export" (e.g. "csv export").
OutputKind export_output_kind(ExportFormat format);

// Pure formatting of collected data.
void write_csv(const ExportData& data, std::ostream& out);
void write_json(const ExportData& data, std::ostream& out);
// One row per logged frame, sessions in id order (study/frame_export.cpp).
void write_frames_csv(const ExportData& data, std::ostream& out);
// One row per logged frame with a gaze sample, valid or not, sessions in id order.
void write_gaze_csv(const ExportData& data, std::ostream& out);
// One row per note, sessions in id order, each session's notes in the order they were noted.
void write_notes_csv(const ExportData& data, std::ostream& out);
// One row per press, sessions in id order, each session's presses in the order logged.
void write_presses_csv(const ExportData& data, std::ostream& out);
// Every session of the database, trials or not (a session may have notes or presses before its
// first trial started): what NotesCsv writes, and what collect_presses adds the presses to.
Result<ExportData> collect_sessions(const StudyStore& store);
// Every session of the database with its presses (what PressesCsv writes).
Result<ExportData> collect_presses(const StudyStore& store);
// Adds the frame logs of data.sessions that hold gaze (what GazeCsv writes), or their trials'
// gaze summaries (what Csv and Json write); sessions are told by the roster's gaze flag, so a
// session without gaze costs no read of its frames (study/gaze_export.cpp).
Result<void> add_gaze_frames(const StudyStore& store, ExportData& data);
Result<void> add_trial_gaze(const StudyStore& store, ExportData& data);

// Collects and writes. The path form first checks `path` and the record of its source beside
// it (`path`.source, study/export_source.h) with check_output's rules (the store's own file is an
// input), collects, refuses an existing export of another study (OtherSource) unless `force`,
// then writes both files beside their places and renames them there only when both are
// complete, so a failure never leaves a truncated export and a refusal changes nothing.
// Refusals are worded by `wording` (default: output_error, the library's words).
Result<void> export_trials(const StudyStore& store, ExportFormat format, std::ostream& out);
Result<void> export_trials(const StudyStore& store, ExportFormat format,
                           const std::filesystem::path& path, bool force = false,
                           const OutputWording& wording = {});

// Building blocks, exposed for tests and other writers.
// RFC 4180: a field with a comma, double quote, CR or LF is quoted, inner quotes doubled.
std::string csv_field(std::string_view value);
// A CSV cell of text (every text cell of the exports: notes, text and choice variables, codes,
// scene names; anything a person typed): csv_field, except that text a spreadsheet would
// evaluate as a formula (OWASP, CSV injection), one that begins with =, +, -, @, tab or CR after
// any apostrophes, gets one more leading apostrophe and is always quoted: =1+1 is written
// "'=1+1", quotes included. Counting the apostrophes keeps it reversible for every text.
std::string csv_text(std::string_view value);
// The text as typed from a cell's value (quotes already removed by the CSV reader): one leading
// apostrophe removed where apostrophes are followed by one of those characters, as docs/data.md
// shows for R and pandas.
std::string csv_text_original(std::string_view cell);
// A CSV header line of these column names, comma-separated (no line break): the names are
// identifiers, never quoted.
std::string csv_header(const std::vector<std::string_view>& columns);
// Integer nanoseconds as exact decimal seconds, '.' as the point regardless of locale:
// 1500000000 -> "1.5", 0 -> "0.0", 1 -> "0.000000001".
std::string seconds_text(std::int64_t ns);
// A protocol hash as the export and `study list` write it: "fnv1a64:" + 16 hex digits. The
// prefix keeps it text in pandas and R: a bare hash of digits would be read as a number (and R
// reads "0x..." as one too), losing leading zeros.
std::string hash_text(std::uint64_t hash);
// The shortest text that reads back as the same double, '.' as the point ("8", "39.5", "1.6").
std::string number_text(double value);

}  // namespace monoplane::study
