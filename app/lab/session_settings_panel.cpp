// The Headset step's session settings: the performance preset (performance_preset.h), a
// frame-time measurement run on a worker (frame_time_job.h) so the window keeps drawing, the
// estimate per preset and the verdict against the headset's refresh rate; and the warning when
// the headset check found that nobody can answer (app/headset/answer_channels.h).
#include <imgui.h>

#include <algorithm>
#include <climits>
#include <string>
#include <vector>

#include "app/headset/answer_channels.h"
#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {

// "protocol" is the protocol's [responses] (no --keys); the others are --keys' own words.
void LauncherPanels::draw_keys_choice() {
    ImGui::TextUnformatted("Answer keys:");
    ImGui::SameLine();
    std::string chosen = model_.keys().empty() ? "protocol" : model_.keys();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    draw_choice(controls_, "keys", "##keys", {"protocol", "default", "none"}, chosen);
    const std::string keys = chosen == "protocol" ? "" : chosen;
    if (keys != model_.keys()) note(model_.set_keys(keys));
    ImGui::SameLine();
    coloured_text(kDim, model_.answer_keys_enabled()
                            ? "keys answer too, in the session's window (Left/Right switch, "
                              "Return confirms, unless the protocol names others)"
                            : "no keys: only the controller (or a simulated observer) answers");
}

bool LauncherPanels::measuring_refuses(const char* what) {
    if (!frame_time_job_.running()) return false;
    ui_.action_message = std::string(
                             "the frame time is being measured: wait for it, or cancel "
                             "it, before ") +
                         what;
    return true;
}

void LauncherPanels::draw_session_settings() {
    poll_measurement();
    if (!model_.preset()) return;
    ImGui::Spacing();
    ImGui::TextUnformatted("Performance preset:");
    ImGui::SameLine();
    std::vector<std::string> names;
    for (const PerformancePreset& p : model_.presets()) names.push_back(p.name);
    std::string chosen = model_.preset()->name;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    ImGui::BeginDisabled(frame_time_job_.running());
    draw_choice(controls_, "preset", "##preset", names, chosen);
    ImGui::EndDisabled();
    if (chosen != model_.preset()->name) note(model_.set_preset(chosen));
    ImGui::SameLine();
    if (frame_time_job_.running()) {
        if (ImGui::Button("Cancel measuring")) frame_time_job_.cancel();
        controls_.mark("cancel-measure");
    } else if (actions_.probe_frame_time) {
        if (ImGui::Button("Measure frame time")) measure_frame_time();
        controls_.mark("measure");
    }
    coloured_text(kDim, model_.preset()->description);
    draw_estimates();
    draw_measurement();
    draw_verdict();
}

// One line: each preset's estimate as measured, "-" before.
void LauncherPanels::draw_estimates() {
    std::string line = "Estimated frame time:";
    for (const PerformancePreset& p : model_.presets()) {
        const std::optional<double> ms = model_.estimate_ms(p.name);
        line += "  " + p.name + " " + (ms ? format_frame_time(*ms) : std::string("-"));
    }
    ImGui::TextUnformatted(line.c_str());
    controls_.mark("estimates", false, false);
}

// Green when the chosen preset keeps the rate, yellow when only just, red when it cannot; a
// line kept empty before the measurement, so Start does not move when the verdict comes.
void LauncherPanels::draw_verdict() {
    const std::optional<FrameTimeVerdict> verdict = model_.frame_time_verdict();
    if (!verdict) {
        ImGui::TextUnformatted(" ");
    } else {
        coloured_text(!verdict->fits ? kError : verdict->tight ? kWarn : kGood, verdict->text);
    }
    controls_.mark("verdict", false, false);
}

void LauncherPanels::draw_measurement() {
    const FrameTimeMeasurement& m = model_.measurement();
    if (frame_time_job_.running()) {
        const ProbeProgress p = frame_time_job_.progress();
        const std::string text =
            "Measuring '" + m.preset + "': frame " + std::to_string(p.frames_done + 1) + " of " +
            std::to_string(std::max(p.frames_planned, 1)) +
            (p.condition.empty() ? std::string(" (preparing the scenes)") : ", " + p.condition);
        coloured_text(kWarn, text);
        FrameTimeMeasurement now = m;
        now.message = p.condition;
        now.frames_done = p.frames_done;
        now.frames_planned = p.frames_planned;
        model_.set_measurement(std::move(now));
    } else if (m.state == "failed" || m.state == "cancelled") {
        coloured_text(kError, "Measurement " + m.state + ": " + m.message);
    } else if (m.state == "done") {
        coloured_text(kDim, "Measured '" + m.preset + "': the slowest condition was " + m.message);
    } else {
        coloured_text(kDim,
                      "Measure renders the protocol's scenes with the preset for about 2 s "
                      "after preparing them, on this computer's graphics device.");
    }
}

void LauncherPanels::measure_frame_time() {
    if (!actions_.probe_frame_time || !model_.protocol() || !model_.preset()) return;
    FrameTimeProbeRequest request;
    request.protocol = *model_.protocol();
    request.preset = *model_.preset();
    const HeadsetReport& report = model_.headset_report();
    // The app uses the HMD profile's size where no runtime recommended one.
    request.recommended_width = report.runtime_available ? report.width : 0;
    request.recommended_height = report.runtime_available ? report.height : 0;
    request.budget_s = 2.0;
    request.frames_per_condition = 3;
    if (!note(frame_time_job_.start(actions_.probe_frame_time, std::move(request)))) return;
    model_.set_measurement({"running", model_.preset()->name, "", 0, 0});
}

void LauncherPanels::poll_measurement() {
    std::optional<Result<FrameTimeEstimate>> result = frame_time_job_.take_result();
    if (!result) return;
    FrameTimeMeasurement m = model_.measurement();
    if (*result) {
        model_.set_frame_time_estimate({m.preset, (*result)->frame_ms});
        m.state = "done";
        m.message = (*result)->slowest + " on " + (*result)->device;
    } else {
        const std::string& why = result->error().message;
        m.state = why.find("cancelled") != std::string::npos ? "cancelled" : "failed";
        m.message = why;
    }
    model_.set_measurement(std::move(m));
}

std::string LauncherPanels::answers_warning(const std::string& profile, std::int64_t frames) const {
    if (model_.protocol() == nullptr || model_.headset() == "none") return {};
    headset::AnswerChannels channels;
    channels.interaction_profile = profile;
    channels.focused_syncs = static_cast<int>(std::min<std::int64_t>(frames, INT_MAX));
    channels.keys = model_.answer_keys_enabled();
    channels.observer = model_.observer_answers();
    return headset::cannot_answer_message(channels).value_or("");
}

void LauncherPanels::judge_answers(const std::string& profile, std::int64_t frames) {
    HeadsetReport report = model_.headset_report();
    const std::string warning = answers_warning(profile, frames);
    if (warning == report.answer_warning) return;
    report.answer_warning = warning;
    model_.set_headset_report(std::move(report));
}

}  // namespace monoplane::lab
