#include "app/lab/frame_time_probe.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>
#include <utility>

#include "app/commands/study_renderers.h"
#include "app/commands/study_scenes.h"
#include "study/render_mode.h"

namespace monoplane::lab {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// What a frame holds the headset's loop for: with two frames in flight the loop records one frame
// while the GPU runs the other, so the longer of the two sets the pace. Without timestamps (a
// device that has none), the frame's wall time, waited for.
double frame_cost_ms(const profile::FrameStats& stats, double wall_ms) {
    const double ms = std::max(stats.gpu_frame_ms, stats.cpu_record_ms);
    return ms > 0.0 ? ms : wall_ms;
}

std::uint64_t fragments_of(const profile::FrameStats& stats) {
    std::uint64_t sum = 0;
    for (const profile::ViewStatistics& view : stats.views) sum += view.fragment_invocations;
    return sum;
}

// The eyes as the session's first frame of a trial sees them: the scene's seat with the head
// at rest, the profile's frusta, IPD and cant, the protocol's clip range.
modes::StereoViewInputs seated_views(const hmd::HmdProfile& hmd, const rig::Pose& seat,
                                     const study::Protocol& protocol) {
    modes::StereoViewInputs views;
    views.head = seat;
    views.ipd = hmd.ipd;
    views.left = hmd.left;
    views.right = hmd.right;
    views.cant = hmd::cant_radians(hmd);
    views.near = protocol.near;
    views.far = protocol.far;
    return views;
}

struct Condition {
    std::string scene;
    study::RenderMode mode{};
    bool warmed = false;
    std::vector<double> ms;  // measured frames
    std::uint64_t fragments = 0;
    std::string label(double m) const {
        std::ostringstream text;
        text << scene << " / " << study::render_mode_name(mode) << " at " << m << " m";
        return text.str();
    }
};

// One probe run: the renderers, the conditions and the schedule of their frames.
class Probe {
  public:
    Probe(const FrameTimeProbeRequest& request, const ProbeCallback& progress)
        : request_(request), progress_(progress), start_(Clock::now()) {
        nearest_ = *std::min_element(request.protocol.mono_planes.begin(),
                                     request.protocol.mono_planes.end());
        // The reference alternative (the protocol's first) of every scene first: it is usually
        // the dearer, and a tight budget may end the probe before the others.
        for (study::RenderMode mode : request.protocol.alternatives) {
            for (const std::string& scene : request.protocol.scenes) {
                const bool seen = std::any_of(
                    conditions_.begin(), conditions_.end(),
                    [&](const Condition& c) { return c.scene == scene && c.mode == mode; });
                if (seen) continue;
                Condition c;
                c.scene = scene;
                c.mode = mode;
                conditions_.push_back(std::move(c));
            }
        }
        planned_ = static_cast<int>(conditions_.size()) * (1 + request.frames_per_condition);
    }

    // false: cancelled.
    bool prepare(const vk_core::Context& ctx, vk::Extent2D eye) {
        if (!ask("preparing the scenes")) return false;
        app::ImportedStudyScenes imported =
            app::load_imported_scenes(request_.protocol.scene_files, request_.protocol.source)
                .value_or_throw();
        study::RenderSettings render = request_.protocol.render;
        render.detail = request_.preset.detail;
        renderers_.emplace(ctx, request_.protocol, eye, render, std::move(imported));
        frames_start_ = Clock::now();
        return true;
    }

    // Every condition's warm-up and first measured frame (the first condition's whatever the
    // budget), then the rest round by round while the budget lasts. false: cancelled.
    bool render_all() {
        for (std::size_t i = 0; i < conditions_.size(); ++i) {
            if (i > 0 && over_budget()) return true;
            if (!render(conditions_[i])) return false;
            if (!render(conditions_[i])) return false;
        }
        for (int round = 1; round < request_.frames_per_condition; ++round) {
            for (Condition& c : conditions_) {
                if (over_budget()) return true;
                if (!render(c)) return false;
            }
        }
        return true;
    }

    FrameTimeEstimate estimate(vk::Extent2D eye, const std::string& device) const;

  private:
    bool over_budget() const { return seconds_since(frames_start_) >= request_.budget_s; }

    bool ask(const std::string& condition) const {
        return !progress_ || progress_({done_, planned_, condition, seconds_since(start_)});
    }

    // The condition's next frame: its warm-up first. false: cancelled before it.
    bool render(Condition& c) {
        if (!ask(c.label(nearest_))) return false;
        modes::ModeRenderer& renderer = renderers_->renderer(c.scene, c.mode);
        modes::FrameInputs inputs;
        inputs.views = seated_views(request_.hmd, renderers_->seat(c.scene), request_.protocol);
        inputs.mono_plane = nearest_;
        inputs.nearest_auto_plane = nearest_;  // hybrid-auto: the trial's distance
        const Clock::time_point before = Clock::now();
        const profile::FrameStats stats = renderer.render_frame(inputs);
        const double wall_ms = 1000.0 * seconds_since(before);
        ++done_;
        if (!c.warmed) {
            c.warmed = true;
            return true;
        }
        if (c.ms.empty()) c.fragments = fragments_of(stats);
        c.ms.push_back(frame_cost_ms(stats, wall_ms));
        return true;
    }

    const FrameTimeProbeRequest& request_;
    const ProbeCallback& progress_;
    Clock::time_point start_;
    Clock::time_point frames_start_;  // the renderers ready: the budget counts from here
    double nearest_ = 0.0;
    std::vector<Condition> conditions_;
    int planned_ = 0;
    int done_ = 0;
    std::optional<app::StudyRenderers> renderers_;
};

FrameTimeEstimate Probe::estimate(vk::Extent2D eye, const std::string& device) const {
    FrameTimeEstimate e;
    e.eye_width = static_cast<int>(eye.width);
    e.eye_height = static_cast<int>(eye.height);
    e.device = device;
    e.complete = true;
    for (const Condition& c : conditions_) {
        ProbeCondition out;
        out.scene = c.scene;
        out.alternative = std::string(study::render_mode_name(c.mode));
        out.mono_plane = nearest_;
        out.frames = static_cast<int>(c.ms.size());
        out.fragments = c.fragments;
        if (!c.ms.empty()) out.frame_ms = median(c.ms);
        if (out.frames < request_.frames_per_condition) e.complete = false;
        if (out.frames > 0 && out.frame_ms > e.frame_ms) {
            e.frame_ms = out.frame_ms;
            e.slowest = c.label(nearest_);
        }
        e.conditions.push_back(std::move(out));
    }
    e.elapsed_s = seconds_since(start_);
    return e;
}

Result<void> check_request(const FrameTimeProbeRequest& request) {
    if (request.recommended_width <= 0 || request.recommended_height <= 0) {
        return Error{"the frame-time probe needs the headset's recommended eye size (got " +
                     std::to_string(request.recommended_width) + " x " +
                     std::to_string(request.recommended_height) + ")"};
    }
    if (request.frames_per_condition < 1) {
        return Error{"the frame-time probe needs at least one measured frame per condition"};
    }
    return Ok{};
}

}  // namespace

Result<FrameTimeEstimate> probe_frame_time(const vk_core::Context& ctx,
                                           const FrameTimeProbeRequest& request,
                                           const ProbeCallback& progress) {
    MONOPLANE_TRY(check_request(request));
    const EyeSize size = scaled_eye_size(request.recommended_width, request.recommended_height,
                                         request.preset.resolution_scale);
    const vk::Extent2D eye(static_cast<std::uint32_t>(size.width),
                           static_cast<std::uint32_t>(size.height));
    // The renderers throw what the session would report (UserError) and Vulkan's errors; both
    // become this probe's refusal, and the device is idle again before the renderers go.
    try {
        Probe probe(request, progress);
        const bool finished = probe.prepare(ctx, eye) && probe.render_all();
        ctx.device().waitIdle();
        if (!finished) return Error{"the frame-time probe was cancelled"};
        FrameTimeEstimate estimate = probe.estimate(eye, ctx.device_info().name);
        return estimate;
    } catch (const std::exception& e) {
        ctx.device().waitIdle();
        return Error{std::string("the frame-time probe failed: ") + e.what()};
    }
}

Result<FrameTimeEstimate> probe_frame_time(const vk_core::ContextOptions& options,
                                           const FrameTimeProbeRequest& request,
                                           const ProbeCallback& progress) {
    MONOPLANE_TRY(check_request(request));
    Result<std::unique_ptr<vk_core::Context>> ctx = vk_core::Context::create(options);
    MONOPLANE_TRY(ctx);
    Result<FrameTimeEstimate> estimate = probe_frame_time(**ctx, request, progress);
    const vk_core::ValidationMessages& messages = (*ctx)->validation_messages();
    if (estimate && messages.count() > 0) {
        std::string text = "the frame-time probe drew " + std::to_string(messages.count()) +
                           " validation message(s):";
        for (const std::string& m : messages.first_messages()) text += "\n  " + m;
        return Error{text};
    }
    return estimate;
}

}  // namespace monoplane::lab
