#include "study/export.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

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

// "fnv1a64:" + 16 hex digits. The prefix keeps it text in pandas and R: a bare hash of digits
// only would be read as a number (and R reads "0x..." as one too), losing leading zeros.
std::string hash_text(std::uint64_t hash) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
    return buffer;
}

Cell optional_number(const std::optional<double>& value) {
    return value ? number(number_text(*value)) : na();
}

// The row for one trial, in export_columns() order. Outcome columns are NA until decided; the
// staircase columns are NA unless `staircase` (its scene's estimate after the trial) is given.
std::vector<Cell> row(const TrialRecord& r, const SessionInfo& s,
                      const ThresholdEstimate* staircase) {
    const ScheduledTrial& t = r.trial;
    const TrialOutcome& o = r.outcome;
    const bool d = r.decided;
    return {
        text(r.participant_code),
        integer(r.session_id),
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
    };
}

// The trial's staircase estimate after its decision, or null (constant sessions, practice and
// undecided trials).
const ThresholdEstimate* staircase_estimate(const ExportData& data, const TrialRecord& record) {
    const auto session = data.staircase_estimates.find(record.session_id);
    if (session == data.staircase_estimates.end()) return nullptr;
    const auto found = session->second.find(record.trial.index);
    return found == session->second.end() ? nullptr : &found->second;
}

template <class Write>
void for_each_row(const ExportData& data, Write write) {
    for (const TrialRecord& record : data.trials) {
        write(row(record, data.sessions.at(record.session_id), staircase_estimate(data, record)));
    }
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
    }
}

Result<bool> check_stream(const std::ostream& out, std::string_view where) {
    if (!out.good()) {
        const int err = errno;
        return Error{"writing the export to " + std::string(where) + " failed" +
                     (err != 0 ? std::string(": ") + std::strerror(err) : std::string())};
    }
    return true;
}

}  // namespace

std::string_view export_format_name(ExportFormat format) {
    switch (format) {
        case ExportFormat::Csv:
            return "csv";
        case ExportFormat::Json:
            return "json";
        case ExportFormat::FramesCsv:
            return "frames-csv";
    }
    return "csv";
}

Result<ExportFormat> parse_export_format(std::string_view name) {
    if (name == "csv") return ExportFormat::Csv;
    if (name == "json") return ExportFormat::Json;
    if (name == "frames-csv") return ExportFormat::FramesCsv;
    return Error{"unknown export format '" + std::string(name) +
                 "'; use csv, json or frames-csv (the frame and head log)"};
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
    };
    return columns;
}

Result<ExportData> collect_export(const StudyStore& store, ExportFormat format) {
    Result<std::vector<TrialRecord>> trials = store.trials();
    if (!trials) return trials.error();
    ExportData data;
    data.trials = std::move(trials).value();
    for (const TrialRecord& record : data.trials) {
        if (data.sessions.contains(record.session_id)) continue;
        Result<SessionInfo> info = store.session(record.session_id);
        if (!info) return info.error();
        data.sessions.emplace(record.session_id, std::move(info).value());
    }
    for (const auto& [id, info] : data.sessions) {
        if (info.procedure != Procedure::Staircase) continue;
        Result<std::map<int, ThresholdEstimate>> estimates =
            replay_staircase_estimates(info, data.trials);
        if (!estimates) return estimates.error();
        data.staircase_estimates.emplace(id, std::move(estimates).value());
    }
    if (format != ExportFormat::FramesCsv) return data;
    for (const auto& [id, info] : data.sessions) {
        Result<std::vector<FrameRecord>> frames = store.frames(id);
        if (!frames) return frames.error();
        data.frames.emplace(id, std::move(frames).value());
    }
    return data;
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

std::string json_string(std::string_view value) {
    std::string out = "\"";
    for (char c : value) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char escape[8];
                    std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
                    out += escape;
                } else {
                    out += c;  // UTF-8 passes through unchanged
                }
        }
    }
    return out + '"';
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

void write_csv(const ExportData& data, std::ostream& out) {
    std::string line;
    for (std::string_view column : export_columns())
        line += (line.empty() ? "" : ",") + std::string(column);
    out << line << '\n';
    for_each_row(data, [&](const std::vector<Cell>& cells) {
        line.clear();
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i > 0) line += ',';
            const Cell& cell = cells[i];
            switch (cell.type) {
                // NA and TRUE/FALSE as R writes them: read.csv and pandas.read_csv take them
                // without options as missing and as logical / bool columns.
                case Cell::Type::Na:
                    line += "NA";
                    break;
                case Cell::Type::Text:
                    line += csv_field(cell.text);
                    break;
                case Cell::Type::Number:
                    line += cell.text;
                    break;
                case Cell::Type::Bool:
                    line += cell.flag ? "TRUE" : "FALSE";
                    break;
            }
        }
        out << line << '\n';
    });
}

namespace {

std::string json_value(const Cell& cell) {
    switch (cell.type) {
        case Cell::Type::Na:
            return "null";
        case Cell::Type::Text:
            return json_string(cell.text);
        case Cell::Type::Number:
            return cell.text;
        case Cell::Type::Bool:
            return cell.flag ? "true" : "false";
    }
    return "null";
}

// The files `scene` was read from when the session began: none for a built-in scene.
std::string json_scene_files(const SessionInfo& session, const std::string& scene) {
    std::string files;
    for (const SceneFileRecord& file : session.scene_files) {
        if (file.scene != scene) continue;
        files += std::string(files.empty() ? "" : ", ") +
                 "{\"file_index\": " + std::to_string(file.file_index) +
                 ", \"path\": " + json_string(file.path.string()) +
                 ", \"size_bytes\": " + std::to_string(file.digest.size_bytes) +
                 ", \"sha256\": " + json_string(file.digest.sha256) + "}";
    }
    return "[" + files + "]";
}

std::string json_notes(const SessionInfo& session) {
    std::string notes;
    for (const SessionNote& note : session.notes) {
        notes += std::string(notes.empty() ? "" : ", ") +
                 "{\"noted_utc\": " + json_string(note.noted_utc) +
                 ", \"note\": " + json_string(note.text) + "}";
    }
    return "[" + notes + "]";
}

// One trial's object: the export's columns, then two keys CSV has no room for, the trial's
// scene files and its session's notes.
std::string json_object(const TrialRecord& record, const SessionInfo& session,
                        const ThresholdEstimate* staircase) {
    const std::vector<std::string_view>& columns = export_columns();
    const std::vector<Cell> cells = row(record, session, staircase);
    std::string object = "{";
    for (std::size_t i = 0; i < cells.size(); ++i) {
        object += (i > 0 ? ", " : "") + json_string(columns[i]) + ": " + json_value(cells[i]);
    }
    return object + ", \"scene_files\": " + json_scene_files(session, record.trial.scene) +
           ", \"session_notes\": " + json_notes(session) + "}";
}

}  // namespace

void write_json(const ExportData& data, std::ostream& out) {
    out << '[';
    bool first = true;
    for (const TrialRecord& record : data.trials) {
        out << (first ? "\n  " : ",\n  ")
            << json_object(record, data.sessions.at(record.session_id),
                           staircase_estimate(data, record));
        first = false;
    }
    out << (first ? "]\n" : "\n]\n");
}

Result<bool> export_trials(const StudyStore& store, ExportFormat format, std::ostream& out) {
    Result<ExportData> data = collect_export(store, format);
    if (!data) return data.error();
    write_export(*data, format, out);
    out.flush();
    return check_stream(out, "the output stream");
}

Result<bool> export_trials(const StudyStore& store, ExportFormat format,
                           const std::filesystem::path& path) {
    // Collect first: a database error leaves no file behind at all.
    Result<ExportData> data = collect_export(store, format);
    if (!data) return data.error();
    const std::string target = path.string();
    const std::string temporary = target + ".tmp";
    {
        errno = 0;
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            const int err = errno;
            return Error{"cannot write export file '" + temporary + "'" +
                         (err != 0 ? std::string(": ") + std::strerror(err) : std::string()) +
                         "; check that the directory exists and is writable."};
        }
        write_export(*data, format, out);
        out.close();
        if (Result<bool> ok = check_stream(out, "'" + temporary + "'"); !ok) {
            ::unlink(temporary.c_str());
            return ok;
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        ::unlink(temporary.c_str());
        return Error{"cannot move the export into place at '" + target + "': " + ec.message()};
    }
    return true;
}

}  // namespace monoplane::study
