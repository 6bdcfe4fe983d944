#include "app/commands/analysis_scene_images.h"

#include <cmath>
#include <exception>
#include <memory>
#include <optional>

#include "app/commands/scene_source.h"
#include "app/png.h"
#include "common/result.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/vk/context.h"
#include "scenes/generate.h"
#include "study/scene_files.h"

namespace monoplane::app {
namespace {

// Wide enough to recognise the scene under the heat map, small enough for the page: the figure
// embeds it (a few tens of kilobytes as PNG).
constexpr std::uint32_t kPictureWidth = 320;

Result<scenes::Scene> load_study_scene(const std::string& name, const GazeViewSource& source) {
    const std::optional<scenes::Detail> detail =
        scenes::parse_detail(source.detail.empty() ? "low" : source.detail);
    if (!detail) return Error{"the sessions' detail '" + source.detail + "' is not known"};
    if (const std::optional<scenes::SceneId> id = scenes::parse_scene_id(name))
        return scenes::generate_scene(*id, *detail);
    const auto file = source.scene_files.find(name);
    if (file == source.scene_files.end())
        return Error{"no session recorded the file of scene '" + name + "'"};
    SceneSource scene_source;
    scene_source.file = file->second;
    scene_source.label = name;
    return load_scene(scene_source, *detail);
}

// One frame of stereo at the scene's default viewpoint; the left eye as PNG.
analysis::report::SceneImage render_left_eye(const vk_core::Context& ctx,
                                             const scenes::Scene& scene, const SeatView& view) {
    const scenes::Viewpoint* seat = scene.find_viewpoint("default");
    if (!seat) throw UserError("the scene has no default viewpoint");
    const hmd::HmdProfile& p = view.profile;
    const vk::Extent2D extent(
        kPictureWidth, static_cast<std::uint32_t>(
                           std::lround(static_cast<double>(kPictureWidth) * p.height / p.width)));
    modes::RendererOptions options;
    modes::ModeRenderer renderer(ctx, scene, plan::Mode::kStereo, extent, options);
    modes::FrameInputs inputs;
    inputs.views.head = seat->head;
    inputs.views.ipd = p.ipd;
    inputs.views.left = p.left;
    inputs.views.right = p.right;
    inputs.views.cant = hmd::cant_radians(p);
    inputs.mono_plane = inputs.views.far;
    renderer.set_read_back(true);
    renderer.render_frame(inputs);
    const modes::RgbaImage& left = renderer.eye_image(modes::Eye::kLeft);
    return {png_bytes(left), static_cast<int>(left.width), static_cast<int>(left.height)};
}

}  // namespace

void add_sessions(GazeViewSource& source,
                  const std::map<std::int64_t, study::SessionInfo>& sessions) {
    for (const auto& [id, info] : sessions) {
        source.hmds.push_back(info.hmd);
        if (source.detail.empty()) source.detail = info.render.detail;
        for (const auto& [entry, path] : study::recorded_scene_paths(info.scene_files))
            source.scene_files.emplace(entry, path);
    }
}

SeatView seat_view(const GazeViewSource& source) {
    SeatView view;
    const std::string recorded = source.hmds.empty() ? std::string() : source.hmds.front();
    for (const std::string& key : hmd::builtin_hmd_names()) {
        Result<hmd::HmdProfile> profile = hmd::load_hmd_profile(key);
        if (!profile || (profile->name != recorded && key != recorded)) continue;
        view.profile = std::move(profile).value();
        view.key = key;
        break;
    }
    if (view.key.empty()) {
        view.profile = hmd::load_hmd_profile("vive").value_or_throw();
        view.key = "vive";
        if (!recorded.empty())
            view.note = "the sessions' HMD profile '" + recorded +
                        "' is not a built-in one; drawn for vive";
    }
    for (const std::string& hmd : source.hmds)
        if (hmd != recorded && view.note.empty())
            view.note = "sessions ran on different HMD profiles; drawn for the first's";
    const hmd::HmdProfile& p = view.profile;
    view.eye = {.ipd = p.ipd,
                .tan_left = p.left.left,
                .tan_right = p.left.right,
                .tan_down = p.left.down,
                .tan_up = p.left.up,
                .cant = hmd::cant_radians(p)[rig::kLeft]};
    return view;
}

void add_scene_images(analysis::report::GazeResults& gaze, const GazeViewSource& source,
                      const SeatView& view) {
    if (gaze.densities.empty()) return;
    std::unique_ptr<vk_core::Context> ctx;
    try {
        ctx = vk_core::Context::create({}).value_or_throw();
    } catch (const std::exception& e) {
        gaze.image_note = std::string("no Vulkan device to render the scene (") + e.what() + ").";
        return;
    }
    for (const analysis::GazeDensity& d : gaze.densities) {
        try {
            const scenes::Scene scene = load_study_scene(d.scene, source).value_or_throw();
            gaze.images[d.scene] = render_left_eye(*ctx, scene, view);
        } catch (const std::exception& e) {
            gaze.image_note += "scene '" + d.scene + "' could not be rendered (" + e.what() + "). ";
        }
    }
}

}  // namespace monoplane::app
