// The launcher window's frame: the step bar, the current step's panel, the roster and the footer,
// and the keys and buttons that move between the steps or act on them (Start, Export, Analyse).
// Each step's panel is in its own launcher_panels_*.cpp.
#include "app/lab/launcher_panels.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <array>
#include <string>
#include <utility>

#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {
namespace {

// The steps a person goes through, in the bar at the top (Session is the session's own window).
constexpr std::array kShownSteps{LauncherStep::Database, LauncherStep::Protocol,
                                 LauncherStep::Participant, LauncherStep::Headset,
                                 LauncherStep::Summary};

const char* step_title(LauncherStep step) {
    switch (step) {
        case LauncherStep::Database:
            return "1 Database";
        case LauncherStep::Protocol:
            return "2 Protocol";
        case LauncherStep::Participant:
            return "3 Participant";
        case LauncherStep::Headset:
            return "4 Headset and Start";
        case LauncherStep::Session:
            return "Session running";
        case LauncherStep::Summary:
            return "5 Summary";
    }
    return "";
}

}  // namespace

bool LauncherPanels::note(const Result<void>& result) {
    ui_.action_message = result ? std::string() : result.error().message;
    return static_cast<bool>(result);
}

void LauncherPanels::key(const window::KeyPress& press) {
    if (press.key == GLFW_KEY_TAB && (press.mods & GLFW_MOD_CONTROL) == 0)
        controls_.tab((press.mods & GLFW_MOD_SHIFT) != 0);
    if ((press.mods & GLFW_MOD_CONTROL) == 0) return;
    switch (press.key) {
        case GLFW_KEY_RIGHT:
            next_step();
            break;
        case GLFW_KEY_LEFT:
            if (model_.step() > LauncherStep::Database && model_.step() != LauncherStep::Summary)
                go_to(static_cast<LauncherStep>(static_cast<int>(model_.step()) - 1));
            else if (model_.step() == LauncherStep::Summary)
                go_to(LauncherStep::Participant);
            break;
        case GLFW_KEY_ENTER:
        case GLFW_KEY_KP_ENTER:
            start();
            break;
        case GLFW_KEY_H:
            request_check();
            break;
        case GLFW_KEY_E:
            if (model_.step() == LauncherStep::Summary) export_data();
            break;
        case GLFW_KEY_R:
            if (model_.step() == LauncherStep::Summary) analyse();
            break;
        case GLFW_KEY_Q:
            quit_ = true;
            break;
        default:
            break;
    }
}

void LauncherPanels::go_to(LauncherStep step) {
    note(model_.go_to(step));
}

void LauncherPanels::next_step() {
    switch (model_.step()) {
        case LauncherStep::Database:
            go_to(LauncherStep::Protocol);
            break;
        case LauncherStep::Protocol:
            go_to(LauncherStep::Participant);
            break;
        case LauncherStep::Participant:
            go_to(LauncherStep::Headset);
            break;
        case LauncherStep::Headset:
            start();
            break;
        case LauncherStep::Summary:
            next_participant();
            break;
        case LauncherStep::Session:
            break;
    }
}

void LauncherPanels::next_participant() {
    if (!note(model_.next_participant())) return;
    ui_.summary_lines.clear();
    ui_.export_message.clear();
    ui_.analysis_message.clear();
}

void LauncherPanels::start() {
    if (measuring_refuses("starting the session")) return;
    Result<LaunchRequest> request = model_.start();
    if (!request) {
        ui_.action_message = request.error().message;
        return;
    }
    ui_.action_message.clear();
    ui_.export_message.clear();
    ui_.analysis_message.clear();
    launch_ = std::move(request).value();
}

void LauncherPanels::export_data() {
    if (!actions_.export_data) return;
    Result<std::filesystem::path> written = actions_.export_data();
    ui_.export_message = written ? "exported to " + written->string() : written.error().message;
}

void LauncherPanels::analyse() {
    if (!actions_.analyse) return;
    Result<std::filesystem::path> written = actions_.analyse();
    ui_.analysis_message =
        written ? "report written: " + written->string() : written.error().message;
}

void LauncherPanels::focus_on_entry() {
    if (focused_step_ == model_.step()) return;
    focused_step_ = model_.step();
    ImGui::SetKeyboardFocusHere();
}

void LauncherPanels::focus_item_on_entry() {
    if (focused_step_ == model_.step()) return;
    focused_step_ = model_.step();
    // Dear ImGui 1.86 focuses only text fields by SetKeyboardFocusHere; a button takes the
    // keyboard navigation's focus directly.
    ImGui::SetFocusID(ImGui::GetItemID(), ImGui::GetCurrentWindow());
    ImGui::GetCurrentContext()->NavDisableHighlight = false;
}

void LauncherPanels::draw() {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->WorkPos);
    ImGui::SetNextWindowSize(viewport->WorkSize);
    // A scroll bar only when a step is taller than the window (the roster scrolls on its own).
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::Begin("monoplane lab", nullptr, flags);
    controls_.begin_frame();
    if (drawn_step_ != model_.step()) {
        // A refusal belongs to the step it was made in.
        if (drawn_step_) ui_.action_message.clear();
        drawn_step_ = model_.step();
        if (model_.step() == LauncherStep::Protocol) model_.rescan_protocols_if_changed();
    }
    if (model_.step() != LauncherStep::Headset) probed_choice_.reset();  // probe on entry
    draw_steps();
    draw_protocol_line();
    ImGui::Separator();
    switch (model_.step()) {
        case LauncherStep::Database:
            draw_database();
            break;
        case LauncherStep::Protocol:
            draw_protocol();
            break;
        case LauncherStep::Participant:
            draw_participant();
            break;
        case LauncherStep::Headset:
            draw_headset();
            break;
        case LauncherStep::Session:
            ImGui::TextUnformatted("The session is running.");
            break;
        case LauncherStep::Summary:
            draw_summary();
            break;
    }
    ImGui::Spacing();
    ImGui::Separator();
    draw_roster();
    draw_footer();
    controls_.end_frame();
    std::vector<ControlRect> rects = controls_.rects();
    rects.push_back({"window", viewport->Pos.x, viewport->Pos.y, viewport->Size.x, viewport->Size.y,
                     true, true});
    model_.set_controls(std::move(rects));
    model_.set_window_message(ui_.action_message);
    ImGui::End();
}

void LauncherPanels::draw_protocol_line() {
    if (const study::Protocol* protocol = model_.protocol()) {
        ImGui::Text("Protocol: %s (%s)", protocol->name.c_str(),
                    model_.protocol_path().filename().string().c_str());
    } else {
        ImGui::TextColored(kDim, "Protocol: none chosen yet");
    }
    controls_.mark("protocol-line", false, false);
}

void LauncherPanels::draw_steps() {
    for (const LauncherStep step : kShownSteps) {
        if (step != kShownSteps.front()) ImGui::SameLine(0.0f, 24.0f);
        if (step == model_.step())
            ImGui::TextColored(kGood, "[%s]", step_title(step));
        else
            ImGui::TextColored(kDim, " %s ", step_title(step));
    }
}

// The footer sits at the bottom of the window, whatever its size; its height is measured as
// drawn, for the next frame's roster to leave it room.
void LauncherPanels::draw_footer() {
    const float bottom = ImGui::GetWindowHeight() - footer_height_;
    if (footer_height_ > 0.0f && ImGui::GetCursorPosY() < bottom) ImGui::SetCursorPosY(bottom);
    const float top = ImGui::GetCursorPosY();
    ImGui::Spacing();
    ImGui::Separator();
    message_line(ui_.action_message);
    dim_text(
        "Keys: Tab / Shift+Tab move, Space or Enter acts, Ctrl+Right next step, Ctrl+Left back, "
        "Ctrl+H check the headset, Ctrl+Enter Start, Ctrl+Q quit");
    controls_.mark("footer", false, false);
    footer_height_ = ImGui::GetCursorPosY() - top + ImGui::GetStyle().WindowPadding.y;
}

}  // namespace monoplane::lab
