// `monoplane analyze [--db FILE...] [--csv FILE...] --out DIR` (issue 7):
// merges the sessions of several study databases and CSV exports (a multi-site study), excludes
// and counts practice, undecided and invalid trials, and writes report.html (self-contained,
// figures inline), summary.json, CSV tables and the figures as SVG and PNG (docs/analysis.md),
// among them the psychometric functions per participant and scene (issue 21). A study day (issue
// 30): several sessions per participant, repetitions, participant variables and notes in the
// report, the Latin square's rows counted over all inputs, and participant codes that several
// inputs hold joined only as `--codes` says. Integrity (issue 42): the protocol versions the
// sessions ran are listed, designs that differ pooled only with `--pool-protocols`, and a session
// several files hold counted once only with `--drop-duplicates` (and only when the copies agree).
// Eye gaze (issue 45): where participants looked, and the choice on hybrid's error there.
// The work is run_analysis() (analysis_run.h), which the launcher calls too; this file parses the
// options and prints.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/report/report.h"
#include "app/commands/analysis_run.h"
#include "app/commands/commands.h"

namespace monoplane::app {
namespace {

struct AnalyzeOptions {
    std::vector<std::string> dbs;
    std::vector<std::string> csvs;
    std::string out;
    bool force = false;
    bool log2_distance = false;
    bool no_scene_terms = false;
    std::string codes;  // --codes: "" (refuse shared codes), same-person or per-database
    bool pool_protocols = false;
    bool drop_duplicates = false;
    bool no_scene_pictures = false;
};

analysis::SharedCodes shared_codes_rule(const std::string& codes) {
    if (codes == "same-person") return analysis::SharedCodes::SamePerson;
    if (codes == "per-database") return analysis::SharedCodes::PerDatabase;
    return analysis::SharedCodes::Refuse;
}

// The protocol versions on stderr, and what was pooled or counted once on request: a reader of
// the log sees what the numbers rest on without opening the report.
void print_inputs(const analysis::report::InputRecords& inputs) {
    for (const analysis::ProtocolVersion& v : inputs.protocol_versions) {
        std::cerr << "protocol " << v.name << " "
                  << (v.hash.empty() ? "(hash not recorded)" : v.hash) << ": " << v.sessions
                  << (v.sessions == 1 ? " session" : " sessions") << ", design "
                  << (v.design == 0 ? "not known" : std::to_string(v.design)) << "\n";
    }
    if (inputs.pooled_protocols)
        std::cerr << "pooled " << inputs.protocol_versions.size()
                  << " protocol versions of different designs (--pool-protocols)\n";
    for (const analysis::DroppedCopy& d : inputs.dropped_copies) {
        std::cerr << "counted once: participant " << d.participant << ", session "
                  << d.session_number << " (" << d.session_uuid << ") from " << d.kept
                  << ", its identical copy in";
        for (const std::string& source : d.dropped) std::cerr << " " << source;
        std::cerr << " left out (--drop-duplicates)\n";
    }
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

// Eye gaze, where sessions recorded it: the regression's verdict and whether the densities got
// their scene pictures.
void print_gaze(const analysis::report::GazeResults& g) {
    if (!g.recorded) return;
    std::cerr << "gaze: " << g.by_scene.back().trials_with_gaze << " analysed trials with gaze, "
              << g.by_scene.back().samples << " gaze samples\n";
    if (!g.fit)
        std::cerr << "analyze: the regression on the error at gaze is not estimable on these data ("
                  << g.fit_error << "); the report marks it so\n";
    if (!g.image_note.empty())
        std::cerr << "analyze: gaze densities drawn without a picture: " << g.image_note << "\n";
}

void run_analyze(const AnalyzeOptions& o) {
    AnalyzeRequest request;
    request.dbs.assign(o.dbs.begin(), o.dbs.end());
    request.csvs.assign(o.csvs.begin(), o.csvs.end());
    request.out = o.out;
    request.force = o.force;
    request.log2_distance = o.log2_distance;
    request.no_scene_terms = o.no_scene_terms;
    request.codes = shared_codes_rule(o.codes);
    request.pool_protocols = o.pool_protocols;
    request.drop_duplicates = o.drop_duplicates;
    request.scene_pictures = !o.no_scene_pictures;
    request.on_read = [](const std::string& line) { std::cerr << line << "\n"; };
    const AnalysisWritten written = run_analysis(request).value_or_throw();
    const analysis::report::AnalysisResults& results = written.results;

    print_inputs(results.inputs);
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
    print_gaze(results.gaze);
    std::cout << "report: " << written.html.string() << "\n";
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
    cmd->add_option("--out", o->out,
                    "Output folder: a new one, or an earlier analysis's, which is replaced whole "
                    "(no file of it stays); one that holds other files is refused without --force")
        ->required();
    cmd->add_flag("--force", o->force,
                  "Write into an --out that holds files analyze did not write: files of the same "
                  "names are replaced, the others kept");
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
    cmd->add_flag("--pool-protocols", o->pool_protocols,
                  "Pool sessions of protocol versions whose designs differ (scenes, distances, "
                  "alternatives, procedure, ...) or cannot be compared (CSV exports hold only the "
                  "protocol's hash); without it they are refused. The report lists the versions");
    cmd->add_flag("--drop-duplicates", o->drop_duplicates,
                  "Count once a session that several input files hold in identical copies (a "
                  "copy, a backup of the database); without it they are refused. Copies that "
                  "differ are refused all the same");
    cmd->add_flag("--no-scene-pictures", o->no_scene_pictures,
                  "Draw the gaze densities (sessions that recorded eye gaze) without rendering "
                  "each scene under them, which needs a Vulkan device (docs/gaze.md)");
    cmd->callback([o] { run_analyze(*o); });
}

}  // namespace monoplane::app
