#include "study/export.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <set>

#include "common/json_writer.h"
#include "study/export_source.h"
#include "study/staircase_estimates.h"

namespace monoplane::study {
namespace {

// One export cell. Numbers arrive already as locale-free text; the writers only decide quoting
// and how NA and booleans look.
struct Cell {
    enum class Type { Na, Text, Number, Bool } type = Type::Na;
    std::string text;
    bool flag = false;
};

Cell na() {
    return {};
}
Cell text(std::string value) {
    return {Cell::Type::Text, std::move(value), false};
}
Cell number(std::string value) {
    return {Cell::Type::Number, std::move(value), false};
}
Cell integer(std::int64_t value) {
    return number(std::to_string(value));
}
Cell boolean(bool value) {
    return {Cell::Type::Bool, {}, value};
}

Cell optional_number(const std::optional<double>& value) {
    return value ? number(number_text(*value)) : na();
}

// gaze_samples .. gaze_fixations, the last of export_columns().
constexpr std::size_t kGazeColumns = 7;

// A variable's value: integer and number variables as numbers (their stored text is canonical;
// one that is not a plain number stays text rather than break the JSON), the others as text.
Cell variable_cell(const VariableValue& value) {
    const bool numeric = value.type == VariableType::Integer || value.type == VariableType::Number;
    return numeric && is_json_number(value.value) ? number(value.value) : text(value.value);
}

// The cells of the var_ columns: the session's participant's value, NA where none was given.
void append_variables(std::vector<Cell>& cells, const SessionInfo& s,
                      const std::vector<std::string>& names) {
    for (const std::string& name : names) {
        const auto found = std::find_if(s.variables.begin(), s.variables.end(),
                                        [&](const VariableValue& v) { return v.name == name; });
        cells.push_back(found == s.variables.end() ? na() : variable_cell(*found));
    }
}

// The gaze columns: NA where the session recorded no gaze; a trial of a session that did but
// that showed no label (never started) has no samples and no fixations.
void append_gaze(std::vector<Cell>& cells, const ExportData& data, const TrialRecord& r) {
    const auto session = data.trial_gaze.find(r.session_id);
    if (session == data.trial_gaze.end()) {
        cells.insert(cells.end(), kGazeColumns, na());
        return;
    }
    const auto found = session->second.find(r.trial.index);
    const TrialGaze none;
    const TrialGaze& g = found == session->second.end() ? none : found->second;
    cells.push_back(integer(g.valid_samples));
    cells.push_back(optional_number(g.share_beyond_m));
    for (const auto* values : {&g.error_mean_arcmin, &g.error_max_arcmin})
        for (const std::optional<double>& value : *values) cells.push_back(optional_number(value));
    cells.push_back(integer(static_cast<std::int64_t>(g.fixations.size())));
}

// The trial's staircase estimate after its decision, or null (constant sessions, practice and
// undecided trials).
const ThresholdEstimate* staircase_estimate(const ExportData& data, const TrialRecord& record) {
    const auto session = data.staircase_estimates.find(record.session_id);
    if (session == data.staircase_estimates.end()) return nullptr;
    const auto found = session->second.find(record.trial.index);
    return found == session->second.end() ? nullptr : &found->second;
}

// The row for one trial, in export_columns() order, then one cell per variable of `variables`.
// Outcome columns are NA until decided; the staircase columns are NA unless the trial has its
// scene's estimate after it; the gaze columns NA unless its session recorded gaze.
std::vector<Cell> row(const ExportData& data, const TrialRecord& r,
                      const std::vector<std::string>& variables) {
    const SessionInfo& s = data.sessions.at(r.session_id);
    const ThresholdEstimate* staircase = staircase_estimate(data, r);
    const ScheduledTrial& t = r.trial;
    const TrialOutcome& o = r.outcome;
    const bool d = r.decided;
    std::vector<Cell> cells = {
        text(r.participant_code),
        integer(s.session_number),
        integer(t.index),
        t.practice ? na() : integer(t.block),
        text(t.scene),
        number(number_text(t.mono_plane)),
        text(std::string(render_mode_name(t.label1_mode))),
        d ? integer(o.choice) : na(),
        d ? text(std::string(render_mode_name(o.chosen_mode))) : na(),
        d ? boolean(o.valid) : na(),
        d ? integer(o.switches) : na(),
        d ? number(seconds_text(o.time_on_label_ns[0])) : na(),
        d ? number(seconds_text(o.time_on_label_ns[1])) : na(),
        d ? number(seconds_text(o.decision_time_ns)) : na(),
        boolean(t.practice),
        boolean(d),
        text(std::string(render_mode_name(t.label2_mode))),
        integer(s.participant_index),
        text(s.protocol_name),
        text(hash_text(s.protocol_hash)),
        s.observer.empty() ? na() : text(s.observer),  // NA: a person
        text(s.runtime),
        text(s.hmd),
        text(std::string(session_status_name(s.status))),
        text(s.render.anti_aliasing),
        text(s.render.ssao),
        s.render.detail.empty() ? na() : text(s.render.detail),  // NA: not recorded (schema 1)
        text(std::string(procedure_name(s.procedure))),
        staircase ? number(number_text(staircase->threshold_m)) : na(),
        staircase ? optional_number(staircase->lower_m) : na(),
        staircase ? optional_number(staircase->upper_m) : na(),
        integer(r.session_id),
        integer(t.repetition),
        integer(s.participant_number + 1),  // 1-based, as --participant-number takes it
        d ? integer(o.runs) : na(),
        s.session_uuid.empty() ? na() : text(s.session_uuid),  // NA: a session made by hand
        text(s.software_version.empty() ? std::string("unknown") : s.software_version),
    };
    append_gaze(cells, data, r);
    append_variables(cells, s, variables);
    return cells;
}

// The var_ column names without their prefix.
std::vector<std::string> variable_names(const ExportData& data) {
    std::vector<std::string> names;
    std::set<std::string, std::less<>> seen;
    const auto add = [&](const std::string& name) {
        if (seen.insert(name).second) names.push_back(name);
    };
    for (const std::string& name : data.variable_names) add(name);
    for (const auto& [id, session] : data.sessions)
        for (const VariableValue& value : session.variables) add(value.name);
    return names;
}

template <class Write>
void for_each_row(const ExportData& data, Write write) {
    const std::vector<std::string> variables = variable_names(data);
    for (const TrialRecord& record : data.trials) write(row(data, record, variables));
}

void write_export(const ExportData& data, ExportFormat format, std::ostream& out) {
    switch (format) {
        case ExportFormat::Csv:
            write_csv(data, out);
            return;
        case ExportFormat::Json:
            write_json(data, out);
            return;
        case ExportFormat::FramesCsv:
            write_frames_csv(data, out);
            return;
        case ExportFormat::NotesCsv:
            write_notes_csv(data, out);
            return;
        case ExportFormat::PressesCsv:
            write_presses_csv(data, out);
            return;
        case ExportFormat::GazeCsv:
            write_gaze_csv(data, out);
            return;
    }
}

// The header line of a CSV export whose columns begin with the first `count` of `columns`: a
// file whose first line starts so is one of ours.
bool csv_header_starts_with(std::string_view head, const std::vector<std::string_view>& columns,
                            std::size_t count) {
    std::string prefix;
    for (std::size_t i = 0; i < count && i < columns.size(); ++i)
        prefix += (i > 0 ? "," : "") + std::string(columns[i]);
    if (!head.starts_with(prefix)) return false;
    return head.size() > prefix.size() &&
           std::string_view(",\r\n").find(head[prefix.size()]) != std::string_view::npos;
}

// The JSON export's shape: an array, empty or of objects whose first key is "participant".
bool is_json_export(std::string_view head) {
    const auto skip_space = [&](std::size_t at) {
        while (at < head.size() &&
               std::string_view(" \t\r\n").find(head[at]) != std::string_view::npos)
            ++at;
        return at;
    };
    std::size_t at = skip_space(0);
    if (at >= head.size() || head[at] != '[') return false;
    at = skip_space(at + 1);
    if (at < head.size() && head[at] == ']') return skip_space(at + 1) == head.size();
    if (at >= head.size() || head[at] != '{') return false;
    return head.substr(skip_space(at + 1)).starts_with("\"participant\":");
}

}  // namespace

std::string hash_text(std::uint64_t hash) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
    return buffer;
}

std::string_view export_format_name(ExportFormat format) {
    switch (format) {
        case ExportFormat::Csv:
            return "csv";
        case ExportFormat::Json:
            return "json";
        case ExportFormat::FramesCsv:
            return "frames-csv";
        case ExportFormat::NotesCsv:
            return "notes-csv";
        case ExportFormat::PressesCsv:
            return "presses-csv";
        case ExportFormat::GazeCsv:
            return "gaze-csv";
    }
    return "csv";
}

Result<ExportFormat> parse_export_format(std::string_view name) {
    if (name == "csv") return ExportFormat::Csv;
    if (name == "json") return ExportFormat::Json;
    if (name == "frames-csv") return ExportFormat::FramesCsv;
    if (name == "notes-csv") return ExportFormat::NotesCsv;
    if (name == "presses-csv") return ExportFormat::PressesCsv;
    if (name == "gaze-csv") return ExportFormat::GazeCsv;
    return Error{"unknown export format '" + std::string(name) +
                 "'; use csv, json, frames-csv (the frame and head log), notes-csv (the "
                 "sessions' notes), presses-csv (the participant's presses) or gaze-csv (the "
                 "eye gaze samples)"};
}

OutputKind export_output_kind(ExportFormat format) {
    switch (format) {
        case ExportFormat::Csv:
            return {"csv export", [](std::string_view head) {
                        return csv_header_starts_with(head, export_columns(), 5);
                    }};
        case ExportFormat::Json:
            return {"json export", is_json_export};
        case ExportFormat::FramesCsv:
            // Seven columns: gaze-csv's first six are the same.
            return {"frames-csv export", [](std::string_view head) {
                        return csv_header_starts_with(head, frame_export_columns(), 7);
                    }};
        case ExportFormat::NotesCsv:
            return {"notes-csv export", [](std::string_view head) {
                        return csv_header_starts_with(head, notes_export_columns(), 7);
                    }};
        case ExportFormat::PressesCsv:
            return {"presses-csv export", [](std::string_view head) {
                        return csv_header_starts_with(head, presses_export_columns(), 8);
                    }};
        case ExportFormat::GazeCsv:
            return {"gaze-csv export", [](std::string_view head) {
                        return csv_header_starts_with(head, gaze_export_columns(), 8);
                    }};
    }
    return {"export", [](std::string_view) { return false; }};
}

const std::vector<std::string_view>& export_columns() {
    static const std::vector<std::string_view> columns = {
        "participant",
        "session",
        "trial_index",
        "block",
        "scene",
        "mono_plane",
        "label1_mode",
        "choice",
        "chosen_mode",
        "valid",
        "switches",
        "time_label1_s",
        "time_label2_s",
        "decision_time_s",
        "practice",
        "decided",
        "label2_mode",
        "participant_index",
        "protocol",
        "protocol_hash",
        "observer",
        "runtime",
        "hmd",
        "session_status",
        "anti_aliasing",
        "ssao",
        "detail",
        "procedure",
        "staircase_threshold_m",
        "staircase_lower_m",
        "staircase_upper_m",
        "session_id",
        "repetition",
        "participant_number",
        "runs",
        "session_uuid",
        "software_version",
        // Eye gaze while the trial's labels were shown (docs/data.md): appended, so that every
        // earlier column keeps its place.
        "gaze_samples",
        "gaze_share_beyond_m",
        "gaze_error_mean_arcmin_1",
        "gaze_error_mean_arcmin_2",
        "gaze_error_max_arcmin_1",
        "gaze_error_max_arcmin_2",
        "gaze_fixations",
    };
    return columns;
}

std::vector<std::string> variable_columns(const ExportData& data) {
    std::vector<std::string> columns;
    for (const std::string& name : variable_names(data)) columns.push_back("var_" + name);
    return columns;
}

Result<ExportData> collect_sessions(const StudyStore& store) {
    Result<std::vector<RosterRow>> roster = store.roster();
    MONOPLANE_TRY(roster);
    ExportData data;
    for (const RosterRow& row : *roster) {
        Result<SessionInfo> info = store.session(row.session_id);
        MONOPLANE_TRY(info);
        data.sessions.emplace(row.session_id, std::move(info).value());
    }
    return data;
}

namespace {

// The variables the sessions' protocols declare, so that a column exists for a variable no
// participant has been given yet. A stored protocol this build cannot parse any more declares
// none here: its sessions' stored values still get their columns (variable_columns).
std::vector<std::string> declared_variables(const std::map<std::int64_t, SessionInfo>& sessions) {
    std::vector<std::string> names;
    std::set<std::string, std::less<>> protocols_seen;
    for (const auto& [id, session] : sessions) {
        const std::string key = std::to_string(session.protocol_hash) + session.protocol_name;
        if (!protocols_seen.insert(key).second) continue;  // the same protocol: parsed once
        Result<Protocol> protocol =
            parse_protocol(session.protocol_text, "session " + std::to_string(id) + "'s protocol");
        if (!protocol) continue;
        for (const ParticipantVariable& variable : protocol->day.variables) {
            if (std::find(names.begin(), names.end(), variable.name) == names.end())
                names.push_back(variable.name);
        }
    }
    return names;
}

}  // namespace

Result<ExportData> collect_export(const StudyStore& store, ExportFormat format) {
    if (format == ExportFormat::NotesCsv) return collect_sessions(store);
    if (format == ExportFormat::PressesCsv) return collect_presses(store);
    Result<std::vector<TrialRecord>> trials = store.trials();
    MONOPLANE_TRY(trials);
    ExportData data;
    data.trials = std::move(trials).value();
    for (const TrialRecord& record : data.trials) {
        if (data.sessions.contains(record.session_id)) continue;
        Result<SessionInfo> info = store.session(record.session_id);
        MONOPLANE_TRY(info);
        data.sessions.emplace(record.session_id, std::move(info).value());
    }
    data.variable_names = declared_variables(data.sessions);
    for (const auto& [id, info] : data.sessions) {
        if (info.procedure != Procedure::Staircase) continue;
        Result<std::map<int, ThresholdEstimate>> estimates =
            replay_staircase_estimates(info, data.trials);
        MONOPLANE_TRY(estimates);
        data.staircase_estimates.emplace(id, std::move(estimates).value());
    }
    if (format == ExportFormat::GazeCsv) {
        MONOPLANE_TRY(add_gaze_frames(store, data));
        return data;
    }
    if (format != ExportFormat::FramesCsv) {
        MONOPLANE_TRY(add_trial_gaze(store, data));
        return data;
    }
    for (const auto& [id, info] : data.sessions) {
        Result<std::vector<FrameRecord>> frames = store.frames(id);
        MONOPLANE_TRY(frames);
        data.frames.emplace(id, std::move(frames).value());
    }
    return data;
}

std::string csv_header(const std::vector<std::string_view>& columns) {
    std::string line;
    for (std::string_view column : columns) line += (line.empty() ? "" : ",") + std::string(column);
    return line;
}

std::string csv_field(std::string_view value) {
    if (value.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(value);
    std::string quoted = "\"";
    for (char c : value) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

namespace {

// Text a spreadsheet would take for a formula (OWASP, "CSV Injection"): its first character
// after any apostrophes. Counting the apostrophes makes the rule reversible: "'=x" typed as
// such is written "''=x" and comes back as "'=x".
bool looks_like_formula(std::string_view value) {
    const std::size_t first = value.find_first_not_of('\'');
    return first != std::string_view::npos &&
           std::string_view("=+-@\t\r").find(value[first]) != std::string_view::npos;
}

}  // namespace

std::string csv_text(std::string_view value) {
    if (!looks_like_formula(value)) return csv_field(value);
    // Quoted, so that the apostrophe is part of the cell's text in every CSV reader.
    std::string quoted = "\"'";
    for (char c : value) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string csv_text_original(std::string_view cell) {
    if (cell.starts_with('\'') && looks_like_formula(cell.substr(1)))
        return std::string(cell.substr(1));
    return std::string(cell);
}

std::string seconds_text(std::int64_t ns) {
    // Integer arithmetic, not a double: the export shows exactly the stored nanoseconds.
    const bool negative = ns < 0;
    const std::uint64_t magnitude =
        negative ? 0 - static_cast<std::uint64_t>(ns) : static_cast<std::uint64_t>(ns);
    char fraction[16];
    std::snprintf(fraction, sizeof fraction, "%09llu",
                  static_cast<unsigned long long>(magnitude % 1000000000u));
    std::string digits = fraction;
    while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
    return (negative ? "-" : "") + std::to_string(magnitude / 1000000000u) + "." + digits;
}

std::string number_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);  // shortest, C locale
    return std::string(buffer, result.ptr);
}

namespace {

// One CSV cell: NA and TRUE/FALSE as R writes them (read.csv and pandas.read_csv take them
// without options as missing and as logical / bool columns); text guarded against formulas.
std::string csv_cell(const Cell& cell) {
    switch (cell.type) {
        case Cell::Type::Na:
            return "NA";
        case Cell::Type::Text:
            return csv_text(cell.text);
        case Cell::Type::Number:
            return cell.text;
        case Cell::Type::Bool:
            return cell.flag ? "TRUE" : "FALSE";
    }
    return "NA";
}

}  // namespace

void write_csv(const ExportData& data, std::ostream& out) {
    std::string line = csv_header(export_columns());
    for (const std::string& column : variable_columns(data)) line += "," + column;
    out << line << '\n';
    for_each_row(data, [&](const std::vector<Cell>& cells) {
        line.clear();
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i > 0) line += ',';
            line += csv_cell(cells[i]);
        }
        out << line << '\n';
    });
}

const std::vector<std::string_view>& notes_export_columns() {
    static const std::vector<std::string_view> columns = {
        "participant", "session", "trial", "noted_utc", "runtime_time_ns", "source", "note"};
    return columns;
}

void write_notes_csv(const ExportData& data, std::ostream& out) {
    std::string line;
    out << csv_header(notes_export_columns()) << '\n';
    for (const auto& [id, session] : data.sessions) {
        for (const SessionNote& note : session.notes) {
            line = csv_text(session.participant_code) + ',' +
                   std::to_string(session.session_number) + ',';
            line += (note.trial_index ? std::to_string(*note.trial_index) : "NA") + ',';
            line += csv_text(note.noted_utc) + ',';
            line += (note.runtime_time_ns ? std::to_string(*note.runtime_time_ns) : "NA") + ',';
            line += csv_text(note_source_name(note.source)) + ',' + csv_text(note.text);
            out << line << '\n';
        }
    }
}

namespace {

// The export's layout: one trial per line, ", " and ": " within it (docs/data.md shows it).
constexpr JsonFormat kExportJson{.indented = true, .line_levels = 1};

void write_cell(JsonWriter& json, std::string_view key, const Cell& cell) {
    switch (cell.type) {
        case Cell::Type::Na:
            json.null(key);
            return;
        case Cell::Type::Text:
            json.value(key, cell.text);
            return;
        case Cell::Type::Number:
            json.formatted_number(key, cell.text);
            return;
        case Cell::Type::Bool:
            json.value(key, cell.flag);
            return;
    }
}

// The files `scene` was read from when the session began: none for a built-in scene.
void write_scene_files(JsonWriter& json, const SessionInfo& session, const std::string& scene) {
    json.begin_array("scene_files");
    for (const SceneFileRecord& file : session.scene_files) {
        if (file.scene != scene) continue;
        json.begin_object()
            .value("file_index", file.file_index)
            .value("path", file.path.string())
            .value("size_bytes", file.digest.size_bytes)
            .value("sha256", file.digest.sha256)
            .end_object();
    }
    json.end_array();
}

// The session's notes with every field, their text exactly as typed (JSON needs no guard
// against spreadsheet formulas).
void write_notes(JsonWriter& json, const SessionInfo& session) {
    json.begin_array("session_notes");
    for (const SessionNote& note : session.notes) {
        json.begin_object()
            .value("noted_utc", note.noted_utc)
            .value("note", note.text)
            .value("source", note_source_name(note.source));
        if (note.runtime_time_ns)
            json.value("runtime_time_ns", *note.runtime_time_ns);
        else
            json.null("runtime_time_ns");
        if (note.trial_index)
            json.value("trial", *note.trial_index);
        else
            json.null("trial");
        json.end_object();
    }
    json.end_array();
}

// One trial's object: the export's columns (`keys`), then two keys CSV has no room for, the
// trial's scene files and its session's notes.
void write_object(JsonWriter& json, const std::vector<std::string>& keys,
                  const std::vector<Cell>& cells, const SessionInfo& session,
                  const std::string& scene) {
    json.begin_object();
    for (std::size_t i = 0; i < cells.size(); ++i) write_cell(json, keys[i], cells[i]);
    write_scene_files(json, session, scene);
    write_notes(json, session);
    json.end_object();
}

}  // namespace

void write_json(const ExportData& data, std::ostream& out) {
    std::vector<std::string> keys(export_columns().begin(), export_columns().end());
    for (const std::string& column : variable_columns(data)) keys.push_back(column);
    const std::vector<std::string> variables = variable_names(data);
    JsonWriter json(kExportJson);
    json.begin_array();
    for (const TrialRecord& record : data.trials) {
        const SessionInfo& session = data.sessions.at(record.session_id);
        write_object(json, keys, row(data, record, variables), session, record.trial.scene);
        out << json.take();  // a trial at a time: the export need not fit in memory twice
    }
    json.end_array();
    out << json.take();
}

Result<void> export_trials(const StudyStore& store, ExportFormat format, std::ostream& out) {
    Result<ExportData> data = collect_export(store, format);
    MONOPLANE_TRY(data);
    write_export(*data, format, out);
    out.flush();
    if (!out.good()) return Error{"writing the export to the output stream failed"};
    return Ok{};
}

Result<void> export_trials(const StudyStore& store, ExportFormat format,
                           const std::filesystem::path& path, bool force,
                           const OutputWording& wording) {
    const OutputWording word = wording ? wording : output_error;
    // Checked before anything is read or written: a refusal changes nothing.
    if (std::optional<OutputProblem> problem =
            export_output_problem(path, format, store.path(), force))
        return word(*problem);
    // Collected before the file is begun: a database error leaves no file behind at all.
    Result<ExportData> data = collect_export(store, format);
    MONOPLANE_TRY(data);
    // Only the sessions read tell whether an earlier export there is of this study.
    const ExportSource source = export_source(*data, format, store.path());
    if (std::optional<OutputProblem> problem = export_source_problem(path, source, force))
        return word(*problem);
    return write_files_atomically({
        {path,
         [&](std::ostream& out) -> Result<void> {
             write_export(*data, format, out);
             return Ok{};
         }},
        {export_source_path(path),
         [&](std::ostream& out) -> Result<void> {
             write_export_source(source, out);
             return Ok{};
         }},
    });
}

}  // namespace monoplane::study
