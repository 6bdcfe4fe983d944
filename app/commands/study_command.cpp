// `monoplane study run|resume|export`: sessions of the 2AFC study. With
// `--headset none` a simulated observer answers on a virtual clock: no rendering, a whole session
// in well under a second. With `--headset simulated|openxr` the session runs on an OpenXR headset
// (study_headset.h): monoplane's simulated runtime, or whichever runtime is active.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <utility>

#include "app/commands/commands.h"
#include "app/commands/study_headset.h"
#include "app/commands/study_rows.h"
#include "app/commands/study_scenes.h"
#include "hmd/profile.h"
#include "study/export.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_runner.h"
#include "study/staircase_estimates.h"
#include "study/study_store.h"

namespace monoplane::app {
namespace {

struct StudyOptions {
    std::string protocol;
    std::string participant;
    std::string db;
    std::string headset = "none";
    std::string observer;  // "": default without a person (none, simulated), none with openxr
    std::string hmd = "vive";
    std::optional<std::uint64_t> seed;
    std::optional<std::int64_t> session;
    double pace_ms = 0.0;
    bool trace = false;
    bool accept_changed_scenes = false;  // resume: go on although scene files changed
    std::string format = "csv";
    std::string out;
    HeadsetStudyOptions headset_options;
};

void check_headset(const std::string& headset) {
    if (headset == "none" || headset == "simulated" || headset == "openxr") return;
    throw UserError("--headset " + headset + ": use none, simulated or openxr");
}

// Who answers: a simulated observer unless a person holds the controller (openxr) or the
// simulated runtime's script plays the controller (`--observer none`).
std::string observer_for(const StudyOptions& o, const std::string& recorded = {}) {
    if (!o.observer.empty()) return o.observer;
    if (!recorded.empty()) return recorded;
    return o.headset == "openxr" ? "none" : "default";
}

// The observer's stimulus strength (study_rows.h).
std::function<double(const study::ScheduledTrial&)> error_model(const hmd::HmdProfile& hmd,
                                                                const study::Protocol& protocol) {
    return trial_error_model(hmd, protocol);
}

study::RunOptions run_options(const StudyOptions& o, const hmd::HmdProfile& hmd,
                              const study::Protocol& protocol) {
    study::RunOptions options;
    options.pace_ns = static_cast<std::int64_t>(o.pace_ms * 1e6);
    options.neutral_ns = static_cast<std::int64_t>(o.headset_options.neutral_s * 1e9);
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

// After a staircase session (or its part run now): each scene's threshold as its staircase
// estimates it from the stored decisions, so the experimenter sees at once whether a staircase
// converged. `trials`: the session's, as the store holds them now.
void print_staircase_estimates(const study::StudyStore& store, std::int64_t session_id,
                               const study::Protocol& protocol,
                               const std::vector<study::TrialRecord>& trials) {
    if (protocol.procedure != study::Procedure::Staircase) return;
    const study::SessionInfo info = store.session(session_id).value_or_throw();
    const auto estimates = study::final_staircase_estimates(info, trials).value_or_throw();
    for (const auto& [scene, estimate] : estimates) {
        std::fprintf(stderr, "staircase %s: threshold %.3g m", scene.c_str(), estimate.threshold_m);
        if (estimate.lower_m && estimate.upper_m) {
            std::fprintf(stderr, " (95 %% credible interval %.3g-%.3g m)", *estimate.lower_m,
                         *estimate.upper_m);
        }
        std::fprintf(stderr, " after %d trials\n", estimate.trials);
    }
}

void run_on_headset(
    const StudyOptions& o, const GlobalOptions& global, study::StudyStore& store,
    const study::Protocol& protocol, ImportedStudyScenes imported, study::Observer* observer,
    const hmd::HmdProfile& hmd,
    const std::function<std::int64_t(const std::string&, const std::string&)>& begin) {
    HeadsetStudyOptions options = o.headset_options;
    options.headset = o.headset;
    options.hmd = o.hmd;
    options.trace = o.trace;
    std::optional<std::int64_t> session_id;
    const auto begin_and_note = [&](const std::string& runtime, const std::string& device) {
        session_id = begin(runtime, device);
        return *session_id;
    };
    const study::SessionStatus status =
        run_headset_session(options, global, store, protocol, std::move(imported), observer,
                            error_model(hmd, protocol), begin_and_note);
    std::cerr << "session " << study::session_status_name(status) << "\n";
    if (session_id && protocol.procedure == study::Procedure::Staircase) {
        print_staircase_estimates(store, *session_id, protocol,
                                  store.trials(*session_id).value_or_throw());
    }
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
    print_staircase_estimates(store, session_id, protocol, trials);
}

void run_study(const StudyOptions& o, const GlobalOptions& global) {
    check_headset(o.headset);
    const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    // Scene files are loaded and digested before anything is written: a broken file refuses the
    // session, and the digests go into the session's row with it.
    ImportedStudyScenes imported =
        load_imported_scenes(protocol.scene_files, protocol.source).value_or_throw();
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
    const std::string observer_name = observer_for(o);
    info.observer = observer_name == "none" ? "" : observer_name;
    // The protocol's [render] table, --detail overriding its detail; stored with the session,
    // which a headset loop (and a resume) renders with.
    info.render = protocol.render;
    if (!o.headset_options.detail.empty()) info.render.detail = o.headset_options.detail;
    info.scene_files = scene_file_records(imported);
    std::unique_ptr<study::Observer> observer;
    if (observer_name != "none")
        observer = study::make_observer(observer_name, seed).value_or_throw();
    // started_utc is left empty: the store stamps the session's start when it writes it.
    const auto begin = [&](const std::string& runtime, const std::string& device) {
        info.runtime = runtime;
        info.device = device;
        const std::int64_t id = store->begin_session(info, schedule).value_or_throw();
        std::cerr << "session " << id << ": participant " << o.participant << " (index "
                  << participant_index << "), protocol " << protocol.name << ", seed " << seed
                  << ", " << schedule.trials.size() << " trials\n";
        return id;
    };
    if (o.headset != "none") {
        run_on_headset(o, global, *store, protocol, std::move(imported), observer.get(), hmd,
                       begin);
        return;
    }
    if (!observer) throw UserError("--headset none needs an observer to answer (not none)");
    imported.clear();  // recorded; nothing renders them without a headset
    const std::int64_t session_id = begin("none", "none");
    finish(*store, session_id, protocol, *observer, run_options(o, hmd, protocol));
}

void resume_study(const StudyOptions& o, const GlobalOptions& global) {
    check_headset(o.headset);
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
    check_scene_files_before_resume(*store, info, o.accept_changed_scenes);
    // The protocol as it was when the session began, not the file as it is now; its scene files
    // where the session recorded them.
    study::Protocol protocol =
        study::parse_protocol(info.protocol_text, "session " + std::to_string(session_id))
            .value_or_throw();
    protocol.scene_files = study::recorded_scene_paths(info.scene_files);
    const hmd::HmdProfile hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const int first = store->first_undecided_trial(session_id).value_or_throw();
    std::cerr << "resuming session " << session_id << " (participant " << info.participant_code
              << ") at trial " << first << "\n";
    const std::string observer_name = observer_for(o, info.observer);
    std::unique_ptr<study::Observer> observer;
    if (observer_name != "none") {
        observer =
            study::make_observer(observer_name, info.seed ^ (0x9E3779B97F4A7C15ull * (first + 1)))
                .value_or_throw();
    }
    if (o.headset != "none") {
        ImportedStudyScenes imported =
            load_imported_scenes(protocol.scene_files, protocol.source).value_or_throw();
        run_on_headset(o, global, *store, protocol, std::move(imported), observer.get(), hmd,
                       [session_id](const std::string&, const std::string&) { return session_id; });
        return;
    }
    if (!observer) throw UserError("--headset none needs an observer to answer (not none)");
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

// The options of a session on a headset, shared by run and resume.
void add_headset_options(CLI::App* cmd, StudyOptions& o) {
    HeadsetStudyOptions& h = o.headset_options;
    cmd->add_option("--window", h.window,
                    "Experimenter window: auto (when a display exists), on or off")
        ->capture_default_str();
    cmd->add_option("--detail", h.detail,
                    "Scene detail (test, low, medium, high, ultra) instead of the protocol's "
                    "[render] detail; stored with the session (study run only: a resume renders "
                    "as the session began)");
    cmd->add_option("--resolution-scale", h.resolution_scale,
                    "Eye size relative to the runtime's recommendation")
        ->capture_default_str()
        ->check(CLI::Range(0.05, 2.0));
    cmd->add_option("--neutral-s", h.neutral_s, "Neutral screen between trials, seconds")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 60.0));
    cmd->add_option("--layer-depth", h.layer_depth,
                    "Submit each eye's depth with its colour when the OpenXR runtime offers "
                    "XR_KHR_composition_layer_depth (auto), or never (off)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "off"}));
    cmd->add_option("--screenshot", h.screenshot,
                    "PNG of the experimenter window when the session ends");
    cmd->add_option("--screenshot-frame", h.screenshot_frame,
                    "Take the --screenshot after this frame instead");
    cmd->add_option("--sim-script", h.sim_script,
                    "simulated: the runtime's script (head poses, controller input; "
                    "docs/simxr.md); default: written from --hmd, --sim-rate, --dump-frames");
    cmd->add_option("--sim-rate", h.sim_rate_hz, "simulated: display rate in Hz (virtual clock)")
        ->capture_default_str()
        ->check(CLI::Range(1.0, 1000.0));
    cmd->add_option("--sim-head-motion", h.sim_head_motion,
                    "simulated: the head's motion, seated (a seated person's small continuous "
                    "turns and sways) or still")
        ->capture_default_str()
        ->check(CLI::IsMember({"seated", "still"}));
    cmd->add_option("--dump-frames", h.dump_frames,
                    "simulated: write every submitted frame's eyes as PNG into this folder");
}

void add_study_command(CLI::App& root, const GlobalOptions& global) {
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
                    "Simulated observer: default, chance, reference, or none (a person, or the "
                    "simulated runtime's scripted controller); default: none with openxr, else "
                    "default");
    run->add_option("--hmd", options->hmd,
                    "HMD profile: the observer's error model, and the simulated headset")
        ->capture_default_str();
    run->add_option("--seed", options->seed, "Session seed (default: drawn and recorded)");
    run->add_option("--pace-ms", options->pace_ms, "Sleep per logged event (tests)");
    run->add_flag("--trace", options->trace, "Print each durable write on stdout");
    add_headset_options(run, *options);
    run->callback([options, &global] { run_study(*options, global); });

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
    resume->add_flag("--accept-changed-scenes", options->accept_changed_scenes,
                     "Resume although scene files (glTF) changed since the session began; "
                     "refused without it. The session's notes record each changed file");
    add_headset_options(resume, *options);
    resume->callback([options, &global] { resume_study(*options, global); });

    CLI::App* exp = study->add_subcommand("export", "Export the trials as CSV or JSON");
    exp->add_option("--db", options->db, "Study database (SQLite)")->required();
    exp->add_option(
           "--format", options->format,
           "csv or json (the trials), or frames-csv (the frame and head log of headset sessions)")
        ->capture_default_str();
    exp->add_option("--out", options->out, "Output file")->required();
    exp->callback([options] { export_study(*options); });
}

}  // namespace monoplane::app
