// Pages of text in the headset (instructions, breaks, the end of a session): the text wrapped to
// a panel straight ahead (text/line_break.h: at spaces, and between CJK characters), its capital
// letters sized in degrees of visual angle at the headset's resolution (docs/headsets.md, "What
// the participant sees"), in the protocol's font. Pure: no GPU.
//
// The panel lies on the eyes' image plane (tangent space, at infinity like every overlay): a
// capital letter straight ahead subtends the asked angle; toward the panel's edges a flat panel's
// letters subtend a little less (the smallest is reported). The panel is rasterised at the eye's
// own pixel density, so that it is blitted 1:1.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "app/headset/eye_compositor.h"
#include "app/headset/overlay_text.h"
#include "rig/tangents.h"
#include "text/font.h"

namespace monoplane::headset {

// The text as the headset draws it: tabs as spaces, carriage returns dropped, bytes that are not
// UTF-8 as U+FFFD; line breaks kept. (The experimenter window mirrors pages in this form.)
std::string shown_text(std::string_view utf8);

// Pixels per degree of visual angle straight ahead, vertically, in an eye image of this frustum
// and size: the rows a degree centred on tangent 0 spans (the image spans the tangents linearly).
double pixels_per_degree(const rig::Tangents& eye, vk::Extent2D extent);

// The angle, in radians, that a vertical extent of one tangent unit subtends at direction
// (x, y) of the tangent plane: sqrt(1 + x^2) / (1 + x^2 + y^2).
double radians_per_tangent(double x, double y);

struct TextPanelOptions {
    double text_height_deg = 1.0;  // the height of a capital letter, degrees of visual angle
    double max_width_deg = 40.0;   // the panel's widest, centred straight ahead
    double top_tan = 0.18;         // the panel's upper edge (tan 10 degrees up); it grows down
    std::string font = text::kDefaultFontPath;  // the protocol's [text] font
};

struct TextPanel {
    std::vector<std::string> lines;  // wrapped, the footer's after a blank line
    TextStyle style;                 // style.capital_px: a capital's height in the eye's pixels
    OverlayPlacement placement;      // for EyeCompositor, from the rasterised image's size
    // The angle a capital letter subtends straight ahead, degrees: text_height_deg, unless shrunk.
    double capital_deg = 0.0;
    // The smallest angle a capital subtends anywhere on the panel (at its corners), degrees.
    double smallest_capital_deg = 0.0;
    // The text was too long for the view at text_height_deg and is drawn smaller.
    bool shrunk = false;
};

// Lays out `body` (wrapped) and `footer` lines on a panel for eyes of these frusta and swapchain
// size. The panel is centred horizontally, at most max_width_deg wide and inside both eyes'
// views; its top is at top_tan, moved up only as far as a long text needs to stay in view (and
// never above 30 degrees up nor below 40 degrees down: text too long for that is drawn smaller).
// Pixel density and placement follow eyes[0] (the other eye's differs by a fraction of a pixel
// on the headsets monoplane knows).
TextPanel layout_text_panel(const std::string& body, const std::vector<std::string>& footer,
                            const std::array<rig::Tangents, 2>& eyes, vk::Extent2D extent,
                            const TextPanelOptions& options);

}  // namespace monoplane::headset
