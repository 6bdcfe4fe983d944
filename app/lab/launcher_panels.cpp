#include "app/lab/launcher_panels.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <utility>

#include "app/lab/shell_words.h"

namespace monoplane::lab {
namespace {

const ImVec4 kError(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kGood(0.5f, 0.9f, 0.5f, 1.0f);
const ImVec4 kDim(0.65f, 0.65f, 0.7f, 1.0f);

void error_text(const std::string& message) {
    if (message.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, kError);
    ImGui::TextWrapped("%s", message.c_str());
    ImGui::PopStyleColor();
}

// A message's line, kept (empty) when there is none: the controls under it stay where they are
// when a message comes or goes, so a click aimed at one never lands on the message.
void message_line(const std::string& message) {
    if (message.empty())
        ImGui::TextUnformatted(" ");
    else
        error_text(message);
}

void dim_text(const std::string& text) {
    if (text.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, kDim);
    ImGui::TextWrapped("%s", text.c_str());  // a command line can be longer than the window
    ImGui::PopStyleColor();
}

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

void LauncherPanels::draw_database() {
    ImGui::TextUnformatted(
        "Study database (a .sqlite file; every session of the study goes in it)");
    if (ui_.database_text.empty()) ui_.database_text = model_.database().string();
    focus_on_entry();
    controls_.before_text("database");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.7f);
    const bool enter =
        ImGui::InputText("##database", &ui_.database_text, ImGuiInputTextFlags_EnterReturnsTrue);
    controls_.mark("database", true);
    ImGui::SameLine();
    const bool open = ImGui::Button("Open") || enter;
    controls_.mark("open");
    ImGui::SameLine();
    const bool create = ImGui::Button("Create");
    controls_.mark("create");
    if (open || create) {
        if (note(model_.open_database(ui_.database_text, create))) go_to(LauncherStep::Protocol);
    }
    if (model_.database_open())
        ImGui::TextColored(kGood, "open: %s", model_.database().string().c_str());
    else
        ImGui::TextUnformatted(" ");
    message_line(model_.database_message());
    dim_text("Enter opens an existing file; Create starts a new one.");
}

void LauncherPanels::choose_protocol(const std::filesystem::path& path) {
    if (note(model_.select_protocol(path))) go_to(LauncherStep::Participant);
}

// A listed file or protocol name, or a path to a protocol anywhere.
void LauncherPanels::choose_typed_protocol() {
    const auto& list = model_.protocols();
    const auto found = std::find_if(list.begin(), list.end(), [&](const ProtocolChoice& c) {
        return c.file == ui_.protocol_text || c.name == ui_.protocol_text;
    });
    if (found != list.end()) {
        choose_protocol(found->path);
    } else if (ui_.protocol_text.find('/') != std::string::npos) {
        choose_protocol(ui_.protocol_text);
    } else {
        ui_.action_message = "no protocol '" + ui_.protocol_text + "' in the folder " +
                             model_.protocols_folder().string() +
                             " (type a file name of the list, or a full path to a .toml file)";
    }
}

void LauncherPanels::draw_protocol() {
    ImGui::Text("Protocols in %s", model_.protocols_folder().string().c_str());
    message_line(model_.protocols_message());
    ImGui::TextUnformatted("File name or path (Enter chooses it):");
    ImGui::SameLine();
    focus_on_entry();
    controls_.before_text("protocol");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    // Enter leaves the field: a refused name is focused again, selected, to be typed over.
    const ImGuiInputTextFlags flags =
        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll;
    if (ImGui::InputText("##protocol", &ui_.protocol_text, flags)) {
        ImGui::SetKeyboardFocusHere(-1);
        choose_typed_protocol();
    }
    controls_.mark("protocol", true);
    for (const ProtocolChoice& choice : model_.protocols()) {
        const bool chosen = model_.protocol() != nullptr && model_.protocol_path() == choice.path;
        const std::string label =
            choice.file + (choice.valid ? "   (" + choice.name + ", ok)" : "   (has errors)");
        ImGui::PushStyleColor(ImGuiCol_Text,
                              choice.valid ? ImGui::GetStyleColorVec4(ImGuiCol_Text) : kError);
        if (ImGui::Selectable(label.c_str(), chosen)) choose_protocol(choice.path);
        controls_.mark("protocol:" + choice.file);
        ImGui::PopStyleColor();
        // Errors in place, with file and line, as `protocol check` prints them.
        if (!choice.valid) {
            ImGui::Indent();
            error_text(choice.message);
            ImGui::Unindent();
        }
    }
}

void LauncherPanels::draw_participant() {
    ImGui::TextUnformatted("Participant code:");
    ImGui::SameLine();
    focus_on_entry();
    controls_.before_text("code");
    std::string code = model_.participant_code();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 14.0f);
    const bool enter = ImGui::InputText("##code", &code, ImGuiInputTextFlags_EnterReturnsTrue);
    controls_.mark("code", true);
    if (code != model_.participant_code()) model_.set_participant_code(code);
    if (enter) next_step();
    message_line(model_.code_message());
    if (const auto& known = model_.participant()) {
        std::string sessions;
        for (const auto& [number, id] : known->sessions)
            sessions += (sessions.empty() ? "" : ", ") + std::to_string(number);
        ImGui::Text("Returning participant (number %d); earlier sessions: %s",
                    known->participant_number + 1, sessions.c_str());
    } else if (!code.empty() && model_.code_message().empty()) {
        ImGui::TextUnformatted("New participant.");
    } else {
        ImGui::TextUnformatted(" ");
    }
    ImGui::Text("This will be session %d.", model_.next_session_number());
    if (!model_.variables().empty()) {
        ImGui::Spacing();
        ImGui::TextUnformatted("Participant variables (* required):");
        for (const VariableField& field : model_.variables()) draw_variable(field);
    }
    draw_participant_problems();
    if (ImGui::Button("Next (Ctrl+Right)")) next_step();
    controls_.mark("next");
}

void LauncherPanels::draw_participant_problems() {
    std::string problems;
    for (const std::string& problem : model_.participant_problems())
        problems += (problems.empty() ? "" : "\n") + problem;
    message_line(problems);
}

void LauncherPanels::draw_variable(const VariableField& field) {
    const study::ParticipantVariable& v = field.declaration;
    ImGui::PushID(v.name.c_str());
    ImGui::BeginDisabled(field.recorded);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 14.0f);
    const std::string label = v.name + (v.required ? " *" : "");
    std::string text = field.text;
    if (v.type == study::VariableType::Choice) {
        draw_choice(controls_, "var:" + v.name, label, v.choices, text);
    } else {
        // No character filter: Dear ImGui's numeric filters drop what they do not take (a
        // decimal comma: "6,5" became 65); the field's message says what is wrong instead.
        controls_.before_text("var:" + v.name);
        ImGui::InputText(label.c_str(), &text);
        controls_.mark("var:" + v.name, true);
    }
    ImGui::EndDisabled();
    if (text != field.text) note(model_.set_variable(v.name, text));
    if (field.recorded) {
        ImGui::SameLine();
        dim_text("(recorded with the participant)");
    }
    dim_text(v.help);
    message_line(field.message);
    ImGui::PopID();
}

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
    }
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
    if (ImGui::Button("Check the headset (Ctrl+H)")) request_check();
    controls_.mark("check");
    ImGui::SameLine();
    dim_text("shows the participant a calibration screen until CONFIRM");
    draw_check_result();
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
    }
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

// The first line is the roster's word for the session (an interrupted session is "interrupted"
// there and here, where summarize_session's first line says its stored status, "running"); the
// rest are summarize_session's. A session that never began has no number to show.
void LauncherPanels::draw_summary() {
    if (const auto& outcome = model_.summary()) {
        if (outcome->session_id == 0) {
            ImGui::Text("The session for participant %s did not start.",
                        outcome->participant.c_str());
        } else {
            ImGui::Text("Session %lld: participant %s, session %d, %s",
                        static_cast<long long>(outcome->session_id), outcome->participant.c_str(),
                        outcome->session_number, outcome->state.c_str());
        }
        error_text(outcome->error);
    }
    for (std::size_t i = 1; i < ui_.summary_lines.size(); ++i)
        ImGui::TextUnformatted(ui_.summary_lines[i].c_str());
    ImGui::Spacing();
    if (ImGui::Button("Export (Ctrl+E)")) export_data();
    focus_item_on_entry();
    controls_.mark("export");
    ImGui::SameLine();
    if (ImGui::Button("Analyse (Ctrl+R)")) analyse();
    controls_.mark("analyse");
    ImGui::SameLine();
    if (ImGui::Button("Next participant")) next_participant();
    controls_.mark("next-participant");
    if (!ui_.export_message.empty()) ImGui::TextWrapped("%s", ui_.export_message.c_str());
    if (!ui_.analysis_message.empty()) ImGui::TextWrapped("%s", ui_.analysis_message.c_str());
}

void LauncherPanels::draw_roster() {
    if (!model_.database_open()) return;
    ImGui::Text("Sessions in %s", model_.database().filename().string().c_str());
    if (model_.roster().empty()) {
        dim_text("no sessions yet");
        return;
    }
    // The table scrolls in what the window leaves above the footer (at least a few lines), so
    // a long day's roster never pushes Resume or the footer off the window.
    const float rows = ImGui::GetTextLineHeightWithSpacing() * 6.0f;
    const float height = std::max(rows, ImGui::GetContentRegionAvail().y - footer_height_);
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollY;
    if (!ImGui::BeginTable("roster", 5, flags, ImVec2(0.0f, height))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* heading : {"participant", "session", "state", "trials", ""})
        ImGui::TableSetupColumn(heading);
    ImGui::TableHeadersRow();
    for (const RosterLine& line : model_.roster()) draw_roster_line(line);
    ImGui::EndTable();
}

void LauncherPanels::draw_roster_line(const RosterLine& line) {
    const study::RosterRow& row = line.entry.row;
    ImGui::PushID(static_cast<int>(row.session_id));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.participant_code.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%d", row.session_number);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(line.state.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%d / %d", row.trials_decided, row.trials_planned);
    ImGui::TableNextColumn();
    if (line.state != "completed") {
        ImGui::BeginDisabled(!line.resume_offered);
        if (ImGui::Button("Resume") && !measuring_refuses("resuming a session")) {
            Result<LaunchRequest> request = model_.resume(row.session_id, false);
            if (request)
                launch_ = std::move(request).value();
            else
                ui_.action_message = request.error().message;
        }
        controls_.mark("resume:" + std::to_string(row.session_id));
        ImGui::EndDisabled();
        if (!line.resume_refusal.empty()) {
            ImGui::SameLine();
            ImGui::TextColored(kError, "%s", line.resume_refusal.c_str());
        }
    }
    ImGui::PopID();
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
