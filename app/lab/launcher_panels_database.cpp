// The Database step: the study's .sqlite file, opened or created.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {

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

}  // namespace monoplane::lab
