// `monoplane analyze [--db FILE...] [--csv FILE...] --out DIR` (issue 7):
// merges the sessions of several study databases and CSV exports (a multi-site study), excludes
// and counts practice, undecided and invalid trials, and writes report.html (self-contained,
// figures inline), summary.json, CSV tables and the figures as SVG and PNG (docs/analysis.md),
// among them the psychometric functions per participant and scene (issue 21).
#include <filesystem>
#include <iostream>
#include <set>
#include <system_error>

#include "analysis/dataset.h"
#include "analysis/report/report.h"
#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/study_rows.h"
#include "charts/png/svg_to_png.h"

namespace monoplane::app {
namespace {

struct AnalyzeOptions {
    std::vector<std::string> dbs;
    std::vector<std::string> csvs;
    std::string out;
    bool log2_distance = false;
    bool no_scene_terms = false;
};

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
        analysis::Dataset one = read_study_database(db).value_or_throw();
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
        analysis::merge(merged, std::move(one).value());
    }
    analysis::derive_session_fields(merged.trials);
    return merged;
}

void run_analyze(const AnalyzeOptions& o) {
    if (o.dbs.empty() && o.csvs.empty()) {
        throw UserError(
            "analyze: no input; give at least one --db FILE (study database) or "
            "--csv FILE (`monoplane study export --format csv`)");
    }
    check_distinct(o);
    const std::filesystem::path out = prepare_output_directory("--out", o.out);
    const analysis::Dataset data = read_inputs(o);

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
    cmd->callback([o] { run_analyze(*o); });
}

}  // namespace monoplane::app
