// `monoplane study run|resume|export` (DESIGN.md section 8): sessions of the 2AFC study. With
// `--headset none` a simulated observer answers on a virtual clock: no rendering, a whole session
// in well under a second. The headsets (simulated OpenXR runtime, real OpenXR) arrive with the
// headset issue.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>

#include "app/commands/commands.h"
#include "hmd/profile.h"
#include "renderer/rig/rig.h"
#include "study/export.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_runner.h"
#include "study/study_store.h"

namespace monoplane::app {
namespace {

struct StudyOptions {
    std::string protocol;
    std::string participant;
    std::string db;
    std::string headset = "none";
    std::string observer = "default";
    std::string hmd = "vive";
    std::optional<std::uint64_t> seed;
    std::optional<std::int64_t> session;
    double pace_ms = 0.0;
    bool trace = false;
    std::string format = "csv";
    std::string out;
};

void require_headless(const std::string& headset) {
    if (headset == "none") return;
    if (headset == "simulated" || headset == "openxr") {
        throw UserError("--headset " + headset +
                        ": not available yet (the OpenXR session and the simulated runtime arrive "
                        "with the headset issue); use --headset none");
    }
    throw UserError("--headset " + headset + ": use none, simulated or openxr");
}

// The observer's stimulus strength: the rig's largest projection error for the trial's hybrid
// alternative at its mono plane (DESIGN.md section 3); 0 when both alternatives are stereo-like.
std::function<double(const study::ScheduledTrial&)> error_model(const hmd::HmdProfile& hmd,
                                                                const study::Protocol& protocol) {
    return [hmd, protocol](const study::ScheduledTrial& trial) {
        const bool hybrid_shown = trial.label1_mode == study::RenderMode::Hybrid ||
                                  trial.label2_mode == study::RenderMode::Hybrid ||
                                  trial.label1_mode == study::RenderMode::HybridFarfield ||
                                  trial.label2_mode == study::RenderMode::HybridFarfield;
        if (!hybrid_shown) return 0.0;
        rig::RigInputs inputs = hmd::rig_inputs(hmd, trial.mono_plane);
        inputs.near = protocol.near;
        inputs.far = protocol.far;
        const auto rig = rig::build_rig(inputs);
        return rig ? rig->max_error_px : 0.0;
    };
}

study::RunOptions run_options(const StudyOptions& o, const hmd::HmdProfile& hmd,
                              const study::Protocol& protocol) {
    study::RunOptions options;
    options.pace_ns = static_cast<std::int64_t>(o.pace_ms * 1e6);
    options.trial_error_px = error_model(hmd, protocol);
    if (o.trace) {
        // One line per durable write, flushed: a test that kills the process knows what was
        // committed before the kill.
        options.on_committed = [](const std::string& what) {
            std::printf("committed %s\n", what.c_str());
            std::fflush(stdout);
        };
    }
    return options;
}

void finish(study::StudyStore& store, std::int64_t session_id, const study::Protocol& protocol,
            study::Observer& observer, const study::RunOptions& options) {
    const auto status =
        study::run_session(store, session_id, protocol, observer, options).value_or_throw();
    const auto trials = store.trials(session_id).value_or_throw();
    int decided = 0;
    for (const auto& t : trials) decided += t.decided ? 1 : 0;
    std::cerr << "session " << session_id << " " << study::session_status_name(status) << ": "
              << decided << " of " << trials.size() << " trials decided\n";
}

void run_study(const StudyOptions& o) {
    require_headless(o.headset);
    const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    auto store = study::StudyStore::open(o.db).value_or_throw();
    const int participant_index = store->participant_count().value_or_throw();
    const std::uint64_t seed = o.seed ? *o.seed : std::random_device{}() * 0x100000001ull;
    const study::Schedule schedule = study::make_schedule(protocol, seed, participant_index);

    study::SessionInfo info;
    info.participant_code = o.participant;
    info.participant_index = participant_index;
    info.protocol_name = protocol.name;
    info.protocol_hash = protocol.text_hash;
    info.protocol_text = protocol.text;
    info.seed = seed;
    info.software_version = "monoplane 0.1.0";
    info.hmd = hmd.name;
    info.runtime = o.headset;
    info.device = "none";
    info.observer = o.observer;
    // started_utc is left empty: the store stamps the session's start when it writes it.
    const std::int64_t session_id = store->begin_session(info, schedule).value_or_throw();
    std::cerr << "session " << session_id << ": participant " << o.participant << " (index "
              << participant_index << "), protocol " << protocol.name << ", seed " << seed << ", "
              << schedule.trials.size() << " trials\n";
    auto observer = study::make_observer(o.observer, seed).value_or_throw();
    finish(*store, session_id, protocol, *observer, run_options(o, hmd, protocol));
}

void resume_study(const StudyOptions& o) {
    require_headless(o.headset);
    auto store = study::StudyStore::open(o.db).value_or_throw();
    std::int64_t session_id = 0;
    if (o.session) {
        session_id = *o.session;
    } else {
        const auto latest = store->latest_unfinished_session().value_or_throw();
        if (!latest) throw UserError(o.db + ": no unfinished session to resume");
        session_id = *latest;
    }
    const study::SessionInfo info = store->session(session_id).value_or_throw();
    if (info.status == study::SessionStatus::Completed) {
        throw UserError("session " + std::to_string(session_id) + " is already completed");
    }
    // The protocol as it was when the session began, not the file as it is now.
    const study::Protocol protocol =
        study::parse_protocol(info.protocol_text, "session " + std::to_string(session_id))
            .value_or_throw();
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const int first = store->first_undecided_trial(session_id).value_or_throw();
    std::cerr << "resuming session " << session_id << " (participant " << info.participant_code
              << ") at trial " << first << "\n";
    const std::string observer_name = info.observer.empty() ? o.observer : info.observer;
    auto observer =
        study::make_observer(observer_name, info.seed ^ (0x9E3779B97F4A7C15ull * (first + 1)))
            .value_or_throw();
    finish(*store, session_id, protocol, *observer, run_options(o, hmd, protocol));
}

void export_study(const StudyOptions& o) {
    const study::ExportFormat format = study::parse_export_format(o.format).value_or_throw();
    auto store = study::StudyStore::open(o.db).value_or_throw();
    // Written to a temporary file and renamed: a failed export leaves no truncated file.
    study::export_trials(*store, format, std::filesystem::path(o.out)).value_or_throw();
    std::cerr << "wrote " << o.out << "\n";
}

}  // namespace

void add_study_command(CLI::App& root, const GlobalOptions& /*global*/) {
    CLI::App* study = root.add_subcommand("study", "Run, resume and export 2AFC study sessions");
    study->require_subcommand(1);
    auto options = std::make_shared<StudyOptions>();

    CLI::App* run = study->add_subcommand("run", "Run a session of a protocol");
    run->add_option("--protocol", options->protocol, "Protocol file (TOML)")->required();
    run->add_option("--participant", options->participant,
                    "Pseudonymous participant code (no names)")
        ->required();
    run->add_option("--db", options->db, "Study database (SQLite)")->required();
    run->add_option("--headset", options->headset, "none, simulated or openxr")
        ->capture_default_str();
    run->add_option("--observer", options->observer,
                    "Simulated observer: default, chance, reference")
        ->capture_default_str();
    run->add_option("--hmd", options->hmd, "HMD profile (for the observer's error model)")
        ->capture_default_str();
    run->add_option("--seed", options->seed, "Session seed (default: drawn and recorded)");
    run->add_option("--pace-ms", options->pace_ms, "Sleep per logged event (tests)");
    run->add_flag("--trace", options->trace, "Print each durable write on stdout");
    run->callback([options] { run_study(*options); });

    CLI::App* resume = study->add_subcommand("resume", "Continue an interrupted session");
    resume->add_option("--db", options->db, "Study database (SQLite)")->required();
    resume->add_option("--session", options->session,
                       "Session id (default: the latest unfinished)");
    resume->add_option("--headset", options->headset, "none, simulated or openxr")
        ->capture_default_str();
    resume->add_option("--observer", options->observer,
                       "Simulated observer (default: the session's)");
    resume->add_option("--hmd", options->hmd, "HMD profile")->capture_default_str();
    resume->add_option("--pace-ms", options->pace_ms, "Sleep per logged event (tests)");
    resume->add_flag("--trace", options->trace, "Print each durable write on stdout");
    resume->callback([options] { resume_study(*options); });

    CLI::App* exp = study->add_subcommand("export", "Export the trials as CSV or JSON");
    exp->add_option("--db", options->db, "Study database (SQLite)")->required();
    exp->add_option("--format", options->format, "csv or json")->capture_default_str();
    exp->add_option("--out", options->out, "Output file")->required();
    exp->callback([options] { export_study(*options); });
}

}  // namespace monoplane::app
