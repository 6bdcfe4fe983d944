// The model of `monoplane lab`, the experimenter's launcher: what each step shows and whether the
// session may start, without any window toolkit, so the window only draws it and forwards input,
// and tests drive it directly.
//
// Every rule comes from the code the commands call, never from a copy here: protocols are judged
// by study::load_protocol (as `protocol check` does), participant codes by
// study::check_participant_code, each variable field by study::check_variable_value, the whole
// request by study::plan_session (as `study run` does), the roster by study::read_roster and a
// session's hold by study::SessionHold. Start produces the options `study run` takes
// (LaunchRequest), so a session started here is the command's session.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/lab/performance_preset.h"
#include "common/result.h"
#include "study/protocol.h"
#include "study/roster.h"
#include "study/session_start.h"
#include "study/study_store.h"

namespace monoplane::lab {

// The launcher's steps, in the order the day goes through them.
enum class LauncherStep { Database, Protocol, Participant, Headset, Session, Summary };

// "database", "protocol", "participant", "headset", "session", "summary": state_json's names.
std::string_view step_name(LauncherStep step);

// One *.toml file of the protocols folder with the verdict `protocol check` gives its text.
struct ProtocolChoice {
    std::filesystem::path path;
    std::string file;     // the file name, as listed
    bool valid = false;   // study::load_protocol accepted it
    std::string name;     // the protocol's name when valid
    std::string message;  // load_protocol's problems, one per line, "FILE:LINE:COL: ..."
};

// The *.toml files of `folder`, sorted by file name, each loaded with study::load_protocol.
// Imported glTF scenes are not loaded here (run_study loads and digests them at Start, as the
// command does): a protocol naming a broken glTF file lists as valid. Errors: a folder that
// does not exist or cannot be read. Any time; reads every file.
Result<std::vector<ProtocolChoice>> list_protocols(const std::filesystem::path& folder);

// A roster line with what the launcher may offer for it.
struct RosterLine {
    study::RosterEntry entry;
    std::string state;  // entry.state(): "completed", "interrupted", "running (process ...)"
    // `study resume` would continue it now: not completed, not held by a running process,
    // and its scene files as recorded.
    bool resume_offered = false;
    // Only the scene files stand in the way: `study resume --accept-changed-scenes` would go on.
    bool scene_files_changed = false;
    // Why Resume is not offered for a session that is not completed (held, changed scene files);
    // empty otherwise.
    std::string resume_refusal;
};

// The roster of `database` (study::read_roster) with each unfinished session's resume verdict.
// Errors: the store's, naming the file. Any time, also while sessions run; reads the recorded
// scene files of every unfinished session.
Result<std::vector<RosterLine>> read_launcher_roster(const std::filesystem::path& database);

// A form field of one declared participant variable.
struct VariableField {
    study::ParticipantVariable declaration;
    std::string text;       // as typed (or as recorded for a returning participant)
    std::string message;    // study::check_variable_value's problem with the text; empty if none
    bool recorded = false;  // a returning participant's: read-only, variables do not change
};

// What the headset step found (filled in by the window, which probes OpenXR); shown as is.
struct HeadsetReport {
    bool runtime_available = false;
    std::string runtime;              // the OpenXR runtime's name
    std::string system;               // the headset's system name
    int width = 0, height = 0;        // recommended eye image size, pixels
    double refresh_hz = 0.0;          // 0: not reported
    std::optional<double> ipd_m;      // the IPD the runtime reports
    std::string interaction_profile;  // once bound
    // Whether the headset tracks the eyes: "tracked", "not tracked", "not offered" (by the
    // runtime), "" not known; and that in a sentence for the experimenter.
    std::string eye_gaze;
    std::string eye_gaze_text;
    std::string message;  // e.g. "no OpenXR runtime"; empty when available
    // Set by the window from the last check: "no controller bound: ..." when the check found no
    // controller bound and neither [responses] keys nor a simulated observer answer; else "".
    std::string answer_warning;
    // The last headset check: how it ended ("" none yet, "confirmed", "cancelled", "timed out",
    // "runtime ended the session", "runtime lost", "failed": it could not run), what it said,
    // and the frames it showed the participant.
    std::string check;
    std::string check_message;
    std::int64_t check_frames = 0;
    std::int64_t check_gaze_frames = 0;  // of check_frames, those with a valid gaze sample
};

// What Start (or Resume) hands to `study run` (or `study resume`): the fields of the commands'
// StudyOptions (app/commands/study_options.h) of the same names, nothing else set.
struct LaunchRequest {
    enum class Command { Run, Resume };
    Command command = Command::Run;
    std::string protocol;     // run: the protocol file
    std::string db;           // the study database
    std::string participant;  // run: the participant code
    std::optional<int> session_number;
    std::optional<int> participant_number;
    std::vector<std::string> variables;  // run: "NAME=VALUE", as --var takes them
    std::optional<std::uint64_t> seed;   // none: drawn by run_study and recorded, as the command
    std::optional<std::int64_t> session_id;  // resume: the database's session id
    bool accept_changed_scenes = false;      // resume only
    std::string headset = "simulated";       // none, simulated or openxr
    std::string observer;                    // "": the command's default for the headset
    // The sessions' other options as `study run` takes them ("--detail", "test", ...): what
    // `monoplane lab` was given for its sessions, so the shown command is the session's.
    std::vector<std::string> session_arguments;
    // The session settings' performance preset (none: the command's defaults): run gets its
    // detail and resolution scale, resume its resolution scale only (a resumed session renders
    // at the detail it began with).
    std::optional<PerformancePreset> preset;
    // The participant's answer keys as `study run --keys` takes them: "" the protocol's
    // [responses], "default" (Left/Right switch, Return confirms) or "none".
    std::string keys;

    // The same request as a command line after `monoplane` ("study", "run", "--protocol", ...):
    // shown to the experimenter so the session can be repeated from a shell. Any time.
    std::vector<std::string> arguments() const;
};

// A control the window drew, where it drew it (window pixels): the state dump lists them so that
// scripted checks click where a person would.
struct ControlRect {
    std::string name;
    float x = 0, y = 0, width = 0, height = 0;
    bool enabled = true;
    bool visible = true;   // not scrolled out of its list
    bool focused = false;  // has the keyboard
    bool open = false;     // a combo box whose list is open (keys go to the list)
};

// A finished (or stopped) session, for the summary step.
struct SessionOutcome {
    std::int64_t session_id = 0;
    std::string participant;
    int session_number = 0;
    std::string state;  // as the roster says it
    int trials_decided = 0;
    int trials_planned = 0;
    std::string started_utc, ended_utc;
    std::string error;  // what run_study reported when it stopped with an error; empty if none
};

// The session settings' frame-time measurement as the window runs it (frame_time_job.h).
struct FrameTimeMeasurement {
    std::string state;    // "" none yet, "running", "done", "failed", "cancelled"
    std::string preset;   // the preset measured
    std::string message;  // running: the condition drawn next; failed: why
    int frames_done = 0;
    int frames_planned = 0;
};

struct LauncherSettings {
    std::filesystem::path db;         // --db FILE; empty: chosen in the window
    std::filesystem::path protocols;  // --protocols DIR
    // How the messages about the participant's request name its inputs: `monoplane lab` gives
    // launcher_request_names() (the window's fields), so a problem is said where it is fixed.
    study::RequestNames names = study::study_request_names();
    // LaunchRequest::session_arguments of every request.
    std::vector<std::string> session_arguments = {};
    // `monoplane lab --detail / --resolution-scale`: they choose the performance preset of the
    // same detail and scale, else a preset "custom" of them (docs/lab.md, "Session settings").
    std::optional<std::string> detail = std::nullopt;
    std::optional<double> resolution_scale = std::nullopt;
};

// How the launcher names the inputs of a request in its messages: the window's fields and
// buttons ("the 'age' field", "session 2"), never command-line options.
const study::RequestNames& launcher_request_names();

class LauncherModel {
  public:
    // Lists the protocols folder and opens (creating) the database when the settings name them;
    // a failure of either is kept as that step's message. Any time.
    explicit LauncherModel(LauncherSettings settings);
    ~LauncherModel();
    LauncherModel(LauncherModel&&) noexcept;
    LauncherModel& operator=(LauncherModel&&) noexcept;

    LauncherStep step() const { return step_; }
    // Moves to an earlier step, or to the next one when this one is done (database open,
    // protocol chosen, participant code valid). Session and Summary come from start() and
    // session_ended() only, and no step is left while a session runs. Any time.
    Result<void> go_to(LauncherStep step);

    // Database step. Opens `path` with study::StudyStore::open; a missing file is created only
    // when `create` (the window's "Create"). Reads the roster. Any time but during a session.
    Result<void> open_database(const std::filesystem::path& path, bool create);
    bool database_open() const { return store_ != nullptr; }
    const std::filesystem::path& database() const { return db_; }
    const std::string& database_message() const { return db_message_; }
    // Reads the roster again (after a session, or when another PC may have written). Any time
    // with a database open; the error is also kept as the database step's message.
    Result<void> refresh_roster();
    const std::vector<RosterLine>& roster() const { return roster_; }

    // Protocol step. Lists `folder` again (list_protocols). Any time but during a session.
    Result<void> scan_protocols(const std::filesystem::path& folder);
    // Lists the folder again when its files changed (a file saved, added or removed, the folder
    // made or removed) since the last listing; true when it did. Cheap (one directory listing):
    // the window calls it every second. Any time but during a session.
    bool rescan_protocols_if_changed();
    const std::vector<ProtocolChoice>& protocols() const { return protocols_; }
    const std::string& protocols_message() const { return protocols_message_; }
    // Chooses a protocol file: one listed, or any other path (a protocol kept elsewhere); it is
    // loaded again, so an edit since the listing counts. Refused: no such file, or one that is
    // not valid (its problems; no protocol is chosen then). Rebuilds the variables form.
    // Any time but during a session.
    Result<void> select_protocol(const std::filesystem::path& path);
    const study::Protocol* protocol() const { return protocol_ ? &*protocol_ : nullptr; }
    const std::filesystem::path& protocol_path() const { return protocol_path_; }
    const std::filesystem::path& protocols_folder() const { return protocols_dir_; }

    // Participant step: each call validates at once (the window calls them per keystroke).
    void set_participant_code(const std::string& code);
    const std::string& participant_code() const { return code_; }
    const std::string& code_message() const { return code_message_; }
    // The participant as the database knows them; none for a new (or invalid) code.
    const std::optional<study::ParticipantRecord>& participant() const { return participant_; }
    // The session the participant would start: their next, unless set_session_number says.
    int next_session_number() const;
    std::optional<int> session_number() const { return session_number_; }
    std::optional<int> participant_number() const { return participant_number_; }
    void set_session_number(std::optional<int> number);
    void set_participant_number(std::optional<int> number);
    // Sets a form field's text; refused for an undeclared name or a recorded field.
    Result<void> set_variable(const std::string& name, const std::string& text);
    const std::vector<VariableField>& variables() const { return fields_; }
    // What keeps this participant from starting that the Participant step can fix (a required
    // field empty, their sessions all done, an unfinished earlier session), in the window's
    // words; empty when nothing there stands in the way. Any time.
    const std::vector<std::string>& participant_problems() const { return participant_problems_; }
    // "Next participant": a new code and form for the same protocol (and database, headset):
    // the code, the typed variables, the session and participant numbers and the summary are
    // cleared, and the step is Participant (Protocol when none is chosen). Any time but during
    // a session.
    Result<void> next_participant();

    // Headset step. `headset`: none, simulated or openxr. `observer`: "" (the command's
    // default), none, or a simulated observer study::make_observer accepts.
    Result<void> set_headset(const std::string& headset);
    Result<void> set_observer(const std::string& observer);
    // The probe's (or check's) report for the headset chosen now: with no runtime, Start is
    // disabled with the report's message.
    void set_headset_report(HeadsetReport report);
    // How the window draws (its monitor's content scale and the font size that gives), for the
    // state dump: the window sets it when it opens. Any time.
    void set_window_scale(double content_scale, double font_pixels) {
        content_scale_ = content_scale;
        font_pixels_ = font_pixels;
    }
    const std::string& headset() const { return headset_; }
    const std::string& observer() const { return observer_; }
    const HeadsetReport& headset_report() const { return headset_report_; }
    // Where the window drew its controls this frame (for the state dump). Any time.
    void set_controls(std::vector<ControlRect> controls) { controls_ = std::move(controls); }
    const std::vector<ControlRect>& controls() const { return controls_; }
    // The footer's message (the last refused action), for the state dump. Any time.
    void set_window_message(std::string message) { window_message_ = std::move(message); }
    // A fixed seed (tests, a repeated session); none: drawn and recorded, as the command does.
    void set_seed(std::optional<std::uint64_t> seed);

    // Session settings (Headset step). The presets for the chosen protocol (presets_for, plus
    // "custom" when the command line's --detail / --resolution-scale match none); empty with no
    // protocol. The chosen one: the command line's match, else "full", until set_preset.
    const std::vector<PerformancePreset>& presets() const { return presets_; }
    const PerformancePreset* preset() const;
    Result<void> set_preset(const std::string& name);
    // A measured estimate (kept per preset until the protocol or the eye size changes).
    void set_frame_time_estimate(PresetEstimate estimate);
    std::optional<double> estimate_ms(const std::string& preset) const;
    const std::vector<PresetEstimate>& estimates() const { return estimates_; }
    // judge_frame_time of the chosen preset's estimate at the headset's refresh rate; none
    // before it was measured.
    std::optional<FrameTimeVerdict> frame_time_verdict() const;
    void set_measurement(FrameTimeMeasurement measurement) {
        measurement_ = std::move(measurement);
    }
    const FrameTimeMeasurement& measurement() const { return measurement_; }
    // The Headset step's answer keys (LaunchRequest::keys): "", "default" or "none"; refused as
    // `study run --keys` refuses it. Any time.
    Result<void> set_keys(const std::string& keys);
    const std::string& keys() const { return keys_; }
    // Whether keys answer: the protocol's [responses] with the keys choice over it.
    bool answer_keys_enabled() const;
    // Whether a simulated observer answers the sessions, as run_study decides: a named observer
    // on any headset; "none", or openxr without one, leaves the answers to the participant.
    bool observer_answers() const;

    // Whether study::plan_session accepts the request as it stands (with a database open and a
    // protocol chosen); otherwise the message says why, one problem per line.
    bool start_enabled() const { return start_message_.empty(); }
    const std::string& start_message() const { return start_message_; }
    // The request as it stands, whether or not Start is enabled. Any time.
    LaunchRequest request() const;
    // Start: the request for run_study, and the Session step. Refused with start_message()
    // while Start is disabled. Any time before a session runs.
    Result<LaunchRequest> start();
    // Resume of a roster session (by database session id): the request for resume_study, and
    // the Session step. Refused when the roster does not offer it (its refusal), unless only
    // scene files changed and `accept_changed_scenes`. Any time before a session runs.
    Result<LaunchRequest> resume(std::int64_t session_id, bool accept_changed_scenes);
    // The window's session has returned (`error`: run_study's message if it threw): reads the
    // session's summary and the roster again, and moves to Summary. Only in the Session step.
    Result<void> session_ended(const std::string& error);
    const std::optional<SessionOutcome>& summary() const { return summary_; }

    // Everything a step shows, as one JSON object (keys: step, database, protocols, protocol,
    // participant, variables, headset, start, roster, summary): the window's state dump, which
    // end-to-end tests read. Any time.
    std::string state_json() const;

  private:
    // The roster from the snapshot open now (store_); its error is kept as the database step's
    // message.
    Result<void> read_roster_lines();

    void revalidate();
    // The presets for protocol_ and the command line's options (launcher_session_settings.cpp).
    void rebuild_presets();
    void find_participant_problems();
    void rebuild_fields();
    // After a Resume from a step before Protocol: the folder's protocol of the resumed session's
    // name, so that Next participant goes on with it.
    void choose_protocol_named(const std::string& name);
    Result<void> step_done(LauncherStep step) const;

    study::RequestNames names_;  // LauncherSettings::names
    LauncherStep step_ = LauncherStep::Database;
    std::filesystem::path db_;
    std::unique_ptr<study::StudyStore> store_;
    std::string db_message_;
    std::vector<RosterLine> roster_;
    std::filesystem::path protocols_dir_;
    std::vector<ProtocolChoice> protocols_;
    std::string protocols_message_;
    std::string protocols_signature_;  // the folder's files when last listed
    std::filesystem::path protocol_path_;
    std::optional<study::Protocol> protocol_;
    std::string code_;
    std::string code_message_;
    std::optional<study::ParticipantRecord> participant_;
    std::optional<int> session_number_;
    std::optional<int> participant_number_;
    std::vector<VariableField> fields_;
    std::vector<std::string> participant_problems_;
    std::vector<std::string> session_arguments_;
    std::vector<ControlRect> controls_;
    std::string window_message_;
    bool headset_probed_ = false;  // headset_report_ is the chosen headset's
    std::string headset_ = "simulated";
    std::string observer_;
    HeadsetReport headset_report_;
    double content_scale_ = 0.0;  // 0: no window has opened
    double font_pixels_ = 0.0;
    std::optional<std::uint64_t> seed_;
    std::string start_message_;
    std::optional<LaunchRequest> launched_;
    int launched_session_number_ = 0;  // the participant's session Start planned
    std::optional<SessionOutcome> summary_;
    std::optional<std::string> detail_option_;  // LauncherSettings::detail
    std::optional<double> scale_option_;        // LauncherSettings::resolution_scale
    std::vector<PerformancePreset> presets_;
    std::string preset_name_;
    bool preset_chosen_ = false;  // set_preset was called: the experimenter's choice stays
    std::vector<PresetEstimate> estimates_;
    FrameTimeMeasurement measurement_;
    std::string keys_;  // LaunchRequest::keys
};

}  // namespace monoplane::lab
