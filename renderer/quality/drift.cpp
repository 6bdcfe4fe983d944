#include "renderer/quality/drift.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "renderer/quality/luma.h"

namespace monoplane::quality {
namespace {

// The first input problem, or an empty string.
std::string check_inputs(const ImageView& reference, const ImageView& test,
                         std::span<const std::uint8_t> mask, const DriftOptions& options) {
    if (!is_well_formed(reference) || !is_well_formed(test)) {
        return "drift needs non-empty 8-bit images with 1, 3 or 4 channels and width * height * "
               "channels bytes; got " +
               describe(reference) + " and " + describe(test);
    }
    if (reference.width != test.width || reference.height != test.height) {
        return "drift compares images of the same size; got " + size_text(reference) + " and " +
               size_text(test) + " (render both at the same resolution)";
    }
    const std::size_t pixels = std::size_t{reference.width} * reference.height;
    if (!mask.empty() && mask.size() != pixels) {
        return "drift mask has " + std::to_string(mask.size()) + " entries; the " +
               size_text(reference) + " images need " + std::to_string(pixels);
    }
    if (options.patch_radius < 1 || options.grid_step < 1 || options.search_radius < 0) {
        return "drift needs patch radius >= 1, grid step >= 1 and search radius >= 0; got " +
               std::to_string(options.patch_radius) + ", " + std::to_string(options.grid_step) +
               " and " + std::to_string(options.search_radius);
    }
    if (!std::isfinite(options.min_luma_stddev) || options.min_luma_stddev < 0.0) {
        return "drift needs a minimum luma standard deviation >= 0; got " +
               std::to_string(options.min_luma_stddev);
    }
    if (!(options.min_correlation >= -1.0 && options.min_correlation <= 1.0)) {
        return "drift needs a minimum correlation in [-1, 1]; got " +
               std::to_string(options.min_correlation);
    }
    return {};
}

// Luma variance below this counts as flat: rounding leaves deviations of about 1e-14 in a patch of
// one value, and their ZNCC would be noise in [-1, 1]. Far below one 8-bit step (variance 1/12
// for uniform quantisation noise), so no real texture is lost.
constexpr double kFlatVariance = 1e-9;

// A square patch's luma minus its mean, and the sum of the squared deviations. Both images' patches
// go through the same code, so the ZNCC of a pair does not depend on which image each came from.
struct ZeroMeanPatch {
    std::vector<double> deviations;
    double sum_squares = 0.0;
    bool flat = true;
};

class LumaImage {
  public:
    explicit LumaImage(const ImageView& image) : width_(image.width), values_(luma(image)) {}

    // The patch of the given radius centred on (cx, cy), which must lie inside the image.
    void read_patch(std::ptrdiff_t cx, std::ptrdiff_t cy, std::ptrdiff_t radius,
                    ZeroMeanPatch& patch) const {
        const std::size_t side = static_cast<std::size_t>(2 * radius + 1);
        patch.deviations.resize(side * side);
        double sum = 0.0;
        std::size_t i = 0;
        for (std::ptrdiff_t y = cy - radius; y <= cy + radius; ++y) {
            const double* row = &values_[static_cast<std::size_t>(y) * width_];
            for (std::ptrdiff_t x = cx - radius; x <= cx + radius; ++x, ++i) {
                patch.deviations[i] = row[x];
                sum += row[x];
            }
        }
        const double count = static_cast<double>(patch.deviations.size());
        const double mean = sum / count;
        double sum_squares = 0.0;
        for (double& value : patch.deviations) {
            value -= mean;
            sum_squares += value * value;
        }
        patch.sum_squares = sum_squares;
        patch.flat = sum_squares / count < kFlatVariance;
    }

  private:
    std::size_t width_;
    std::vector<double> values_;
};

// Zero-mean normalised cross-correlation in [-1, 1]; 0 when either patch is flat. Symmetric in
// its arguments bit for bit (products and the sum are taken in the same order either way).
double zncc(const ZeroMeanPatch& a, const ZeroMeanPatch& b) {
    if (a.flat || b.flat) return 0.0;
    double dot = 0.0;
    for (std::size_t i = 0; i < a.deviations.size(); ++i) dot += a.deviations[i] * b.deviations[i];
    return dot / std::sqrt(a.sum_squares * b.sum_squares);
}

// Offset of the vertex of the parabola through (-1, minus), (0, centre), (+1, plus), limited to
// half a pixel: the integer search already chose the nearest whole displacement, so a larger
// offset would only come from neighbours that disagree with it. 0 when the points do not form a
// peak (straight or curving upwards), since then there is no vertex to trust.
double parabola_peak_offset(double minus, double centre, double plus) {
    const double curvature = minus - 2.0 * centre + plus;
    if (!(curvature < 0.0)) return 0.0;
    return std::clamp((minus - plus) / (2.0 * curvature), -0.5, 0.5);
}

bool patch_in_mask(std::span<const std::uint8_t> mask, std::size_t width, std::ptrdiff_t cx,
                   std::ptrdiff_t cy, std::ptrdiff_t radius) {
    if (mask.empty()) return true;
    for (std::ptrdiff_t y = cy - radius; y <= cy + radius; ++y) {
        const std::uint8_t* row = &mask[static_cast<std::size_t>(y) * width];
        for (std::ptrdiff_t x = cx - radius; x <= cx + radius; ++x) {
            if (row[x] == 0) return false;
        }
    }
    return true;
}

struct Displacement {
    double dx = 0.0;
    double dy = 0.0;
};

// Linear interpolation between order statistics at rank q (n - 1), numpy's default.
double quantile(const std::vector<double>& sorted, double q) {
    const double rank = q * static_cast<double>(sorted.size() - 1);
    const std::size_t below = static_cast<std::size_t>(std::floor(rank));
    if (below + 1 >= sorted.size()) return sorted.back();
    const double fraction = rank - static_cast<double>(below);
    return sorted[below] + fraction * (sorted[below + 1] - sorted[below]);
}

DriftMeasurement summarise(const std::vector<Displacement>& displacements, std::size_t rejected) {
    DriftMeasurement result;
    result.rejected_patches = rejected;
    result.patches = displacements.size();
    if (displacements.empty()) return result;

    std::vector<double> magnitudes;
    magnitudes.reserve(displacements.size());
    double sum_dx = 0.0;
    double sum_dy = 0.0;
    for (const Displacement& d : displacements) {
        magnitudes.push_back(std::hypot(d.dx, d.dy));
        sum_dx += d.dx;
        sum_dy += d.dy;
    }
    std::sort(magnitudes.begin(), magnitudes.end());
    result.median_px = quantile(magnitudes, 0.5);
    result.p95_px = quantile(magnitudes, 0.95);
    result.max_px = magnitudes.back();
    result.mean_dx_px = sum_dx / static_cast<double>(displacements.size());
    result.mean_dy_px = sum_dy / static_cast<double>(displacements.size());
    return result;
}

}  // namespace

Result<DriftMeasurement> measure_drift(const ImageView& reference, const ImageView& test,
                                       std::span<const std::uint8_t> mask,
                                       const DriftOptions& options) {
    if (std::string problem = check_inputs(reference, test, mask, options); !problem.empty()) {
        return Error{std::move(problem)};
    }
    // Wide integers: the options are validated only for sign, and radius + search must not wrap.
    const std::ptrdiff_t width = reference.width;
    const std::ptrdiff_t height = reference.height;
    const std::ptrdiff_t radius = options.patch_radius;
    const std::ptrdiff_t search = options.search_radius;
    const std::ptrdiff_t step = options.grid_step;
    const std::ptrdiff_t margin = radius + search;
    // Checked before reading the images, so absurd radii never size a patch buffer.
    if (2 * margin + 1 > width || 2 * margin + 1 > height) return summarise({}, 0);

    const LumaImage reference_luma(reference);
    const LumaImage test_luma(test);
    const double min_variance =
        std::max(options.min_luma_stddev * options.min_luma_stddev, kFlatVariance);

    std::vector<Displacement> displacements;
    std::size_t rejected = 0;
    ZeroMeanPatch reference_patch;
    ZeroMeanPatch candidate;
    ZeroMeanPatch anchor;  // the best-matching test patch, for the backward correlations
    const auto patch_count = static_cast<double>((2 * radius + 1) * (2 * radius + 1));
    const std::ptrdiff_t side = 2 * search + 1;
    std::vector<double> forward(static_cast<std::size_t>(side * side));

    for (std::ptrdiff_t cy = margin; cy + margin < height; cy += step) {
        for (std::ptrdiff_t cx = margin; cx + margin < width; cx += step) {
            if (!patch_in_mask(mask, reference.width, cx, cy, radius)) continue;
            reference_luma.read_patch(cx, cy, radius, reference_patch);
            if (reference_patch.sum_squares / patch_count < min_variance) continue;

            // Forward ZNCC for every displacement in the window, kept for the refinement.
            std::ptrdiff_t best_dx = 0;
            std::ptrdiff_t best_dy = 0;
            double best = -2.0;
            for (std::ptrdiff_t dy = -search; dy <= search; ++dy) {
                for (std::ptrdiff_t dx = -search; dx <= search; ++dx) {
                    test_luma.read_patch(cx + dx, cy + dy, radius, candidate);
                    const double value = zncc(reference_patch, candidate);
                    forward[static_cast<std::size_t>((dy + search) * side + (dx + search))] = value;
                    const bool closer = dx * dx + dy * dy < best_dx * best_dx + best_dy * best_dy;
                    if (value > best || (value == best && closer)) {
                        best = value;
                        best_dx = dx;
                        best_dy = dy;
                    }
                }
            }
            if (best < options.min_correlation) {
                ++rejected;
                continue;
            }

            const auto forward_at = [&](std::ptrdiff_t dx, std::ptrdiff_t dy) {
                return forward[static_cast<std::size_t>((dy + search) * side + (dx + search))];
            };
            // Backward: the best test patch against the reference patch moved the opposite way.
            test_luma.read_patch(cx + best_dx, cy + best_dy, radius, anchor);
            const auto symmetric_at = [&](std::ptrdiff_t ex, std::ptrdiff_t ey) {
                reference_luma.read_patch(cx - ex, cy - ey, radius, candidate);
                return 0.5 * (forward_at(best_dx + ex, best_dy + ey) + zncc(anchor, candidate));
            };
            Displacement d{static_cast<double>(best_dx), static_cast<double>(best_dy)};
            if (best_dx > -search && best_dx < search) {
                d.dx += parabola_peak_offset(symmetric_at(-1, 0), best, symmetric_at(1, 0));
            }
            if (best_dy > -search && best_dy < search) {
                d.dy += parabola_peak_offset(symmetric_at(0, -1), best, symmetric_at(0, 1));
            }
            displacements.push_back(d);
        }
    }
    return summarise(displacements, rejected);
}

}  // namespace monoplane::quality
