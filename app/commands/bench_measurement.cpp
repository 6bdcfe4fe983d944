#include "app/commands/bench_measurement.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "app/commands/frame_summary.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/profile/driver_compiles.h"
#include "renderer/vk/memory.h"
#include "rig/pose_path.h"

namespace monoplane::app::bench {
namespace {

// The pixels a view's passes cover: an eye's image (its composite and transparency too), both
// eyes' for the single-pass "eyes", C's viewport (eq. 8) for "mono"; 0 for a view it does not
// know.
std::uint64_t view_pixels(const modes::ModeRenderer& renderer, const std::string& view) {
    const vk::Extent2D eye = renderer.eye_extent();
    const std::uint64_t eye_pixels = std::uint64_t{eye.width} * eye.height;
    const auto pass = plan::statistics_scope_pass(view);
    if (!pass) return 0;
    switch (pass->second) {
        case plan::ViewId::kLeft:
        case plan::ViewId::kRight:
            return eye_pixels;  // an eye's forward, composite or transparency pass
        case plan::ViewId::kEyes:
            return 2 * eye_pixels;
        case plan::ViewId::kMono:
            if (!renderer.last_rig()) return 0;
            return static_cast<std::uint64_t>(renderer.last_rig()->mono.viewport_width) *
                   static_cast<std::uint64_t>(renderer.last_rig()->mono.viewport_height);
        case plan::ViewId::kNone:
            break;
    }
    return 0;
}

// The turning-head configuration (--turning-frames): after a run's measured frames, the same
// renderer alternates the run's still pose with poses along the "turn" path (yaw back and forth
// at 30 degrees a second, 90 frames a second: every turning pose is new). A turning frame's GPU
// time over the still frame beside it, median over the pairs; the driver's compiles over those
// frames where they can be counted, and their share of the wall time. A driver that keys shader
// variants on view-dependent values compiles on every turning frame and the ratio shows it.
void measure_turning(modes::ModeRenderer& renderer, const modes::FrameInputs& still, int pairs,
                     BenchRun& run) {
    const rig::PosePath turn = *rig::builtin_pose_path("turn");
    constexpr double kFrameRateHz = 90.0;
    std::vector<profile::FrameStats> frames;
    const auto wall_start = std::chrono::steady_clock::now();
    const profile::DriverCompiles before = profile::driver_compiles();
    for (int i = 0; i < 2 * pairs; ++i) {
        modes::FrameInputs inputs = still;
        if (i % 2 == 1) {
            inputs.views.head = rig::pose_along(turn, still.views.head, (i / 2 + 1) / kFrameRateHz);
        }
        renderer.submit_frame(inputs);
        for (profile::FrameStats& s : renderer.take_completed()) frames.push_back(std::move(s));
    }
    for (profile::FrameStats& s : renderer.finish_frames()) frames.push_back(std::move(s));
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    const profile::DriverCompiles during =
        profile::compiles_between(before, profile::driver_compiles());
    std::vector<double> ratios;
    for (std::size_t i = 1; i < frames.size(); i += 2) {
        if (frames[i - 1].gpu_frame_ms > 0.0) {
            ratios.push_back(frames[i].gpu_frame_ms / frames[i - 1].gpu_frame_ms);
        }
    }
    run.turning_frames = pairs;
    if (!ratios.empty()) run.turning_time_ratio = percentile(ratios, 0.5);
    if (during.measurable) {
        run.turning_driver_compiles = during.modules;
        run.turning_compile_share = wall_s > 0.0 ? during.seconds / wall_s : 0.0;
    }
}

// The measured frames' times and counts, summed and per view, into the run.
void add_frame_summary(const modes::ModeRenderer& renderer, const FrameSummary& summary,
                       BenchRun& run) {
    run.frames = summary.frames;
    run.frame_ms_median = summary.frame_ms_median;
    run.frame_ms_p90 = summary.frame_ms_p90;
    run.cpu_ms_median = summary.cpu_ms_median;
    run.frame_ms_p10 = summary.frame_ms_p10;
    run.pass_ms_median = summary.pass_ms_median;
    run.pass_ms_p10 = summary.pass_ms_p10;
    run.pass_ms_p90 = summary.pass_ms_p90;
    for (const profile::ViewStatistics& v : summary.views) {
        run.fragments += v.fragment_invocations;
        run.view_fragments[v.view] = v.fragment_invocations;
        if (const std::uint64_t pixels = view_pixels(renderer, v.view); pixels > 0) {
            run.view_fragments_per_pixel[v.view] =
                static_cast<double>(v.fragment_invocations) / static_cast<double>(pixels);
        }
        // A composite is not scene work (transparency is).
        const auto pass = plan::statistics_scope_pass(v.view);
        if (pass && pass->first == plan::PassKind::kComposite) continue;
        run.primitives += v.clipping_invocations;
        run.vertex_invocations += v.vertex_invocations;
        run.geometry_invocations += v.geometry_invocations;
        run.view_primitives[v.view] = v.clipping_invocations;
        run.view_draws[v.view] = v.draws;
    }
}

}  // namespace

BenchRun measure(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                 const BenchOptions& o, modes::ModeRenderer* reference,
                 const modes::FrameInputs* reference_inputs) {
    renderer.set_read_back(false);
    if (reference) reference->set_read_back(false);
    // Frames in flight: nothing waits for the GPU until the end; each renderer's statistics
    // arrive in submission order, so frame i of one pairs with frame i of the other.
    std::vector<profile::FrameStats> measured;
    std::vector<profile::FrameStats> paired;
    const auto take = [](modes::ModeRenderer& r, std::vector<profile::FrameStats>& into,
                         bool finish) {
        for (profile::FrameStats& stats : finish ? r.finish_frames() : r.take_completed()) {
            into.push_back(std::move(stats));
        }
    };
    for (int i = 0; i < o.warmup + o.frames; ++i) {
        if (reference && i % 2 == 0) reference->submit_frame(*reference_inputs);
        renderer.submit_frame(inputs);
        if (reference && i % 2 == 1) reference->submit_frame(*reference_inputs);
        take(renderer, measured, false);
        if (reference) take(*reference, paired, false);
    }
    take(renderer, measured, true);
    if (reference) take(*reference, paired, true);
    std::vector<profile::FrameStats> frames;
    std::vector<double> ratios;
    std::vector<double> reference_ms;
    std::vector<double> frame_mono_planes;
    for (std::size_t i = static_cast<std::size_t>(o.warmup); i < measured.size(); ++i) {
        if (reference && i < paired.size() && paired[i].gpu_frame_ms > 0.0) {
            ratios.push_back(measured[i].gpu_frame_ms / paired[i].gpu_frame_ms);
            reference_ms.push_back(paired[i].gpu_frame_ms);
        }
        if (measured[i].mono_plane) frame_mono_planes.push_back(*measured[i].mono_plane);
        frames.push_back(std::move(measured[i]));
    }
    BenchRun run;
    add_frame_summary(renderer, summarize(frames), run);
    if (!ratios.empty()) {
        run.time_ratio = percentile(ratios, 0.5);
        run.time_ratio_p25 = percentile(ratios, 0.25);
        run.time_ratio_p75 = percentile(ratios, 0.75);
        run.stereo_frame_ms_median = percentile(reference_ms, 0.5);
    }
    run.plan = renderer.last_plan();
    run.device_memory =
        DeviceMemoryFigures::from_bytes(vk_core::live_device_bytes(vk_core::MemoryKind::kImage),
                                        vk_core::live_device_bytes(vk_core::MemoryKind::kBuffer));
    run.frame_mono_planes = std::move(frame_mono_planes);
    if (o.turning_frames > 0) measure_turning(renderer, inputs, o.turning_frames, run);
    return run;
}

}  // namespace monoplane::app::bench
