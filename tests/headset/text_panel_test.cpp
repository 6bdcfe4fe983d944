// Pages of text in the headset without a GPU: the text as the font can draw it, word wrapping,
// and the panel's letters sized in degrees of visual angle for the Vive (hmd/profiles/vive.toml),
// checked against angles worked out here from the profile's tangents, through the compositor's
// own placement (overlay_rect).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "app/headset/eye_compositor.h"
#include "app/headset/overlay_text.h"
#include "app/headset/text_panel.h"
#include "hmd/profile.h"
#include "tests/text/freetype_reference.h"
#include "text/line_break.h"

namespace monoplane::headset {
namespace {

constexpr double kPi = 3.14159265358979323846;

const std::string kParagraph =
    "You will see two versions of each scene, one after the other. Press SWITCH to change between "
    "them as often as you like, then press CONFIRM to choose the one that looked more natural. "
    "There are no right or wrong answers; please answer as you see it.";

TEST(ShownText, TabsAsSpacesCarriageReturnsDroppedInvalidBytesReplaced) {
    EXPECT_EQ(shown_text("caf\xc3\xa9\tend\r\n"), "caf\xc3\xa9 end\n");
    EXPECT_EQ(shown_text("a\xff"
                         "b"),
              "a\xef\xbf\xbd"
              "b");  // not UTF-8: U+FFFD per byte
    EXPECT_EQ(shown_text("\u201cHi\u201d \u2014 \u4e2d\u6587"),
              "\u201cHi\u201d \u2014 \u4e2d\u6587");
}

class VivePanel : public ::testing::Test {
  protected:
    void SetUp() override {
        const Result<hmd::HmdProfile> vive = hmd::load_hmd_profile("vive");
        ASSERT_TRUE(vive.ok());
        eyes_ = {vive.value().left, vive.value().right};
        extent_ = vk::Extent2D(static_cast<std::uint32_t>(vive.value().width),
                               static_cast<std::uint32_t>(vive.value().height));
    }

    // The angle, degrees, between the eye's directions through two pixel centres of a column.
    double degrees_between(double x_px, double y0_px, double y1_px) const {
        const rig::Tangents& t = eyes_[0];
        const double x = t.left + x_px / extent_.width * (t.right - t.left);
        const auto dir_y = [&](double y_px) {
            return t.up - y_px / extent_.height * (t.up - t.down);
        };
        const double a[3] = {x, dir_y(y0_px), 1.0};
        const double b[3] = {x, dir_y(y1_px), 1.0};
        const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + 1.0);
        const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + 1.0);
        return std::acos(std::min(1.0, dot / (na * nb))) * 180.0 / kPi;
    }

    // The panel's image is FreeType's rendering of its lines, blended ink over background:
    // pixel for pixel, with no difference tolerated.
    void expect_reference_image(const modes::RgbaImage& image, const TextPanel& panel) {
        expect_reference_image(image, panel, reference_);
    }
    static void expect_reference_image(const modes::RgbaImage& image, const TextPanel& panel,
                                       testing::FreeTypeReference& reference) {
        const double em_px = panel.style.capital_px / reference.cap_height_em();
        const testing::FreeTypeReference::Image expected =
            reference.render(panel.lines, em_px, panel.style.padding_px);
        ASSERT_EQ(image.width, static_cast<std::uint32_t>(expected.width));
        ASSERT_EQ(image.height, static_cast<std::uint32_t>(expected.height));
        std::size_t differing = 0;
        for (std::size_t p = 0; p < expected.coverage.size(); ++p) {
            for (std::size_t k = 0; k < 4; ++k) {
                const double from = panel.style.background[k];
                const double to = panel.style.ink[k];
                const auto want = static_cast<std::uint8_t>(
                    std::lround(from + (to - from) * expected.coverage[p] / 255.0));
                differing += image.pixels[p * 4 + k] != want;
            }
        }
        EXPECT_EQ(differing, 0u);
    }

    std::array<rig::Tangents, 2> eyes_;
    vk::Extent2D extent_;
    testing::FreeTypeReference reference_{testing::kDejaVuSans};
};

TEST_F(VivePanel, PixelsPerDegreeStraightAhead) {
    // The Vive's left eye spans tan_up - tan_down = 2.933106 over 1512 rows: a degree centred
    // straight ahead is 2 tan(0.5 deg) * 1512 / 2.933106 = 8.998 rows.
    const double n = 2.0 * std::tan(0.5 * kPi / 180.0) * 1512.0 / (1.464287 + 1.468819);
    EXPECT_NEAR(n, 8.998, 0.001);
    EXPECT_NEAR(pixels_per_degree(eyes_[0], extent_), n, 0.001);
}

TEST_F(VivePanel, CapitalsSubtendTheAskedHeightStraightAhead) {
    const double n = 2.0 * std::tan(0.5 * kPi / 180.0) * 1512.0 / (1.464287 + 1.468819);
    for (const double degrees : {1.0, 1.5}) {
        TextPanelOptions options;
        options.text_height_deg = degrees;
        const TextPanel panel =
            layout_text_panel(kParagraph, {"Press CONFIRM to begin"}, eyes_, extent_, options);
        const modes::RgbaImage image = render_text(panel.lines, panel.style);
        const PixelRect rect =
            overlay_rect(panel.placement, image.width, image.height, eyes_[0], extent_);
        // Blitted 1:1: the rectangle is the image's size (the width to a pixel: the eye's
        // pixels are not quite square in tangent units).
        EXPECT_EQ(rect.y1 - rect.y0, static_cast<int>(image.height));
        EXPECT_NEAR(rect.x1 - rect.x0, static_cast<int>(image.width), 1);
        // A capital letter is `degrees` times 8.998 pixels of the eye; the font is drawn at
        // that over its cap height (DejaVu Sans: 'H' is 1493 of 2048 units), to 1/64 pixel.
        const double capital_px = panel.style.capital_px;
        EXPECT_NEAR(capital_px, degrees * n, 0.001);  // n from the profile's tangents to 6 digits
        const double em_px = capital_px / reference_.cap_height_em();
        EXPECT_NEAR(text_geometry(panel.style).em_px, em_px, 1.0 / 128.0);
        // What the headset draws is FreeType's rasterisation of the lines at that size.
        expect_reference_image(image, panel);
        EXPECT_FALSE(panel.shrunk);
        EXPECT_DOUBLE_EQ(panel.capital_deg, degrees);
        // Centred straight ahead (tangent 0: column 1344 * 1.391937 / 2.639346, row
        // 1512 * 1.464287 / 2.933106), that many rows subtend `degrees`.
        const double x0 = 1344.0 * 1.391937 / 2.639346;
        const double y0 = 1512.0 * 1.464287 / 2.933106;
        EXPECT_NEAR(degrees_between(x0, y0 - capital_px / 2, y0 + capital_px / 2), degrees, 1e-6);
        // At the panel's corners a flat panel's letters subtend less: the reported smallest.
        double smallest = degrees;
        for (const int x : {rect.x0, rect.x1}) {
            smallest = std::min(smallest, degrees_between(x, rect.y0, rect.y0 + capital_px));
            smallest = std::min(smallest, degrees_between(x, rect.y1 - capital_px, rect.y1));
        }
        EXPECT_NEAR(panel.smallest_capital_deg, smallest, 0.01 * degrees);
        EXPECT_GT(smallest, 0.85 * degrees);
        // No wider than 40 degrees, and wrapped (the paragraph is longer than a line).
        const double t0 = eyes_[0].left + rect.x0 * (eyes_[0].right - eyes_[0].left) / 1344.0;
        const double t1 = eyes_[0].left + rect.x1 * (eyes_[0].right - eyes_[0].left) / 1344.0;
        EXPECT_LE((std::atan(t1) - std::atan(t0)) * 180.0 / kPi, 40.0);
        EXPECT_GT(panel.lines.size(), 4u);
        EXPECT_EQ(panel.lines[panel.lines.size() - 2], "");  // the footer after a blank line
        EXPECT_EQ(panel.lines.back(), "Press CONFIRM to begin");
    }
}

TEST_F(VivePanel, ALongPageGrowsDownwardsAndStaysInView) {
    const TextPanelOptions options;
    const TextPanel short_page = layout_text_panel("Thank you.", {}, eyes_, extent_, options);
    // A long instruction page: three paragraphs, some 800 characters.
    std::string long_text;
    for (int i = 0; i < 3; ++i) long_text += kParagraph + "\n\n";
    const TextPanel long_page =
        layout_text_panel(long_text, {"Page 1 of 2"}, eyes_, extent_, options);
    const auto rect_of = [&](const TextPanel& panel) {
        const modes::RgbaImage image = render_text(panel.lines, panel.style);
        return overlay_rect(panel.placement, image.width, image.height, eyes_[0], extent_);
    };
    const PixelRect s = rect_of(short_page);
    const PixelRect l = rect_of(long_page);
    EXPECT_EQ(l.y0, s.y0);  // the same top edge
    EXPECT_GT(l.y1, s.y1 + 150);
    EXPECT_FALSE(long_page.shrunk);
    EXPECT_DOUBLE_EQ(long_page.capital_deg, 1.0);
    // Inside the eye's image: not clamped, so not squeezed.
    EXPECT_GT(l.x0, 0);
    EXPECT_LT(l.x1, static_cast<int>(extent_.width));
    EXPECT_LT(l.y1, static_cast<int>(extent_.height));
    const double em_px = long_page.style.capital_px / reference_.cap_height_em();
    for (const std::string& line : long_page.lines) {
        double advances = 0.0;  // FreeType's own advances of the line
        for (const char32_t c : testing::utf32(line)) advances += reference_.advance_em(c) * em_px;
        EXPECT_LE(advances + 2 * long_page.style.padding_px, l.x1 - l.x0 + 1) << line;
    }
}

TEST_F(VivePanel, TextTooLongForTheViewIsDrawnSmallerAndSaysSo) {
    std::string text;
    for (int i = 0; i < 40; ++i) text += kParagraph + "\n";
    const TextPanel panel = layout_text_panel(text, {}, eyes_, extent_, {});
    EXPECT_TRUE(panel.shrunk);
    EXPECT_LT(panel.capital_deg, 1.0);
    EXPECT_GT(panel.capital_deg, 0.1);
    const modes::RgbaImage image = render_text(panel.lines, panel.style);
    const PixelRect r = overlay_rect(panel.placement, image.width, image.height, eyes_[0], extent_);
    EXPECT_GT(r.y0, 0);
    EXPECT_LT(r.y1, static_cast<int>(extent_.height));
    EXPECT_EQ(r.y1 - r.y0, static_cast<int>(image.height));
}

// Pages in the participant's language: a German page in the default font and a Chinese one in
// a CJK font, wrapped to the Vive's panel and drawn as FreeType draws them.
TEST_F(VivePanel, GermanAndChinesePagesAreFreeTypesGlyphs) {
    const std::string german =
        "Dr\u00fccken Sie SWITCH, um zwischen Version 1 und Version 2 zu wechseln. Wechseln Sie "
        "so oft Sie m\u00f6chten und lassen Sie sich Zeit: Es gibt kein Zeitlimit. Gr\u00f6\u00dfe "
        "und Schl\u00fcssel, \u00c4pfel und \u00d6l.";
    TextPanelOptions options;
    const TextPanel de = layout_text_panel(german, {"Page 2 of 3 - CONFIRM: next, SWITCH: back"},
                                           eyes_, extent_, options);
    EXPECT_GT(de.lines.size(), 3u);
    expect_reference_image(render_text(de.lines, de.style), de);
    testing::FreeTypeReference wqy(testing::kWqyMicroHei);
    if (!wqy.ok()) GTEST_SKIP() << testing::kWqyMicroHei << " missing (fonts-wqy-microhei)";
    const std::string chinese =
        "\u6bcf\u4e2a\u573a\u666f\u90fd\u4f1a\u4ee5\u4e24\u4e2a\u7248\u672c\u663e\u793a"
        "\u3002\u6309 SWITCH \u952e\u5728\u4e24\u4e2a\u7248\u672c\u4e4b\u95f4\u5207\u6362"
        "\uff0c\u6b21\u6570\u4e0d\u9650\u3002\u6309 CONFIRM \u952e\u9009\u62e9\u5f53\u524d"
        "\u663e\u793a\u7684\u7248\u672c\u3002\u7b2c\u4e00\u6b21\u8bd5\u9a8c\u662f\u7ec3"
        "\u4e60\uff08\u4e0d\u8ba1\u5165\u7ed3\u679c\uff09\u3002";
    options.font = testing::kWqyMicroHei;
    options.max_width_deg = 20.0;  // narrow: several lines without a space to break at
    const TextPanel zh = layout_text_panel(chinese, {}, eyes_, extent_, options);
    ASSERT_GT(zh.lines.size(), 2u);
    for (std::size_t i = 1; i < zh.lines.size(); ++i) {
        const char32_t first = testing::utf32(zh.lines[i]).front();
        EXPECT_EQ(std::u32string(U"\u3002\uff0c\uff09").find(first), std::u32string::npos)
            << zh.lines[i];
    }
    // Every character kept (spaces at a break are dropped).
    const auto without_spaces = [](std::string text) {
        std::erase(text, ' ');
        return text;
    };
    std::string rejoined;
    for (const std::string& line : zh.lines) rejoined += line;
    EXPECT_EQ(without_spaces(rejoined), without_spaces(chinese));
    // A capital letter is as high as in the Latin font: the sizing rule holds for every font.
    EXPECT_NEAR(zh.style.capital_px, de.style.capital_px, 1e-9);
    expect_reference_image(render_text(zh.lines, zh.style), zh, wqy);
}

}  // namespace
}  // namespace monoplane::headset
