// The launcher's controls as one ring: where each was drawn (for the state dump, so scripted
// checks click where a person would) and the Tab order through all of them. Dear ImGui 1.86 stops
// Tab only at text fields, so a window with one field (the database step) kept Tab there; this
// ring takes Tab from Dear ImGui and moves through every enabled control in drawing order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/lab/launcher_model.h"

namespace monoplane::lab {

class ControlRing {
  public:
    // Before the frame's first control: starts a new list, and takes this frame's Tab and a
    // text field's Escape from Dear ImGui (Escape there would throw away what was typed; it
    // leaves the field instead, keeping the text). Between new_frame() and the first control.
    void begin_frame();
    // Before a text field named `name` is drawn: gives it the keyboard when Tab moved there.
    void before_text(const std::string& name);
    // After the control named `name` was drawn (the last item): records it, and gives it the
    // focus when Tab moved there. `focusable` false: only where it is (a text, not a control).
    void mark(const std::string& name, bool text = false, bool focusable = true);
    // Tab (or Shift+Tab): the next (previous) enabled control of the last frame gets the focus
    // in the next one. Between poll_events() and new_frame().
    void tab(bool backwards);
    // A control drawn at `x`, `y` (screen), `width` x `height`, with Dear ImGui's `id`: for one
    // that is not the last item when it is done (a combo box whose list is open).
    void mark_at(const std::string& name, unsigned int id, float x, float y, float width,
                 float height, bool open = false);
    // The controls of the frame drawn last, in drawing order.
    std::vector<ControlRect> rects() const;
    void end_frame();

  private:
    struct Entry {
        ControlRect rect;
        unsigned int id = 0;
        bool text = false;
        bool focusable = true;
    };
    void record(Entry e);
    std::vector<Entry> current_, last_;
    std::optional<std::string> target_;
};

// A combo box of `choices` with `text` chosen, recorded in `controls` as `name`: Enter opens it
// and Enter picks in it, as Space does (Dear ImGui 1.86 takes only Space). Inside a window.
void draw_choice(ControlRing& controls, const std::string& name, const std::string& label,
                 const std::vector<std::string>& choices, std::string& text);

}  // namespace monoplane::lab
