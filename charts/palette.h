// Series colours: the Okabe-Ito palette (Okabe & Ito 2008, "Color Universal Design"), eight
// colours that stay distinct under the common colour-vision deficiencies and in greyscale print
// better than rainbow palettes.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace monoplane::charts {

// Ordered by contrast on white: the first colours are those most charts use. Yellow comes late
// because it is faint as a thin line; black last, as it competes with the axes.
inline constexpr std::array<std::string_view, 8> kOkabeIto = {
    "#0072B2",  // blue
    "#E69F00",  // orange
    "#009E73",  // bluish green
    "#D55E00",  // vermillion
    "#CC79A7",  // reddish purple
    "#56B4E9",  // sky blue
    "#F0E442",  // yellow
    "#000000",  // black
};

// How the series with this index is drawn unless the caller chose a colour.
struct SeriesLook {
    std::string color;
    std::string dash;  // stroke-dasharray; empty: solid
};

// The palette repeats after eight series; the second round is dashed and the third dotted, so
// series 0 and 8 (e.g. the 1st and 9th of ten mono-plane distances) stay apart.
SeriesLook series_look(std::size_t index);

}  // namespace monoplane::charts
