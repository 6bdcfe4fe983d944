// LauncherModel's session settings (Headset step): the performance presets of the chosen
// protocol, the one chosen, the measured frame-time estimates and the verdict on them.
#include <algorithm>
#include <cstdio>

#include "app/lab/launcher_model.h"
#include "study/protocol_responses.h"

namespace monoplane::lab {
namespace {

std::string scale_text(double scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", scale);
    return text;
}

// The command line's --detail / --resolution-scale as a preset: the presets' own where one has
// exactly that detail and scale, so the window shows a named preset; else "custom".
PerformancePreset custom_preset(const study::Protocol& protocol,
                                const std::optional<std::string>& detail,
                                std::optional<double> scale) {
    PerformancePreset p;
    p.name = "custom";
    p.detail = detail.value_or(protocol.render.detail);
    p.protocol_detail = p.detail == protocol.render.detail;
    p.resolution_scale = scale.value_or(1.0);
    const PerformancePreset full = preset_for(protocol, "full").value();
    p.anti_aliasing = full.anti_aliasing;
    p.ssao = full.ssao;
    p.description = "as `monoplane lab` was given: detail " + p.detail +
                    (p.protocol_detail ? " (the protocol's)" : "") + ", eyes at " +
                    scale_text(p.resolution_scale) + " of the recommended size, anti-aliasing " +
                    p.anti_aliasing + " as the protocol sets it";
    return p;
}

}  // namespace

void LauncherModel::rebuild_presets() {
    presets_.clear();
    estimates_.clear();
    measurement_ = {};
    if (!protocol_) return;
    presets_ = presets_for(*protocol_);
    std::string matched = "full";
    if (detail_option_ || scale_option_) {
        const PerformancePreset given = custom_preset(*protocol_, detail_option_, scale_option_);
        const auto same = std::ranges::find_if(presets_, [&](const PerformancePreset& p) {
            return p.detail == given.detail && p.resolution_scale == given.resolution_scale;
        });
        if (same != presets_.end()) {
            matched = same->name;
        } else {
            presets_.push_back(given);
            matched = given.name;
        }
    }
    // The experimenter's choice stays across protocols; the command line's is the default.
    if (!preset_chosen_ || !preset()) preset_name_ = matched;
}

const PerformancePreset* LauncherModel::preset() const {
    const auto found = std::ranges::find(presets_, preset_name_, &PerformancePreset::name);
    return found == presets_.end() ? nullptr : &*found;
}

Result<void> LauncherModel::set_preset(const std::string& name) {
    if (std::ranges::find(presets_, name, &PerformancePreset::name) == presets_.end()) {
        std::string names;
        for (const PerformancePreset& p : presets_) names += (names.empty() ? "" : ", ") + p.name;
        if (names.empty()) return Error{"choose a protocol first: presets are the protocol's"};
        return Error{"no performance preset '" + name + "': choose " + names};
    }
    preset_name_ = name;
    preset_chosen_ = true;
    revalidate();
    return Ok{};
}

void LauncherModel::set_frame_time_estimate(PresetEstimate estimate) {
    std::erase_if(estimates_, [&](const PresetEstimate& e) { return e.preset == estimate.preset; });
    estimates_.push_back(std::move(estimate));
}

std::optional<double> LauncherModel::estimate_ms(const std::string& preset) const {
    const auto found = std::ranges::find(estimates_, preset, &PresetEstimate::preset);
    if (found == estimates_.end()) return std::nullopt;
    return found->frame_ms;
}

std::optional<FrameTimeVerdict> LauncherModel::frame_time_verdict() const {
    const std::optional<double> ms = estimate_ms(preset_name_);
    if (!ms || !(*ms > 0.0)) return std::nullopt;
    return judge_frame_time(preset_name_, *ms, headset_report_.refresh_hz, estimates_);
}

Result<void> LauncherModel::set_keys(const std::string& keys) {
    if (!keys.empty()) {
        Result<study::ResponseSettings> parsed = study::parse_keys_option(
            keys, protocol_ ? protocol_->responses : study::ResponseSettings{});
        MONOPLANE_TRY(parsed);
    }
    keys_ = keys;
    revalidate();
    return Ok{};
}

// As the session resolves them (study::parse_keys_option over the protocol's [responses]).
bool LauncherModel::answer_keys_enabled() const {
    const study::ResponseSettings protocol =
        protocol_ ? protocol_->responses : study::ResponseSettings{};
    if (keys_.empty()) return protocol.enabled;
    Result<study::ResponseSettings> parsed = study::parse_keys_option(keys_, protocol);
    return parsed && parsed->enabled;
}

bool LauncherModel::observer_answers() const {
    if (observer_ == "none") return false;
    return !(headset_ == "openxr" && observer_.empty());
}

}  // namespace monoplane::lab
