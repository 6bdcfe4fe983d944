// quality::max_channel_difference on hand-made images whose largest difference is known.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "renderer/quality/channel_difference.h"

namespace monoplane::quality {
namespace {

ImageView view_of(const std::vector<std::uint8_t>& pixels, std::uint32_t width,
                  std::uint32_t height, std::uint32_t channels = 4) {
    return ImageView{width, height, channels, pixels};
}

TEST(ChannelDifference, IdenticalImagesDifferByZero) {
    const std::vector<std::uint8_t> a = {10, 20, 30, 255, 0, 0, 0, 255};
    EXPECT_EQ(max_channel_difference(view_of(a, 2, 1), view_of(a, 2, 1)).value_or_throw(), 0);
}

TEST(ChannelDifference, TheLargestOfAnyChannelInEitherDirection) {
    const std::vector<std::uint8_t> a = {10, 20, 30, 255, 200, 0, 0, 255};
    const std::vector<std::uint8_t> b = {11, 20, 30, 255, 147, 3, 0, 255};  // 1, 53 down, 3 up
    EXPECT_EQ(max_channel_difference(view_of(a, 2, 1), view_of(b, 2, 1)).value_or_throw(), 53);
    EXPECT_EQ(max_channel_difference(view_of(b, 2, 1), view_of(a, 2, 1)).value_or_throw(), 53);
    const std::vector<std::uint8_t> black = {0, 0, 0, 0};
    const std::vector<std::uint8_t> white = {255, 255, 255, 255};
    EXPECT_EQ(max_channel_difference(view_of(black, 1, 1), view_of(white, 1, 1)).value_or_throw(),
              255);
}

TEST(ChannelDifference, RefusesImagesOfDifferentShape) {
    const std::vector<std::uint8_t> two = {0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_FALSE(max_channel_difference(view_of(two, 2, 1), view_of(two, 1, 2)).ok());
    const std::vector<std::uint8_t> short_buffer = {0, 0, 0};
    EXPECT_FALSE(max_channel_difference(view_of(two, 2, 1), view_of(short_buffer, 2, 1)).ok());
}

// Colour channels only: alpha differs by 255 here and must not count. (1 + 53 + 3 + 0 + 0 + 0)
// over six colour channels.
TEST(ChannelDifference, TheMeanOverTheColourChannels) {
    const std::vector<std::uint8_t> a = {10, 20, 30, 255, 200, 0, 0, 255};
    const std::vector<std::uint8_t> b = {11, 20, 30, 0, 147, 3, 0, 0};
    EXPECT_DOUBLE_EQ(mean_channel_difference(view_of(a, 2, 1), view_of(b, 2, 1)).value_or_throw(),
                     57.0 / 6.0);
    EXPECT_FALSE(mean_channel_difference(view_of(a, 2, 1), view_of(a, 1, 2)).ok());
}

}  // namespace
}  // namespace monoplane::quality
