// The Participant step: the code (new or returning), the session's number and the protocol's
// participant variables.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <string>

#include "app/lab/launcher_panels.h"
#include "app/lab/launcher_panels_text.h"

namespace monoplane::lab {

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

}  // namespace monoplane::lab
