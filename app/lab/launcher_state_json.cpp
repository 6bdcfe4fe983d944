// LauncherModel::state_json: the window's state dump. Its keys are read by the end-to-end
// tests of `monoplane lab`, so they change only together with them.
#include <optional>

#include "app/lab/launcher_model.h"
#include "app/lab/shell_words.h"
#include "common/json_writer.h"

namespace monoplane::lab {
namespace {

void optional_int(JsonWriter& w, std::string_view key, std::optional<int> value) {
    if (value)
        w.value(key, *value);
    else
        w.null(key);
}

void write_protocols(JsonWriter& w, const LauncherModel& m) {
    w.begin_object("protocols")
        .value("folder", m.protocols_folder().string())
        .value("message", m.protocols_message());
    w.begin_array("files");
    for (const ProtocolChoice& p : m.protocols()) {
        w.begin_object()
            .value("file", p.file)
            .value("path", p.path.string())
            .value("valid", p.valid)
            .value("name", p.name)
            .value("message", p.message)
            .end_object();
    }
    w.end_array().end_object();
    if (!m.protocol()) {
        w.null("protocol");
        return;
    }
    w.begin_object("protocol")
        .value("path", m.protocol_path().string())
        .value("name", m.protocol()->name)
        .value("sessions", m.protocol()->day.sessions)
        .value("trials", m.protocol()->trials_per_session())
        .end_object();
}

// The participant's earlier sessions carry the roster's state of each.
void write_participant(JsonWriter& w, const LauncherModel& m) {
    w.begin_object("participant")
        .value("code", m.participant_code())
        .value("message", m.code_message())
        .value("known", m.participant().has_value());
    w.begin_array("sessions");
    if (m.participant()) {
        for (const auto& [number, id] : m.participant()->sessions) {
            std::string state;
            for (const RosterLine& line : m.roster())
                if (line.entry.row.session_id == id) state = line.state;
            w.begin_object()
                .value("session_number", number)
                .value("session_id", id)
                .value("state", state)
                .end_object();
        }
    }
    w.end_array().value("next_session_number", m.next_session_number());
    optional_int(w, "session_number", m.session_number());
    optional_int(w, "participant_number", m.participant_number());
    w.begin_array("problems");
    for (const std::string& problem : m.participant_problems()) w.value({}, problem);
    w.end_array().end_object();
}

void write_variables(JsonWriter& w, const LauncherModel& m) {
    w.begin_array("variables");
    for (const VariableField& f : m.variables()) {
        const study::ParticipantVariable& d = f.declaration;
        w.begin_object()
            .value("name", d.name)
            .value("type", study::variable_type_name(d.type))
            .value("required", d.required)
            .value("help", d.help);
        if (d.min) w.value("min", *d.min);
        if (d.max) w.value("max", *d.max);
        w.begin_array("choices");
        for (const std::string& choice : d.choices) w.value({}, choice);
        w.end_array()
            .value("value", f.text)
            .value("message", f.message)
            .value("recorded", f.recorded)
            .end_object();
    }
    w.end_array();
}

void write_headset(JsonWriter& w, const LauncherModel& m) {
    const HeadsetReport& h = m.headset_report();
    w.begin_object("headset")
        .value("choice", m.headset())
        .value("observer", m.observer())
        .value("runtime_available", h.runtime_available)
        .value("runtime", h.runtime)
        .value("system", h.system)
        .value("width", h.width)
        .value("height", h.height)
        .value("refresh_hz", h.refresh_hz);
    if (h.ipd_m)
        w.value("ipd_m", *h.ipd_m);
    else
        w.null("ipd_m");
    w.value("interaction_profile", h.interaction_profile)
        .value("answer_warning", h.answer_warning)
        .value("keys", m.keys())
        .value("keys_answer", m.answer_keys_enabled())
        .value("message", h.message)
        .value("check", h.check)
        .value("check_message", h.check_message)
        .value("check_frames", h.check_frames)
        .value("eye_gaze", h.eye_gaze)
        .value("eye_gaze_frames", h.check_gaze_frames)
        .end_object();
}

void optional_ms(JsonWriter& w, std::string_view key, std::optional<double> ms) {
    if (ms)
        w.value(key, *ms);
    else
        w.null(key);
}

// The session settings: every preset with what it passes to `study run` and its estimate (null
// until measured), the chosen one, its verdict and the measurement as it stands.
void write_settings(JsonWriter& w, const LauncherModel& m) {
    w.begin_object("settings");
    if (const PerformancePreset* p = m.preset())
        w.value("preset", p->name);
    else
        w.null("preset");
    w.begin_array("presets");
    for (const PerformancePreset& p : m.presets()) {
        w.begin_object().value("name", p.name).value("description", p.description);
        w.value("detail", p.detail).value("resolution_scale", p.resolution_scale);
        w.begin_array("arguments");
        for (const std::string& a : study_run_arguments(p)) w.value({}, a);
        w.end_array();
        optional_ms(w, "estimate_ms", m.estimate_ms(p.name));
        w.end_object();
    }
    w.end_array();
    optional_ms(w, "estimate_ms", m.preset() ? m.estimate_ms(m.preset()->name) : std::nullopt);
    if (const std::optional<FrameTimeVerdict> v = m.frame_time_verdict()) {
        w.begin_object("verdict")
            .value("text", v->text)
            .value("fits", v->fits)
            .value("tight", v->tight)
            .value("refresh_hz", v->refresh_hz)
            .value("ratio", v->ratio)
            .end_object();
    } else {
        w.null("verdict");
    }
    const FrameTimeMeasurement& f = m.measurement();
    w.begin_object("measurement")
        .value("state", f.state)
        .value("preset", f.preset)
        .value("message", f.message)
        .value("frames_done", f.frames_done)
        .value("frames_planned", f.frames_planned)
        .end_object();
    w.end_object();
}

void write_start(JsonWriter& w, const LauncherModel& m) {
    w.begin_object("start").value("enabled", m.start_enabled()).value("message", m.start_message());
    const std::vector<std::string> arguments = m.request().arguments();
    w.begin_array("arguments");
    for (const std::string& a : arguments) w.value({}, a);
    w.end_array().value("command_line", shell_command_line(arguments)).end_object();
}

// Each control as {"x", "y", "width", "height", "enabled"} under its name, in window pixels.
void write_controls(JsonWriter& w, const LauncherModel& m) {
    w.begin_object("controls");
    for (const ControlRect& c : m.controls()) {
        w.begin_object(c.name)
            .value("x", c.x)
            .value("y", c.y)
            .value("width", c.width)
            .value("height", c.height)
            .value("enabled", c.enabled)
            .value("visible", c.visible)
            .value("focused", c.focused)
            .value("open", c.open)
            .end_object();
    }
    w.end_object();
}

void write_roster(JsonWriter& w, const LauncherModel& m) {
    w.begin_array("roster");
    for (const RosterLine& line : m.roster()) {
        const study::RosterRow& r = line.entry.row;
        w.begin_object()
            .value("participant", r.participant_code)
            .value("participant_number", r.participant_number + 1)
            .value("session_number", r.session_number)
            .value("session_id", r.session_id)
            .value("status", study::session_status_name(r.status))
            .value("state", line.state)
            .value("trials_decided", r.trials_decided)
            .value("trials_planned", r.trials_planned)
            .value("started_utc", r.started_utc)
            .value("ended_utc", r.ended_utc)
            .value("resume_offered", line.resume_offered)
            .value("scene_files_changed", line.scene_files_changed)
            .value("resume_refusal", line.resume_refusal)
            .end_object();
    }
    w.end_array();
}

void write_summary(JsonWriter& w, const LauncherModel& m) {
    if (!m.summary()) {
        w.null("summary");
        return;
    }
    const SessionOutcome& s = *m.summary();
    w.begin_object("summary")
        .value("session_id", s.session_id)
        .value("participant", s.participant)
        .value("session_number", s.session_number)
        .value("state", s.state)
        .value("trials_decided", s.trials_decided)
        .value("trials_planned", s.trials_planned)
        .value("started_utc", s.started_utc)
        .value("ended_utc", s.ended_utc)
        .value("error", s.error)
        .end_object();
}

}  // namespace

std::string LauncherModel::state_json() const {
    JsonWriter w(JsonFormat{.indented = true, .significant_digits = 0});
    w.begin_object().value("step", step_name(step_));
    w.begin_object("database")
        .value("path", db_.string())
        .value("open", store_ != nullptr)
        .value("message", db_message_)
        .end_object();
    write_protocols(w, *this);
    write_participant(w, *this);
    write_variables(w, *this);
    write_headset(w, *this);
    write_settings(w, *this);
    write_start(w, *this);
    write_roster(w, *this);
    write_summary(w, *this);
    w.begin_object("window")
        .value("content_scale", content_scale_)
        .value("font_pixels", font_pixels_)
        .value("message", window_message_)
        .end_object();
    write_controls(w, *this);
    w.end_object();
    return w.str();
}

}  // namespace monoplane::lab
