#include "app/commands/bench_accuracy.h"

#include <algorithm>
#include <cstdint>

#include "renderer/passes/shared/view_constants.h"
#include "renderer/quality/channel_difference.h"
#include "renderer/quality/drift.h"
#include "renderer/quality/ssim.h"

namespace monoplane::app::bench {

Reference read_reference(modes::ModeRenderer& stereo, const modes::FrameInputs& inputs) {
    Reference reference;
    stereo.set_read_back(true);
    stereo.render_frame(inputs);
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        reference.images[static_cast<int>(eye)] = stereo.eye_image(eye);
        reference.depth[static_cast<int>(eye)] = stereo.eye_linear_depth(eye);
    }
    stereo.set_read_back(false);
    return reference;
}

int max_channel_difference(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                           const Reference& reference) {
    renderer.set_read_back(true);
    renderer.render_frame(inputs);
    renderer.set_read_back(false);
    int largest = 0;
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        largest = std::max(largest, quality::max_channel_difference(
                                        quality::rgba_view(reference.images[static_cast<int>(eye)]),
                                        quality::rgba_view(renderer.eye_image(eye)))
                                        .value_or_throw());
    }
    return largest;
}

Accuracy measure_accuracy(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                          const Reference& reference, std::optional<double> beyond_m) {
    renderer.set_read_back(true);
    renderer.render_frame(inputs);
    renderer.set_read_back(false);
    Accuracy accuracy;
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        const int e = static_cast<int>(eye);
        const quality::ImageView a = quality::rgba_view(reference.images[e]);
        const quality::ImageView b = quality::rgba_view(renderer.eye_image(eye));
        accuracy.ssim += 0.5 * quality::ssim(a, b).value_or_throw().mean;
        accuracy.mean_abs_difference +=
            0.5 * quality::mean_channel_difference(a, b).value_or_throw();
        // Drift where stereo sees beyond the plane (where hybrid can differ at all).
        std::vector<std::uint8_t> beyond(reference.depth[e].size());
        for (std::size_t i = 0; i < beyond.size(); ++i) {
            beyond[i] = reference.depth[e][i] > beyond_m.value_or(inputs.mono_plane) ? 1 : 0;
        }
        const quality::DriftMeasurement drift =
            quality::measure_drift(a, b, beyond).value_or_throw();
        accuracy.drift_px = std::max(accuracy.drift_px, drift.p95_px);
        accuracy.drift_patches += drift.patches;
    }
    return accuracy;
}

double farthest_visible_depth(const Reference& reference) {
    double farthest = 0.0;
    for (const std::vector<float>& depth : reference.depth) {
        for (const float d : depth) {
            if (d < 0.5f * static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH)) {
                farthest = std::max(farthest, static_cast<double>(d));
            }
        }
    }
    return farthest;
}

}  // namespace monoplane::app::bench
