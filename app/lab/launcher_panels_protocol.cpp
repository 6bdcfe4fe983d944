// The Protocol step: the protocols folder's files with their errors in place, or a name or path
// typed in.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {

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

}  // namespace monoplane::lab
