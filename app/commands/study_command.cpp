// `monoplane study run|resume|export|list|note|migrate`: the command line of 2AFC study sessions
// (docs/study.md). This file declares the options; study_session.cpp runs and resumes sessions,
// study_roster.cpp exports, lists and notes, study_migrate.cpp migrates.
#include <memory>

#include "app/commands/commands.h"
#include "app/commands/runtime_lost.h"
#include "app/commands/study_options.h"
#include "app/commands/study_probe_command.h"

namespace monoplane::app {
namespace {

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
    cmd->add_option("--end-s", h.end_s,
                    "How long the protocol's end screen stays in the headset, seconds (closing "
                    "the experimenter window ends it sooner)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 600.0));
    cmd->add_option("--layer-depth", h.layer_depth,
                    "Submit each eye's depth with its colour when the OpenXR runtime offers "
                    "XR_KHR_composition_layer_depth (auto), or never (off)")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "off"}));
    cmd->add_option("--screenshot", h.screenshot,
                    "PNG of the experimenter window when the session ends, and the window's state "
                    "as JSON beside it (the same name, .json)");
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
    cmd->add_option("--keys", h.keys,
                    "The participant's answer keys over the protocol's [responses]: default "
                    "(Left/Right switch, Return confirms), none, or switch=KEY,confirm=KEY with X "
                    "key names (an action named twice gets two keys); read from the experimenter "
                    "window, or from --response-device (docs/study.md)");
    cmd->add_option("--response-device", h.response_device,
                    "Read the answer keys from this evdev device (a response box seen as a "
                    "keyboard), e.g. /dev/input/by-id/usb-...-event-kbd; needs read access "
                    "(the 'input' group)");
}

// Which session: the participant's number, or the database's id (study list shows both).
void add_session_choice(CLI::App* cmd, StudyOptions& o, const std::string& what) {
    cmd->add_option("--participant", o.participant, "Participant code" + what);
    cmd->add_option("--session", o.session_number,
                    "The participant's session number (1, 2, ...; with --participant)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--session-id", o.session_id,
                    "The database's session id instead (study list shows it)");
}

void add_run_command(CLI::App* study, const std::shared_ptr<StudyOptions>& options,
                     const GlobalOptions& global) {
    CLI::App* run = study->add_subcommand("run", "Run a session of a protocol");
    run->add_option("--protocol", options->protocol, "Protocol file (TOML; docs/protocols.md)")
        ->required();
    run->add_option("--participant", options->participant,
                    "Pseudonymous participant code (1-64 of A-Z a-z 0-9 _ -; never a name)")
        ->required();
    run->add_option("--db", options->db, "Study database (SQLite; created if absent)")->required();
    run->add_option("--session", options->session_number,
                    "The participant's session number (default: their next; the protocol's "
                    "`sessions` says how many)");
    run->add_option("--var", options->variables,
                    "A participant variable the protocol declares, NAME=VALUE (repeatable; "
                    "recorded at the participant's first session)");
    run->add_option("--participant-number", options->participant_number,
                    "The participant's number in the whole study, 1-based, which picks the "
                    "Latin-square row (default: their position in this database; give it when "
                    "a study runs on several PCs or sites)");
    run->add_option(
        "--abandon", options->abandon,
        "SESSION \"reason\": end the participant's interrupted session SESSION for good "
        "(recorded with the reason; study list shows it abandoned) and start their "
        "next. Without it an interrupted session must be resumed first");
    run->add_option("--protocol-changed", options->protocol_changed,
                    "\"reason\": start a session whose protocol's design (scenes, distances, "
                    "alternatives, procedure, repetitions, ...) differs from the participant's "
                    "earlier sessions'; the reason and the differences are recorded");
    run->add_option("--headset", options->headset, "none, simulated or openxr")
        ->capture_default_str();
    run->add_option("--observer", options->observer,
                    "Simulated observer: default, chance, reference, psychometric:... or none (a "
                    "person, or the simulated runtime's scripted controller); default: none with "
                    "openxr, else default");
    run->add_option("--hmd", options->hmd,
                    "HMD profile: the observer's error model, and the simulated headset")
        ->capture_default_str();
    run->add_option("--seed", options->seed,
                    "Session seed: the same protocol, seed and participant and session numbers "
                    "give the same schedule (default: drawn and recorded)");
    run->add_option("--pace-ms", options->pace_ms, "Sleep per logged event (tests)");
    run->add_flag("--trace", options->trace, "Print each durable write on stdout");
    run->add_flag("--trace-stop", options->trace_stop,
                  "As --trace, and stop (SIGSTOP) after each line until SIGCONT (test harnesses)");
    add_headset_options(run, *options);
    run->footer(kSessionExitStatusHelp);
    run->callback([options, &global] { run_study(*options, global); });
}

void add_resume_command(CLI::App* study, const std::shared_ptr<StudyOptions>& options,
                        const GlobalOptions& global) {
    CLI::App* resume = study->add_subcommand(
        "resume", "Continue an interrupted session (not one another process is running)");
    resume->add_option("--db", options->db, "Study database (SQLite)")->required();
    add_session_choice(resume, *options,
                       " (default: the database's latest unfinished session; with it alone: "
                       "the participant's latest unfinished one)");
    resume->add_option("--headset", options->headset, "none, simulated or openxr")
        ->capture_default_str();
    resume->add_option("--observer", options->observer,
                       "Simulated observer (default: the session's)");
    resume->add_option("--hmd", options->hmd, "HMD profile")->capture_default_str();
    resume->add_option("--pace-ms", options->pace_ms, "Sleep per logged event (tests)");
    resume->add_flag("--trace", options->trace, "Print each durable write on stdout");
    resume->add_flag(
        "--trace-stop", options->trace_stop,
        "As --trace, and stop (SIGSTOP) after each line until SIGCONT (test harnesses)");
    resume->add_flag("--accept-changed-scenes", options->accept_changed_scenes,
                     "Resume although scene files (glTF) changed since the session began; "
                     "refused without it. The session's notes record each changed file");
    add_headset_options(resume, *options);
    resume->footer(kSessionExitStatusHelp);
    resume->callback([options, &global] { resume_study(*options, global); });
}

void add_export_command(CLI::App* study, const std::shared_ptr<StudyOptions>& options) {
    CLI::App* exp =
        study->add_subcommand("export", "Export the trials, frames, notes, presses or gaze");
    exp->add_option("--db", options->db, "Study database (SQLite)")->required();
    exp->add_option("--format", options->format,
                    "csv or json (the trials), frames-csv (the frame and head log of headset "
                    "sessions), notes-csv (the sessions' notes), presses-csv (every press of "
                    "the participant's controller and keys, with its source) or gaze-csv (every "
                    "eye gaze sample of the sessions that recorded gaze: personal data)")
        ->capture_default_str();
    exp->add_option("--out", options->out,
                    "Output file: written beside and renamed into place, with FILE.source (the "
                    "study it came from) beside it; never a database, and an existing file only "
                    "if it is an earlier export of the same format and study")
        ->required();
    exp->add_flag("--force", options->force,
                  "Replace an existing --out that is not an earlier export of this format, or "
                  "is another study's (never a database)");
    exp->callback([options] { export_study(*options); });
}

void add_list_command(CLI::App* study, const std::shared_ptr<StudyOptions>& options) {
    CLI::App* list = study->add_subcommand(
        "list",
        "The roster: every participant and session, with status, progress and whether it holds "
        "eye gaze");
    list->add_option("--db", options->dbs,
                     "Study database(s) (SQLite; repeatable); read, never written")
        ->required();
    list->add_flag("--json", options->json, "JSON instead of a table");
    list->callback([options] { list_study(*options); });
}

void add_note_command(CLI::App* study, const std::shared_ptr<StudyOptions>& options) {
    CLI::App* note = study->add_subcommand(
        "note", "Add an experimenter's note to a session (stored at once, with the time)");
    note->add_option("--db", options->db, "Study database (SQLite)")->required();
    add_session_choice(note, *options, " (with --session: that session; else their latest)");
    note->add_option("text", options->note, "The note")->required();
    note->callback([options] { note_study(*options); });
}

void add_migrate_command(CLI::App* study, const std::shared_ptr<StudyOptions>& options) {
    CLI::App* migrate = study->add_subcommand(
        "migrate",
        "Bring a study database of an older schema to this build's, keeping the original as "
        "FILE.schema<N>.bak (list, export and analyze read older schemas without it)");
    migrate->add_option("--db", options->db, "Study database (SQLite)")->required();
    migrate->callback([options] { migrate_study(*options); });
}

}  // namespace

void add_study_command(CLI::App& root, const GlobalOptions& global) {
    CLI::App* study = root.add_subcommand(
        "study",
        "Run, resume, export, list, annotate and migrate 2AFC study sessions (docs/study.md)");
    study->require_subcommand(1);
    auto options = std::make_shared<StudyOptions>();
    add_run_command(study, options, global);
    add_resume_command(study, options, global);
    add_export_command(study, options);
    add_list_command(study, options);
    add_note_command(study, options);
    add_migrate_command(study, options);
    add_study_probe_command(study, global);
}

}  // namespace monoplane::app
