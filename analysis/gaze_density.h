// A smoothed 2D histogram of where gaze samples landed in the seat's left-eye image
// (gaze_projection.h): the report's gaze density per scene. Bins are equal fractions of the
// image; the histogram is blurred with a Gaussian so that a few hundred samples give a readable
// map rather than scattered single bins.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/gaze_projection.h"

namespace monoplane::analysis {

struct DensityGrid {
    int columns = 64;  // across the image
    int rows = 72;     // down the image (the Vive's eye image is a little taller than wide)
    double blur_sigma_bins = 1.5;  // the Gaussian's standard deviation, in bins
};

struct GazeDensity {
    std::string scene;
    int columns = 0;
    int rows = 0;
    // Row-major from the top-left bin: the share of the samples inside the view that fell in
    // each bin, blurred (sums to 1 before the blur; the blur loses what spreads past the edges).
    std::vector<double> share;
    int samples = 0;  // the scene's samples
    int inside = 0;   // of them, landing inside the left eye's image
    double at(int column, int row) const {
        return share[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                     static_cast<std::size_t>(column)];
    }
    double peak() const;
    // The bin of the peak (the first in row-major order among equals): {column, row}.
    std::pair<int, int> peak_bin() const;
};

// The bin of an image point: column floor(u * columns), row floor(v * rows).
int density_column(const EyeImagePoint& p, const DensityGrid& grid);
int density_row(const EyeImagePoint& p, const DensityGrid& grid);

// The density of `scene`'s samples among `samples`. With no sample inside, every share is 0.
GazeDensity gaze_density(const std::vector<GazeSampleRow>& samples, const std::string& scene,
                         const SeatEye& eye, const DensityGrid& grid = {});

}  // namespace monoplane::analysis
