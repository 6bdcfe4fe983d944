// `monoplane lab`: the experimenter's launcher window (docs/lab.md). It leads through a session
// (database, protocol, participant, headset, Start) and, after it, shows the summary with Export
// and Analyse. Every rule is the commands' own: the window draws lab::LauncherModel, a session is
// run_study / resume_study (as `study run` / `study resume`), Export is `study export`'s
// check_output_option + export_trials, Analyse is run_analysis (as `analyze`).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands/analysis_run.h"
#include "app/commands/commands.h"
#include "app/commands/headset_check.h"
#include "app/commands/option_wording.h"
#include "app/commands/session_summary.h"
#include "app/commands/study_options.h"
#include "app/commands/validation_report.h"
#include "app/install/install_layout.h"
#include "app/lab/frame_time_probe.h"
#include "app/lab/lab_config.h"
#include "app/lab/launcher_model.h"
#include "app/lab/launcher_window.h"
#include "app/window/desktop_window.h"
#include "study/export.h"
#include "study/study_store.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;

struct LabOptions {
    std::string db;
    std::string protocols;
    std::string state_file;
    std::string screenshot_dir;
    HeadsetStudyOptions headset;  // the sessions' headset options (dry runs and tests shorten)
    // The headset step's first choices (the window may change them) and a fixed seed: the same
    // meaning as `study run --headset/--observer/--seed`, handed to the model, not kept here.
    std::string initial_headset;
    std::string initial_observer;
    std::optional<std::uint64_t> seed;
    // The sessions' options given on the command line, as `study run` takes them: shown in the
    // window's command line, which is then the session's command.
    std::vector<std::string> session_arguments;
    bool protocols_given = false;  // --protocols: not the remembered folder
    // --detail / --resolution-scale as given: they choose the window's performance preset, which
    // then passes them to the session (and shows them in its command line).
    std::optional<std::string> detail_given;
    std::optional<double> scale_given;
};

// The protocols shipped with monoplane (share/monoplane/protocols beside the executable: the
// installed ones, or the source tree's through the build folder); else ./protocols.
std::string default_protocols_folder() {
    if (const auto shipped = shipped_protocols()) return shipped->string();
    return "protocols";
}

// `study export --format csv --out <db stem>.csv` beside the database: the command's checks and
// writer, so the launcher writes the same file and refuses the same way.
Result<fs::path> export_beside(const fs::path& db) {
    const fs::path out = db.parent_path() / (db.stem().string() + ".csv");
    const study::ExportFormat format = study::ExportFormat::Csv;
    MONOPLANE_TRY(check_output_option(out, export_option_kind(format), {db}, false));
    Result<std::unique_ptr<study::StudyStore>> store = study::StudyStore::open_read_only(db);
    MONOPLANE_TRY(store);
    MONOPLANE_TRY(study::export_trials(**store, format, out, false, output_option_error));
    return out;
}

// `analyze --db DB --out <db stem>-analysis/`.
Result<fs::path> analyse_beside(const fs::path& db) {
    AnalyzeRequest request;
    request.dbs = {db};
    request.out = db.parent_path() / (db.stem().string() + "-analysis");
    Result<AnalysisWritten> written = run_analysis(request);
    MONOPLANE_TRY(written);
    return written->html;
}

StudyOptions study_options(const lab::LaunchRequest& r, const LabOptions& lab) {
    StudyOptions o;
    o.protocol = r.protocol;
    o.db = r.db;
    o.participant = r.participant;
    o.session_number = r.session_number;
    o.participant_number = r.participant_number;
    o.variables = r.variables;
    o.seed = r.seed;
    o.session_id = r.session_id;
    o.accept_changed_scenes = r.accept_changed_scenes;
    o.headset = r.headset;
    o.observer = r.observer;
    o.headset_options = lab.headset;                       // window "auto", as the command
    if (!r.keys.empty()) o.headset_options.keys = r.keys;  // the window's Keys choice
    // The session settings' preset stands for --detail and --resolution-scale (run only: a
    // resumed session renders at the detail it began with).
    if (r.preset) {
        if (r.command == lab::LaunchRequest::Command::Run)
            o.headset_options.detail = r.preset->protocol_detail ? "" : r.preset->detail;
        o.headset_options.resolution_scale = r.preset->resolution_scale;
    }
    return o;
}

// Runs the session as `study run|resume` would; returns its error message, empty when it
// finished. Never throws: the launcher comes back whatever happened.
std::string run_session(const lab::LaunchRequest& request, const LabOptions& lab,
                        const GlobalOptions& global) {
    const StudyOptions o = study_options(request, lab);
    try {
        if (request.command == lab::LaunchRequest::Command::Run)
            run_study(o, global);
        else
            resume_study(o, global);
        return {};
    } catch (const UserError& e) {
        return e.what();
    } catch (const vk::SystemError& e) {
        return std::string("Vulkan error: ") + e.what();
    } catch (const std::exception& e) {
        return e.what();
    }
}

// The summary's lines (summarize_session), or why there are none.
std::vector<std::string> summary_lines(const lab::LauncherModel& model) {
    if (!model.summary() || model.summary()->session_id == 0) return {};
    Result<std::unique_ptr<study::StudyStore>> store =
        study::StudyStore::open_read_only(model.database());
    if (!store) return {store.error().message};
    Result<SessionSummary> summary = summarize_session(**store, model.summary()->session_id);
    if (!summary) return {summary.error().message};
    return session_summary_lines(*summary);
}

// The headset step's probe: the runtime `study run --headset HEADSET` would use, with the lab's
// simulated-headset options.
Result<lab::HeadsetReport> probe_for_lab(const std::string& headset, const LabOptions& o,
                                         const GlobalOptions& global) {
    Result<headset::HeadsetProbe> probe =
        probe_headset(headset == "simulated", o.headset, global.validation);
    MONOPLANE_TRY(probe);
    lab::HeadsetReport r;
    r.runtime_available = probe->runtime_available;
    r.runtime = probe->runtime;
    r.system = probe->system;
    r.width = probe->width;
    r.height = probe->height;
    r.eye_gaze = headset::eye_gaze_name(probe->eye_gaze);
    r.eye_gaze_text = headset::eye_gaze_text(probe->eye_gaze);
    r.message = probe->message;
    return r;
}

lab::HeadsetReport report_of(const HeadsetCheck& check) {
    lab::HeadsetReport r;
    r.runtime_available = true;
    r.runtime = check.runtime;
    r.system = check.system;
    r.width = check.width;
    r.height = check.height;
    r.refresh_hz = check.refresh_hz;
    r.ipd_m = check.ipd_m;
    r.interaction_profile = check.interaction_profile;
    r.eye_gaze = headset::eye_gaze_name(check.eye_gaze);
    r.eye_gaze_text = headset::eye_gaze_text(check.eye_gaze);
    r.check_gaze_frames = check.gaze_frames;
    r.check = check_end_name(check.end);
    r.check_message = check.message;
    r.check_frames = check.frames_shown;
    return r;
}

// On the simulated headset the simulated observer answers the check, as it answers the
// session's trials: it confirms once the calibration screen has been shown for this many frames.
constexpr std::int64_t kObserverConfirmFrames = 10;

// The headset check (run_headset_check), the launcher answering each turn. Never throws.
Result<lab::HeadsetReport> check_for_lab(
    const std::string& headset, bool observer_answers,
    const std::function<lab::CheckAnswer(const lab::HeadsetCheckTurn&)>& turn, const LabOptions& o,
    const GlobalOptions& global) {
    HeadsetCheckOptions options;
    options.headset = o.headset;
    options.headset.headset = headset;
    options.global = global;
    options.on_turn = [&turn, observer_answers](const HeadsetCheckProgress& p) {
        const lab::CheckAnswer answer =
            turn({p.frames_shown, p.refresh_hz, p.ipd_m, p.interaction_profile,
                  p.eye_gaze == headset::EyeGaze::Tracked, p.gaze_frames});
        if (observer_answers && answer == lab::CheckAnswer::Continue &&
            p.frames_shown >= kObserverConfirmFrames)
            return CheckRequest::Confirm;
        switch (answer) {
            case lab::CheckAnswer::Confirm:
                return CheckRequest::Confirm;
            case lab::CheckAnswer::Cancel:
                return CheckRequest::Cancel;
            case lab::CheckAnswer::Continue:
                break;
        }
        return CheckRequest::Continue;
    };
    try {
        Result<HeadsetCheck> check = run_headset_check(options);
        MONOPLANE_TRY(check);
        lab::HeadsetReport report = report_of(*check);
        if (observer_answers && check->end == CheckEnd::Confirmed &&
            check->frames_shown >= kObserverConfirmFrames)
            report.check_message = "the simulated observer pressed CONFIRM after " +
                                   std::to_string(check->frames_shown) + " frames";
        return report;
    } catch (const std::exception& e) {
        return Error{std::string("the headset check stopped: ") + e.what()};
    }
}

// The session settings' probe on a device of its own (the launcher's device and validation
// options), with the HMD profile of the sessions' simulated headset; its eye size where no
// runtime recommended one.
Result<lab::FrameTimeEstimate> probe_for_settings(lab::FrameTimeProbeRequest request,
                                                  const lab::ProbeCallback& progress,
                                                  const LabOptions& o,
                                                  const GlobalOptions& global) {
    Result<hmd::HmdProfile> profile = hmd::load_hmd_profile(o.headset.hmd);
    MONOPLANE_TRY(profile);
    request.hmd = std::move(profile).value();
    if (request.recommended_width <= 0 || request.recommended_height <= 0) {
        request.recommended_width = request.hmd.width;
        request.recommended_height = request.hmd.height;
    }
    return lab::probe_frame_time(global.context_options(), request, progress);
}

// One opening of the launcher window, on a Context of its own that goes with it (the session
// creates its own, with the headset's requirements).
lab::LauncherExit open_launcher(lab::LauncherModel& model, lab::LauncherUi& ui, const LabOptions& o,
                                const GlobalOptions& global) {
    vk_core::ContextOptions options = global.context_options();
    options.instance_extensions = window::required_instance_extensions().value_or_throw();
    options.device_extensions = window::required_device_extensions();
    auto ctx = vk_core::Context::create(options).value_or_throw();
    lab::LauncherActions actions;
    actions.export_data = [&model] { return export_beside(model.database()); };
    actions.analyse = [&model] { return analyse_beside(model.database()); };
    actions.probe_headset = [&o, &global](const std::string& headset) {
        return probe_for_lab(headset, o, global);
    };
    actions.probe_frame_time = [&o, &global](const lab::FrameTimeProbeRequest& request,
                                             const lab::ProbeCallback& progress) {
        return probe_for_settings(request, progress, o, global);
    };
    actions.check_headset = [&o, &global, &model](const std::string& headset, const auto& turn) {
        // With the simulated headset an observer answers unless told none (a script's
        // controller, or the experimenter's Fits, answers then).
        const bool observer = headset == "simulated" && model.observer() != "none";
        return check_for_lab(headset, observer, turn, o, global);
    };
    auto window = lab::LauncherWindow::create(*ctx, model, ui, actions).value_or_throw();
    const lab::LauncherExit exit = window->run();
    window.reset();
    // With --validation, any message of the launcher's own device fails the command, as a
    // session's do.
    fail_on_validation_messages(*ctx, global);
    return exit;
}

// The launcher remembers the database and protocols folder it last used; what the command
// line gives goes first. An unreadable settings file is said and ignored.
lab::LabConfig remembered_or_given(const LabOptions& o) {
    Result<lab::LabConfig> remembered = lab::read_lab_config(lab::lab_config_file());
    if (!remembered) std::cerr << "monoplane lab: " << remembered.error().message << "\n";
    lab::LabConfig config = remembered ? *remembered : lab::LabConfig{};
    std::error_code ec;
    if (!config.db.empty() && !fs::exists(config.db, ec)) config.db.clear();  // moved or gone
    if (!o.db.empty()) config.db = o.db;
    if (o.protocols_given || config.protocols.empty()) config.protocols = o.protocols;
    return config;
}

// What the window has open now becomes what the next launch opens.
void remember(const lab::LauncherModel& model, lab::LabConfig& saved) {
    lab::LabConfig now = saved;
    if (model.database_open()) now.db = model.database();
    if (!model.protocols_folder().empty()) now.protocols = model.protocols_folder();
    if (now.db == saved.db && now.protocols == saved.protocols) return;
    if (Result<void> written = lab::write_lab_config(lab::lab_config_file(), now); !written)
        std::cerr << "monoplane lab: not remembered: " << written.error().message << "\n";
    saved = now;
}

void run_lab(const LabOptions& o, const GlobalOptions& global) {
    lab::LabConfig config = remembered_or_given(o);
    lab::LauncherSettings settings;
    settings.db = config.db;
    settings.protocols = config.protocols;
    settings.names = lab::launcher_request_names();
    settings.session_arguments = o.session_arguments;
    settings.detail = o.detail_given;
    settings.resolution_scale = o.scale_given;
    lab::LauncherModel model(std::move(settings));
    if (!o.initial_headset.empty())
        if (Result<void> ok = model.set_headset(o.initial_headset); !ok)
            throw UserError("--headset: " + ok.error().message);
    if (!o.initial_observer.empty())
        if (Result<void> ok = model.set_observer(o.initial_observer); !ok)
            throw UserError("--observer: " + ok.error().message);
    model.set_seed(o.seed);
    lab::LauncherUi ui;
    ui.state_file = o.state_file;
    ui.screenshot_dir = o.screenshot_dir;
    ui.database_text = config.db.string();
    lab::LabConfig saved;  // what the file holds: written when it changes
    if (Result<lab::LabConfig> read = lab::read_lab_config(lab::lab_config_file())) saved = *read;
    for (;;) {
        const lab::LauncherExit exit = open_launcher(model, ui, o, global);
        remember(model, saved);
        if (!exit.launch) return;
        const std::string error = run_session(*exit.launch, o, global);
        if (!error.empty()) std::cerr << "monoplane lab: the session stopped: " << error << "\n";
        if (Result<void> ended = model.session_ended(error); !ended)
            ui.action_message = ended.error().message;
        ui.summary_lines = summary_lines(model);
    }
}

// The sessions' options as given ("--detail", "test", ...), in the order --help lists them; a
// script's path made absolute, so the shown command runs from any folder.
std::vector<std::string> given_session_options(const CLI::App& cmd) {
    std::vector<std::string> given;
    // --detail and --resolution-scale are the performance preset's (LabOptions::detail_given).
    for (const char* name : {"--neutral-s", "--end-s", "--sim-script", "--sim-rate"}) {
        const CLI::Option* option = cmd.get_option(name);
        if (option->count() == 0) continue;
        std::string value = option->results().back();
        if (std::string_view(name) == "--sim-script") value = fs::absolute(value).string();
        given.insert(given.end(), {name, value});
    }
    return given;
}

}  // namespace

void add_lab_command(CLI::App& root, const GlobalOptions& global) {
    auto o = std::make_shared<LabOptions>();
    o->protocols = default_protocols_folder();
    CLI::App* cmd = root.add_subcommand(
        "lab",
        "The experimenter's launcher window: database, protocol, participant, headset, "
        "session, summary, export and analysis (docs/lab.md)");
    cmd->add_option("--db", o->db, "Study database to open (created if missing)");
    cmd->add_option("--protocols", o->protocols, "Folder of protocol files")->capture_default_str();
    cmd->add_option("--state-file", o->state_file,
                    "Keep the launcher's state (JSON) in this file (tests, scripted checks)");
    cmd->add_option("--screenshot-dir", o->screenshot_dir,
                    "Save a PNG of each step shown into this folder (NN-<step>.png)");
    cmd->add_option("--headset", o->initial_headset,
                    "The headset step's first choice: none, simulated (default) or openxr")
        ->check(CLI::IsMember({"none", "simulated", "openxr"}));
    cmd->add_option("--observer", o->initial_observer,
                    "Who answers: none or a simulated observer, as `study run --observer`");
    cmd->add_option("--seed", o->seed,
                    "Sessions started here use this seed (as `study run --seed`); default: drawn "
                    "and recorded");
    HeadsetStudyOptions& h = o->headset;
    cmd->add_option("--detail", h.detail,
                    "Sessions: scene detail instead of the protocol's; with --resolution-scale it "
                    "chooses the window's performance preset (docs/lab.md)");
    cmd->add_option("--resolution-scale", h.resolution_scale,
                    "Sessions: eye size relative to the runtime's recommendation")
        ->capture_default_str()
        ->check(CLI::Range(0.05, 2.0));
    cmd->add_option("--neutral-s", h.neutral_s, "Sessions: neutral screen between trials, seconds")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 60.0));
    cmd->add_option("--end-s", h.end_s, "Sessions: how long the end screen stays, seconds")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 600.0));
    cmd->add_option("--sim-script", h.sim_script,
                    "The simulated headset's simxr script (sessions and the headset check)");
    cmd->add_option("--sim-rate", h.sim_rate_hz,
                    "Sessions on the simulated headset: its display rate in Hz (virtual clock)")
        ->capture_default_str()
        ->check(CLI::Range(1.0, 1000.0));
    cmd->callback([o, cmd, &global] {
        o->protocols_given = cmd->count("--protocols") > 0;
        o->session_arguments = given_session_options(*cmd);
        if (cmd->count("--detail") > 0) o->detail_given = o->headset.detail;
        if (cmd->count("--resolution-scale") > 0) o->scale_given = o->headset.resolution_scale;
        // The program's own options go with every session too (they may follow the command).
        std::vector<std::string> program;
        if (!global.device.empty()) program = {"--device", global.device};
        if (global.validation) program.push_back("--validation");
        o->session_arguments.insert(o->session_arguments.begin(), program.begin(), program.end());
        run_lab(*o, global);
    });
}

}  // namespace monoplane::app
