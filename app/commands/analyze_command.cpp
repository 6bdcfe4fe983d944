// `monoplane analyze [--db FILE...] [--csv FILE...] --out DIR` (issue 7):
// merges the sessions of several study databases and CSV exports (a multi-site study), excludes
// and counts practice, undecided and invalid trials, and writes report.html (self-contained,
// figures inline), summary.json, CSV tables and the figures as SVG and PNG (docs/analysis.md),
// among them the psychometric functions per participant and scene (issue 21). A study day (issue
// 30): several sessions per participant, repetitions, participant variables and notes in the
// report, the Latin square's rows counted over all inputs, and participant codes that several
// inputs hold joined only as `--codes` says.
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string_view>
#include <system_error>
#include <utility>

#include "analysis/dataset.h"
#include "analysis/report/report.h"
#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/study_rows.h"
#include "charts/png/svg_to_png.h"
#include "study/export.h"
#include "study/schedule.h"

namespace monoplane::app {
namespace {

struct AnalyzeOptions {
    std::vector<std::string> dbs;
    std::vector<std::string> csvs;
    std::string out;
    bool log2_distance = false;
    bool no_scene_terms = false;
    std::string codes;  // --codes: "" (refuse shared codes), same-person or per-database
};

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
    s.started_utc = info.started_utc;
    Result<study::Protocol> protocol =
        study::parse_protocol(info.protocol_text, "session " + std::to_string(info.id));
    if (protocol) {
        s.first_scene_order = study::first_scene_name(protocol->first_scene);
        s.scenes = static_cast<int>(protocol->scenes.size());
        if (protocol->first_scene == study::FirstSceneBalance::LatinSquare && s.scenes > 0)
            s.latin_square_rows = study::balanced_latin_square_rows(s.scenes);
    }
    for (const study::VariableValue& v : info.variables) s.variables.emplace_back(v.name, v.value);
    for (const study::SessionNote& note : info.notes) {
        s.notes.push_back({note.noted_utc, note.trial_index,
                           std::string(study::note_source_name(note.source)), note.text});
    }
    return s;
}

// read_study_database() gives the trial rows; the sessions' own fields (session numbers,
// repetitions, participant numbers, variables, notes) come from the same database's export.
analysis::Dataset read_database(const std::string& db) {
    analysis::Dataset dataset = read_study_database(db).value_or_throw();
    Result<std::unique_ptr<study::StudyStore>> store = study::StudyStore::open(db);
    if (!store) throw UserError("--db " + db + ": " + store.error().message);
    Result<study::ExportData> data = study::collect_export(*store.value());
    if (!data) throw UserError("--db " + db + ": " + data.error().message);
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
    return dataset;
}

// A CSV export does not record the protocol's first_scene: its sessions are taken to use the
// default Latin square, over the scenes their data trials show.
void add_latin_square_rows(analysis::Dataset& dataset) {
    for (analysis::SessionRow& s : dataset.sessions)
        if (s.latin_square_rows == 0 && s.first_scene_order.empty() && s.scenes > 0)
            s.latin_square_rows = study::balanced_latin_square_rows(s.scenes);
}

analysis::SharedCodes shared_codes_rule(const std::string& codes) {
    if (codes == "same-person") return analysis::SharedCodes::SamePerson;
    if (codes == "per-database") return analysis::SharedCodes::PerDatabase;
    return analysis::SharedCodes::Refuse;
}

// The same file named twice would count its sessions twice.
void check_distinct(const AnalyzeOptions& o) {
    std::set<std::filesystem::path> seen;
    for (const auto* list : {&o.dbs, &o.csvs}) {
        for (const std::string& file : *list) {
            std::error_code ec;
            std::filesystem::path key = std::filesystem::weakly_canonical(file, ec);
            if (ec) key = file;
            if (!seen.insert(key).second) {
                throw UserError(file + " is given twice: its sessions would be counted twice");
            }
        }
    }
}

analysis::Dataset read_inputs(const AnalyzeOptions& o) {
    analysis::Dataset merged;
    for (const std::string& db : o.dbs) {
        analysis::Dataset one = read_database(db);
        std::cerr << "read " << db << ": " << one.trials.size() << " trials, " << one.answers.size()
                  << " questionnaire answers\n";
        analysis::merge(merged, std::move(one));
    }
    for (const std::string& csv : o.csvs) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(csv, ec))
            throw UserError("--csv " + csv + ": no such file");
        Result<analysis::Dataset> one = analysis::read_export_csv(csv);
        if (!one) throw UserError("--csv " + csv + ": " + one.error().message);
        if (one->trials.empty()) throw UserError("--csv " + csv + ": the export holds no trials");
        std::cerr << "read " << csv << ": " << one->trials.size() << " trials\n";
        add_latin_square_rows(one.value());
        analysis::merge(merged, std::move(one).value());
    }
    analysis::derive_session_fields(merged.trials);
    Result<bool> joined = analysis::join_participant_codes(merged, shared_codes_rule(o.codes));
    if (!joined) throw UserError(joined.error().message);
    return merged;
}

// The Latin square's rows on stderr, with a warning when they are unevenly filled (the case of
// files that each restarted the rotation at their first participant).
void print_counterbalancing(const analysis::Counterbalancing& c) {
    if (!c.applicable) return;
    std::cerr << "counterbalancing: participants per Latin-square row 1.." << c.latin_square_rows
              << ":";
    for (int count : c.participants_per_row) std::cerr << " " << count;
    std::cerr << (c.balanced ? " (balanced)\n" : "\n");
    if (!c.balanced) {
        std::cerr << "analyze: warning: the Latin-square rows' participant counts differ by more "
                     "than one, so the scene order is not balanced; number participants across "
                     "the whole study with `study run --participant-number N` (the report "
                     "lists the rows)\n";
    }
}

void run_analyze(const AnalyzeOptions& o) {
    if (o.dbs.empty() && o.csvs.empty()) {
        throw UserError(
            "analyze: no input; give at least one --db FILE (study database) or "
            "--csv FILE (`monoplane study export --format csv`)");
    }
    check_distinct(o);
    // Inputs first: a refusal (a shared code, a bad file) leaves no output directory behind.
    const analysis::Dataset data = read_inputs(o);
    const std::filesystem::path out = prepare_output_directory("--out", o.out);

    analysis::report::ReportOptions options;
    options.logistic.log2_distance = o.log2_distance;
    options.logistic.scene_terms = !o.no_scene_terms;
    const analysis::report::AnalysisResults results = analysis::report::analyse(data, options);
    const std::vector<analysis::report::Figure> figures = analysis::report::report_figures(results);
    const analysis::report::WrittenReport written =
        analysis::report::write_report(results, figures, out).value_or_throw();
    for (const analysis::report::Figure& figure : figures) {
        // Twice the SVG's size: sharp on slides and in print.
        charts::write_svg_as_png(figure.svg, out / "figures" / (figure.name + ".png"), 2.0)
            .value_or_throw();
    }

    const analysis::Exclusions& e = results.exclusions;
    std::cerr << "merged " << results.sources.size() << " source(s): " << results.sessions
              << " sessions, " << results.participants << " participants, " << results.trials
              << " trials (" << results.data_trials << " data trials); excluded " << e.practice
              << " practice, " << e.undecided << " undecided, " << e.invalid
              << " invalid; analysed " << e.kept << "\n";
    if (results.overall.n > 0) {
        std::cerr << results.test_mode << " chosen in " << results.overall.test_chosen << " of "
                  << results.overall.n << " valid decisions\n";
    }
    if (!results.logistic) {
        std::cerr << "analyze: the logistic regression is not estimable on these data ("
                  << results.logistic_error << "); the report marks it so\n";
    }
    // Thresholds that the data cannot locate are common with one decision per distance: say how
    // many fits there are, so a reader looks at the reasons in the report.
    if (!results.psychometric.empty()) {
        int estimable = 0;
        for (const analysis::PsychometricFit& f : results.psychometric) {
            estimable += f.estimable ? 1 : 0;
        }
        std::cerr << "psychometric functions: " << estimable << " of "
                  << results.psychometric.size()
                  << " fits estimable (per scene the group's and each participant's)\n";
    }
    print_counterbalancing(results.day.counterbalancing);
    std::cout << "report: " << std::filesystem::absolute(written.html).string() << "\n";
}

}  // namespace

void add_analyze_command(CLI::App& root, const GlobalOptions&) {
    auto o = std::make_shared<AnalyzeOptions>();
    CLI::App* cmd = root.add_subcommand(
        "analyze",
        "Analyse study sessions: choice rates, chi-square, clustered logistic regression, "
        "report.html, summary.json, CSV tables and figures (docs/analysis.md)");
    cmd->add_option("--db", o->dbs, "Study database (SQLite); repeat for several sites")
        ->take_all();
    cmd->add_option("--csv", o->csvs,
                    "Trial export of `monoplane study export --format csv`; "
                    "repeatable")
        ->take_all();
    cmd->add_option("--out", o->out, "Output directory")->required();
    cmd->add_flag("--log2-distance", o->log2_distance,
                  "Regress on log2 of the mono-plane distance instead of metres");
    cmd->add_flag("--no-scene-terms", o->no_scene_terms,
                  "Regress on the distance alone, without scene terms");
    cmd->add_option("--codes", o->codes,
                    "What a participant code found in more than one input file means (without "
                    "this option such a code is an error): same-person (one person, e.g. "
                    "sessions on two lab PCs: analysed as one participant) or per-database "
                    "(each file's codes are its own, e.g. two sites: each code is prefixed with "
                    "its file's name, site-a/a1)")
        ->check(CLI::IsMember({"same-person", "per-database"}));
    cmd->callback([o] { run_analyze(*o); });
}

}  // namespace monoplane::app
