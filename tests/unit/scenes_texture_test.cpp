// Texture preparation for the renderer (scenes/texture_resample.h, texture_mips.h,
// texture_arrays.h). Expected values come from the sRGB transfer function written out here and
// from the filters' definitions worked by hand, not from the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "scenes/texture_arrays.h"
#include "scenes/texture_mips.h"
#include "scenes/texture_resample.h"

namespace monoplane::scenes {
namespace {

double decode(int encoded) {
    const double c = encoded / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
int encode(double linear) {
    const double c =
        linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    return static_cast<int>(std::lround(c * 255.0));
}

// A grey texture: one encoded value per texel, alpha 255.
SceneTexture grey(std::uint32_t width, std::uint32_t height, const std::vector<int>& values,
                  TextureWrap wrap = TextureWrap::Repeat) {
    SceneTexture texture;
    texture.width = width;
    texture.height = height;
    texture.wrap_u = texture.wrap_v = wrap;
    for (const int v : values) {
        const auto b = static_cast<std::uint8_t>(v);
        texture.rgba8_srgb.insert(texture.rgba8_srgb.end(), {b, b, b, 255});
    }
    return texture;
}

TEST(TextureMips, LevelCountsFollowVulkansFullChain) {
    EXPECT_EQ(mip_level_count(1, 1), 1u);
    EXPECT_EQ(mip_level_count(2, 1), 2u);
    EXPECT_EQ(mip_level_count(256, 256), 9u);
    EXPECT_EQ(mip_level_count(300, 200), 9u);  // floor(log2(300)) + 1
    EXPECT_EQ(mip_level_count(1, 1024), 11u);
}

TEST(TextureMips, LevelsAverageInLinearLightNotInEncodedValues) {
    // Top half white, bottom half black: the 1 x 1 level is linear 0.5, which sRGB encodes as
    // 188; averaging the encoded bytes would give 128.
    const SceneTexture texture =
        grey(4, 4, {255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0, 0, 0, 0, 0});
    const std::vector<MipLevel> chain = make_mip_chain(texture);
    ASSERT_EQ(chain.size(), 3u);
    EXPECT_EQ(chain[1].width, 2u);
    EXPECT_EQ(chain[1].height, 2u);
    EXPECT_EQ(chain[1].rgba8_srgb[0], 255);    // top row stays white
    EXPECT_EQ(chain[1].rgba8_srgb[2 * 4], 0);  // bottom row stays black
    ASSERT_EQ(chain[2].rgba8_srgb.size(), 4u);
    EXPECT_EQ(encode(0.5), 188);
    EXPECT_EQ(chain[2].rgba8_srgb[0], 188);
    EXPECT_EQ(chain[2].rgba8_srgb[3], 255);  // alpha averaged as it is
}

TEST(TextureMips, AnOddSideLosesNoTexel) {
    // 3 x 1 to 1 x 1: each texel weighs a third (a 2 x 2 footprint would drop the last one).
    const std::vector<MipLevel> chain = make_mip_chain(grey(3, 1, {255, 0, 0}));
    ASSERT_EQ(chain.size(), 2u);
    EXPECT_EQ(chain[1].rgba8_srgb[0], encode(1.0 / 3.0));
    // 5 x 1 to 2 x 1: footprints [0, 2.5) and [2.5, 5).
    const std::vector<MipLevel> five = make_mip_chain(grey(5, 1, {255, 255, 255, 0, 0}));
    EXPECT_EQ(five[1].rgba8_srgb[0], 255);
    EXPECT_EQ(five[1].rgba8_srgb[4], encode(0.5 / 2.5));
}

TEST(TextureResample, GrowingInterpolatesAcrossTheEdgeAsTheWrapModeSays) {
    // 2 x 1 (A = white, B = black) to 4 x 1: new centres at source coordinates -0.25, 0.25,
    // 0.75, 1.25; the first takes a quarter of its left neighbour, which repeat finds at B.
    const double a = decode(255), b = decode(0);
    for (const TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge}) {
        const LinearImage grown =
            resample(decode_srgb(grey(2, 1, {255, 0}, wrap)), 4, 1, wrap, wrap);
        ASSERT_EQ(grown.rgba.size(), 16u);
        const double left_neighbour = wrap == TextureWrap::Repeat ? b : a;
        EXPECT_NEAR(grown.rgba[0], 0.75 * a + 0.25 * left_neighbour, 1e-6);
        EXPECT_NEAR(grown.rgba[4], 0.75 * a + 0.25 * b, 1e-6);
        EXPECT_NEAR(grown.rgba[8], 0.25 * a + 0.75 * b, 1e-6);
    }
}

TEST(TextureResample, ShrinkingKeepsTheMean) {
    std::vector<int> values;
    double mean = 0.0;
    for (int i = 0; i < 7 * 5; ++i) {
        values.push_back((i * 37) % 256);
        mean += decode(values.back());
    }
    mean /= 35.0;
    const LinearImage small =
        resample(decode_srgb(grey(7, 5, values)), 3, 2, TextureWrap::Repeat, TextureWrap::Repeat);
    double small_mean = 0.0;
    for (std::size_t i = 0; i < small.rgba.size(); i += 4) small_mean += small.rgba[i];
    EXPECT_NEAR(small_mean / 6.0, mean, 1e-5);
}

TEST(TextureArrays, EachTextureGoesToTheSmallestArrayItFits) {
    EXPECT_EQ(texture_array_for(1, 1), 0u);
    EXPECT_EQ(texture_array_for(128, 128), 0u);
    EXPECT_EQ(texture_array_for(129, 1), 1u);
    EXPECT_EQ(texture_array_for(600, 1024), 3u);
    EXPECT_EQ(texture_array_for(8192, 100), 6u);
    EXPECT_EQ(texture_array_for(10000, 10), 6u);  // the largest array, scaled down
    EXPECT_EQ(TextureArrayLayout::side(6), kMaxTextureArraySide);

    const std::vector<SceneTexture> textures = {
        grey(1, 1, {0}), grey(200, 1, std::vector<int>(200)), grey(2, 2, {0, 0, 0, 0})};
    const TextureArrayLayout layout = layout_texture_arrays(textures);
    ASSERT_EQ(layout.slots.size(), 3u);
    EXPECT_EQ(layout.slots[0].array, 0u);
    EXPECT_EQ(layout.slots[0].layer, 0u);
    EXPECT_EQ(layout.slots[1].array, 1u);
    EXPECT_EQ(layout.slots[1].layer, 0u);
    EXPECT_EQ(layout.slots[2].array, 0u);
    EXPECT_EQ(layout.slots[2].layer, 1u);
    EXPECT_EQ(layout.layers[0], 2u);
    EXPECT_EQ(layout.layers[1], 1u);
    EXPECT_EQ(layout.layers[2], 0u);
}

TEST(TextureArrays, ALayerIsTheTextureScaledToTheArraysSide) {
    // A 2 x 2 checker of white and black scaled to 4 x 4 with repeat: every texel is the
    // repeat-wrapped bilinear mix, a quarter-weighted blend of the neighbours; the mean is kept.
    const SceneTexture layer = texture_as_layer(grey(2, 2, {255, 0, 0, 255}), 4);
    ASSERT_EQ(layer.width, 4u);
    ASSERT_EQ(layer.height, 4u);
    ASSERT_EQ(layer.rgba8_srgb.size(), 64u);
    // Texel (0, 0): source coordinates (-0.25, -0.25): weights 9/16 on (0,0) white, 3/16 on the
    // wrapped (1,0) and (0,1) black, 1/16 on the wrapped (1,1) white.
    EXPECT_EQ(layer.rgba8_srgb[0], encode(10.0 / 16.0));
    // Texel (1, 0): source (0.25, -0.25): (3/4)(3/4) on white (0,0) + (1/4)(1/4) on the wrapped
    // white (1,1) = 10/16 once more.
    EXPECT_EQ(layer.rgba8_srgb[4], encode(10.0 / 16.0));
    // Texel (2, 0): source (0.75, -0.25): mostly (1, 0), black: 6/16 white.
    EXPECT_EQ(layer.rgba8_srgb[8], encode(6.0 / 16.0));
    const SceneTexture same = texture_as_layer(grey(4, 4, std::vector<int>(16, 77)), 4);
    EXPECT_EQ(same.rgba8_srgb[0], 77);
}

}  // namespace
}  // namespace monoplane::scenes
