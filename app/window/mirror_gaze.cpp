#include "app/window/mirror_gaze.h"

#include <algorithm>

namespace monoplane::window {
namespace {

// A saturated green with a dark outline: visible on the bright pages and the dark scenes alike.
constexpr ImU32 kMarker = IM_COL32(70, 255, 110, 255);
constexpr ImU32 kFaded = IM_COL32(70, 255, 110, 110);
constexpr ImU32 kOutline = IM_COL32(0, 0, 0, 200);
constexpr ImU32 kFadedOutline = IM_COL32(0, 0, 0, 90);
constexpr ImU32 kLabelBackground = IM_COL32(0, 0, 0, 170);
constexpr float kStroke = 2.0f;
constexpr float kOutlineStroke = 4.0f;

ImVec2 at_uv(const FitRect& mirror, const std::array<double, 2>& uv) {
    return ImVec2(mirror.x + static_cast<float>(uv[0]) * mirror.width,
                  mirror.y + static_cast<float>(uv[1]) * mirror.height);
}

std::array<double, 2> clamped(const std::array<double, 2>& uv) {
    return {std::clamp(uv[0], 0.0, 1.0), std::clamp(uv[1], 0.0, 1.0)};
}

void ring(ImDrawList& list, ImVec2 centre, float radius, ImU32 colour, ImU32 outline = kOutline) {
    list.AddCircle(centre, radius, outline, 32, kOutlineStroke);
    list.AddCircle(centre, radius, colour, 32, kStroke);
}

// The cross's arms stop short of the centre, which stays visible: it is what the participant
// looks at.
void cross(ImDrawList& list, ImVec2 c, float radius) {
    const float inner = radius * 0.45f;
    const float outer = radius * 1.6f;
    const ImVec2 arms[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const ImVec2& d : arms) {
        const ImVec2 from(c.x + d.x * inner, c.y + d.y * inner);
        const ImVec2 to(c.x + d.x * outer, c.y + d.y * outer);
        list.AddLine(from, to, kOutline, kOutlineStroke);
        list.AddLine(from, to, kMarker, kStroke);
    }
}

void label(ImDrawList& list, ImVec2 centre, float radius, const FitRect& mirror, const char* text) {
    const ImVec2 size = ImGui::CalcTextSize(text);
    // Beside the ring, kept inside the mirror.
    const float x =
        std::clamp(centre.x + radius + 4.0f, mirror.x, mirror.x + mirror.width - size.x - 4.0f);
    const float y =
        std::clamp(centre.y - size.y * 0.5f, mirror.y, mirror.y + mirror.height - size.y - 2.0f);
    list.AddRectFilled(ImVec2(x - 2, y - 1), ImVec2(x + size.x + 2, y + size.y + 1),
                       kLabelBackground);
    list.AddText(ImVec2(x, y), kMarker, text);
}

bool inside(const std::array<double, 2>& uv) {
    return uv[0] >= 0.0 && uv[0] <= 1.0 && uv[1] >= 0.0 && uv[1] <= 1.0;
}

}  // namespace

const char* gaze_shown_name(GazeShown shown) {
    switch (shown) {
        case GazeShown::Nothing:
            return "none";
        case GazeShown::Point:
            return "point";
        case GazeShown::Outside:
            return "outside";
        case GazeShown::Lost:
            return "lost";
    }
    return "invalid";
}

void draw_gaze_marker(ImDrawList& list, const FitRect& mirror, const ExperimenterView& view,
                      GazeMarkerState& state) {
    state.shown = GazeShown::Nothing;
    state.centre.reset();
    if (!view.gaze_tracked) {
        state.last_uv.reset();
        return;
    }
    // A marker about 5 % of the mirror's width across: seen at a glance, hiding little.
    const float radius = std::clamp(mirror.width * 0.025f, 8.0f, 18.0f);
    state.radius = radius;
    if (view.gaze_uv) {
        state.last_uv = clamped(*view.gaze_uv);
        state.centre = at_uv(mirror, *state.last_uv);
        if (inside(*view.gaze_uv)) {
            state.shown = GazeShown::Point;
            ring(list, *state.centre, radius, kMarker);
            cross(list, *state.centre, radius);
        } else {
            state.shown = GazeShown::Outside;
            ring(list, *state.centre, radius, kMarker);
            label(list, *state.centre, radius, mirror, "outside the view");
        }
        return;
    }
    state.shown = GazeShown::Lost;
    // Never seen yet: the label alone, in the mirror's corner.
    const ImVec2 corner(mirror.x + 4.0f, mirror.y + 4.0f + radius);
    if (state.last_uv) {
        state.centre = at_uv(mirror, *state.last_uv);
        ring(list, *state.centre, radius, kFaded, kFadedOutline);
    }
    label(list, state.centre.value_or(corner), state.last_uv ? radius : 0.0f, mirror, "no gaze");
}

}  // namespace monoplane::window
