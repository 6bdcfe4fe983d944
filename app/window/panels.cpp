#include "app/window/panels.h"

#include <cstdio>
#include <string>

#include "app/window/view_text.h"

namespace monoplane::window {
namespace {

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings;
constexpr float kLeftColumn = 0.62f;  // of the window width: mirror and log
constexpr float kMirrorRows = 0.70f;  // of the window height: the mirror above the log
const ImVec4 kAccent(0.95f, 0.75f, 0.25f, 1.0f);
const ImVec4 kAlarm(1.0f, 0.35f, 0.30f, 1.0f);

void place(float x, float y, float width, float height) {
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
}

void heading(const char* text) {
    ImGui::Spacing();
    ImGui::TextColored(kAccent, "%s", text);
    ImGui::Separator();
}

void labelled(const char* label, const std::string& value) {
    ImGui::TextDisabled("%s", label);
    ImGui::SameLine(110.0f);
    ImGui::TextUnformatted(value.empty() ? "-" : value.c_str());
}

void draw_mirror(const ExperimenterView& view, const MirrorImage& mirror, PanelState& state) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 room = ImGui::GetContentRegionAvail();
    const FitRect fit = fit_aspect(room.x, room.y, mirror.width, mirror.height);
    if (fit.width < 1.0f || fit.height < 1.0f) return;
    ImGui::SetCursorScreenPos(ImVec2(origin.x + fit.x, origin.y + fit.y));
    state.mirror_rect = FitRect{origin.x + fit.x, origin.y + fit.y, fit.width, fit.height};
    ImDrawList* draw_list = ImGui::GetWindowDrawList();
    draw_list->AddCallback(mirror.bind, mirror.bind_data);
    ImGui::Image(mirror.texture, ImVec2(fit.width, fit.height));
    draw_list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
    // After the reset: the marker is drawn with ImGui's own texture, over the mirror.
    draw_gaze_marker(*draw_list, state.mirror_rect, view, state.gaze);
}

void draw_session(const ExperimenterView& view) {
    heading("Session");
    labelled("Participant", view.participant);
    labelled("Protocol", view.protocol);
    labelled("Headset", view.headset);
    labelled("HMD", view.hmd);
    labelled("Device", view.device);
}

void draw_progress(const ExperimenterView& view) {
    heading("Progress");
    const std::string text = progress_text(view);
    ImGui::ProgressBar(progress_fraction(view), ImVec2(-1.0f, 0.0f), text.c_str());
    if (view.practice) {
        ImGui::TextColored(kAccent, "PRACTICE TRIAL (not analysed)");
    }
    labelled("Session time", format_duration(view.elapsed_s));
    labelled("Trial time", format_duration(view.trial_elapsed_s));
    labelled("Scene", view.scene);
    char plane[32];
    std::snprintf(plane, sizeof(plane), "%.2f m", view.mono_plane);
    labelled("Mono plane m", view.trial_number > 0 ? std::string(plane) : std::string());
}

void draw_trial_state(const ExperimenterView& view, std::vector<Command>& commands) {
    heading("Trial state");
    for (const std::string& line : trial_state_lines(view)) ImGui::TextUnformatted(line.c_str());
    bool unblinded = view.unblinded;
    if (ImGui::Checkbox("Unblind (show the modes behind the labels)", &unblinded)) {
        commands.push_back(Command{Command::Kind::Unblind, 0, unblinded ? 1 : 0});
    }
}

void draw_controls(const ExperimenterView& view, std::vector<Command>& commands) {
    heading("Controls");
    const bool over =
        view.phase == Phase::Finished || view.phase == Phase::Aborted || view.phase == Phase::End;
    if (view.phase == Phase::Paused) {
        if (ImGui::Button("Resume", ImVec2(110, 0))) commands.push_back({Command::Kind::Resume});
    } else {
        const bool can_pause = view.phase == Phase::Trial || view.phase == Phase::Neutral;
        ImGui::BeginDisabled(!can_pause);
        if (ImGui::Button("Pause", ImVec2(110, 0))) commands.push_back({Command::Kind::Pause});
        ImGui::EndDisabled();
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(over);
    ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.55f, 0.12f, 0.10f, 1.0f));
    if (ImGui::Button("Abort session...", ImVec2(140, 0))) ImGui::OpenPopup("Abort session?");
    ImGui::PopStyleColor();
    ImGui::EndDisabled();
    if (ImGui::BeginPopupModal("Abort session?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted("End this session now? Decisions so far stay recorded;");
        ImGui::TextUnformatted("the session is marked aborted.");
        if (ImGui::Button("Abort", ImVec2(100, 0))) {
            commands.push_back({Command::Kind::Abort});
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(100, 0)) ||
            ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    ImGui::TextDisabled("Keys: Space/Tab switch (a page back), Enter confirm, P pause/resume");
}

void draw_questionnaire(const ExperimenterView& view, std::vector<Command>& commands) {
    heading("Questionnaire");
    ImGui::TextDisabled("1 = strongly disagree ... %d = strongly agree", view.scale_points);
    for (std::size_t i = 0; i < view.questionnaire_items.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        ImGui::TextWrapped("%zu. %s", i + 1, view.questionnaire_items[i].c_str());
        const int answer = i < view.answers.size() ? view.answers[i] : 0;
        for (int value = 1; value <= view.scale_points; ++value) {
            if (value > 1) ImGui::SameLine();
            const std::string label = std::to_string(value);
            if (ImGui::RadioButton(label.c_str(), answer == value)) {
                commands.push_back(Command{Command::Kind::Answer, static_cast<int>(i), value});
            }
        }
        ImGui::PopID();
    }
    const bool complete = questionnaire_complete(view);
    ImGui::BeginDisabled(!complete);
    if (ImGui::Button("Submit answers", ImVec2(160, 0))) {
        commands.push_back({Command::Kind::SubmitAnswers});
    }
    ImGui::EndDisabled();
    if (!complete) {
        ImGui::SameLine();
        ImGui::TextDisabled("(answer every item)");
    }
}

// The page the participant reads, as the headset shows it (scrolls when long).
void draw_page(const ExperimenterView& view) {
    heading("Participant's screen");
    ImGui::TextWrapped("%s", page_heading(view).c_str());
    const float lines = ImGui::GetTextLineHeightWithSpacing() * 8.0f;
    ImGui::BeginChild("page text", ImVec2(0.0f, lines), true);
    ImGui::TextWrapped("%s", view.page_text.c_str());
    ImGui::EndChild();
}

// A note on the session: Enter sends it (stored at once, with the time and the trial) and clears
// the field; the outcome comes back in the view.
void draw_note(const ExperimenterView& view, PanelState& state, std::vector<Command>& commands) {
    heading("Notes");
    ImGui::PushItemWidth(-ImGui::CalcTextSize("Note").x - ImGui::GetStyle().ItemInnerSpacing.x);
    if (ImGui::InputText("Note", state.note.data(), state.note.size(),
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
        commands.push_back(Command{Command::Kind::Note, 0, 0, std::string(state.note.data())});
        state.note.fill('\0');
    }
    ImGui::PopItemWidth();
    if (view.note_status.empty()) {
        ImGui::TextDisabled("Enter stores the note with the time and the trial");
    } else {
        ImGui::TextWrapped("%s", view.note_status.c_str());
    }
}

void draw_log(const ExperimenterView& view, PanelState& state) {
    ImGui::BeginChild("log lines", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    // Follow new lines unless the experimenter scrolled up to read.
    const bool at_bottom = ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 1.0f;
    for (const std::string& line : view.log_tail) ImGui::TextUnformatted(line.c_str());
    if (view.log_tail.size() != state.log_lines_seen && at_bottom) ImGui::SetScrollHereY(1.0f);
    state.log_lines_seen = view.log_tail.size();
    ImGui::EndChild();
}

}  // namespace

std::vector<Command> draw_panels(const ExperimenterView& view, const MirrorImage& mirror,
                                 PanelState& state) {
    std::vector<Command> commands;
    // Nothing shown unless the mirror is drawn this frame (a window too small has none).
    state.gaze.shown = GazeShown::Nothing;
    state.gaze.centre.reset();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float left = display.x * kLeftColumn;
    const float mirror_height = display.y * kMirrorRows;

    place(0, 0, left, mirror_height);
    if (ImGui::Begin("Participant's view", nullptr, kPanelFlags)) draw_mirror(view, mirror, state);
    ImGui::End();

    place(0, mirror_height, left, display.y - mirror_height);
    if (ImGui::Begin("Log", nullptr, kPanelFlags)) draw_log(view, state);
    ImGui::End();

    place(left, 0, display.x - left, display.y);
    if (ImGui::Begin("Study", nullptr, kPanelFlags)) {
        draw_session(view);
        draw_progress(view);
        if (shows_page(view.phase)) draw_page(view);
        draw_trial_state(view, commands);
        draw_controls(view, commands);
        draw_note(view, state, commands);
        if (view.phase == Phase::Questionnaire) draw_questionnaire(view, commands);
        if (view.phase == Phase::Aborted) ImGui::TextColored(kAlarm, "Session aborted");
        ImGui::Spacing();
        ImGui::Separator();
        ImGui::TextWrapped("%s", view.status_line.c_str());
        ImGui::TextDisabled("frame %llu  %.2f ms",
                            static_cast<unsigned long long>(view.frame_index), view.frame_ms);
    }
    ImGui::End();
    return commands;
}

}  // namespace monoplane::window
