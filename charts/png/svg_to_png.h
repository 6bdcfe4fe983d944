// Rasterizes the charts' SVG documents (charts/svg_writer.h) to PNG with librsvg and cairo, so each
// figure also exists as a bitmap for slides, word processors and image viewers without SVG.
// Text is drawn with whatever fonts fontconfig offers for the SVG's font-family (DejaVu Sans on
// Debian); a missing font changes glyph shapes, never the layout of axes and marks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace monoplane::charts {

// Straight (not premultiplied) RGBA, rows top to bottom, 4 bytes per pixel.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
};

// The document's width and height attributes (pixels) times `scale`, rounded; scale 2 gives a
// sharper bitmap of the same figure. Errors: not SVG, no size, scale not in (0, 16].
Result<RgbaImage> rasterize_svg(std::string_view svg, double scale = 1.0);

// Rasterizes and writes a PNG to `path` (replacing it). The error names the file.
Result<void> write_svg_as_png(std::string_view svg, const std::filesystem::path& path,
                              double scale = 1.0);

}  // namespace monoplane::charts
