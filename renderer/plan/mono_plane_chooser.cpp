#include "renderer/plan/mono_plane_chooser.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace monoplane::plan {
namespace {

// Exponential averaging of the frames' costs: about the last ten frames count.
constexpr double kAveraging = 0.1;
// From stereo, hybrid is tried again when this share of the image lies beyond the floor.
constexpr double kReprobeShare = 0.25;

bool same_eyes(const rig::RigInputs& a, const rig::RigInputs& b) {
    auto same = [](const rig::Tangents& x, const rig::Tangents& y) {
        return x.left == y.left && x.right == y.right && x.down == y.down && x.up == y.up;
    };
    return same(a.eyes[0], b.eyes[0]) && same(a.eyes[1], b.eyes[1]) && a.ipd == b.ipd &&
           a.near == b.near && a.far == b.far && a.cant == b.cant && a.eye_width == b.eye_width &&
           a.eye_height == b.eye_height;
}

void average_into(std::optional<double>& average, double value) {
    average = average ? (1.0 - kAveraging) * *average + kAveraging * value : value;
}

}  // namespace

MonoPlaneChooser::MonoPlaneChooser(AutoMonoPlaneParams params) : params_(std::move(params)) {}

Result<double> MonoPlaneChooser::error_at(const rig::RigInputs& eyes, double m,
                                          double depth) const {
    if (m >= eyes.far) return 0.0;
    rig::RigInputs at = eyes;
    at.mono_plane = m;
    at.nearest_mono_plane = 0.0;
    Result<rig::Rig> rig = rig::build_rig(at);
    if (!rig) return rig.error();
    return rig::measured(rig::angular_error_at_depth(*rig, depth), params_.measure);
}

Result<double> MonoPlaneChooser::budget_floor(const rig::RigInputs& eyes, double content_depth) {
    // The content's depth changes a little every frame; a floor for a depth within 0.5 % (at the
    // same eyes) differs by far less than the hysteresis, and the search costs a few dozen rigs.
    const bool cached =
        floor_eyes_ && same_eyes(*floor_eyes_, eyes) &&
        (std::isinf(content_depth) ? std::isinf(floor_depth_)
                                   : std::abs(content_depth / floor_depth_ - 1.0) < 0.005 &&
                                         content_depth <= floor_depth_);
    if (cached) return floor_;
    // Computed for a little more depth than asked, so that the cached floor holds while the
    // content's depth stays within that margin.
    const double depth = std::isinf(content_depth) ? content_depth : content_depth * 1.005;
    Result<rig::BudgetChoice> choice =
        rig::nearest_mono_plane_within(eyes, params_.error_budget_arcmin, params_.measure, depth);
    if (!choice) return choice.error();
    floor_eyes_ = eyes;
    floor_depth_ = depth;
    floor_ = choice->mono_plane;
    return floor_;
}

double MonoPlaneChooser::gap_beyond(double floor) const {
    if (!histogram_ || histogram_->geometry_pixels() == 0) return floor;
    const DepthHistogram& h = *histogram_;
    const double threshold = params_.gap_share * static_cast<double>(h.geometry_pixels());
    auto smoothed = [&](int b) {
        auto at = [&](int i) {
            return static_cast<double>(
                h.counts[static_cast<std::size_t>(std::clamp(i, 0, DepthHistogram::kBins - 1))]);
        };
        return 0.25 * at(b - 1) + 0.5 * at(b) + 0.25 * at(b + 1);
    };
    const int first = h.bin_of(floor);
    if (smoothed(first) <= threshold) return floor;  // nothing to cut at the floor already
    const int last = h.bin_of(floor * std::pow(2.0, params_.gap_octaves));
    for (int b = first + 1; b <= last; ++b) {
        if (smoothed(b) > threshold) continue;
        int end = b;
        while (end + 1 < DepthHistogram::kBins && smoothed(end + 1) <= threshold) ++end;
        // A run reaching past the last content is no gap: nothing lies beyond it to save.
        if (end + 1 >= DepthHistogram::kBins || h.bin_low(end + 1) > h.farthest) return floor;
        return std::max(floor, std::sqrt(h.bin_low(b) * h.bin_high(end)));
    }
    return floor;
}

Result<double> MonoPlaneChooser::step_towards(const rig::RigInputs& eyes, double target,
                                              double depth) const {
    const double from = *current_;
    if (from == target) return target;
    Result<double> from_error = error_at(eyes, from, depth);
    if (!from_error) return from_error.error();
    Result<double> target_error = error_at(eyes, target, depth);
    if (!target_error) return target_error.error();
    if (std::abs(*target_error - *from_error) <= params_.max_step_arcmin) return target;
    // The m between them whose error differs from the current one by one step: the error falls
    // as m grows, so bisect on log m.
    const double wanted = *target_error < *from_error ? *from_error - params_.max_step_arcmin
                                                      : *from_error + params_.max_step_arcmin;
    const double far_edge = eyes.far * (1.0 - 1e-9);
    double lo = std::min(std::min(from, target), far_edge);
    double hi = std::min(std::max(from, target), far_edge);
    for (int i = 0; i < 60 && hi / lo > 1.0 + 1e-9; ++i) {
        const double mid = std::sqrt(lo * hi);
        Result<double> error = error_at(eyes, mid, depth);
        if (!error) return error.error();
        (*error > wanted ? lo : hi) = mid;
    }
    // Round towards the current m: never more than one step.
    return target > from ? lo : hi;
}

std::optional<std::string> MonoPlaneChooser::stereo_reason(double far, double floor) {
    if (!params_.stereo_when_slower) return std::nullopt;
    const bool in_stereo = current_ && *current_ >= far;
    if (in_stereo && stereo_frames_ >= params_.reprobe_frames) {
        const bool budget_missed = params_.time_budget_ms && stereo_estimate_ms_ &&
                                   *stereo_estimate_ms_ > *params_.time_budget_ms;
        const bool much_beyond = histogram_ && histogram_->share_beyond(floor) >= kReprobeShare;
        if (budget_missed || (!params_.time_budget_ms && much_beyond)) {
            // Hybrid again: its own frames will tell whether it pays now.
            mono_forward_ms_.reset();
            hybrid_only_ms_.reset();
            stereo_frames_ = 0;
            return std::nullopt;
        }
        stereo_frames_ = 0;  // look again after another period
    }
    if (params_.time_budget_ms && stereo_estimate_ms_ &&
        *stereo_estimate_ms_ <= *params_.time_budget_ms) {
        return "stereo: the estimated stereo frame fits the time budget";
    }
    if (mono_forward_ms_ && hybrid_only_ms_ && *hybrid_only_ms_ >= *mono_forward_ms_) {
        return "stereo: hybrid's own passes cost more than C's forward pass saves";
    }
    if (in_stereo && !mono_forward_ms_) return "stereo: until hybrid is tried again";
    return std::nullopt;
}

Result<MonoPlaneDecision> MonoPlaneChooser::next(const rig::RigInputs& eyes, double content_depth,
                                                 std::optional<double> nearest) {
    Result<double> budget = budget_floor(eyes, content_depth);
    if (!budget) return budget.error();
    const double least = std::min(nearest.value_or(params_.min_mono_plane), eyes.far);
    const Result<double> floor = std::max(*budget, least);
    MonoPlaneDecision decision;
    decision.floor = *floor;
    decision.content_depth = content_depth;
    double candidate = *floor;
    if (content_depth <= *floor) {
        // Nothing can lie beyond the plane: C would draw only the sky. Stereo, and at no visible
        // cost, since no content is shown through the plane.
        candidate = eyes.far;
        decision.reason = "stereo: no content beyond the floor";
    } else if (std::optional<std::string> stereo = stereo_reason(eyes.far, *floor)) {
        candidate = eyes.far;
        decision.reason = *stereo;
    } else {
        candidate = gap_beyond(*floor);
        decision.reason = candidate > *floor ? "gap" : "floor";
    }
    // Hysteresis: a target that moved little is not followed, unless the floor passed it.
    const bool small_move = target_ > 0.0 && target_ < eyes.far && candidate < eyes.far &&
                            target_ >= *floor &&
                            std::abs(std::log(candidate / target_)) < params_.hysteresis;
    if (!small_move) target_ = candidate;
    decision.target = target_;

    double m = target_;
    if (current_) {
        Result<double> stepped = step_towards(eyes, target_, content_depth);
        if (!stepped) return stepped.error();
        m = *stepped;
        if (m != target_ && decision.reason.rfind("stereo", 0) != 0) decision.reason = "moving";
    }
    if (m < *floor) {
        decision.jumped = current_.has_value();
        decision.reason = "floor";
        m = *floor;
    }
    Result<double> error = error_at(eyes, m, content_depth);
    if (!error) return error.error();
    decision.mono_plane = m;
    decision.error_arcmin = *error;
    current_ = m;
    return decision;
}

void MonoPlaneChooser::record(const std::optional<DepthHistogram>& histogram,
                              const FrameCost& cost) {
    if (histogram) histogram_ = histogram;
    if (cost.hybrid) {
        average_into(mono_forward_ms_, cost.mono_forward_ms);
        average_into(hybrid_only_ms_, cost.hybrid_only_ms);
        average_into(stereo_estimate_ms_,
                     cost.frame_ms + cost.mono_forward_ms - cost.hybrid_only_ms);
        stereo_frames_ = 0;
    } else {
        average_into(stereo_estimate_ms_, cost.frame_ms);
        ++stereo_frames_;
    }
}

void add_pass_time(FrameCost& cost, PassKind kind, ViewId view, double gpu_ms) {
    if (kind == PassKind::kForward && view == ViewId::kMono) {
        cost.hybrid = true;
        cost.mono_forward_ms += gpu_ms;
    } else if (runs_only_in_hybrid(kind, view) && kind != PassKind::kTransparency) {
        cost.hybrid_only_ms += gpu_ms;
    }
}

}  // namespace monoplane::plan
