// The headset check while it runs: the app's check driven frame by frame, the window's panel
// with Fits and Cancel, and the outcome into the headset report.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <utility>

#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {

void LauncherPanels::run_check(const std::function<CheckAnswer(const HeadsetCheckTurn&)>& turn) {
    if (!actions_.check_headset) return;
    check_focused_ = false;
    check_answer_ = CheckAnswer::Continue;
    HeadsetReport report = model_.headset_report();
    Result<HeadsetReport> checked = actions_.check_headset(model_.headset(), turn);
    if (checked) {
        const HeadsetReport probed = std::move(report);
        report = std::move(checked).value();
        // The check's eyes are at the session's scale: the step keeps the runtime's recommended
        // size, which the presets scale (and the estimates were measured for).
        if (probed.runtime_available && probed.width > 0) {
            report.width = probed.width;
            report.height = probed.height;
        }
    } else {
        // It could not run (no Vulkan device, the runtime refused a session): the probe's
        // report stays, with why.
        report.check = "failed";
        report.check_message = checked.error().message;
        report.check_frames = 0;
        report.check_gaze_frames = 0;
    }
    // Judged as the report is stored, not at the next frame's drawing: no frame (nor the
    // state the window reports) shows a check's end without its verdict on the answers.
    report.answer_warning = answers_warning(report.interaction_profile, report.check_frames);
    model_.set_headset_report(std::move(report));
}

void LauncherPanels::check_key(const window::KeyPress& press) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    if (press.key == GLFW_KEY_ESCAPE) check_answer_ = CheckAnswer::Cancel;
    if (ctrl && press.key == GLFW_KEY_F) check_answer_ = CheckAnswer::Confirm;
    if (ctrl && press.key == GLFW_KEY_Q) {
        check_answer_ = CheckAnswer::Cancel;
        quit_ = true;
    }
}

CheckAnswer LauncherPanels::draw_check(const HeadsetCheckTurn& turn) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->WorkPos);
    ImGui::SetNextWindowSize(viewport->WorkSize);
    ImGui::Begin("monoplane lab", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
    draw_steps();
    ImGui::Separator();
    ImGui::TextUnformatted("Checking the headset: the participant sees a grid and a cross.");
    ImGui::TextWrapped(
        "Ask them to adjust the headset until the text is sharp and the grid square, then to "
        "press CONFIRM on the controller (or press Fits here).");
    char ipd[32] = "-";
    if (turn.ipd_m) std::snprintf(ipd, sizeof ipd, "%.1f", *turn.ipd_m * 1000.0);
    ImGui::Text(
        "Showing the check in the headset: frames %lld, IPD %s mm, refresh %.1f Hz, "
        "profile %s",
        static_cast<long long>(turn.frames_shown), ipd, turn.refresh_hz,
        turn.interaction_profile.empty() ? "none yet" : turn.interaction_profile.c_str());
    if (turn.gaze_tracked) {
        ImGui::Text("Eye gaze: valid in %lld of %lld frames",
                    static_cast<long long>(turn.gaze_frames),
                    static_cast<long long>(turn.frames_shown));
    }
    // Said at once, while the participant waits for an answer they cannot give.
    judge_answers(turn.interaction_profile, turn.frames_shown);
    message_line(model_.headset_report().answer_warning);
    if (ImGui::Button("Fits (Ctrl+F)")) check_answer_ = CheckAnswer::Confirm;
    if (!check_focused_) {
        check_focused_ = true;
        ImGui::SetFocusID(ImGui::GetItemID(), ImGui::GetCurrentWindow());
        ImGui::GetCurrentContext()->NavDisableHighlight = false;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) check_answer_ = CheckAnswer::Cancel;
    ImGui::End();
    return std::exchange(check_answer_, CheckAnswer::Continue);
}

}  // namespace monoplane::lab
