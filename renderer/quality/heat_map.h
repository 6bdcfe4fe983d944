// Pictures of local SSIM like papers/000 Fig. 6, which shows (1 - SSIM) x 10: a difference of
// 0.1 in SSIM already saturates, so the small, localised errors of hybrid rendering (edges of
// far objects drifting by a pixel or two) are visible rather than lost near white.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/result.h"
#include "renderer/quality/image_view.h"
#include "renderer/quality/ssim.h"

namespace monoplane::quality {

// RGBA8 image (result.width x result.height, row-major) colouring v = clamp((1 - SSIM) * scale,
// 0, 1) with inferno (colormap.h): identical regions are inferno(0) = (0, 0, 4), v >= 1 is pale
// yellow (252, 255, 164). Pixels without a value (the border where the window does not fit) are
// transparent black (0, 0, 0, 0), so blend_heat_map leaves the rendering visible there; all
// others are opaque. Requires scale > 0 and finite (checked in every build; aborts otherwise).
std::vector<std::uint8_t> ssim_heat_map_rgba(const SsimResult& result, float scale = 10.0f);

// The rendering with the heat map laid over it: out = (1 - a) * base + a * heat per colour
// channel, with a = alpha * heat_alpha / 255, rounded; output alpha is 255. So border pixels
// show the base unchanged, alpha = 0 gives the base, alpha = 1 the heat map. base may have 1, 3
// or 4 channels (grey is spread to RGB); heat_rgba is base.width * base.height * 4 bytes, e.g.
// from ssim_heat_map_rgba of an SSIM computed on base. Returns an error for a malformed base, a
// heat map of another size, or alpha outside [0, 1].
Result<std::vector<std::uint8_t>> blend_heat_map(const ImageView& base,
                                                 std::span<const std::uint8_t> heat_rgba,
                                                 float alpha = 0.6f);

}  // namespace monoplane::quality
