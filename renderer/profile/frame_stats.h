// What one frame cost: GPU time per pass and pipeline statistics per view. Plain data, so the
// app can print it as JSON and the benchmark can aggregate it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/plan/frame_plan.h"

namespace monoplane::profile {

struct PassTime {
    std::string name;  // e.g. "shadow", "left.forward", "left.tonemap"
    double gpu_ms = 0.0;
    // The planned pass it timed: what code compares (the name is for people and JSON).
    plan::PassKind kind = plan::PassKind::kCulling;
    plan::ViewId view = plan::ViewId::kNone;
};

// Counters of VK_QUERY_TYPE_PIPELINE_STATISTICS for all draws of one view.
struct ViewStatistics {
    std::string view;  // "left", "right", "mono", "eyes" (single pass), "left.composite", ...
    // The planned pass whose draws it counts (a view's forward pass, an eye's composite or
    // transparency): what code compares.
    plan::PassKind pass_kind = plan::PassKind::kForward;
    plan::ViewId pass_view = plan::ViewId::kNone;
    std::uint64_t input_primitives = 0;      // input assembly primitives
    std::uint64_t clipping_invocations = 0;  // primitives entering clipping
    std::uint64_t clipping_primitives = 0;   // primitives leaving clipping
    std::uint64_t vertex_invocations = 0;
    // Geometry shader (single-pass stereo by duplication): invocations (one per input triangle)
    // and primitives emitted; 0 without a geometry shader or where the device has none.
    std::uint64_t geometry_invocations = 0;
    std::uint64_t geometry_primitives = 0;
    std::uint64_t fragment_invocations = 0;
    // Chunks drawn (the GPU culling's indirect draw count); C: after occlusion culling, and
    // before it in draws_before_occlusion_culling. 0 for views that draw no chunks.
    std::uint32_t draws = 0;
    std::uint32_t draws_before_occlusion_culling = 0;
};

struct FrameStats {
    std::vector<PassTime> passes;
    std::vector<ViewStatistics> views;
    double gpu_frame_ms = 0.0;   // first pass start to last pass end
    double cpu_record_ms = 0.0;  // command recording and culling on the CPU
    // Hybrid modes: the frame's mono plane (the far plane: drawn as stereo), and with
    // `--mono-plane auto` why the chooser put it there (renderer/plan/mono_plane_chooser.h).
    std::optional<double> mono_plane;
    std::string mono_plane_reason;
};

}  // namespace monoplane::profile
