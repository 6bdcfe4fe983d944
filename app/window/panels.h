// The experimenter window's panels, drawn with Dear ImGui between NewFrame() and Render().
#pragma once

#include <imgui.h>

#include <array>
#include <vector>

#include "app/window/experimenter_view.h"
#include "app/window/mirror_gaze.h"
#include "app/window/mirror_texture.h"

namespace monoplane::window {

// How to draw the mirror: its size, and a draw-list callback that binds its texture (the Vulkan
// backend of ImGui 1.86 ignores texture ids; see imgui_backend_access.h).
struct MirrorImage {
    float width = 0, height = 0;
    ImTextureID texture = nullptr;
    ImDrawCallback bind = nullptr;
    void* bind_data = nullptr;
};

// What the panels remember between frames.
struct PanelState {
    FitRect mirror_rect;   // where the mirror was drawn last, in window pixels
    GazeMarkerState gaze;  // the gaze marker over the mirror
    std::size_t log_lines_seen = 0;
    std::array<char, 1024> note{};  // the note being typed (sent and cleared on Enter)
};

// Draws every panel for `view`; returns the commands the experimenter gave with them.
std::vector<Command> draw_panels(const ExperimenterView& view, const MirrorImage& mirror,
                                 PanelState& state);

}  // namespace monoplane::window
