// The colours and message lines every panel of the launcher window draws its text with
// (launcher_panels*.cpp).
#pragma once

#include <imgui.h>

#include <string>

namespace monoplane::lab {

inline const ImVec4 kError(1.0f, 0.45f, 0.4f, 1.0f);
inline const ImVec4 kWarn(1.0f, 0.85f, 0.3f, 1.0f);
inline const ImVec4 kGood(0.5f, 0.9f, 0.5f, 1.0f);
inline const ImVec4 kDim(0.65f, 0.65f, 0.7f, 1.0f);

// Wrapped: a message or a command line can be longer than the window.
inline void coloured_text(const ImVec4& colour, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

inline void error_text(const std::string& message) {
    if (message.empty()) return;
    coloured_text(kError, message);
}

// A message's line, kept (empty) when there is none: the controls under it stay where they are
// when a message comes or goes, so a click aimed at one never lands on the message.
inline void message_line(const std::string& message) {
    if (message.empty())
        ImGui::TextUnformatted(" ");
    else
        error_text(message);
}

inline void dim_text(const std::string& text) {
    if (text.empty()) return;
    coloured_text(kDim, text);
}

}  // namespace monoplane::lab
