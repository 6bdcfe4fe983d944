// `monoplane simulate-threshold --protocol P --observer psychometric:threshold=T,slope=B,lapse=L
// --runs R --out DIR` (issue 21): the validation by simulation of docs/analysis.md. R simulated
// participants with a known psychometric function, each through the session engine of `study
// run --headset none` (a staircase protocol: one session each, its staircases choosing m; a
// constant protocol: --sessions sessions each, pooled, as repeated measurements); per scene the
// threshold is estimated after n answers by QUEST+'s posterior and by analyze's fit
// (threshold_recovery.h), and per estimator and n: coverage of the 95 % intervals, bias and RMSE
// of log10 threshold, and the fewest trials that reach --precision-log10. Deterministic for a
// seed.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>

#include "analysis/report/report.h"
#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/simulated_sessions.h"
#include "app/commands/study_rows.h"
#include "app/commands/threshold_recovery.h"
#include "charts/svg_writer.h"
#include "common/json_writer.h"
#include "hmd/profile.h"
#include "study/observer_spec.h"
#include "study/protocol.h"

namespace monoplane::app {
namespace {

struct ThresholdOptions {
    std::string protocol;
    std::string observer;
    int runs = 0;
    int sessions = 4;
    int fit_every = 0;  // 0: the number of mono_planes
    double precision_log10 = 0.1;
    std::uint64_t seed = 1;
    std::string hmd = "vive";
    std::string out;
};

using SceneAnswers = std::map<std::string, std::vector<Answer>>;

// The valid data decisions of one run by scene, in trial order (sessions one after another).
SceneAnswers simulate_run(const study::Protocol& protocol, const ThresholdOptions& o, int run,
                          const std::function<double(const study::ScheduledTrial&)>& error_px) {
    const bool staircase = protocol.procedure == study::Procedure::Staircase;
    const int sessions = staircase ? 1 : o.sessions;
    SceneAnswers answers;
    for (int k = 0; k < sessions; ++k) {
        // A staircase participant per run rotates the Latin square over the runs; a constant
        // run's sessions rotate it within the run.
        const int participant = staircase ? run : k;
        for (const auto& [trial, outcome] : simulate_trials(
                 protocol, o.observer, session_seed(o.seed, run, k), participant, error_px)) {
            if (trial.practice || !outcome.valid) continue;
            answers[trial.scene].push_back(
                {trial.mono_plane, outcome.chosen_mode == protocol.alternatives[0]});
        }
    }
    return answers;
}

struct Checkpoints {
    std::vector<int> posterior, ml;
};

Checkpoints checkpoints(const study::Protocol& protocol, const ThresholdOptions& o) {
    Checkpoints c;
    if (protocol.procedure == study::Procedure::Staircase) {
        const int most = protocol.staircase.trials_per_scene;
        const int every =
            o.fit_every > 0 ? o.fit_every : static_cast<int>(protocol.mono_planes.size());
        for (int n = 1; n <= most; ++n) c.posterior.push_back(n);
        for (int n = every; n < most; n += every) c.ml.push_back(n);
        c.ml.push_back(most);
    } else {
        const int per_session = static_cast<int>(protocol.mono_planes.size());
        for (int k = 1; k <= o.sessions; ++k) c.posterior.push_back(k * per_session);
        c.ml = c.posterior;
    }
    return c;
}

std::string summary_json(const study::Protocol& protocol, const ThresholdOptions& o,
                         const study::PsychometricFunction& truth,
                         const std::vector<RecoverySummary>& summaries) {
    JsonWriter json(JsonFormat{true, 6});
    json.begin_object();
    json.value("protocol", protocol.name)
        .value("procedure", study::procedure_name(protocol.procedure));
    if (protocol.procedure == study::Procedure::Staircase) {
        json.value("rule", study::staircase_rule_name(protocol.staircase.rule));
    } else {
        json.value("sessions_pooled", o.sessions);
    }
    json.value("observer", o.observer)
        .value("true_threshold_m", truth.threshold)
        .value("slope", truth.slope)
        .value("lapse", truth.lapse)
        .value("runs", o.runs)
        .value("seed", std::to_string(o.seed))
        .value("precision_log10", o.precision_log10);
    json.begin_object("trials_to_precision");
    for (const char* estimator : {"posterior", "ml"}) {
        const std::optional<int> n = trials_to_precision(summaries, estimator, o.precision_log10);
        if (n) {
            json.value(estimator, *n);
        } else {
            json.null(estimator);
        }
    }
    json.end_object();
    json.begin_array("estimators");
    for (const RecoverySummary& s : summaries) {
        json.begin_object()
            .value("estimator", s.estimator)
            .value("trials", s.trials)
            .value("estimates", s.estimates)
            .value("mean_answers", s.mean_answers)
            .value("estimable", s.estimable)
            .value("covered", s.covered)
            .value("coverage", s.coverage)
            .value("coverage_ci_lower", s.coverage_ci.lower)
            .value("coverage_ci_upper", s.coverage_ci.upper)
            .value("bias_log10", s.bias_log10)
            .value("bias_log10_se", s.bias_log10_se)
            .value("rmse_log10", s.rmse_log10)
            .value("median_width_log10", s.median_width_log10)
            .end_object();
    }
    json.end_array();
    json.end_object();
    return json.str();
}

void print_summary(const std::vector<RecoverySummary>& summaries, const ThresholdOptions& o,
                   const std::vector<int>& ml_checkpoints) {
    using charts::format_fixed;
    for (const RecoverySummary& s : summaries) {
        // The posterior at the ML checkpoints only: one line per fit the user compares.
        if (std::ranges::find(ml_checkpoints, s.trials) == ml_checkpoints.end()) continue;
        std::cerr << s.estimator << ", " << s.trials << " trials per scene: coverage "
                  << format_fixed(s.coverage, 3) << " [" << format_fixed(s.coverage_ci.lower, 3)
                  << ", " << format_fixed(s.coverage_ci.upper, 3) << "], bias "
                  << format_fixed(s.bias_log10, 4) << " +- " << format_fixed(s.bias_log10_se, 4)
                  << " log10, RMSE " << format_fixed(s.rmse_log10, 4) << " log10, " << s.estimable
                  << " of " << s.estimates << " estimable, " << format_fixed(s.mean_answers, 1)
                  << " answers on average\n";
    }
    for (const char* estimator : {"posterior", "ml"}) {
        const std::optional<int> n = trials_to_precision(summaries, estimator, o.precision_log10);
        std::cerr << estimator << ": RMSE <= " << o.precision_log10 << " log10 "
                  << (n ? "from " + std::to_string(*n) + " trials per scene"
                        : std::string("not reached"))
                  << "\n";
    }
}

void run_threshold_simulation(const ThresholdOptions& o) {
    if (o.runs < 1) throw UserError("--runs must be at least 1");
    if (o.sessions < 1) throw UserError("--sessions must be at least 1");
    if (!(o.precision_log10 > 0.0)) throw UserError("--precision-log10 must be positive");
    const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
    if (!o.observer.starts_with(study::kPsychometricPrefix)) {
        throw UserError("--observer " + o.observer +
                        ": the validation needs an observer with a known threshold, "
                        "psychometric:threshold=T,slope=B,lapse=L");
    }
    const study::PsychometricFunction truth =
        study::parse_psychometric_spec(o.observer).value_or_throw();
    if (protocol.mono_planes.size() < 2) {
        throw UserError(o.protocol + ": a threshold needs at least two mono_planes");
    }
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const std::filesystem::path out = prepare_output_directory("--out", o.out);
    const auto error_px = trial_error_model(hmd, protocol);
    const Checkpoints at = checkpoints(protocol, o);

    std::cerr << "simulate-threshold: " << protocol.name << " ("
              << study::procedure_name(protocol.procedure) << "), observer " << o.observer << ", "
              << o.runs << " runs, seed " << o.seed << "\n";
    std::vector<RecoveryEstimate> estimates;
    const int report_every = std::max(1, o.runs / 10);
    for (int run = 0; run < o.runs; ++run) {
        for (const auto& [scene, answers] : simulate_run(protocol, o, run, error_px)) {
            add_posterior_estimates(run, scene, answers, protocol.staircase, protocol.mono_planes,
                                    at.posterior, estimates);
            add_ml_estimates(run, scene, answers, at.ml, estimates);
        }
        if ((run + 1) % report_every == 0 || run + 1 == o.runs) {
            std::cerr << "simulate-threshold: " << run + 1 << " of " << o.runs << " runs\n";
        }
    }
    const std::vector<RecoverySummary> summaries = summarise_recovery(estimates, truth.threshold);
    namespace report = analysis::report;
    report::write_text_file(out / "thresholds.csv", recovery_csv(estimates, truth.threshold))
        .value_or_throw();
    report::write_text_file(out / "thresholds.json", summary_json(protocol, o, truth, summaries))
        .value_or_throw();
    print_summary(summaries, o, at.ml);
    std::cout << "thresholds: " << std::filesystem::absolute(out / "thresholds.json").string()
              << "\n";
}

}  // namespace

void add_simulate_threshold_command(CLI::App& root, const GlobalOptions&) {
    auto o = std::make_shared<ThresholdOptions>();
    CLI::App* cmd = root.add_subcommand(
        "simulate-threshold",
        "Validation by simulation: how well a protocol's procedure recovers a known threshold "
        "(coverage, bias, precision over trials; docs/analysis.md)");
    cmd->add_option("--protocol", o->protocol, "Protocol file (TOML), staircase or constant")
        ->required();
    cmd->add_option("--observer", o->observer,
                    "psychometric:threshold=T,slope=B,lapse=L (the known threshold)")
        ->required();
    cmd->add_option("--runs", o->runs, "Simulated participants")->required();
    cmd->add_option("--out", o->out, "Output directory")->required();
    cmd->add_option("--sessions", o->sessions,
                    "Constant procedure: sessions per participant, pooled (repeated measurements)")
        ->capture_default_str();
    cmd->add_option("--fit-every", o->fit_every,
                    "Staircase: analyze's fit every N trials per scene (default: the number of "
                    "mono_planes)");
    cmd->add_option("--precision-log10", o->precision_log10,
                    "The RMSE of log10 threshold to reach (0.1: about 26 %)")
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the whole simulation")->capture_default_str();
    cmd->add_option("--hmd", o->hmd, "HMD profile (the observer's stimulus for other observers)")
        ->capture_default_str();
    cmd->callback([o] { run_threshold_simulation(*o); });
}

}  // namespace monoplane::app
