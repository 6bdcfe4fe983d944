// The headset's overlays without a GPU: where a placement lands in an eye (checked against the
// projection worked out by hand for the Vive's left eye) and the text rasteriser's output.
#include <gtest/gtest.h>

#include <set>

#include "app/headset/eye_compositor.h"
#include "app/headset/openxr_headset.h"
#include "app/headset/overlay_text.h"

namespace monoplane::headset {
namespace {

// The Vive's left eye (hmd/profiles/vive.toml) at its full per-eye size.
rig::Tangents vive_left() {
    rig::Tangents t;
    t.left = -1.391937;
    t.right = 1.247409;
    t.up = 1.464287;
    t.down = -1.468819;
    return t;
}

TEST(OverlayRect, LandsWhereTheDirectionProjects) {
    // Centre (0, -0.55): x = (0 + 1.391937) / 2.639346 * 1344 = 708.80,
    // y = (1.464287 + 0.55) / 2.933106 * 1512 = 1038.35; height 0.05 * 1512 / 2.933106 = 25.77,
    // width 25.77 * 10 / 20 = 12.89.
    const PixelRect r = overlay_rect({0.0, -0.55, 0.05}, 10, 20, vive_left(), {1344, 1512});
    EXPECT_EQ(r.x0, 702);   // 708.80 - 6.44
    EXPECT_EQ(r.x1, 715);   // 708.80 + 6.44
    EXPECT_EQ(r.y0, 1025);  // 1038.35 - 12.89
    EXPECT_EQ(r.y1, 1051);  // 1038.35 + 12.89
}

TEST(OverlayRect, ClampedToTheImage) {
    // Far below the frustum: nothing left to draw.
    const PixelRect below = overlay_rect({0.0, -3.0, 0.05}, 10, 10, vive_left(), {1344, 1512});
    EXPECT_EQ(below.y0, 1512);
    EXPECT_EQ(below.y1, 1512);
    // Larger than the view: the whole image.
    const PixelRect huge = overlay_rect({0.0, 0.0, 10.0}, 10, 10, vive_left(), {1344, 1512});
    EXPECT_EQ(huge.x0, 0);
    EXPECT_EQ(huge.x1, 1344);
    EXPECT_EQ(huge.y0, 0);
    EXPECT_EQ(huge.y1, 1512);
}

std::size_t inked_pixels(const modes::RgbaImage& image, const Rgba8& background) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
        n += image.pixels[i] != background[0] || image.pixels[i + 1] != background[1] ||
             image.pixels[i + 2] != background[2];
    }
    return n;
}

TEST(RenderText, SizeFollowsTheLinesAndTheFontsMetrics) {
    // DejaVu Sans (its head, hhea, glyf and hmtx tables): 2048 units per em, 'H' 1493 high,
    // lines 1901 + 483 apart, '1' advances 1303. A capital of 1493 / 2048 * 20 pixels sets the
    // font at 20 pixels per em: lines round(2384 / 2048 * 20) = round(23.28) = 23 pixels apart,
    // '1' ceil(1303 / 2048 * 20) = ceil(12.72) = 13 pixels wide.
    TextStyle style;
    style.capital_px = 1493.0 / 2048.0 * 20.0;
    style.padding_px = 2;
    const modes::RgbaImage one = render_text({"1"}, style);
    EXPECT_EQ(one.height, 23u + 4u);
    EXPECT_EQ(one.width, 13u + 4u);
    const modes::RgbaImage two_lines = render_text({"1", "1"}, style);
    EXPECT_EQ(two_lines.height, 46u + 4u);
    EXPECT_EQ(two_lines.width, one.width);
    // "11": 2 * 12.72 = 25.45 -> 26 pixels.
    EXPECT_EQ(render_text({"11"}, style).width, 26u + 4u);
    style.capital_px *= 3.0;  // 60 pixels per em: lines round(69.84) = 70 apart
    EXPECT_EQ(render_text({"1"}, style).height, 70u + 4u);
}

TEST(RenderText, InkOnBackgroundAndDistinctGlyphs) {
    const TextStyle style;
    const modes::RgbaImage one = render_text({"1"}, style);
    const modes::RgbaImage two = render_text({"2"}, style);
    const std::size_t ink1 = inked_pixels(one, style.background);
    EXPECT_GT(ink1, 0u);
    EXPECT_LT(ink1, one.pixels.size() / 4 / 2);  // mostly background
    // The corner is background (the padding); somewhere inside a stem is fully ink.
    EXPECT_EQ(one.pixels[0], style.background[0]);
    bool full_ink = false;
    for (std::size_t i = 0; i < one.pixels.size(); i += 4)
        full_ink |= one.pixels[i] == style.ink[0];
    EXPECT_TRUE(full_ink);
    // "2" has more strokes than "1".
    EXPECT_GT(inked_pixels(two, style.background), ink1);
    // A character the font lacks is its missing-glyph box, not nothing.
    EXPECT_GT(inked_pixels(render_text({"\u4e2d"}, style), style.background), 0u);
}

TEST(ControllerBindings, EveryProfileBindsEveryControl) {
    const std::set<std::string> profiles = {"/interaction_profiles/khr/simple_controller",
                                            "/interaction_profiles/htc/vive_controller",
                                            "/interaction_profiles/valve/index_controller",
                                            "/interaction_profiles/oculus/touch_controller"};
    std::set<std::string> seen;
    for (const ProfileBindings& p : controller_bindings()) {
        seen.insert(p.profile);
        std::set<Control> controls;
        std::set<std::string> paths;
        for (const ControlBinding& b : p.bindings) {
            controls.insert(b.control);
            EXPECT_EQ(std::string(b.path).rfind("/user/hand/", 0), 0u) << b.path;
            EXPECT_TRUE(paths.insert(b.path).second) << "bound twice: " << b.path;
        }
        EXPECT_EQ(controls.size(), 3u) << p.profile;
    }
    EXPECT_EQ(seen, profiles);
}

}  // namespace
}  // namespace monoplane::headset
