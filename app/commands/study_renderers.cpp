#include "app/commands/study_renderers.h"

#include <algorithm>
#include <iostream>
#include <utility>

#include "app/commands/image_quality_options.h"
#include "common/result.h"
#include "renderer/modes/scene_resources.h"
#include "renderer/vk/memory.h"
#include "scenes/generate.h"

namespace monoplane::app {

plan::RenderModeChoice renderer_mode(study::RenderMode mode) {
    if (mode == study::RenderMode::HybridAuto) return {plan::Mode::kHybrid};
    const auto parsed = plan::parse_render_mode(std::string(study::render_mode_name(mode)));
    if (!parsed) {
        throw UserError("render mode " + std::string(study::render_mode_name(mode)) +
                        " is not implemented; use stereo, stereo-multiview, stereo-gs, "
                        "stereo-instanced, hybrid or hybrid-farfield");
    }
    return *parsed;
}

plan::AutoMonoPlaneParams auto_mono_plane_params(const study::AutoPlaneSettings& settings) {
    plan::AutoMonoPlaneParams params;
    params.error_budget_arcmin = settings.error_budget_arcmin;
    params.measure =
        settings.measure == "disparity" ? rig::ErrorMeasure::kDisparity : rig::ErrorMeasure::kEye;
    params.max_step_arcmin = settings.step_arcmin;
    params.time_budget_ms = settings.time_budget_ms;
    return params;
}

namespace {

// A built-in scene generated at the session's detail, or the imported scene of a file.
std::unique_ptr<scenes::Scene> take_scene(const std::string& name, scenes::Detail detail,
                                          ImportedStudyScenes& imported) {
    if (const auto id = scenes::parse_scene_id(name)) {
        return std::make_unique<scenes::Scene>(scenes::generate_scene(*id, detail));
    }
    const auto entry = imported.find(name);
    if (entry == imported.end()) {
        throw UserError("scene '" + name +
                        "' names a glTF file, but the session has no loaded scene for it (its "
                        "files are recorded when the session begins)");
    }
    return std::make_unique<scenes::Scene>(std::move(entry->second.scene));
}

}  // namespace

StudyRenderers::StudyRenderers(const vk_core::Context& ctx, const study::Protocol& protocol,
                               vk::Extent2D extent, const study::RenderSettings& render,
                               ImportedStudyScenes imported) {
    const double nearest =
        *std::min_element(protocol.mono_planes.begin(), protocol.mono_planes.end());
    const auto detail = scenes::parse_detail(render.detail);
    if (!detail) {
        throw UserError("scene detail '" + render.detail +
                        "': use test, low, medium, high or ultra");
    }
    modes::RendererOptions options;
    options.read_back = false;  // the eyes go to the swapchain on the GPU
    // The session's [render] table (validated with the protocol).
    apply_image_quality_flags(render.anti_aliasing, render.ssao, options);
    std::cerr << "rendering with anti-aliasing " << render.anti_aliasing << ", SSAO " << render.ssao
              << ", detail " << render.detail << "\n";
    const std::uint64_t bytes_before = vk_core::live_device_bytes();
    std::uint64_t scene_bytes = 0;
    for (const std::string& name : protocol.scenes) {
        std::cerr << "preparing " << name << "\n";
        auto scene = take_scene(name, *detail, imported);
        // Geometry, chunk table and shadow map once per scene, for all its alternatives.
        const std::uint64_t before_scene = vk_core::live_device_bytes();
        auto resources = std::make_shared<modes::SceneResources>(ctx, *scene, options.shadow);
        scene_bytes += vk_core::live_device_bytes() - before_scene;
        for (study::RenderMode mode : protocol.alternatives) {
            const auto key = std::make_pair(name, mode);
            if (renderers_.count(key)) continue;
            const plan::RenderModeChoice choice = renderer_mode(mode);
            modes::RendererOptions mode_options = options;
            mode_options.stereo_pass = choice.stereo_pass;
            if (mode == study::RenderMode::HybridAuto) {
                mode_options.auto_mono_plane = auto_mono_plane_params(protocol.auto_plane);
            }
            renderers_[key] = std::make_unique<modes::ModeRenderer>(ctx, resources, choice.mode,
                                                                    extent, mode_options, nearest);
        }
        scenes_[name] = std::move(scene);
    }
    constexpr double kMiB = 1024.0 * 1024.0;
    std::cerr << "prepared " << renderers_.size() << " renderers of " << scenes_.size()
              << " scenes: "
              << static_cast<double>(vk_core::live_device_bytes() - bytes_before) / kMiB
              << " MiB of device memory, " << static_cast<double>(scene_bytes) / kMiB
              << " MiB of it the scenes' geometry and shadow maps, uploaded once each\n";
}

}  // namespace monoplane::app
