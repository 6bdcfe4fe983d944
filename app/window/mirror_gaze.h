// The participant's gaze over the mirrored eye image: a ring with a cross where they look, so the
// experimenter sees what the participant attends to (the scene's content, the label, a page).
#pragma once

#include <imgui.h>

#include <array>
#include <optional>

#include "app/window/experimenter_view.h"
#include "app/window/mirror_texture.h"

namespace monoplane::window {

// What the marker shows. Point: this frame's gaze, inside the mirrored image. Outside: the
// participant looks beyond the mirrored eye's field; a hollow ring on the image's edge, towards
// where they look. Lost: the tracker has no valid sample this frame (a blink, the eyes lost); a
// faded ring where the gaze was last seen, labelled "no gaze", so that blinks do not make the
// marker flicker away and a longer loss is still noticed. Nothing: no gaze is tracked.
enum class GazeShown { Nothing, Point, Outside, Lost };
const char* gaze_shown_name(GazeShown shown);  // "none", "point", "outside", "lost"

// What the marker showed in the last frame (the window's state reports it), and the last valid
// gaze point, kept between frames for a Lost frame.
struct GazeMarkerState {
    GazeShown shown = GazeShown::Nothing;
    std::optional<ImVec2> centre;  // where the marker was drawn, window pixels
    float radius = 0.0f;           // its ring's, pixels
    std::optional<std::array<double, 2>> last_uv;
};

// Draws the marker for `view`'s gaze over the mirror drawn at `mirror` (window pixels).
void draw_gaze_marker(ImDrawList& list, const FitRect& mirror, const ExperimenterView& view,
                      GazeMarkerState& state);

}  // namespace monoplane::window
