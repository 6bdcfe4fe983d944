#include "app/lab/performance_preset.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "common/programming_error.h"
#include "study/scene_files.h"

namespace monoplane::lab {
namespace {

constexpr std::array<std::string_view, 4> kNames = {"full", "balanced", "fast", "minimal"};

// The share of the recommended eye size per preset. Frame time on a GPU-bound device follows the
// pixel count, the square of the scale: 0.7 halves it, 0.5 quarters it.
constexpr std::array<double, 4> kScales = {1.0, 0.7, 0.5, 0.25};

// The detail minimal uses: the generators' smallest, which keeps each scene's layout in depth
// (docs/scenes.md) with fewer objects.
constexpr std::string_view kMinimalDetail = "test";

bool has_built_in_scene(const study::Protocol& protocol) {
    return std::any_of(protocol.scenes.begin(), protocol.scenes.end(),
                       [](const std::string& scene) { return !study::names_scene_file(scene); });
}

std::string shortest(double value) {
    std::array<char, 32> text{};
    const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
    MONOPLANE_EXPECTS(ec == std::errc());
    return std::string(text.data(), end);
}

std::string describe(const PerformancePreset& p, const study::Protocol& protocol) {
    static constexpr std::array<std::string_view, 4> kPixels = {
        "all the headset's pixels", "about half the headset's pixels",
        "a quarter of the headset's pixels", "a sixteenth of the headset's pixels"};
    const auto index =
        static_cast<std::size_t>(std::find(kNames.begin(), kNames.end(), p.name) - kNames.begin());
    std::string text = p.protocol_detail ? "the protocol's scenes (detail " + p.detail + ")"
                                         : "simplified scenes (detail " + p.detail +
                                               " instead of the protocol's " +
                                               protocol.render.detail + ": fewer objects)";
    text += ", " + std::string(kPixels[index]) + " (eyes at " + shortest(p.resolution_scale) +
            " of its size), anti-aliasing " + p.anti_aliasing + " as the protocol sets it";
    return text;
}

PerformancePreset make_preset(const study::Protocol& protocol, std::size_t index) {
    PerformancePreset p;
    p.name = std::string(kNames[index]);
    p.detail = protocol.render.detail;
    const bool minimal = index + 1 == kNames.size();
    if (minimal && has_built_in_scene(protocol) && protocol.render.detail != kMinimalDetail) {
        p.detail = std::string(kMinimalDetail);
        p.protocol_detail = false;
    }
    p.resolution_scale = kScales[index];
    p.anti_aliasing = protocol.render.anti_aliasing;
    p.ssao = protocol.render.ssao;
    p.description = describe(p, protocol);
    return p;
}

std::string format_rate(double hz) {
    return shortest(std::round(hz * 10.0) / 10.0) + " Hz";
}

std::string format_ratio(double ratio) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), ratio >= 10.0 ? "%.0fx" : "%.1fx", ratio);
    return text.data();
}

const PresetEstimate* estimate_of(std::string_view name, std::span<const PresetEstimate> all) {
    for (const PresetEstimate& e : all) {
        if (e.preset == name) return &e;
    }
    return nullptr;
}

// What to do when `preset` misses the budget: the most faithful lower preset estimated to fit;
// else the lower presets not yet estimated, to try; else that no preset keeps the rate.
std::string advice(std::string_view preset, double budget_ms, const std::string& rate,
                   std::span<const PresetEstimate> estimates) {
    const auto chosen = std::find(kNames.begin(), kNames.end(), preset);
    std::vector<std::string_view> untried;
    const PresetEstimate* cheapest_known = nullptr;
    // A preset of no such name (the launcher's "custom", from the command line) is compared with
    // all four: any of them may be the cheaper.
    for (auto name = chosen == kNames.end() ? kNames.begin() : chosen + 1; name != kNames.end();
         ++name) {
        const PresetEstimate* e = estimate_of(*name, estimates);
        if (e && e->frame_ms <= budget_ms) {
            return "choose '" + e->preset + "' (about " + format_frame_time(e->frame_ms) +
                   " per frame)";
        }
        if (e) cheapest_known = e;
        if (!e) untried.push_back(*name);
    }
    if (!untried.empty()) {
        std::string names;
        for (std::size_t i = 0; i < untried.size(); ++i) {
            if (i > 0) names += i + 1 == untried.size() ? " or " : ", ";
            names += "'" + std::string(untried[i]) + "'";
        }
        return "choose " + names;
    }
    const std::string cannot = "this device cannot keep " + rate +
                               " with this protocol: the headset will show frames late (the "
                               "session's frame log counts each missed one)";
    if (!cheapest_known) return "no preset is cheaper; " + cannot;
    return "even '" + cheapest_known->preset + "' needs about " +
           format_frame_time(cheapest_known->frame_ms) + " per frame; " + cannot;
}

}  // namespace

std::span<const std::string_view> performance_preset_names() {
    return kNames;
}

std::vector<PerformancePreset> presets_for(const study::Protocol& protocol) {
    std::vector<PerformancePreset> presets;
    for (std::size_t i = 0; i < kNames.size(); ++i) presets.push_back(make_preset(protocol, i));
    return presets;
}

Result<PerformancePreset> preset_for(const study::Protocol& protocol, std::string_view name) {
    const auto found = std::find(kNames.begin(), kNames.end(), name);
    if (found == kNames.end()) {
        return Error{"no performance preset '" + std::string(name) +
                     "': choose full, balanced, fast or minimal"};
    }
    return make_preset(protocol, static_cast<std::size_t>(found - kNames.begin()));
}

std::vector<std::string> study_run_arguments(const PerformancePreset& preset) {
    std::vector<std::string> arguments;
    if (!preset.protocol_detail) arguments.insert(arguments.end(), {"--detail", preset.detail});
    if (preset.resolution_scale != 1.0) {
        arguments.insert(arguments.end(),
                         {"--resolution-scale", shortest(preset.resolution_scale)});
    }
    return arguments;
}

EyeSize scaled_eye_size(int recommended_width, int recommended_height, double scale) {
    MONOPLANE_EXPECTS(recommended_width > 0 && recommended_height > 0 && scale > 0.0);
    const auto scaled = [scale](int size) {
        return std::max(16, static_cast<int>(std::lround(size * scale)));
    };
    return {scaled(recommended_width), scaled(recommended_height)};
}

std::string format_frame_time(double ms) {
    std::array<char, 32> text{};
    if (ms >= 1000.0)
        std::snprintf(text.data(), text.size(), "%.1f s", ms / 1000.0);
    else
        std::snprintf(text.data(), text.size(), ms >= 100.0 ? "%.0f ms" : "%.1f ms", ms);
    return text.data();
}

FrameTimeVerdict judge_frame_time(std::string_view preset, double frame_ms, double refresh_hz,
                                  std::span<const PresetEstimate> estimates) {
    MONOPLANE_EXPECTS(std::isfinite(frame_ms) && frame_ms > 0.0);
    FrameTimeVerdict v;
    const bool assumed = !(refresh_hz > 0.0);
    v.refresh_hz = assumed ? kAssumedRefreshHz : refresh_hz;
    v.budget_ms = 1000.0 / v.refresh_hz;
    v.ratio = frame_ms / v.budget_ms;
    v.fits = v.ratio <= 1.0;
    v.tight = v.fits && v.ratio > 0.9;
    const std::string rate =
        format_rate(v.refresh_hz) +
        (assumed ? " (assumed: the headset check measures the headset's rate)" : "");
    const std::string per_frame = "about " + format_frame_time(frame_ms) + " per frame";
    if (!v.fits) {
        v.text = "cannot reach " + rate + ": " + per_frame + ", " + format_ratio(v.ratio) +
                 " too slow; " + advice(preset, v.budget_ms, format_rate(v.refresh_hz), estimates);
    } else if (v.tight) {
        v.text = "only just reaches " + rate + ": " + per_frame + " of " +
                 format_frame_time(v.budget_ms) + "; a busier view may miss frames";
    } else {
        v.text = "reaches " + rate + ": " + per_frame + " of " + format_frame_time(v.budget_ms);
    }
    return v;
}

}  // namespace monoplane::lab
