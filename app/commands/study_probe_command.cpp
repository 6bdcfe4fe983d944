#include "app/commands/study_probe_command.h"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands/validation_report.h"
#include "app/lab/frame_time_probe.h"
#include "common/json_writer.h"
#include "hmd/profile.h"
#include "study/protocol.h"

namespace monoplane::app {
namespace {

struct ProbeOptions {
    std::string protocol;
    std::string hmd = "vive";
    int width = 0;  // the recommended eye size; 0: the HMD profile's
    int height = 0;
    std::vector<std::string> presets;  // empty: every preset
    double budget_s = 2.0;
    double refresh_hz = 0.0;  // 0: not known (90 Hz assumed)
};

void write_condition(JsonWriter& j, const lab::ProbeCondition& c) {
    j.begin_object();
    j.value("scene", c.scene).value("alternative", c.alternative);
    j.value("mono_plane", c.mono_plane).value("frames", c.frames);
    if (c.frames > 0)
        j.value("frame_ms", c.frame_ms);
    else
        j.null("frame_ms");
    j.value("fragments", c.fragments);
    j.end_object();
}

void write_preset(JsonWriter& j, const lab::PerformancePreset& p, const lab::FrameTimeEstimate& e,
                  const lab::FrameTimeVerdict& v) {
    j.begin_object();
    j.value("name", p.name).value("description", p.description);
    j.value("detail", p.detail).value("protocol_detail", p.protocol_detail);
    j.value("resolution_scale", p.resolution_scale);
    j.value("anti_aliasing", p.anti_aliasing).value("ssao", p.ssao);
    j.begin_array("study_run_arguments");
    for (const std::string& a : lab::study_run_arguments(p)) j.value({}, a);
    j.end_array();
    j.value("eye_width", e.eye_width).value("eye_height", e.eye_height);
    j.value("frame_ms", e.frame_ms).value("slowest", e.slowest);
    j.value("complete", e.complete).value("elapsed_s", e.elapsed_s);
    j.begin_array("conditions");
    for (const lab::ProbeCondition& c : e.conditions) write_condition(j, c);
    j.end_array();
    j.begin_object("verdict");
    j.value("fits", v.fits).value("tight", v.tight).value("ratio", v.ratio);
    j.value("text", v.text);
    j.end_object();
    j.end_object();
}

// The presets to probe: those named, in the order named, else all four.
std::vector<lab::PerformancePreset> chosen_presets(const study::Protocol& protocol,
                                                   const std::vector<std::string>& names) {
    if (names.empty()) return lab::presets_for(protocol);
    std::vector<lab::PerformancePreset> presets;
    for (const std::string& name : names) {
        presets.push_back(lab::preset_for(protocol, name).value_or_throw());
    }
    return presets;
}

void run_probe(const ProbeOptions& o, const GlobalOptions& global) {
    lab::FrameTimeProbeRequest request;
    request.protocol = study::load_protocol(o.protocol).value_or_throw();
    request.hmd = hmd::load_hmd_profile(o.hmd).value_or_throw();
    request.recommended_width = o.width > 0 ? o.width : request.hmd.width;
    request.recommended_height = o.height > 0 ? o.height : request.hmd.height;
    request.budget_s = o.budget_s;
    const std::vector<lab::PerformancePreset> presets = chosen_presets(request.protocol, o.presets);
    const std::unique_ptr<vk_core::Context> ctx =
        vk_core::Context::create(global.context_options()).value_or_throw();
    std::vector<lab::FrameTimeEstimate> estimates;
    std::vector<lab::PresetEstimate> known;
    for (const lab::PerformancePreset& preset : presets) {
        request.preset = preset;
        const auto report = [&](const lab::ProbeProgress& p) {
            std::cerr << "probe '" << preset.name << "': " << p.condition << " (frame "
                      << p.frames_done + 1 << " of " << p.frames_planned << ")\n";
            return true;
        };
        estimates.push_back(lab::probe_frame_time(*ctx, request, report).value_or_throw());
        known.push_back({preset.name, estimates.back().frame_ms});
    }
    fail_on_validation_messages(*ctx, global);
    JsonWriter j;
    j.begin_object();
    j.value("protocol", request.protocol.source).value("hmd", request.hmd.name);
    j.value("recommended_width", request.recommended_width);
    j.value("recommended_height", request.recommended_height);
    j.value("device", ctx->device_info().name);
    j.begin_array("presets");
    for (std::size_t i = 0; i < presets.size(); ++i) {
        const lab::FrameTimeVerdict verdict =
            lab::judge_frame_time(presets[i].name, estimates[i].frame_ms, o.refresh_hz, known);
        write_preset(j, presets[i], estimates[i], verdict);
    }
    j.end_array();
    j.end_object();
    std::cout << j.str() << "\n";
}

}  // namespace

void add_study_probe_command(CLI::App* study, const GlobalOptions& global) {
    auto o = std::make_shared<ProbeOptions>();
    CLI::App* probe = study->add_subcommand(
        "probe",
        "Estimate a session's frame time on this device for each performance preset (a short "
        "render of the protocol's scenes in both alternatives at its nearest mono plane), with "
        "the verdict against the headset's refresh rate, as JSON (docs/lab.md, Session settings)");
    probe->add_option("--protocol", o->protocol, "Protocol file (TOML)")->required();
    probe->add_option("--hmd", o->hmd, "HMD profile: the eyes' frusta, IPD and default eye size")
        ->capture_default_str();
    probe
        ->add_option("--width", o->width,
                     "The headset's recommended eye width in pixels (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    probe->add_option("--height", o->height, "... and height (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    probe
        ->add_option("--preset", o->presets,
                     "full, balanced, fast or minimal (repeatable; default: all four)")
        ->check(CLI::IsMember({"full", "balanced", "fast", "minimal"}));
    probe
        ->add_option("--budget-s", o->budget_s,
                     "Per preset: no new frame starts after this long (the first condition "
                     "always gets a warm-up and a measured frame)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 600.0));
    probe
        ->add_option("--refresh-hz", o->refresh_hz,
                     "The headset's refresh rate (default: 90 Hz, assumed)")
        ->check(CLI::Range(1.0, 1000.0));
    probe->callback([o, &global] { run_probe(*o, global); });
}

}  // namespace monoplane::app
