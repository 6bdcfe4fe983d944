#include "app/commands/analysis_run.h"

#include <map>
#include <memory>
#include <set>
#include <system_error>
#include <utility>

#include "analysis/duplicate_sessions.h"
#include "analysis/protocol_versions.h"
#include "app/commands/analysis_scene_images.h"
#include "app/commands/option_wording.h"
#include "app/commands/output_folder.h"
#include "app/commands/study_rows.h"
#include "charts/png/svg_to_png.h"
#include "study/export.h"
#include "study/schedule.h"

namespace monoplane::app {
namespace {

// The experimenter's decisions about the session (study run --abandon, --protocol-changed) and a
// change of protocol text, among its notes: the report and summary.json show them with the
// reason given, written by the command.
void add_decisions(analysis::SessionRow& s, const study::SessionInfo& info) {
    for (const study::TrialEvent& e : info.recorded_decisions) {
        const bool abandoned = e.kind == study::EventKind::SessionAbandoned;
        const std::string what = abandoned ? "session abandoned"
                                 : e.kind == study::EventKind::ProtocolChanged
                                     ? "protocol changed"
                                     : "protocol text changed";
        s.notes.push_back({abandoned ? info.ended_utc : info.started_utc, std::nullopt, "command",
                           what + ": " + e.detail});
    }
}

// A session as the analysis sees it: who, which of their sessions, the Latin-square row selector
// and how the protocol it ran orders scenes, the variables and the notes.
analysis::SessionRow session_row(const study::SessionInfo& info, const std::string& source) {
    analysis::SessionRow s;
    s.source = source;
    s.session_id = info.id;
    s.participant = info.participant_code;
    s.session_number = info.session_number;
    s.participant_number = info.participant_number;
    s.protocol = info.protocol_name;
    s.session_uuid = info.session_uuid;
    s.protocol_hash = study::hash_text(info.protocol_hash);  // as the export writes it
    s.software_version = info.software_version.empty() ? "unknown" : info.software_version;
    s.protocol_text = info.protocol_text;
    s.started_utc = info.started_utc;
    Result<study::Protocol> protocol =
        study::parse_protocol(info.protocol_text, "session " + std::to_string(info.id));
    if (protocol) {
        s.first_scene_order = study::first_scene_name(protocol->first_scene);
        s.scenes = static_cast<int>(protocol->scenes.size());
        if (protocol->first_scene == study::FirstSceneBalance::LatinSquare && s.scenes > 0)
            s.latin_square_rows = study::balanced_latin_square_rows(s.scenes);
    }
    for (const study::VariableValue& v : info.variables) {
        s.variables.emplace_back(v.name, v.value);
        s.variable_is_number[v.name] =
            v.type == study::VariableType::Integer || v.type == study::VariableType::Number;
    }
    for (const study::SessionNote& note : info.notes) {
        s.notes.push_back({note.noted_utc, note.trial_index,
                           std::string(study::note_source_name(note.source)), note.text});
    }
    add_decisions(s, info);
    return s;
}

// read_study_database() gives the trial rows; the sessions' own fields (session numbers,
// repetitions, participant numbers, variables, notes) come from the same database's export, and
// how they showed their scenes (HMD, detail, glTF files) goes into `view` for the gaze pictures.
Result<analysis::Dataset> read_database(const std::filesystem::path& path, GazeViewSource& view) {
    const std::string db = path.string();
    // One snapshot and one reading of it: an analysis changes no byte of the file, and reads an
    // older schema as it is.
    Result<std::unique_ptr<study::StudyStore>> store = study::StudyStore::open_read_only(path);
    if (!store) return Error{"--db " + db + ": " + store.error().message};
    Result<study::ExportData> data = study::collect_export(*store.value());
    if (!data) return Error{"--db " + db + ": " + data.error().message};
    Result<analysis::Dataset> read = read_study_database(path, **store, *data);
    MONOPLANE_TRY(read);
    analysis::Dataset dataset = std::move(read).value();
    std::map<std::pair<std::int64_t, int>, const study::TrialRecord*> records;
    for (const study::TrialRecord& record : data->trials)
        records[{record.session_id, record.trial.index}] = &record;
    for (analysis::TrialRow& row : dataset.trials) {
        const auto found = records.find({row.session_id, row.trial_index});
        if (found == records.end()) continue;
        row.session_number = found->second->session_number;
        row.repetition = found->second->trial.repetition;
    }
    for (const auto& [id, info] : data->sessions) dataset.sessions.push_back(session_row(info, db));
    add_sessions(view, data->sessions);
    return dataset;
}

// A CSV export does not record the protocol's first_scene: its sessions are taken to use the
// default Latin square, over the scenes their data trials show.
void add_latin_square_rows(analysis::Dataset& dataset) {
    for (analysis::SessionRow& s : dataset.sessions)
        if (s.latin_square_rows == 0 && s.first_scene_order.empty() && s.scenes > 0)
            s.latin_square_rows = study::balanced_latin_square_rows(s.scenes);
}

// The same file named twice would count its sessions twice.
Result<void> check_distinct(const AnalyzeRequest& r) {
    std::set<std::filesystem::path> seen;
    for (const auto* list : {&r.dbs, &r.csvs}) {
        for (const std::filesystem::path& file : *list) {
            std::error_code ec;
            std::filesystem::path key = std::filesystem::weakly_canonical(file, ec);
            if (ec) key = file;
            if (!seen.insert(key).second)
                return Error{file.string() +
                             " is given twice: its sessions would be counted twice"};
        }
    }
    return Ok{};
}

Result<analysis::Dataset> read_csv(const std::filesystem::path& path) {
    const std::string csv = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Error{"--csv " + csv + ": no such file"};
    Result<analysis::Dataset> one = analysis::read_export_csv(path);
    if (!one) return Error{"--csv " + csv + ": " + one.error().message};
    if (one->trials.empty()) return Error{"--csv " + csv + ": the export holds no trials"};
    add_latin_square_rows(one.value());
    return one;
}

void tell(const AnalyzeRequest& r, const std::string& line) {
    if (r.on_read) r.on_read(line);
}

Result<analysis::Dataset> read_inputs(const AnalyzeRequest& r, GazeViewSource& view) {
    analysis::Dataset merged;
    for (const std::filesystem::path& db : r.dbs) {
        Result<analysis::Dataset> one = read_database(db, view);
        MONOPLANE_TRY(one);
        tell(r, "read " + db.string() + ": " + std::to_string(one->trials.size()) + " trials, " +
                    std::to_string(one->answers.size()) + " questionnaire answers");
        analysis::merge(merged, std::move(one).value());
    }
    for (const std::filesystem::path& csv : r.csvs) {
        Result<analysis::Dataset> one = read_csv(csv);
        MONOPLANE_TRY(one);
        tell(r, "read " + csv.string() + ": " + std::to_string(one->trials.size()) + " trials");
        analysis::merge(merged, std::move(one).value());
    }
    // Copies first: a copy's participant codes are the original's, which is no question of
    // --codes. Then the versions of the sessions that count.
    MONOPLANE_TRY(
        analysis::drop_duplicate_sessions(merged, r.drop_duplicates, "--drop-duplicates"));
    analysis::derive_session_fields(merged.trials);
    MONOPLANE_TRY(analysis::check_protocol_versions(merged, protocol_design_comparison(),
                                                    r.pool_protocols, "--pool-protocols"));
    MONOPLANE_TRY(analysis::join_participant_codes(merged, r.codes, codes_option_names()));
    return merged;
}

// What analyze leaves in its output folder to say that the folder is its own.
const FolderWriter kAnalysisFolder{".monoplane-analysis", "analyze"};

// The report, the tables and the figures (SVG, and PNG at twice their size: sharp on slides and
// in print) into `dir`.
Result<void> write_outputs(AnalysisWritten& done, const std::filesystem::path& dir) {
    const std::vector<analysis::report::Figure> figures =
        analysis::report::report_figures(done.results);
    Result<analysis::report::WrittenReport> written =
        analysis::report::write_report(done.results, figures, dir);
    MONOPLANE_TRY(written);
    done.written = std::move(written).value();
    for (const analysis::report::Figure& figure : figures) {
        const std::filesystem::path png = dir / "figures" / (figure.name + ".png");
        MONOPLANE_TRY(charts::write_svg_as_png(figure.svg, png, 2.0));
        done.pngs.push_back(png);
    }
    return Ok{};
}

// The written files' paths in the staged folder, as they are once it is in place.
void move_paths(AnalysisWritten& done, const StagedFolder& staged) {
    analysis::report::WrittenReport& w = done.written;
    for (std::filesystem::path* path : {&w.html, &w.json}) *path = staged.final_path(*path);
    for (auto* list : {&w.tables, &w.figures, &done.pngs})
        for (std::filesystem::path& path : *list) path = staged.final_path(path);
}

}  // namespace

Result<AnalysisWritten> run_analysis(const AnalyzeRequest& request) {
    if (request.dbs.empty() && request.csvs.empty()) {
        return Error{
            "analyze: no input; give at least one --db FILE (study database) or "
            "--csv FILE (`monoplane study export --format csv`)"};
    }
    MONOPLANE_TRY(check_distinct(request));
    // A folder that may not be replaced is refused before the inputs are read.
    MONOPLANE_TRY(check_output_folder(request.out, kAnalysisFolder, request.force));
    // Inputs next: a refusal (a shared code, a bad file) leaves no output folder behind.
    GazeViewSource view_source;
    Result<analysis::Dataset> data = read_inputs(request, view_source);
    MONOPLANE_TRY(data);
    Result<StagedFolder> staged = StagedFolder::create(request.out, kAnalysisFolder, request.force);
    MONOPLANE_TRY(staged);

    analysis::report::ReportOptions options;
    options.logistic.log2_distance = request.log2_distance;
    options.logistic.scene_terms = !request.no_scene_terms;
    const SeatView seat = seat_view(view_source);
    options.gaze_eye = seat.eye;
    options.gaze_hmd = seat.note.empty() ? seat.key : seat.key + "; " + seat.note;
    AnalysisWritten done;
    done.out = request.out;
    done.results = analysis::report::analyse(*data, options);
    if (request.scene_pictures) add_scene_images(done.results.gaze, view_source, seat);
    MONOPLANE_TRY(write_outputs(done, staged->path()));
    MONOPLANE_TRY(staged.value().commit());
    move_paths(done, *staged);
    done.html = std::filesystem::absolute(done.written.html);
    return done;
}

}  // namespace monoplane::app
