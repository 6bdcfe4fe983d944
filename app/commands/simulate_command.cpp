// `monoplane simulate --protocol P --participants N --observer MODEL --runs R --out DIR` (issue
// 7, docs/analysis.md): power analysis. For each n on a grid up to N, R simulated studies of n
// participants: each participant's schedule from study::make_schedule (the protocol's Latin
// square row n), choices made by the session engine of `study run --headset none` (the simulated
// observer with the rig's projection error as its stimulus, into memory instead of a database),
// then the clustered logistic
// regression of the report; detected = the distance term has p < alpha, counted for the CR1 z
// test and for the small-sample CR2 t test. Deterministic for a seed.
//
// Run r's participant p has the same seed in every n, so the studies of n + 2 participants
// extend those of n (common random numbers): the power curve is not jagged by independent noise.
// Staircase protocols work alike: each session's staircases choose its trials' m.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>

#include "analysis/exclusions.h"
#include "analysis/logistic_regression.h"
#include "analysis/report/power.h"
#include "analysis/report/report.h"
#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/simulated_sessions.h"
#include "app/commands/study_rows.h"
#include "charts/png/svg_to_png.h"
#include "charts/svg_writer.h"
#include "hmd/profile.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/render_mode.h"
#include "study/schedule.h"
#include "study/session_log.h"
#include "study/session_runner.h"

namespace monoplane::app {
namespace {

struct SimulateOptions {
    std::string protocol;
    int participants = 0;
    std::string observer;
    int runs = 0;
    std::string out;
    std::uint64_t seed = 1;
    double alpha = 0.05;
    std::string hmd = "vive";
    bool log2_distance = false;
};

std::string name(study::RenderMode mode) {
    return std::string(study::render_mode_name(mode));
}

// One simulated session (simulated_sessions.h) as analysis rows.
std::vector<analysis::TrialRow> simulate_session(
    const study::Protocol& protocol, const std::string& observer_name, std::uint64_t seed,
    int participant, const std::function<double(const study::ScheduledTrial&)>& error_px) {
    std::vector<analysis::TrialRow> rows;
    for (const auto& [trial, outcome] :
         simulate_trials(protocol, observer_name, seed, participant, error_px)) {
        analysis::TrialRow row;
        row.source = "simulation";
        row.session_id = participant + 1;
        row.participant = "S" + std::to_string(participant + 1);
        row.protocol = protocol.name;
        row.trial_index = trial.index;
        row.practice = trial.practice;
        row.block = trial.block;
        row.scene = trial.scene;
        row.mono_plane = trial.mono_plane;
        row.label1_mode = name(trial.label1_mode);
        row.label2_mode = name(trial.label2_mode);
        row.reference_mode = name(protocol.alternatives[0]);
        row.test_mode = name(protocol.alternatives[1]);
        row.decided = true;
        row.valid = outcome.valid;
        row.chosen_mode = name(outcome.chosen_mode);
        row.chose_test = row.chosen_mode == row.test_mode;
        row.switches = outcome.switches;
        row.decision_time_s = static_cast<double>(outcome.decision_time_ns) * 1e-9;
        rows.push_back(std::move(row));
    }
    return rows;
}

void run_simulate(const SimulateOptions& o) {
    if (o.participants < 1) throw UserError("--participants must be at least 1");
    if (o.runs < 1) throw UserError("--runs must be at least 1");
    if (!(o.alpha > 0.0 && o.alpha < 1.0)) throw UserError("--alpha must lie in (0, 1)");
    const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
    if (protocol.alternatives[0] == protocol.alternatives[1]) {
        throw UserError(o.protocol + ": both alternatives are " + name(protocol.alternatives[0]) +
                        "; nothing to detect");
    }
    // Fails early, with the list of observers, on an unknown name.
    if (o.observer == "none") throw UserError("--observer none: a simulation needs an observer");
    (void)study::make_observer(o.observer, o.seed).value_or_throw();
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const std::filesystem::path out = prepare_output_directory("--out", o.out);
    const auto error_px = trial_error_model(hmd, protocol);

    const std::vector<int> grid = analysis::report::participant_grid(o.participants);
    analysis::LogisticOptions options;
    options.log2_distance = o.log2_distance;
    std::vector<int> detected(grid.size(), 0);
    std::vector<int> detected_cr2(grid.size(), 0);
    std::vector<int> not_estimable(grid.size(), 0);
    std::string distance_term = o.log2_distance ? "log2_mono_plane_m" : "mono_plane_m";
    std::string last_error;

    std::cerr << "simulate: " << protocol.name << ", observer " << o.observer << ", " << hmd.name
              << ", n = ";
    for (std::size_t i = 0; i < grid.size(); ++i) std::cerr << (i ? ", " : "") << grid[i];
    std::cerr << "; " << o.runs << " studies each, alpha " << o.alpha << ", seed " << o.seed
              << "\n";
    const int report_every = std::max(1, o.runs / 10);
    for (int run = 0; run < o.runs; ++run) {
        // Participants in order, so that the first n of them are the study of n.
        std::vector<analysis::TrialRow> rows;
        std::vector<std::size_t> end_of_participant;
        for (int p = 0; p < o.participants; ++p) {
            std::vector<analysis::TrialRow> session =
                simulate_session(protocol, o.observer, session_seed(o.seed, run, p), p, error_px);
            rows.insert(rows.end(), std::make_move_iterator(session.begin()),
                        std::make_move_iterator(session.end()));
            end_of_participant.push_back(rows.size());
        }
        for (std::size_t g = 0; g < grid.size(); ++g) {
            const std::vector<analysis::TrialRow> study(
                rows.begin(),
                rows.begin() + static_cast<std::ptrdiff_t>(end_of_participant[grid[g] - 1]));
            analysis::Exclusions excluded;
            const std::vector<analysis::TrialRow> kept =
                analysis::analysable_trials(study, excluded);
            const Result<analysis::LogisticFit> fit = analysis::fit_choice_model(kept, options);
            if (!fit) {
                ++not_estimable[g];
                last_error = fit.error().message;
                continue;
            }
            distance_term = fit->distance_term;
            for (const analysis::Coefficient& c : fit->coefficients) {
                if (c.name != fit->distance_term) continue;
                if (c.p < o.alpha) ++detected[g];
                if (c.p_cr2 < o.alpha) ++detected_cr2[g];
            }
        }
        if ((run + 1) % report_every == 0 || run + 1 == o.runs) {
            std::cerr << "simulate: " << run + 1 << " of " << o.runs << " studies\n";
        }
    }

    analysis::report::PowerStudy power;
    power.protocol = protocol.name;
    power.observer = o.observer;
    power.hmd = hmd.name;
    power.distance_term = distance_term;
    power.alpha = o.alpha;
    power.seed = o.seed;
    power.runs = o.runs;
    for (const study::ScheduledTrial& t : study::make_schedule(protocol, o.seed, 0).trials) {
        power.trials_per_participant += t.practice ? 0 : 1;
    }
    for (std::size_t g = 0; g < grid.size(); ++g) {
        power.points.push_back(analysis::report::power_point(grid[g], o.runs, detected[g],
                                                             not_estimable[g], detected_cr2[g]));
        const auto& p = power.points.back();
        std::cerr << "n = " << p.participants << ": power " << charts::format_fixed(p.power, 3)
                  << " [" << charts::format_fixed(p.wilson.lower, 3) << ", "
                  << charts::format_fixed(p.wilson.upper, 3) << "] (" << p.detected << " of "
                  << p.runs << " detected, " << p.not_estimable << " not estimable); CR2 "
                  << charts::format_fixed(p.power_cr2, 3) << " ["
                  << charts::format_fixed(p.wilson_cr2.lower, 3) << ", "
                  << charts::format_fixed(p.wilson_cr2.upper, 3) << "] (" << p.detected_cr2
                  << " detected)\n";
    }
    if (!last_error.empty()) {
        std::cerr << "simulate: fits not estimable count as not detected; the last reason: "
                  << last_error << "\n";
    }
    namespace report = analysis::report;
    report::write_text_file(out / "power.csv", report::power_csv(power)).value_or_throw();
    report::write_text_file(out / "power.json", report::power_json(power)).value_or_throw();
    const std::string svg = report::power_svg(power);
    report::write_text_file(out / "power.svg", svg).value_or_throw();
    charts::write_svg_as_png(svg, out / "power.png", 2.0).value_or_throw();
    std::cout << "power: " << std::filesystem::absolute(out / "power.csv").string() << "\n";
}

}  // namespace

void add_simulate_command(CLI::App& root, const GlobalOptions&) {
    auto o = std::make_shared<SimulateOptions>();
    CLI::App* cmd = root.add_subcommand(
        "simulate",
        "Power analysis: simulated studies of up to N participants with a simulated "
        "observer; the probability of detecting the distance effect (docs/analysis.md)");
    cmd->add_option("--protocol", o->protocol, "Protocol file (TOML)")->required();
    cmd->add_option("--participants", o->participants,
                    "Largest number of participants N (the grid runs 2, 4, ... up to N)")
        ->required();
    cmd->add_option("--observer", o->observer,
                    "Simulated observer: default, chance, reference, or "
                    "psychometric:threshold=T,slope=B,lapse=L")
        ->required();
    cmd->add_option("--runs", o->runs, "Simulated studies per number of participants")->required();
    cmd->add_option("--out", o->out, "Output directory")->required();
    cmd->add_option("--seed", o->seed, "Seed of the whole simulation")->capture_default_str();
    cmd->add_option("--alpha", o->alpha, "Significance level of the distance term")
        ->capture_default_str();
    cmd->add_option("--hmd", o->hmd,
                    "HMD profile: the rig's projection error, the observer's "
                    "stimulus")
        ->capture_default_str();
    cmd->add_flag("--log2-distance", o->log2_distance,
                  "Regress on log2 of the mono-plane distance instead of metres");
    cmd->callback([o] { run_simulate(*o); });
}

}  // namespace monoplane::app
