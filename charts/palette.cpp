#include "charts/palette.h"

namespace monoplane::charts {

SeriesLook series_look(std::size_t index) {
    static constexpr std::array<std::string_view, 3> kDashes = {"", "7 4", "2 3"};
    const std::size_t round = (index / kOkabeIto.size()) % kDashes.size();
    return {std::string(kOkabeIto[index % kOkabeIto.size()]), std::string(kDashes[round])};
}

}  // namespace monoplane::charts
