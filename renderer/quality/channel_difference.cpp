#include "renderer/quality/channel_difference.h"

#include <algorithm>
#include <cstdlib>

namespace monoplane::quality {

namespace {

Result<void> check_comparable(const char* metric, const ImageView& a, const ImageView& b) {
    if (!is_well_formed(a) || !is_well_formed(b)) {
        return Error{std::string(metric) + ": malformed image (" + describe(a) + ", " +
                     describe(b) + ")"};
    }
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        return Error{std::string(metric) + ": the images differ in size (" + describe(a) +
                     " against " + describe(b) + ")"};
    }
    return Ok{};
}

}  // namespace

Result<int> max_channel_difference(const ImageView& a, const ImageView& b) {
    MONOPLANE_TRY(check_comparable("max_channel_difference", a, b));
    int largest = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        largest = std::max(largest, std::abs(int{a.pixels[i]} - int{b.pixels[i]}));
    }
    return largest;
}

}  // namespace monoplane::quality

namespace monoplane::quality {

Result<double> mean_channel_difference(const ImageView& a, const ImageView& b) {
    MONOPLANE_TRY(check_comparable("mean_channel_difference", a, b));
    const std::uint32_t colour = a.channels == 4 ? 3 : a.channels;
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % a.channels >= colour) continue;
        sum += std::abs(int{a.pixels[i]} - int{b.pixels[i]});
        ++count;
    }
    return sum / static_cast<double>(count);
}

}  // namespace monoplane::quality
