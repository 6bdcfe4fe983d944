#include "app/commands/bench_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

#include "app/commands/image_quality_options.h"
#include "common/result.h"
#include "study/protocol.h"

namespace monoplane::app::bench {
namespace {

std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        if (!item.empty()) items.push_back(item);
    }
    return items;
}

std::vector<Plane> parse_planes(const BenchOptions& o, double far) {
    std::vector<Plane> planes;
    if (!o.protocol.empty()) {
        const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
        for (double m : protocol.mono_planes) planes.push_back({m, false});
        planes.push_back({far, true});
        return planes;
    }
    for (const std::string& item : split_list(o.mono_planes)) {
        if (item == "far") {
            planes.push_back({far, true});
            continue;
        }
        if (item == "auto") {
            planes.push_back({far, false, true});
            continue;
        }
        char* end = nullptr;
        const double m = std::strtod(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !std::isfinite(m) || m <= 0.1) {
            throw UserError("--mono-planes: '" + item +
                            "' is not a distance in metres beyond the near plane (0.1), 'far' "
                            "or 'auto'");
        }
        planes.push_back({std::min(m, far), m >= far});
    }
    if (planes.empty()) throw UserError("--mono-planes: no distance given");
    return planes;
}

}  // namespace

std::string plane_text(double metres) {
    std::ostringstream text;
    text << metres;
    return text.str();
}

BenchSweep parse_sweep(const BenchOptions& o) {
    BenchSweep sweep;
    for (const std::string& name : split_list(o.scenes)) {
        Result<SceneSource> source = parse_scene_source(name);
        if (!source) throw UserError("--scenes: '" + name + "': " + source.error().message);
        sweep.scene_sources.push_back(std::move(source).value());
    }
    for (const std::string& name : split_list(o.modes)) {
        const auto mode = plan::parse_render_mode(name);
        if (!mode) {
            throw UserError("--modes: '" + name +
                            "' is not stereo, stereo-multiview, stereo-gs, stereo-instanced, "
                            "hybrid or hybrid-farfield");
        }
        sweep.mode_choices.push_back(*mode);
    }
    sweep.hybrid_stereo_pass = parse_stereo_pass_flag(o.stereo_pass);
    for (const std::string& name : split_list(o.variants)) {
        const auto variant = plan::parse_mono_culling(name);
        if (!variant) {
            throw UserError("--variants: '" + name +
                            "' is not no-opt, discard, occlusion-cull or auto");
        }
        sweep.variants.push_back(*variant);
    }
    sweep.lods = parse_lod_list(o.lod);
    const auto detail = scenes::parse_detail(o.detail);
    if (!detail) throw UserError("--detail " + o.detail + ": use test, low, medium, high or ultra");
    sweep.detail = *detail;
    if ((o.width > 0) != (o.height > 0)) throw UserError("--width and --height go together");
    if (sweep.scene_sources.empty() || sweep.mode_choices.empty())
        throw UserError("nothing to measure");
    return sweep;
}

bool is_two_pass_stereo(const plan::RenderModeChoice& m) {
    return m.mode == plan::Mode::kStereo && m.stereo_pass == plan::StereoPass::kTwoPasses;
}

BenchSetup prepare_setup(const BenchOptions& o, const BenchSweep& sweep) {
    BenchSetup setup;
    setup.profile = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const hmd::HmdProfile& profile = setup.profile;
    setup.extent =
        vk::Extent2D(static_cast<std::uint32_t>(o.width > 0 ? o.width : profile.width),
                     static_cast<std::uint32_t>(o.height > 0 ? o.height : profile.height));
    modes::FrameInputs& base = setup.base;
    base.views.ipd = profile.ipd;
    base.views.left = profile.left;
    base.views.right = profile.right;
    base.views.cant = hmd::cant_radians(profile);
    base.grazing_angle = o.grazing_deg * std::numbers::pi / 180.0;
    setup.planes = parse_planes(o, base.views.far);
    setup.nearest = base.views.far;
    for (const Plane& p : setup.planes) {
        if (!p.automatic) setup.nearest = std::min(setup.nearest, p.metres);
    }
    setup.auto_params = auto_mono_plane_params(o.auto_flags);

    modes::RendererOptions& renderer_options = setup.renderer_options;
    apply_image_quality_flags(o.anti_aliasing, o.ssao, renderer_options);
    renderer_options.vertex_work = o.vertex_work;
    renderer_options.depth_prepass = o.depth_prepass;
    renderer_options.separate_tonemap = o.separate_tonemap;
    if (modes::msaa_samples(renderer_options.anti_aliasing) != vk::SampleCountFlagBits::e1 &&
        std::any_of(
            sweep.mode_choices.begin(), sweep.mode_choices.end(),
            [](const plan::RenderModeChoice& m) { return m.mode != plan::Mode::kStereo; })) {
        throw UserError(
            "--anti-aliasing " + o.anti_aliasing +
            " works in stereo mode only (docs/hybrid.md, \"MSAA: stereo only, and why\"): add "
            "--modes stereo, or use taa");
    }
    return setup;
}

int count_runs(const BenchSweep& sweep, const std::vector<Plane>& planes) {
    int total = 0;
    for (const plan::RenderModeChoice& choice : sweep.mode_choices) {
        if (choice.mode == plan::Mode::kStereo) total += 1;
        if (choice.mode == plan::Mode::kHybrid)
            total += static_cast<int>(planes.size() * sweep.variants.size());
        if (choice.mode == plan::Mode::kHybridFarfield) total += static_cast<int>(planes.size());
    }
    return total * static_cast<int>(sweep.scene_sources.size() * sweep.lods.size());
}

}  // namespace monoplane::app::bench
