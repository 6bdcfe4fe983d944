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
#include <functional>
#include <iostream>
#include <memory>

#include "analysis/exclusions.h"
#include "analysis/logistic_regression.h"
#include "analysis/report/power.h"
#include "analysis/report/report.h"
#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/simulated_gaze.h"
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
    // mono-plane: the regression on the distance (the report's); gaze-error: on hybrid's error
    // where the participant looked (the report's gaze section), with simulated gaze.
    std::string predictor = "mono-plane";
};

std::string name(study::RenderMode mode) {
    return std::string(study::render_mode_name(mode));
}

// One simulated session (simulated_sessions.h) as analysis rows.
std::vector<analysis::TrialRow> simulate_session(
    const study::Protocol& protocol, const std::string& observer_name, std::uint64_t seed,
    int participant, const std::function<double(const study::ScheduledTrial&)>& error_px,
    const SimulatedGaze* gaze, bool observer_on_gaze) {
    std::vector<analysis::TrialRow> rows;
    // The participant's gaze: the gaze observer's stimulus, and what the gaze regression reads.
    const auto error_at_gaze = [gaze, seed](const study::ScheduledTrial& trial) {
        return gaze->error_at_gaze(trial, seed);
    };
    const std::function<double(const study::ScheduledTrial&)> stimulus =
        observer_on_gaze ? std::function<double(const study::ScheduledTrial&)>(error_at_gaze)
                         : error_px;
    for (const auto& [trial, outcome] :
         simulate_trials(protocol, observer_name, seed, participant, stimulus)) {
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
        if (gaze) row.gaze_error_test_arcmin = error_at_gaze(trial);
        rows.push_back(std::move(row));
    }
    return rows;
}

// What every simulated study shares, loaded and checked before the first one.
struct Simulation {
    study::Protocol protocol;
    hmd::HmdProfile hmd;
    std::filesystem::path out;
    std::function<double(const study::ScheduledTrial&)> error_px;
    std::vector<int> grid;  // the numbers of participants
    // Simulated gaze, for a gaze observer or the gaze-error predictor; else none.
    std::unique_ptr<SimulatedGaze> gaze;
    bool observer_on_gaze = false;
    analysis::ChoicePredictor predictor = analysis::ChoicePredictor::Distance;
};

Simulation prepare_simulation(const SimulateOptions& o) {
    if (o.participants < 1) throw UserError("--participants must be at least 1");
    if (o.runs < 1) throw UserError("--runs must be at least 1");
    if (!(o.alpha > 0.0 && o.alpha < 1.0)) throw UserError("--alpha must lie in (0, 1)");
    Simulation simulation;
    simulation.protocol = study::load_protocol(o.protocol).value_or_throw();
    const study::Protocol& protocol = simulation.protocol;
    if (protocol.alternatives[0] == protocol.alternatives[1]) {
        throw UserError(o.protocol + ": both alternatives are " + name(protocol.alternatives[0]) +
                        "; nothing to detect");
    }
    // Fails early, with the list of observers, on an unknown name.
    if (o.observer == "none") throw UserError("--observer none: a simulation needs an observer");
    simulation.observer_on_gaze =
        study::make_observer(o.observer, o.seed).value_or_throw()->decides_on_gaze_error();
    if (o.predictor != "mono-plane" && o.predictor != "gaze-error") {
        throw UserError("--predictor '" + o.predictor + "': mono-plane or gaze-error");
    }
    if (o.predictor == "gaze-error") {
        if (o.log2_distance) throw UserError("--log2-distance goes with --predictor mono-plane");
        simulation.predictor = analysis::ChoicePredictor::GazeError;
    }
    simulation.hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    if (simulation.observer_on_gaze || o.predictor == "gaze-error") {
        simulation.gaze = SimulatedGaze::build(protocol, simulation.hmd).value_or_throw();
    }
    simulation.out = prepare_output_directory("--out", o.out);
    simulation.error_px = trial_error_model(simulation.hmd, protocol);
    simulation.grid = analysis::report::participant_grid(o.participants);
    return simulation;
}

// Per number of participants of the grid, how many studies detected the distance effect.
struct Detections {
    // term: the coefficient tested, as the fits name it.
    Detections(std::size_t grid_size, std::string term)
        : detected(grid_size, 0),
          detected_cr2(grid_size, 0),
          not_estimable(grid_size, 0),
          distance_term(std::move(term)) {}

    std::vector<int> detected;      // CR1 z test
    std::vector<int> detected_cr2;  // small-sample CR2 t test
    std::vector<int> not_estimable;
    std::string distance_term;  // as the fits name it
    std::string last_error;     // the reason the last failed fit gave
};

// Run `run`'s participants in order, so that the first n of them are the study of n: their rows,
// and where each participant's rows end.
struct SimulatedParticipants {
    std::vector<analysis::TrialRow> rows;
    std::vector<std::size_t> end_of_participant;
};

SimulatedParticipants simulate_participants(const SimulateOptions& o, const Simulation& simulation,
                                            int run) {
    SimulatedParticipants result;
    for (int p = 0; p < o.participants; ++p) {
        std::vector<analysis::TrialRow> session = simulate_session(
            simulation.protocol, o.observer, session_seed(o.seed, run, p), p, simulation.error_px,
            simulation.gaze.get(), simulation.observer_on_gaze);
        result.rows.insert(result.rows.end(), std::make_move_iterator(session.begin()),
                           std::make_move_iterator(session.end()));
        result.end_of_participant.push_back(result.rows.size());
    }
    return result;
}

// Fits the regression to the study of each n of the grid (the first n participants) and counts
// whether its distance term is significant.
void count_detections(const SimulatedParticipants& participants, const std::vector<int>& grid,
                      const analysis::LogisticOptions& options, double alpha,
                      Detections& detections) {
    for (std::size_t g = 0; g < grid.size(); ++g) {
        const std::vector<analysis::TrialRow> study(
            participants.rows.begin(),
            participants.rows.begin() +
                static_cast<std::ptrdiff_t>(participants.end_of_participant[grid[g] - 1]));
        analysis::Exclusions excluded;
        const std::vector<analysis::TrialRow> kept = analysis::analysable_trials(study, excluded);
        const Result<analysis::LogisticFit> fit = analysis::fit_choice_model(kept, options);
        if (!fit) {
            ++detections.not_estimable[g];
            detections.last_error = fit.error().message;
            continue;
        }
        detections.distance_term = fit->distance_term;
        for (const analysis::Coefficient& c : fit->coefficients) {
            if (c.name != fit->distance_term) continue;
            if (c.p < alpha) ++detections.detected[g];
            if (c.p_cr2 < alpha) ++detections.detected_cr2[g];
        }
    }
}

Detections simulate_studies(const SimulateOptions& o, const Simulation& simulation) {
    const std::vector<int>& grid = simulation.grid;
    analysis::LogisticOptions options;
    options.log2_distance = o.log2_distance;
    options.predictor = simulation.predictor;
    Detections detections(grid.size(), analysis::predictor_term(options));
    std::cerr << "simulate: " << simulation.protocol.name << ", observer " << o.observer << ", "
              << simulation.hmd.name << ", n = ";
    for (std::size_t i = 0; i < grid.size(); ++i) std::cerr << (i ? ", " : "") << grid[i];
    std::cerr << "; " << o.runs << " studies each, alpha " << o.alpha << ", seed " << o.seed
              << "\n";
    const int report_every = std::max(1, o.runs / 10);
    for (int run = 0; run < o.runs; ++run) {
        count_detections(simulate_participants(o, simulation, run), grid, options, o.alpha,
                         detections);
        if ((run + 1) % report_every == 0 || run + 1 == o.runs) {
            std::cerr << "simulate: " << run + 1 << " of " << o.runs << " studies\n";
        }
    }
    return detections;
}

// The power at each n, with the Wilson intervals, printed as it goes.
analysis::report::PowerStudy power_study(const SimulateOptions& o, const Simulation& simulation,
                                         const Detections& detections) {
    analysis::report::PowerStudy power;
    power.protocol = simulation.protocol.name;
    power.observer = o.observer;
    power.hmd = simulation.hmd.name;
    power.distance_term = detections.distance_term;
    power.alpha = o.alpha;
    power.seed = o.seed;
    power.runs = o.runs;
    for (const study::ScheduledTrial& t :
         study::make_schedule(simulation.protocol, o.seed, 0).trials) {
        power.trials_per_participant += t.practice ? 0 : 1;
    }
    const std::vector<int>& grid = simulation.grid;
    for (std::size_t g = 0; g < grid.size(); ++g) {
        power.points.push_back(
            analysis::report::power_point(grid[g], o.runs, detections.detected[g],
                                          detections.not_estimable[g], detections.detected_cr2[g]));
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
    return power;
}

void write_power_files(const analysis::report::PowerStudy& power,
                       const std::filesystem::path& out) {
    namespace report = analysis::report;
    report::write_text_file(out / "power.csv", report::power_csv(power)).value_or_throw();
    report::write_text_file(out / "power.json", report::power_json(power)).value_or_throw();
    const std::string svg = report::power_svg(power);
    report::write_text_file(out / "power.svg", svg).value_or_throw();
    charts::write_svg_as_png(svg, out / "power.png", 2.0).value_or_throw();
    std::cout << "power: " << std::filesystem::absolute(out / "power.csv").string() << "\n";
}

void run_simulate(const SimulateOptions& o) {
    const Simulation simulation = prepare_simulation(o);
    const Detections detections = simulate_studies(o, simulation);
    const analysis::report::PowerStudy power = power_study(o, simulation, detections);
    if (!detections.last_error.empty()) {
        std::cerr << "simulate: fits not estimable count as not detected; the last reason: "
                  << detections.last_error << "\n";
    }
    write_power_files(power, simulation.out);
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
                    "Simulated observer: default, chance, reference, "
                    "psychometric:threshold=T,slope=B,lapse=L, or gaze:threshold=T,slope=B,lapse=L "
                    "(T in arcmin of error where it looks)")
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
    cmd->add_option("--predictor", o->predictor,
                    "What the choice is regressed on: mono-plane (the distance) or gaze-error "
                    "(hybrid's error where the participant looked, from simulated gaze: "
                    "docs/gaze.md)")
        ->capture_default_str();
    cmd->callback([o] { run_simulate(*o); });
}

}  // namespace monoplane::app
