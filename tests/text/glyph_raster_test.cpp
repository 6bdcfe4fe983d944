// Glyph coverage images (text/glyph_raster.h) compared pixel for pixel with FreeType's own
// rasterisation of the same strings done in the test (freetype_reference.h): the same font and
// size, each glyph loaded with FT_Load_Char and rendered, set at pen positions summed from
// FreeType's linear advances. No difference is tolerated.
#include <gtest/gtest.h>

#include "tests/text/freetype_reference.h"
#include "text/font.h"
#include "text/glyph_raster.h"

namespace monoplane::text {
namespace {

using testing::FreeTypeReference;

void expect_same(const CoverageImage& drawn, const FreeTypeReference::Image& reference,
                 const std::string& what) {
    ASSERT_EQ(drawn.width, static_cast<std::uint32_t>(reference.width)) << what;
    ASSERT_EQ(drawn.height, static_cast<std::uint32_t>(reference.height)) << what;
    std::size_t differing = 0;
    std::size_t inked = 0;
    for (std::size_t i = 0; i < drawn.coverage.size(); ++i) {
        differing += drawn.coverage[i] != reference.coverage[i];
        inked += reference.coverage[i] > 127;
    }
    EXPECT_EQ(differing, 0u) << what;
    EXPECT_GT(inked, 20u) << what;  // something was drawn
}

struct Sample {
    const char* font;
    std::vector<std::string> lines;
};

const Sample kSamples[] = {
    {testing::kDejaVuSans,
     {"Dr\u00fccken Sie SCHALTER \u2013 Gr\u00f6\u00dfe, Stra\u00dfe, \u00c4rger",
      "\u00c9l\u00e8ve, na\u00efve, \u0141\u00f3d\u017a, \u0160koda"}},
    {testing::kDejaVuSans,
     {"\u03a0\u03b1\u03c4\u03ae\u03c3\u03c4\u03b5 \u0395\u039d\u0391\u039b\u039b\u0391\u0393\u0397",
      "\u041d\u0430\u0436\u043c\u0438\u0442\u0435 \u041f\u0415\u0420\u0415\u041a\u041b\u042e"
      "\u0427\u0418\u0422\u042c"}},
    {testing::kWqyMicroHei,
     {"\u8bf7\u6309\u786e\u8ba4\u952e\u5f00\u59cb\u3002",
      "\u300c\u753b\u9762\u300d\uff08\u4e00\uff09 VR \u3042\u30a2\ud55c"}},
};

TEST(GlyphRaster, LinesAreFreeTypesGlyphsAtTheirPenPositions) {
    for (const Sample& sample : kSamples) {
        const Result<Font> font = Font::open(sample.font);
        if (!font.ok()) GTEST_SKIP() << font.error().message;
        FreeTypeReference reference(sample.font);
        ASSERT_TRUE(reference.ok());
        // Sizes as the headset uses them: fractional pixels per em, from a 9 to a 40 pixel
        // capital letter.
        for (const double em_px : {12.3, 20.0, 27.77, 55.5}) {
            for (const int padding : {0, 5}) {
                const LineGeometry geometry = line_geometry(font.value(), em_px, padding);
                const std::string what = std::string(sample.font) + " at " + std::to_string(em_px) +
                                         " px/em, padding " + std::to_string(padding) + ": " +
                                         sample.lines[0];
                expect_same(rasterise_lines(font.value(), sample.lines, geometry),
                            reference.render(sample.lines, em_px, padding), what);
            }
        }
    }
}

TEST(GlyphRaster, GeometryFollowsTheFontsMetrics) {
    const Font font = Font::open(testing::kDejaVuSans).value_or_throw();
    // 30 px per em: ascender 1901 / 2048 * 30 = 27.85 -> 28, line 2384 / 2048 * 30 = 34.92 -> 35.
    const LineGeometry g = line_geometry(font, 30.0, 3);
    EXPECT_EQ(g.ascent_px, 28);
    EXPECT_EQ(g.line_px, 35);
    EXPECT_EQ(g.padding_px, 3);
    EXPECT_DOUBLE_EQ(line_geometry(font, 30.004, 0).em_px, 30.0);  // 26.6: 1/64 pixel
    // A capital 'H' at 30 px per em covers 1493 / 2048 * 30 = 21.87 rows: 21 full rows and
    // partial coverage on the top one.
    const CoverageImage h = rasterise_lines(font, {"H"}, g);
    std::uint32_t first = h.height;
    std::uint32_t last = 0;
    double ink_rows = 0.0;
    for (std::uint32_t y = 0; y < h.height; ++y) {
        std::uint8_t most = 0;
        for (std::uint32_t x = 0; x < h.width; ++x) most = std::max(most, h.at(x, y));
        if (most > 0) {
            first = std::min(first, y);
            last = y;
            ink_rows += most / 255.0;
        }
    }
    EXPECT_EQ(last, 3u + 28u - 1u);  // the bottom row of ink sits on the baseline
    EXPECT_NEAR(ink_rows, 1493.0 / 2048.0 * 30.0, 0.1);
    EXPECT_EQ(first, 3u + 28u - 22u);
}

}  // namespace
}  // namespace monoplane::text
