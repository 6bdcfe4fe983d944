// The sessions: the Summary step after one ended (Export, Analyse, Next participant) and the
// roster of the database's sessions under every step, with Resume.
#include <imgui.h>

#include <algorithm>
#include <string>
#include <utility>

#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {

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

}  // namespace monoplane::lab
