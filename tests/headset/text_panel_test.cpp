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

namespace monoplane::headset {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::string> words_of(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

const std::string kParagraph =
    "You will see two versions of each scene, one after the other. Press SWITCH to change between "
    "them as often as you like, then press CONFIRM to choose the one that looked more natural. "
    "There are no right or wrong answers; please answer as you see it.";

TEST(HeadsetAscii, TypographyBecomesItsAsciiLookAlike) {
    EXPECT_EQ(headset_ascii("\xe2\x80\x9cHi\xe2\x80\x9d \xe2\x80\x94 it\xe2\x80\x99s\xe2\x80\xa6"),
              "\"Hi\" - it's...");
    EXPECT_EQ(headset_ascii("caf\xc3\xa9\tend\r\n"), "caf? end\n");  // one '?' per character
    EXPECT_EQ(headset_ascii("a\xff"
                            "b"),
              "a?b");  // not UTF-8: '?' per byte
    EXPECT_EQ(headset_ascii("plain ASCII"), "plain ASCII");
}

TEST(WrapText, NoLineWiderThanAskedAndWordsKeptWhole) {
    for (const int max_units : {60, 120, 250, 400}) {
        const std::vector<std::string> lines = wrap_text(kParagraph, max_units);
        ASSERT_GT(lines.size(), 1u);
        for (const std::string& line : lines) {
            EXPECT_LE(text_width_units(line), max_units) << line;
            EXPECT_FALSE(line.empty());
            EXPECT_NE(line.front(), ' ');
            EXPECT_NE(line.back(), ' ');
        }
        // Every word whole and in order: the lines' words are the paragraph's.
        EXPECT_EQ(words_of(joined(lines)), words_of(kParagraph)) << max_units;
        // Greedy: a line's next word would not have fitted on it.
        for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
            const std::string next = words_of(lines[i + 1]).front();
            EXPECT_GT(text_width_units(lines[i] + " " + next), max_units);
        }
    }
}

TEST(WrapText, ExplicitLineBreaksAndEmptyLinesAreKept) {
    EXPECT_EQ(wrap_text("First line.\n\nThird line.", 1000),
              (std::vector<std::string>{"First line.", "", "Third line."}));
    EXPECT_EQ(wrap_text("", 1000), std::vector<std::string>{""});
    EXPECT_EQ(wrap_text("end\n", 1000), (std::vector<std::string>{"end", ""}));
    // A break in the middle of a long paragraph starts a new line there.
    const std::vector<std::string> lines = wrap_text("aaa bbb\nccc ddd eee fff", 1000);
    EXPECT_EQ(lines, (std::vector<std::string>{"aaa bbb", "ccc ddd eee fff"}));
}

TEST(WrapText, OnlyAWordWiderThanALineIsSplit) {
    const std::string word(60, 'W');
    const int max_units = text_width_units("WWWWWWWWWW");  // ten of them fit
    const std::vector<std::string> lines = wrap_text("a " + word + " b", max_units);
    std::string rejoined;
    for (const std::string& line : lines) {
        EXPECT_LE(text_width_units(line), max_units) << line;
        rejoined += line;
    }
    EXPECT_EQ(lines.front(), "a");
    EXPECT_EQ(rejoined, "a" + word + "b");
    // Even a line narrower than one character makes progress, a character a line.
    EXPECT_EQ(wrap_text("abc", 1).size(), 3u);
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

    std::array<rig::Tangents, 2> eyes_;
    vk::Extent2D extent_;
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
        // A capital is 7 font units: `degrees` times 8.998 pixels of the eye.
        const double capital_px = kCapitalUnits * panel.style.scale;
        EXPECT_NEAR(capital_px, degrees * n, 0.01);
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
    for (const std::string& line : long_page.lines) {
        EXPECT_LE(text_width_units(line) * long_page.style.scale, l.x1 - l.x0) << line;
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

}  // namespace
}  // namespace monoplane::headset
