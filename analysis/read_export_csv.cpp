// read_export_csv() (declared in dataset.h): the CSV of `monoplane study export` into TrialRows.
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
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
class Row {
  public:
    Row(const std::string& file, const CsvRecord& record,
        const std::map<std::string, std::size_t, std::less<>>& columns)
        : file_(file), record_(record), columns_(columns) {}

    // The export writes NA; pandas' to_csv writes an empty field.
    bool is_na(std::string_view column) const {
        const std::string& value = field(column);
        return value.empty() || value == "NA";
    }

    Result<std::string> text(std::string_view column) const {
        const std::string& value = field(column);
        if (is_na(column)) return fail(column, value, "where a value is needed");
        return value;
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
    const std::map<std::string, std::size_t, std::less<>>& columns_;
};

// Assigns a Result's value or returns its error from the enclosing function.
#define MONOPLANE_ASSIGN(target, expression)  \
    do {                                      \
        auto result_ = (expression);          \
        if (!result_) return result_.error(); \
        target = std::move(result_).value();  \
    } while (false)

Result<TrialRow> trial_row(const Row& row) {
    TrialRow t;
    MONOPLANE_ASSIGN(t.participant, row.text("participant"));
    MONOPLANE_ASSIGN(t.session_id, row.integer("session"));
    std::int64_t index = 0;
    MONOPLANE_ASSIGN(index, row.integer("trial_index"));
    t.trial_index = static_cast<int>(index);
    MONOPLANE_ASSIGN(t.practice, row.boolean("practice"));
    if (row.is_na("block")) {
        t.block = -1;  // NA for practice trials
    } else {
        std::int64_t block = 0;
        MONOPLANE_ASSIGN(block, row.integer("block"));
        t.block = static_cast<int>(block);
    }
    MONOPLANE_ASSIGN(t.scene, row.text("scene"));
    MONOPLANE_ASSIGN(t.mono_plane, row.number("mono_plane"));
    MONOPLANE_ASSIGN(t.label1_mode, row.text("label1_mode"));
    MONOPLANE_ASSIGN(t.label2_mode, row.text("label2_mode"));
    MONOPLANE_ASSIGN(t.decided, row.boolean("decided"));
    if (t.decided) {  // the outcome columns are NA until decided
        MONOPLANE_ASSIGN(t.chosen_mode, row.text("chosen_mode"));
        MONOPLANE_ASSIGN(t.valid, row.boolean("valid"));
        std::int64_t switches = 0;
        MONOPLANE_ASSIGN(switches, row.integer("switches"));
        t.switches = static_cast<int>(switches);
        MONOPLANE_ASSIGN(t.decision_time_s, row.number("decision_time_s"));
    }
    return t;
}

#undef MONOPLANE_ASSIGN

}  // namespace

Result<Dataset> read_export_csv(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{file + ": cannot open the file (does it exist, is it readable?)"};
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return Error{file + ": reading the file failed"};

    Result<std::vector<CsvRecord>> parsed = parse_csv(buffer.str(), file);
    if (!parsed) return parsed.error();
    const std::vector<CsvRecord>& records = *parsed;
    if (records.empty())
        return Error{file +
                     ":1: the file is empty; expected the header of `monoplane study "
                     "export --format csv`"};

    std::map<std::string, std::size_t, std::less<>> columns;
    const CsvRecord& header = records.front();
    for (std::size_t i = 0; i < header.fields.size(); ++i) columns.emplace(header.fields[i], i);
    for (std::string_view name : kRequired) {
        if (!columns.contains(name))
            return Error{file + ":" + std::to_string(header.line) + ": the header has no column '" +
                         std::string(name) +
                         "'; is this the CSV of `monoplane study export --format csv`?"};
    }
    const auto protocol = columns.find(std::string_view("protocol"));

    Dataset dataset;
    dataset.sources.push_back(file);
    for (std::size_t r = 1; r < records.size(); ++r) {
        const CsvRecord& record = records[r];
        if (record.fields.size() != header.fields.size())
            return Error{file + ":" + std::to_string(record.line) + ": " +
                         std::to_string(record.fields.size()) + " fields, but the header has " +
                         std::to_string(header.fields.size())};
        Result<TrialRow> row = trial_row(Row(file, record, columns));
        if (!row) return row.error();
        TrialRow& trial = row.value();
        trial.source = file;
        if (protocol != columns.end()) trial.protocol = record.fields[protocol->second];
        dataset.trials.push_back(std::move(trial));
    }
    derive_session_fields(dataset.trials);
    return dataset;
}

}  // namespace monoplane::analysis
