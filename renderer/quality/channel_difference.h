// The largest difference between two images: what "draws the same image" means for render modes
// that should be exact (single-pass stereo against two passes: 0 or 1 level of rounding).
#pragma once

#include "common/result.h"
#include "renderer/quality/image_view.h"

namespace monoplane::quality {

// The largest absolute difference of any channel (alpha included) of any pixel, in 8-bit
// levels. Fails for malformed images or images of different size or channel count.
Result<int> max_channel_difference(const ImageView& a, const ImageView& b);

// The mean absolute difference of the colour channels (alpha left out) over every pixel, in
// 8-bit levels: how far an approximation (a level of detail) moves the image on average. Fails
// as max_channel_difference does.
Result<double> mean_channel_difference(const ImageView& a, const ImageView& b);

}  // namespace monoplane::quality
