#include "renderer/quality/channel_difference.h"

#include <algorithm>
#include <cstdlib>

namespace monoplane::quality {

Result<int> max_channel_difference(const ImageView& a, const ImageView& b) {
    if (!is_well_formed(a) || !is_well_formed(b)) {
        return Error{"max_channel_difference: malformed image (" + describe(a) + ", " +
                     describe(b) + ")"};
    }
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        return Error{"max_channel_difference: the images differ in size (" + describe(a) +
                     " against " + describe(b) + ")"};
    }
    int largest = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        largest = std::max(largest, std::abs(int{a.pixels[i]} - int{b.pixels[i]}));
    }
    return largest;
}

}  // namespace monoplane::quality
