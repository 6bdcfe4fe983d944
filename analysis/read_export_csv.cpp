// read_export_csv() (declared in dataset.h): the CSV of `monoplane study export` into TrialRows.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include "analysis/csv.h"
#include "analysis/dataset.h"

namespace monoplane::analysis {
namespace {

// The export's columns this reader needs (docs/data.md, "Export"). `protocol` is read when
// present: it is metadata, not data.
constexpr std::string_view kRequired[] = {
    "participant", "session",         "trial_index", "block",       "scene",
    "mono_plane",  "label1_mode",     "label2_mode", "chosen_mode", "valid",
    "switches",    "decision_time_s", "practice",    "decided",
};

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

// One record with its header, turning fields into values or into errors that say where.
using Columns = std::map<std::string, std::size_t, std::less<>>;

class Row {
  public:
    Row(const std::string& file, const CsvRecord& record, const Columns& columns)
        : file_(file), record_(record), columns_(columns) {}

    // The export writes NA; pandas' to_csv writes an empty field.
    bool is_na(std::string_view column) const {
        const std::string& value = field(column);
        return value.empty() || value == "NA";
    }

    bool has(std::string_view column) const { return columns_.contains(column); }

    // A text cell as typed: without the export's guard against spreadsheet formulas.
    std::string raw_text(std::string_view column) const { return unguarded_cell(field(column)); }

    Result<std::string> text(std::string_view column) const {
        const std::string& value = field(column);
        if (is_na(column)) return fail(column, value, "where a value is needed");
        return unguarded_cell(value);
    }

    // The header's columns whose names begin with `prefix`, in the order of the file.
    std::vector<std::string> columns_starting_with(std::string_view prefix) const {
        std::vector<std::pair<std::size_t, std::string>> found;
        for (const auto& [name, index] : columns_)
            if (name.starts_with(prefix)) found.emplace_back(index, name);
        std::sort(found.begin(), found.end());
        std::vector<std::string> names;
        for (auto& [index, name] : found) names.push_back(std::move(name));
        return names;
    }

    Result<std::int64_t> integer(std::string_view column) const {
        const std::string& value = field(column);
        std::int64_t out = 0;
        const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), out);
        if (ec == std::errc() && ptr == value.data() + value.size() && !value.empty()) return out;
        // pandas writes an integer column with NA in it as floats ("2.0"): accept whole numbers.
        Result<double> number = this->number(column);
        if (number && std::floor(*number) == *number && std::abs(*number) < 9.0e15)
            return static_cast<std::int64_t>(*number);
        return fail(column, value, "is not an integer");
    }

    Result<double> number(std::string_view column) const {
        const std::string& value = field(column);
        double out = 0.0;
        const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), out);
        if (ec != std::errc() || ptr != value.data() + value.size() || value.empty() ||
            !std::isfinite(out))
            return fail(column, value, "is not a number");
        return out;
    }

    // The export (and R) writes TRUE/FALSE, pandas True/False, older exports true/false, some
    // tools 1/0.
    Result<bool> boolean(std::string_view column) const {
        const std::string value = lower(field(column));
        if (value == "true" || value == "1") return true;
        if (value == "false" || value == "0") return false;
        return fail(column, field(column), "is not true or false");
    }

  private:
    const std::string& field(std::string_view column) const {
        return record_.fields[columns_.find(column)->second];
    }

    Error fail(std::string_view column, std::string_view value, std::string_view what) const {
        const std::size_t index = columns_.find(column)->second;
        return Error{
            file_ + ":" + std::to_string(record_.line) + ": column '" + std::string(column) +
            "' (column " + std::to_string(index + 1) + "): " +
            (value.empty() ? std::string("an empty field") : "'" + std::string(value) + "'") + " " +
            std::string(what)};
    }

    const std::string& file_;
    const CsvRecord& record_;
    const Columns& columns_;
};

// Assigns a Result's value or returns its error from the enclosing function.
#define MONOPLANE_ASSIGN(target, expression) \
    do {                                     \
        auto result_ = (expression);         \
        MONOPLANE_TRY(result_);              \
        target = std::move(result_).value(); \
    } while (false)

// The command that writes the files read here: the messages about a file that is not one name
// it, so that the user knows what to give instead.
constexpr std::string_view kExportCommand = "monoplane study export --format csv";

// How an export names its sessions (read_export_csv() in dataset.h says why there are three).
enum class SessionLayout {
    IdAndNumber,  // session_id: the database's id; session: the participant's session number
    NumberOnly,   // session: the participant's session number; no id
    IdOnly,       // session: the database's id (exports before participants had sessions)
};

SessionLayout session_layout(const Columns& columns) {
    if (columns.contains(std::string_view("session_id"))) return SessionLayout::IdAndNumber;
    if (columns.contains(std::string_view("repetition"))) return SessionLayout::NumberOnly;
    return SessionLayout::IdOnly;
}

Result<int> small_integer(const Row& row, std::string_view column) {
    std::int64_t value = 0;
    MONOPLANE_ASSIGN(value, row.integer(column));
    return static_cast<int>(value);
}

// The trial's session (the id, NumberOnly's left for the caller) and repetition.
Result<void> session_fields(const Row& row, SessionLayout layout, TrialRow& t) {
    if (layout == SessionLayout::IdOnly) {
        MONOPLANE_ASSIGN(t.session_id, row.integer("session"));
    } else {
        MONOPLANE_ASSIGN(t.session_number, small_integer(row, "session"));
        if (layout == SessionLayout::IdAndNumber)
            MONOPLANE_ASSIGN(t.session_id, row.integer("session_id"));
    }
    if (row.has("repetition") && !row.is_na("repetition"))
        MONOPLANE_ASSIGN(t.repetition, small_integer(row, "repetition"));
    return Ok{};
}

Result<TrialRow> trial_row(const Row& row, SessionLayout layout) {
    TrialRow t;
    MONOPLANE_ASSIGN(t.participant, row.text("participant"));
    MONOPLANE_TRY(session_fields(row, layout, t));
    MONOPLANE_ASSIGN(t.trial_index, small_integer(row, "trial_index"));
    MONOPLANE_ASSIGN(t.practice, row.boolean("practice"));
    if (row.is_na("block")) {
        t.block = -1;  // NA for practice trials
    } else {
        MONOPLANE_ASSIGN(t.block, small_integer(row, "block"));
    }
    MONOPLANE_ASSIGN(t.scene, row.text("scene"));
    MONOPLANE_ASSIGN(t.mono_plane, row.number("mono_plane"));
    MONOPLANE_ASSIGN(t.label1_mode, row.text("label1_mode"));
    MONOPLANE_ASSIGN(t.label2_mode, row.text("label2_mode"));
    MONOPLANE_ASSIGN(t.decided, row.boolean("decided"));
    if (t.decided) {  // the outcome columns are NA until decided
        MONOPLANE_ASSIGN(t.chosen_mode, row.text("chosen_mode"));
        MONOPLANE_ASSIGN(t.valid, row.boolean("valid"));
        MONOPLANE_ASSIGN(t.switches, small_integer(row, "switches"));
        MONOPLANE_ASSIGN(t.decision_time_s, row.number("decision_time_s"));
    }
    if (row.has("protocol")) t.protocol = row.raw_text("protocol");
    // Exports before the column cannot be told from a copy of the same session: "" then.
    if (row.has("session_uuid") && !row.is_na("session_uuid"))
        t.session_uuid = row.raw_text("session_uuid");
    return t;
}

// The session of a trial's row: the participant's number (participant_number, or the older
// exports' participant_index) and variables (every var_<name> column that is not NA).
Result<SessionRow> session_row(const Row& row, const TrialRow& t) {
    SessionRow s;
    s.source = t.source;
    s.session_id = t.session_id;
    s.participant = t.participant;
    s.session_number = t.session_number;
    s.protocol = t.protocol;
    s.session_uuid = t.session_uuid;
    // The hash only: the export does not hold the protocol's text, so its design is not known.
    if (row.has("protocol_hash") && !row.is_na("protocol_hash"))
        s.protocol_hash = row.raw_text("protocol_hash");
    s.software_version = row.has("software_version") && !row.is_na("software_version")
                             ? row.raw_text("software_version")
                             : "unknown";
    if (row.has("participant_number") && !row.is_na("participant_number")) {
        MONOPLANE_ASSIGN(s.participant_number, small_integer(row, "participant_number"));
        s.participant_number -= 1;  // the export's is 1-based, as --participant-number takes it
    } else if (row.has("participant_index") && !row.is_na("participant_index")) {
        MONOPLANE_ASSIGN(s.participant_number, small_integer(row, "participant_index"));
    }
    for (const std::string& column : row.columns_starting_with("var_")) {
        if (column.size() > 4 && !row.is_na(column))
            s.variables.emplace_back(column.substr(4), row.raw_text(column));
    }
    return s;
}

// The export's gaze columns of one trial (docs/gaze.md), where the export has them and the
// trial recorded gaze (NA otherwise): the mean error at gaze while label 1 and label 2 were shown,
// and the share of gaze beyond the mono plane. Which label showed the test alternative is known
// only once derive_session_fields() has run: assign_gaze_error() picks it then.
struct GazeCells {
    std::array<std::optional<double>, 2> error_mean_arcmin;
    std::optional<double> share_beyond_m;
    std::optional<double> fixations;
};

Result<std::optional<double>> optional_number(const Row& row, std::string_view column) {
    if (!row.has(column) || row.is_na(column)) return std::optional<double>();
    double value = 0.0;
    MONOPLANE_ASSIGN(value, row.number(column));
    return std::optional<double>(value);
}

Result<GazeCells> gaze_cells(const Row& row) {
    GazeCells cells;
    MONOPLANE_ASSIGN(cells.error_mean_arcmin[0], optional_number(row, "gaze_error_mean_arcmin_1"));
    MONOPLANE_ASSIGN(cells.error_mean_arcmin[1], optional_number(row, "gaze_error_mean_arcmin_2"));
    MONOPLANE_ASSIGN(cells.share_beyond_m, optional_number(row, "gaze_share_beyond_m"));
    MONOPLANE_ASSIGN(cells.fixations, optional_number(row, "gaze_fixations"));
    return cells;
}

#undef MONOPLANE_ASSIGN

// TrialRow::gaze_error_test_arcmin: the error while the label that showed the test alternative
// was on; a trial showing the test mode under neither label (or both) has none.
void assign_gaze(TrialRow& t, const GazeCells& cells) {
    t.gaze_share_beyond_m = cells.share_beyond_m;
    if (cells.fixations) t.gaze_fixations = static_cast<int>(*cells.fixations);
    const bool first = t.label1_mode == t.test_mode;
    const bool second = t.label2_mode == t.test_mode;
    if (first != second) t.gaze_error_test_arcmin = cells.error_mean_arcmin[first ? 0 : 1];
}

Result<std::vector<CsvRecord>> read_records(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{file + ": cannot open the file (does it exist, is it readable?)"};
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return Error{file + ": reading the file failed"};
    Result<std::vector<CsvRecord>> parsed = parse_csv(buffer.str(), file);
    MONOPLANE_TRY(parsed);
    if (parsed->empty())
        return Error{file + ":1: the file is empty; expected the header of `" +
                     std::string(kExportCommand) + "`"};
    return parsed;
}

Result<Columns> header_columns(const std::string& file, const CsvRecord& header) {
    Columns columns;
    for (std::size_t i = 0; i < header.fields.size(); ++i) columns.emplace(header.fields[i], i);
    for (std::string_view name : kRequired) {
        if (!columns.contains(name))
            return Error{file + ":" + std::to_string(header.line) + ": the header has no column '" +
                         std::string(name) + "'; is this the CSV of `" +
                         std::string(kExportCommand) + "`?"};
    }
    return columns;
}

// Exports without session ids: each participant's session numbers become ids 1, 2, ... in the
// order they appear, so that sessions stay apart by (source, id) as everywhere else.
void number_sessions(std::vector<TrialRow>& trials) {
    std::map<std::pair<std::string, int>, std::int64_t> ids;
    for (TrialRow& t : trials) {
        const auto next = static_cast<std::int64_t>(ids.size()) + 1;
        t.session_id = ids.emplace(std::pair(t.participant, t.session_number), next).first->second;
    }
}

// One SessionRow per session, from its first row, with the distinct scenes of its data trials.
Result<std::vector<SessionRow>> sessions_of(const std::vector<TrialRow>& trials,
                                            const std::vector<Row>& rows) {
    std::map<std::pair<std::string, std::int64_t>, std::size_t> index;
    std::vector<SessionRow> sessions;
    std::vector<std::set<std::string>> scenes;
    for (std::size_t i = 0; i < trials.size(); ++i) {
        const TrialRow& t = trials[i];
        const auto key = std::pair(t.participant, t.session_id);
        auto found = index.find(key);
        if (found == index.end()) {
            Result<SessionRow> session = session_row(rows[i], t);
            MONOPLANE_TRY(session);
            found = index.emplace(key, sessions.size()).first;
            sessions.push_back(std::move(session).value());
            scenes.emplace_back();
        }
        if (!t.practice) scenes[found->second].insert(t.scene);
    }
    for (std::size_t i = 0; i < sessions.size(); ++i)
        sessions[i].scenes = static_cast<int>(scenes[i].size());
    return sessions;
}

}  // namespace

Result<Dataset> read_export_csv(const std::filesystem::path& path) {
    const std::string file = path.string();
    Result<std::vector<CsvRecord>> records = read_records(path);
    MONOPLANE_TRY(records);
    const CsvRecord& header = records->front();
    Result<Columns> columns = header_columns(file, header);
    MONOPLANE_TRY(columns);
    const SessionLayout layout = session_layout(*columns);

    Dataset dataset;
    dataset.sources.push_back(file);
    std::vector<Row> rows;
    std::vector<GazeCells> gaze;
    for (std::size_t r = 1; r < records->size(); ++r) {
        const CsvRecord& record = (*records)[r];
        if (record.fields.size() != header.fields.size())
            return Error{file + ":" + std::to_string(record.line) + ": " +
                         std::to_string(record.fields.size()) + " fields, but the header has " +
                         std::to_string(header.fields.size())};
        rows.emplace_back(file, record, *columns);
        Result<TrialRow> row = trial_row(rows.back(), layout);
        MONOPLANE_TRY(row);
        Result<GazeCells> cells = gaze_cells(rows.back());
        MONOPLANE_TRY(cells);
        gaze.push_back(*cells);
        TrialRow& trial = row.value();
        trial.source = file;
        dataset.trials.push_back(std::move(trial));
    }
    if (layout == SessionLayout::NumberOnly) number_sessions(dataset.trials);
    Result<std::vector<SessionRow>> sessions = sessions_of(dataset.trials, rows);
    MONOPLANE_TRY(sessions);
    dataset.sessions = std::move(sessions).value();
    derive_session_fields(dataset.trials);
    for (std::size_t i = 0; i < dataset.trials.size(); ++i) assign_gaze(dataset.trials[i], gaze[i]);
    return dataset;
}

}  // namespace monoplane::analysis
