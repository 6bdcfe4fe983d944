// The Headset and Start step: the headset chosen and probed, its report and the last check's
// result, who answers, and Start with the equivalent command line. The session settings under
// it are in session_settings_panel.cpp, the check's own frames in
// launcher_panels_headset_check.cpp.
#include <imgui.h>

#include <string>
#include <utility>
#include <vector>

#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"
#include "app/lab/shell_words.h"

namespace monoplane::lab {

void LauncherPanels::probe_if_needed() {
    if (probed_choice_ == model_.headset()) return;
    probed_choice_ = model_.headset();
    const HeadsetReport before = model_.headset_report();
    if (model_.headset() == "none") {
        model_.set_headset_report(HeadsetReport{});
        return;
    }
    if (!actions_.probe_headset) return;
    Result<HeadsetReport> probed = actions_.probe_headset(model_.headset());
    HeadsetReport report;
    if (probed) {
        report = std::move(probed).value();
    } else {
        report.message = probed.error().message;
    }
    // What the last check measured stays while the same headset is shown again.
    if (report.runtime_available && before.runtime == report.runtime &&
        before.system == report.system && !before.check.empty()) {
        report.refresh_hz = before.refresh_hz;
        report.ipd_m = before.ipd_m;
        report.interaction_profile = before.interaction_profile;
        report.check = before.check;
        report.check_message = before.check_message;
        report.check_frames = before.check_frames;
        report.check_gaze_frames = before.check_gaze_frames;
    }
    report.answer_warning = answers_warning(report.interaction_profile, report.check_frames);
    model_.set_headset_report(std::move(report));
}

void LauncherPanels::request_check() {
    if (model_.step() != LauncherStep::Headset) {
        ui_.action_message = "the headset check is in the Headset step";
        return;
    }
    if (measuring_refuses("checking the headset")) return;
    if (!actions_.check_headset || model_.headset() == "none") {
        ui_.action_message = "choose the simulated or the OpenXR headset to check it";
        return;
    }
    if (!model_.headset_report().runtime_available) {
        ui_.action_message = "no headset to check: " + model_.headset_report().message;
        return;
    }
    ui_.action_message.clear();
    check_requested_ = true;
}

void LauncherPanels::draw_headset() {
    probe_if_needed();
    ImGui::TextUnformatted("Headset:");
    for (const char* headset : {"simulated", "openxr", "none"}) {
        ImGui::SameLine();
        if (ImGui::RadioButton(headset, model_.headset() == headset)) {
            note(model_.set_headset(headset));
            probe_if_needed();
        }
        controls_.mark(std::string("headset:") + headset);
    }
    draw_headset_report();
    // As run_study decides: a named observer answers on any headset; "none", or openxr without
    // one, leaves the answers to the controller.
    const std::string& observer = model_.observer();
    if (observer == "none" || (model_.headset() == "openxr" && observer.empty())) {
        ImGui::TextUnformatted(model_.answer_keys_enabled()
                                   ? "Answers: the participant, with the controller or the keys."
                                   : "Answers: the participant, with the controller.");
    } else {
        ImGui::Text("Answers: the simulated observer (%s).",
                    model_.observer().empty() ? "default" : model_.observer().c_str());
    }
    // The check's verdict on the controller, judged again as the protocol or observer changes.
    judge_answers(model_.headset_report().interaction_profile,
                  model_.headset_report().check_frames);
    message_line(model_.headset_report().answer_warning);
    controls_.mark("answer-warning", false, false);
    draw_keys_choice();
    draw_session_settings();
    draw_start();
}

void LauncherPanels::draw_headset_report() {
    const HeadsetReport& report = model_.headset_report();
    if (model_.headset() == "none") {
        dim_text("No headset: the session runs in the window.");
        return;
    }
    if (!report.runtime_available) {
        error_text(report.message.empty() ? "no OpenXR runtime" : report.message);
        if (model_.headset() != "simulated") {
            if (ImGui::Button("Use the simulated headset")) {
                note(model_.set_headset("simulated"));
                probe_if_needed();
            }
            controls_.mark("use-simulated");
        }
        return;
    }
    ImGui::Text("Runtime: %s", report.runtime.c_str());
    ImGui::Text("Headset: %s, %d x %d pixels per eye (recommended)", report.system.c_str(),
                report.width, report.height);
    if (report.refresh_hz > 0.0) ImGui::Text("Refresh rate: %.1f Hz", report.refresh_hz);
    if (report.ipd_m) ImGui::Text("IPD: %.1f mm", *report.ipd_m * 1000.0);
    if (!report.interaction_profile.empty())
        ImGui::Text("Controllers: %s", report.interaction_profile.c_str());
    draw_eye_gaze(report);
    if (ImGui::Button("Check the headset (Ctrl+H)")) request_check();
    controls_.mark("check");
    ImGui::SameLine();
    dim_text("shows the participant a calibration screen until CONFIRM");
    draw_check_result();
}

// Whether gaze can be recorded, and after a check whether the tracker saw the eyes: a tracker
// that lost them in most frames (not calibrated for this participant, the headset badly seated)
// records little.
void LauncherPanels::draw_eye_gaze(const HeadsetReport& report) {
    if (report.eye_gaze.empty()) return;
    if (report.eye_gaze != "tracked") {
        dim_text(report.eye_gaze_text);
        return;
    }
    if (report.check.empty() || report.check_frames == 0) {
        ImGui::TextUnformatted(report.eye_gaze_text.c_str());
        return;
    }
    ImGui::Text("%s; valid in %lld of the check's %lld frames", report.eye_gaze_text.c_str(),
                static_cast<long long>(report.check_gaze_frames),
                static_cast<long long>(report.check_frames));
}

void LauncherPanels::draw_check_result() {
    const HeadsetReport& report = model_.headset_report();
    if (report.check.empty()) return;
    if (report.check == "confirmed") {
        ImGui::TextColored(kGood, "Headset check: confirmed after %lld frames",
                           static_cast<long long>(report.check_frames));
        dim_text(report.check_message);
    } else {
        error_text("Headset check " + report.check + ": " + report.check_message);
    }
}

void LauncherPanels::draw_start() {
    ImGui::Spacing();
    draw_start_button();
    focus_item_on_entry();  // no text here: Space on the focused Start begins
    if (model_.start_enabled())
        draw_command_line();
    else
        message_line(model_.start_message());
}

// Disabled, Start is drawn grey on a dark button, not merely a little fainter: it must not look
// like a button that would start.
void LauncherPanels::draw_start_button() {
    const bool enabled = model_.start_enabled();
    if (enabled) {
        ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.16f, 0.55f, 0.24f, 1.0f));
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.2f, 0.65f, 0.3f, 1.0f));
    } else {
        ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.2f, 0.2f, 0.22f, 1.0f));
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.2f, 0.2f, 0.22f, 1.0f));
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.45f, 0.45f, 0.48f, 1.0f));
    }
    ImGui::BeginDisabled(!enabled);
    if (ImGui::Button("Start (Ctrl+Enter)")) start();
    controls_.mark("start");  // inside BeginDisabled: recorded as disabled
    ImGui::EndDisabled();
    ImGui::PopStyleColor(enabled ? 2 : 3);
}

// The equivalent command, wrapped only between words (a path is never split), and a button that
// copies it whole.
void LauncherPanels::draw_command_line() {
    const std::vector<std::string> arguments = model_.request().arguments();
    if (ImGui::SmallButton("Copy the command")) {
        ImGui::SetClipboardText(shell_command_line(arguments).c_str());
    }
    controls_.mark("copy-command");
    ImGui::PushStyleColor(ImGuiCol_Text, kDim);
    const float right = ImGui::GetContentRegionMax().x;
    const float space = ImGui::CalcTextSize(" ").x;
    ImGui::TextUnformatted("monoplane");
    for (const std::string& argument : arguments) {
        const std::string word = shell_quoted(argument);
        const float width = ImGui::CalcTextSize(word.c_str()).x;
        ImGui::SameLine(0.0f, space);
        if (ImGui::GetCursorPosX() + width > right) ImGui::NewLine();
        ImGui::TextUnformatted(word.c_str());
    }
    ImGui::PopStyleColor();
}

}  // namespace monoplane::lab
