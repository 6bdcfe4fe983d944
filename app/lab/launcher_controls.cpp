#include "app/lab/launcher_controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

namespace monoplane::lab {

namespace {

// The key's press this frame is not seen by the widgets drawn after this call.
void swallow_key(int key) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown[key] = false;
    io.KeysDownDuration[key] = -1.0f;
}

bool enter_pressed() {
    return ImGui::IsKeyPressed(GLFW_KEY_ENTER, false) ||
           ImGui::IsKeyPressed(GLFW_KEY_KP_ENTER, false);
}

}  // namespace

// A combo box that Enter opens and Enter picks in, as Space does (Dear ImGui 1.86 takes only
// Space).
void draw_choice(ControlRing& controls, const std::string& name, const std::string& label,
                 const std::vector<std::string>& choices, std::string& text) {
    const ImGuiID id = ImGui::GetID(label.c_str());
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImGuiID popup = ImHashStr("##ComboPopup", 0, id);
    // Open: the list took the keyboard (its chosen entry has the focus), so keys sent after the
    // state says so land in it.
    controls.mark_at(name, id, at.x, at.y, ImGui::CalcItemWidth(), ImGui::GetFrameHeight(),
                     ImGui::IsPopupOpen(popup, ImGuiPopupFlags_None));
    if (ImGui::BeginCombo(label.c_str(), text.empty() ? "(choose)" : text.c_str())) {
        for (const std::string& choice : choices) {
            const bool chosen = choice == text;
            if (ImGui::Selectable(choice.c_str(), chosen)) text = choice;
            if (chosen) ImGui::SetItemDefaultFocus();
            if (ImGui::IsItemFocused() && enter_pressed()) {
                text = choice;
                ImGui::CloseCurrentPopup();
            }
        }
        ImGui::EndCombo();
    } else if (ImGui::IsItemFocused() && enter_pressed()) {
        ImGui::OpenPopupEx(popup);
    }
}

void ControlRing::begin_frame() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    // Dear ImGui's own Tab request (to the next text field only) gives way to the ring's.
    if (g.NavMoveScoringItems && (g.NavMoveFlags & ImGuiNavMoveFlags_Tabbing) != 0)
        ImGui::NavMoveRequestCancel();
    swallow_key(GLFW_KEY_TAB);
    const bool editing = g.ActiveId != 0 && g.ActiveId == g.InputTextState.ID;
    if (editing && ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) {
        swallow_key(GLFW_KEY_ESCAPE);
        ImGui::ClearActiveID();  // what was typed stays in the field (and the model)
    }
    current_.clear();
}

void ControlRing::before_text(const std::string& name) {
    if (target_ != name) return;
    target_.reset();
    ImGui::SetKeyboardFocusHere();
}

void ControlRing::mark(const std::string& name, bool text, bool focusable) {
    Entry e;
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    e.rect = {name, min.x, min.y, max.x - min.x, max.y - min.y};
    e.rect.visible = ImGui::IsItemVisible();
    e.id = ImGui::GetItemID();
    e.text = text;
    e.focusable = focusable;
    record(std::move(e));
}

void ControlRing::mark_at(const std::string& name, unsigned int id, float x, float y, float width,
                          float height, bool open) {
    Entry e;
    e.rect = {name, x, y, width, height};
    e.rect.open = open;
    e.rect.visible = ImGui::IsRectVisible(ImVec2(x, y), ImVec2(x + width, y + height));
    e.id = id;
    record(std::move(e));
}

void ControlRing::record(Entry e) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    e.rect.enabled = (g.CurrentItemFlags & ImGuiItemFlags_Disabled) == 0;
    e.rect.focused = e.focusable && e.id != 0 && (g.NavId == e.id || g.ActiveId == e.id);
    current_.push_back(e);
    if (target_ != e.rect.name) return;
    target_.reset();
    ImGui::ClearActiveID();
    ImGui::SetFocusID(e.id, ImGui::GetCurrentWindow());
    ImGui::SetScrollHereY();
    g.NavDisableHighlight = false;
}

void ControlRing::tab(bool backwards) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const unsigned int focused = g.ActiveId != 0 ? g.ActiveId : g.NavId;
    std::vector<const Entry*> enabled;
    for (const Entry& e : last_)
        if (e.rect.enabled && e.focusable) enabled.push_back(&e);
    if (enabled.empty()) return;
    const auto at = std::ranges::find(enabled, focused, &Entry::id);
    const int n = static_cast<int>(enabled.size());
    int next = backwards ? n - 1 : 0;
    if (at != enabled.end()) {
        const int i = static_cast<int>(at - enabled.begin());
        next = (i + (backwards ? n - 1 : 1)) % n;
    }
    target_ = enabled[next]->rect.name;
}

std::vector<ControlRect> ControlRing::rects() const {
    std::vector<ControlRect> rects;
    for (const Entry& e : last_) rects.push_back(e.rect);
    return rects;
}

void ControlRing::end_frame() {
    last_ = std::move(current_);
    current_.clear();
    // A target that was not drawn (its step changed) is dropped rather than kept for later.
    if (target_ &&
        std::ranges::none_of(last_, [&](const Entry& e) { return e.rect.name == *target_; }))
        target_.reset();
}

}  // namespace monoplane::lab
