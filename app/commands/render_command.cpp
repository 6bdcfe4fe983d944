// `monoplane render`: one scene, one mode, one viewpoint -> left.png, right.png, stats.json.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <numbers>
#include <optional>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "app/commands/ao_consistency.h"
#include "app/commands/auto_mono_plane_options.h"
#include "app/commands/commands.h"
#include "app/commands/depth_profile_json.h"
#include "app/commands/device_memory_json.h"
#include "app/commands/frame_summary.h"
#include "app/commands/image_quality_options.h"
#include "app/commands/lod_flags.h"
#include "app/commands/output_directory.h"
#include "app/commands/scene_source.h"
#include "app/commands/stereo_comparison.h"
#include "app/commands/validation_report.h"
#include "app/png.h"
#include "common/json_writer.h"
#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/passes/pass_units.h"
#include "renderer/plan/frame_plan_json.h"
#include "renderer/vk/context.h"
#include "renderer/vk/memory.h"
#include "rig/pose_path.h"
#include "scenes/generate.h"

namespace monoplane::app {
namespace {

struct RenderOptions {
    std::string scene = "spheres";
    std::string mode = "stereo";
    std::string stereo_pass;  // empty: the mode's (two for stereo and the hybrid modes)
    std::string mono_plane;   // metres, or "auto"
    AutoMonoPlaneFlags auto_flags;
    double overlap_k = 2.0;
    double grazing_deg = 1.0;  // rig::RigInputs::grazing_angle, degrees
    double blend_band = 0.3;
    std::string debug_view = "none";
    std::string mono_culling = "occlusion-cull";
    std::string hmd = "vive";
    std::optional<double> ipd;
    int width = 0;
    int height = 0;
    std::string view = "default";
    std::uint64_t seed = scenes::kDefaultSeed;
    std::string detail = "low";
    int frames = 1;
    int warmup = 0;
    int shadow_resolution = 4096;
    std::string out;
    bool json = false;
    bool compare_stereo = false;
    std::string anti_aliasing = "none";
    std::string ssao = "off";
    std::string pose_path = "static";
    double fps = 90.0;
    bool depth_prepass = false;
    bool depth_profile = false;  // --depth-profile (docs/scenes.md)
    LodFlags lod;
};

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

// What stats.json reports besides the options: where and what was rendered, and the results.
struct RenderResults {
    const hmd::HmdProfile& profile;
    const scenes::Scene& scene;
    const vk_core::Context& ctx;
    int width = 0;
    int height = 0;
    FrameSummary summary;                                // the measured frames
    const modes::ModeRenderer& renderer;                 // its last frame's rig, plan and variant
    const modes::RgbaImage* mono = nullptr;              // mono.png, if written
    const std::optional<StereoComparison>& comparison;   // --compare-stereo
    const std::optional<quality::InconsistencyMap>& ao;  // --ssao
    std::filesystem::path out;
    DeviceMemoryFigures device_memory;  // after the frames, before the stereo reference's
};

// The configuration rendered: the options as given, with what they resolved to.
void write_configuration(JsonWriter& j, const RenderOptions& o,
                         const plan::RenderModeChoice& choice, const RenderResults& r) {
    j.value("command", "render").value("scene", r.scene.name).value("mode", o.mode);
    j.value("detail", o.detail).value("seed", static_cast<std::uint64_t>(o.seed));
    j.value("view", o.view)
        .value("hmd", r.profile.name)
        .value("ipd", o.ipd.value_or(r.profile.ipd));
    j.value("width", r.width).value("height", r.height);
    j.value("stereo_pass", plan::stereo_pass_name(choice.stereo_pass));
    if (choice.mode != plan::Mode::kStereo || o.debug_view != "none") {
        j.value("debug_view", o.debug_view);
    }
    if (choice.mode == plan::Mode::kHybrid) {
        j.value("variant", o.mono_culling);
        // auto: the variant it resolved to
        j.value("variant_used", plan::mono_culling_name(r.renderer.last_variant()));
    }
    j.value("anti_aliasing", o.anti_aliasing).value("ssao", o.ssao);
    j.value("lod", o.lod.lod).value("lod_error_px", o.lod.error_px);
    // Building the levels (every chunk, at load): their cost and size.
    const modes::SceneResources& resources = r.renderer.scene_resources();
    j.value("lod_build_s", resources.lod_build_seconds());
    j.value("lod_triangles", static_cast<std::uint64_t>(resources.lods().triangle_count()));
    j.value("pose_path", o.pose_path).value("fps", o.fps);
}

void write_rig(JsonWriter& j, const rig::Rig& rig) {
    j.value("mono_plane", rig.inputs.mono_plane).value("mono_skipped", rig.mono_skipped);
    j.value("overlap", rig.overlap).value("max_error_px", rig.max_error_px);
    j.value("max_error_px_2d", rig.max_error_px_2d);
    j.begin_object("mono_camera");
    j.value("offset_behind_eyes", rig.mono.offset_behind_eyes);
    j.value("viewport_width", rig.mono.viewport_width);
    j.value("viewport_height", rig.mono.viewport_height);
    j.end_object();
}

// Each view's pipeline statistics, then the totals of scene primitives and of fragments.
void write_view_statistics(JsonWriter& j, const std::vector<profile::ViewStatistics>& views) {
    std::uint64_t primitives = 0;
    std::uint64_t fragments = 0;
    j.begin_object("views");
    for (const profile::ViewStatistics& v : views) {
        j.begin_object(v.view);
        j.value("input_primitives", v.input_primitives);
        j.value("clipping_invocations", v.clipping_invocations);
        j.value("clipping_primitives", v.clipping_primitives);
        j.value("vertex_invocations", v.vertex_invocations);
        j.value("geometry_invocations", v.geometry_invocations);
        j.value("geometry_primitives", v.geometry_primitives);
        j.value("fragment_invocations", v.fragment_invocations);
        j.value("draws", static_cast<std::uint64_t>(v.draws));
        if (v.view == "mono") {
            j.value("draws_before_occlusion_culling",
                    static_cast<std::uint64_t>(v.draws_before_occlusion_culling));
        }
        j.end_object();
        // Scene primitives only: the composites' full-screen triangles are not scene work.
        if (v.view.find('.') == std::string::npos) primitives += v.clipping_invocations;
        fragments += v.fragment_invocations;
    }
    j.end_object();
    j.value("primitives", primitives).value("fragments", fragments);
}

void write_comparison(JsonWriter& j, const StereoComparison& comparison) {
    j.value("ssim_vs_stereo", comparison.ssim_mean());
    j.value("max_channel_difference_vs_stereo", comparison.max_channel_difference());
    j.begin_object("ssim");
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        const EyeComparison& c = comparison.eyes[static_cast<int>(eye)];
        j.begin_object(modes::eye_name(eye));
        j.value("gaussian", c.ssim).value("local_w4", c.ssim_local_w4);
        j.value("beyond_plane", c.ssim_beyond_plane);
        j.value("pixels_beyond_plane", static_cast<std::uint64_t>(c.pixels_beyond_plane));
        j.end_object();
    }
    j.end_object();
}

// papers/002 Sect. 4.1 over the left eye's pixels.
void write_ao_inconsistency(JsonWriter& j, const quality::InconsistencyMap& ao) {
    j.begin_object("ao_inconsistency");
    j.value("mean", ao.mean).value("max", ao.max);
    j.value("compared_pixels", static_cast<std::uint64_t>(ao.compared));
    j.value("one_eye_only_pixels", static_cast<std::uint64_t>(ao.one_eye_only));
    j.value("normal_rejected_pixels", static_cast<std::uint64_t>(ao.normal_rejected));
    j.value("sky_pixels", static_cast<std::uint64_t>(ao.sky));
    j.end_object();
}

void write_files(JsonWriter& j, const RenderResults& r) {
    const std::filesystem::path& out = r.out;
    j.begin_object("files");
    j.value("left", (out / "left.png").string()).value("right", (out / "right.png").string());
    if (r.mono) j.value("mono", (out / "mono.png").string());
    if (r.ao) {
        j.value("ao_left", (out / "ao_left.png").string());
        j.value("ao_right", (out / "ao_right.png").string());
        j.value("ao_inconsistency", (out / "ao_inconsistency.png").string());
    }
    j.end_object();
}

std::string summary_json(const RenderOptions& o, const plan::RenderModeChoice& choice,
                         const RenderResults& r,
                         const std::function<void(JsonWriter&)>& depth_profile,
                         const std::function<void(JsonWriter&)>& auto_mono_plane) {
    const FrameSummary& s = r.summary;
    JsonWriter j;
    j.begin_object();
    write_configuration(j, o, choice, r);
    if (r.renderer.last_rig()) write_rig(j, *r.renderer.last_rig());
    j.value("device", r.ctx.device_info().name);
    j.value("triangles", static_cast<std::uint64_t>(r.scene.triangle_count()));
    j.value("chunks", static_cast<std::uint64_t>(r.scene.chunks.size()));
    j.value("frames", s.frames).value("warmup_frames", o.warmup);
    j.value("frame_ms_median", s.frame_ms_median).value("frame_ms_p90", s.frame_ms_p90);
    j.value("cpu_ms_median", s.cpu_ms_median);
    j.begin_object("passes");
    for (const auto& [name, ms] : s.pass_ms_median) j.value(name, ms);
    j.end_object();
    write_view_statistics(j, s.views);
    if (r.comparison) write_comparison(j, *r.comparison);
    if (r.ao) write_ao_inconsistency(j, *r.ao);
    j.value("depth_prepass", o.depth_prepass);
    write_device_memory_json(j, r.device_memory);
    if (depth_profile) depth_profile(j);
    auto_mono_plane(j);
    plan::write_plan_json(j, r.renderer.last_plan());  // the last frame's
    write_files(j, r);
    j.end_object();
    return j.str();
}

// A scene wholly beyond the far plane renders as sky alone: say why (glTF files modelled in
// millimetres put a camera "metres" away that are really millimetres, e.g. 2CylinderEngine's
// camera stands 1,500 units from the engine).
void warn_if_beyond_far_plane(const scenes::Scene& scene, const scenes::Viewpoint& view,
                              double far) {
    const glm::dvec3 p = view.head.position;
    const glm::dvec3 nearest =
        glm::clamp(p, glm::dvec3(scene.bounds.min), glm::dvec3(scene.bounds.max));
    const double distance = glm::length(nearest - p);
    if (distance <= far) return;
    std::cerr << "warning: view '" << view.name << "' is " << distance
              << " m from the nearest point of the scene's bounds, beyond the far plane (" << far
              << " m): only sky will show. If the file is modelled in other units than metres, "
                 "scale it, or try --view bench-overview\n";
}

// The options checked and parsed; nothing loaded yet.
struct RenderSetup {
    plan::RenderModeChoice choice;
    std::optional<double> fixed_plane;  // --mono-plane in metres
    bool auto_plane = false;            // --mono-plane auto
    plan::MonoCulling mono_culling = plan::MonoCulling::kOcclusionCull;
    plan::DebugView debug_view = plan::DebugView::kNone;
    std::string unit_debug_view;  // a pass unit's debug view ("depth") instead
    SceneSource scene_source;
    scenes::Detail detail{};
    rig::PosePath pose_path;
    modes::RendererOptions renderer_options;  // completed once the scene is loaded
    bool ssao = false;
};

// --mode with --stereo-pass, which may name the single-pass stereo a mode already implies.
plan::RenderModeChoice parse_mode_flags(const RenderOptions& o) {
    auto choice = plan::parse_render_mode(o.mode);
    if (!choice) {
        throw UserError("--mode " + o.mode +
                        ": unknown; use stereo, stereo-multiview, stereo-gs, stereo-instanced, "
                        "hybrid or hybrid-farfield");
    }
    if (!o.stereo_pass.empty()) {
        const plan::StereoPass pass = parse_stereo_pass_flag(o.stereo_pass);
        if (choice->stereo_pass != plan::StereoPass::kTwoPasses && pass != choice->stereo_pass) {
            throw UserError("--stereo-pass " + o.stereo_pass + " contradicts --mode " + o.mode);
        }
        choice->stereo_pass = pass;
    }
    return *choice;
}

// --mono-plane (which the hybrid modes need and stereo cannot use as auto), --variant and
// --debug-view.
void parse_hybrid_flags(const RenderOptions& o, RenderSetup& setup) {
    const plan::Mode mode = setup.choice.mode;
    if (mode != plan::Mode::kStereo && o.mono_plane.empty()) {
        throw UserError("--mode " + o.mode + " needs --mono-plane M (metres) or auto");
    }
    setup.fixed_plane = o.mono_plane.empty() ? std::optional<double>()
                                             : parse_mono_plane_value("--mono-plane", o.mono_plane);
    setup.auto_plane = !o.mono_plane.empty() && !setup.fixed_plane;
    if (setup.auto_plane && mode == plan::Mode::kStereo) {
        throw UserError("--mono-plane auto needs a hybrid mode: stereo has no mono plane");
    }
    const auto mono_culling = plan::parse_mono_culling(o.mono_culling);
    if (!mono_culling) {
        throw UserError("--variant " + o.mono_culling +
                        " is not one of no-opt, discard, occlusion-cull, auto");
    }
    setup.mono_culling = *mono_culling;
    const std::vector<std::string> unit_views = passes::unit_debug_views();
    if (std::find(unit_views.begin(), unit_views.end(), o.debug_view) != unit_views.end()) {
        setup.unit_debug_view = o.debug_view;
        return;
    }
    const auto debug_view = plan::parse_debug_view(o.debug_view);
    if (!debug_view) {
        std::string names;
        for (const std::string& name : unit_views) names += ", " + name;
        throw UserError("--debug-view " + o.debug_view +
                        ": use none, tint-mono, stereo-only, mono-only, routing" + names);
    }
    setup.debug_view = *debug_view;
}

// --scene, --detail, the image size, --ipd and the head motion.
void parse_scene_and_viewer_flags(const RenderOptions& o, RenderSetup& setup) {
    Result<SceneSource> scene_source = parse_scene_source(o.scene);
    if (!scene_source) {
        throw UserError("--scene " + o.scene + ": " + scene_source.error().message);
    }
    setup.scene_source = std::move(scene_source).value();
    const auto detail = scenes::parse_detail(o.detail);
    if (!detail)
        throw UserError("--detail " + o.detail + ": unknown; use test, low, medium, high or ultra");
    setup.detail = *detail;
    if ((o.width > 0) != (o.height > 0)) throw UserError("--width and --height go together");
    if (o.ipd && !(*o.ipd >= 0.0 && *o.ipd <= 0.1))
        throw UserError("--ipd must be within [0, 0.1] m");
    const auto pose_path = rig::builtin_pose_path(o.pose_path);
    if (!pose_path) {
        throw UserError("--pose-path " + o.pose_path + ": use " +
                        joined(rig::builtin_pose_path_names()));
    }
    setup.pose_path = *pose_path;
    if (!(o.fps > 0.0 && std::isfinite(o.fps))) throw UserError("--fps must be positive");
}

RenderSetup parse_render_flags(const RenderOptions& o) {
    RenderSetup setup;
    setup.choice = parse_mode_flags(o);
    parse_hybrid_flags(o, setup);
    parse_scene_and_viewer_flags(o, setup);
    modes::RendererOptions& renderer_options = setup.renderer_options;
    renderer_options.stereo_pass = setup.choice.stereo_pass;
    apply_image_quality_flags(o.anti_aliasing, o.ssao, renderer_options);
    renderer_options.lod = parse_lod_flags(o.lod.lod, o.lod.error_px);
    // E(p) reprojects the eyes' AO through their depth.
    setup.ssao = renderer_options.ssao.has_value();
    renderer_options.read_back_ao = setup.ssao;
    renderer_options.read_back_depth = setup.ssao || o.depth_profile;
    if (o.depth_profile && !o.json) throw UserError("--depth-profile needs --json");
    return setup;
}

hmd::HmdProfile load_profile(const RenderOptions& o) {
    hmd::HmdProfile profile = hmd::load_hmd_profile(o.hmd).value_or_throw();
    if (o.depth_profile && (profile.cant_deg[0] != 0.0 || profile.cant_deg[1] != 0.0)) {
        // scenes/depth_profile.cpp measures a parallel eye's own depth, which for a canted eye
        // is not the distance in front of the eyes' plane that m is measured by.
        throw UserError("--depth-profile is not available for canted profiles (" + profile.name +
                        "): it measures depth along a parallel eye's axis");
    }
    return profile;
}

scenes::Scene load_render_scene(const RenderOptions& o, const RenderSetup& setup) {
    if (setup.scene_source.builtin) {
        std::cerr << "generating " << o.scene << " (detail " << o.detail << ", seed " << o.seed
                  << ")\n";
    } else {
        std::cerr << "loading " << o.scene << "\n";
    }
    return load_scene(setup.scene_source, setup.detail, o.seed).value_or_throw();
}

// --view among the scene's viewpoints; the error lists them.
const scenes::Viewpoint& find_view(const RenderOptions& o, const scenes::Scene& scene) {
    const scenes::Viewpoint* viewpoint = scene.find_viewpoint(o.view);
    if (!viewpoint) {
        std::vector<std::string> names;
        for (const auto& v : scene.viewpoints) names.push_back(v.name);
        throw UserError("--view " + o.view + ": " + o.scene + " has the views " + joined(names));
    }
    return *viewpoint;
}

// The first frame's inputs; the frames move the head along the pose path from there.
modes::FrameInputs first_frame_inputs(const RenderOptions& o, const RenderSetup& setup,
                                      const hmd::HmdProfile& profile,
                                      const scenes::Viewpoint& viewpoint) {
    modes::FrameInputs inputs;
    inputs.views.head = viewpoint.head;
    inputs.views.ipd = o.ipd.value_or(profile.ipd);
    inputs.views.left = profile.left;
    inputs.views.right = profile.right;
    inputs.views.cant = hmd::cant_radians(profile);
    inputs.mono_plane = setup.fixed_plane.value_or(inputs.views.far);  // auto: the renderer's
    inputs.overlap_k = o.overlap_k;
    inputs.grazing_angle = o.grazing_deg * std::numbers::pi / 180.0;
    inputs.view_blend_band = o.blend_band;
    inputs.debug = setup.debug_view;
    inputs.unit_debug_view = setup.unit_debug_view;
    inputs.mono_culling = setup.mono_culling;
    return inputs;
}

// Frames in flight: each frame is submitted without waiting for the last; only the last is read
// back (the PNGs), and the statistics arrive as the frames complete, in order. Returns the
// statistics of the frames after the warm-up.
std::vector<profile::FrameStats> render_frames(const RenderOptions& o, const rig::PosePath& path,
                                               const scenes::Viewpoint& viewpoint,
                                               modes::ModeRenderer& renderer,
                                               modes::FrameInputs& inputs) {
    std::vector<profile::FrameStats> completed;
    const int total = o.warmup + o.frames;
    for (int frame = 0; frame < total; ++frame) {
        // Frame n at n / fps along the path: TAA's jitter and history follow the frame index.
        inputs.views.head = rig::pose_along(path, viewpoint.head, frame / o.fps);
        inputs.frame_index = static_cast<std::uint64_t>(frame);
        renderer.set_read_back(frame == total - 1);
        renderer.submit_frame(inputs);
        for (profile::FrameStats& stats : renderer.take_completed()) {
            completed.push_back(std::move(stats));
        }
        if (total > 1) std::cerr << "\rframe " << frame + 1 << "/" << total << std::flush;
    }
    for (profile::FrameStats& stats : renderer.finish_frames())
        completed.push_back(std::move(stats));
    std::vector<profile::FrameStats> measured(std::make_move_iterator(completed.begin() + o.warmup),
                                              std::make_move_iterator(completed.end()));
    if (total > 1) std::cerr << "\n";
    return measured;
}

// left.png, right.png and, where the mode has one, mono.png; returns the mono image or nullptr.
const modes::RgbaImage* write_images(const modes::ModeRenderer& renderer,
                                     const std::filesystem::path& out) {
    write_png(out / "left.png", renderer.eye_image(modes::Eye::kLeft)).value_or_throw();
    write_png(out / "right.png", renderer.eye_image(modes::Eye::kRight)).value_or_throw();
    const modes::RgbaImage* mono = renderer.mono_image();
    if (mono) write_png(out / "mono.png", *mono).value_or_throw();
    return mono;
}

// --depth-profile: the last frame's left eye against its own depth read-back (docs/scenes.md).
std::function<void(JsonWriter&)> depth_profile_section(const RenderOptions& o,
                                                       const scenes::Scene& scene,
                                                       const modes::FrameInputs& inputs,
                                                       const modes::ModeRenderer& renderer) {
    return [&o, &scene, &inputs, &renderer](JsonWriter& j) {
        if (!o.depth_profile) return;
        DepthProfileInputs in;
        in.scene = &scene;
        in.head = inputs.views.head;
        in.ipd = inputs.views.ipd;
        in.left = inputs.views.left;
        in.near = inputs.views.near;
        in.far = inputs.views.far;
        write_depth_profile_json(j, "depth_profile", in,
                                 renderer.eye_linear_depth(modes::Eye::kLeft));
    };
}

void run_render(const RenderOptions& o, const GlobalOptions& global) {
    RenderSetup setup = parse_render_flags(o);
    const std::filesystem::path out = prepare_output_directory("--out", o.out);
    const hmd::HmdProfile profile = load_profile(o);
    const int width = o.width > 0 ? o.width : profile.width;
    const int height = o.height > 0 ? o.height : profile.height;
    const vk::Extent2D extent(static_cast<std::uint32_t>(width),
                              static_cast<std::uint32_t>(height));

    auto ctx = vk_core::Context::create(global.context_options()).value_or_throw();
    std::cerr << "device: " << ctx->device_info().name << "\n";
    const scenes::Scene scene = load_render_scene(o, setup);
    const scenes::Viewpoint& viewpoint = find_view(o, scene);
    warn_if_beyond_far_plane(scene, viewpoint, modes::StereoViewInputs{}.far);

    modes::RendererOptions& renderer_options = setup.renderer_options;
    renderer_options.shadow.resolution = static_cast<std::uint32_t>(o.shadow_resolution);
    renderer_options.depth_prepass = o.depth_prepass;
    if (setup.auto_plane) renderer_options.auto_mono_plane = auto_mono_plane_params(o.auto_flags);
    modes::ModeRenderer renderer(*ctx, scene, setup.choice.mode, extent, renderer_options);
    modes::FrameInputs inputs = first_frame_inputs(o, setup, profile, viewpoint);
    const std::vector<profile::FrameStats> measured =
        render_frames(o, setup.pose_path, viewpoint, renderer, inputs);
    const DeviceMemoryFigures device_memory =
        DeviceMemoryFigures::from_bytes(vk_core::live_device_bytes(vk_core::MemoryKind::kImage),
                                        vk_core::live_device_bytes(vk_core::MemoryKind::kBuffer));

    // Auto: the comparisons below look at the last frame, rendered with the chooser's m.
    if (setup.auto_plane && renderer.last_rig())
        inputs.mono_plane = renderer.last_rig()->inputs.mono_plane;
    const modes::RgbaImage* mono = write_images(renderer, out);
    std::optional<quality::InconsistencyMap> ao;
    if (setup.ssao) {
        ao = ao_inconsistency(renderer, inputs);
        write_ao_pictures(renderer, *ao, out);
        std::cerr << "AO inconsistency E (papers/002 Sect. 4.1): mean " << ao->mean << " over "
                  << ao->compared << " pixels\n";
    }
    std::optional<StereoComparison> comparison;
    if (o.compare_stereo && (setup.choice.mode != plan::Mode::kStereo ||
                             setup.choice.stereo_pass != plan::StereoPass::kTwoPasses)) {
        std::cerr << "rendering the stereo reference for SSIM\n";
        comparison =
            compare_with_stereo(*ctx, scene, extent, renderer_options, inputs, renderer, out);
    }
    const auto auto_json = [&](JsonWriter& j) {
        if (setup.auto_plane) {
            write_auto_mono_plane_json(j, *renderer_options.auto_mono_plane, measured);
        }
    };
    const RenderResults results{profile,  scene, *ctx,       width, height, summarize(measured),
                                renderer, mono,  comparison, ao,    out,    device_memory};
    const std::string json = summary_json(
        o, setup.choice, results, depth_profile_section(o, scene, inputs, renderer), auto_json);
    std::ofstream(out / "stats.json") << json << "\n";
    if (o.json) std::cout << json << "\n";
    std::cerr << "wrote " << (out / "left.png").string() << ", " << (out / "right.png").string()
              << (mono ? ", mono.png" : "") << " and stats.json\n";

    fail_on_validation_messages(*ctx, global);
}

}  // namespace

namespace {

// --mode and what the hybrid modes take: the mono plane, the overlap, the blend, the debug
// views and the variant.
void add_mode_flags(CLI::App& cmd, RenderOptions& options) {
    cmd.add_option("--mode", options.mode,
                   "stereo, stereo-multiview, stereo-gs, stereo-instanced, hybrid or "
                   "hybrid-farfield")
        ->capture_default_str();
    cmd.add_option("--stereo-pass", options.stereo_pass,
                   "How the eyes' forward passes are drawn (stereo, and hybrid's near region): "
                   "two (one pass per eye), multiview (VK_KHR_multiview), gs (geometry-shader "
                   "duplication, papers/001) or instanced (two instances per draw, one per "
                   "eye); default two, or the mode's");
    cmd.add_option("--mono-plane", options.mono_plane,
                   "Mono-plane distance m in metres (hybrid modes), or auto: chosen every frame "
                   "within --error-budget-arcmin (docs/hybrid.md, \"Choosing m\")");
    add_auto_mono_plane_flags(cmd, options.auto_flags);
    cmd.add_option("--k", options.overlap_k, "Overlap constant k of eq. 3: eps = k s m")
        ->capture_default_str();
    cmd.add_option("--grazing-deg", options.grazing_deg,
                   "Overlap for surfaces down to this angle to the view rays (0: eps = k s m)")
        ->capture_default_str();
    cmd.add_option("--blend-band", options.blend_band,
                   "Metres below m over which the eyes' view vectors blend into C's (0: off)")
        ->capture_default_str();
    std::string debug_views =
        "Debug view: none, tint-mono, stereo-only, mono-only (hybrid modes), routing (chunks "
        "coloured by the lists the GPU culling put them in: green eyes, blue C, magenta both)";
    for (const plan::PassUnitDeclaration& unit : passes::pass_unit_declarations()) {
        if (unit.debug_view) debug_views += "; " + *unit.debug_view + " (" + unit.help + ")";
    }
    cmd.add_option("--debug-view", options.debug_view, debug_views)->capture_default_str();
    cmd.add_option("--variant", options.mono_culling,
                   "hybrid: how the merged depth pyramid of both eyes saves C's work (papers/000 "
                   "Sect. 5.1): no-opt, discard (C's hidden fragments), occlusion-cull (also "
                   "C's hidden chunks) or auto (measures the three on the frames rendered and "
                   "uses the fastest; same image)")
        ->capture_default_str();
}

// The headset, the image size and where in which scene it stands.
void add_viewer_flags(CLI::App& cmd, RenderOptions& options) {
    cmd.add_option("--hmd", options.hmd,
                   "HMD profile: vive, vive-pro, symmetric-90, "
                   "symmetric-110 or a TOML file")
        ->capture_default_str();
    cmd.add_option("--ipd", options.ipd,
                   "Interpupillary distance in metres (default: the profile's)");
    cmd.add_option("--width", options.width, "Per-eye width in pixels (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    cmd.add_option("--height", options.height, "Per-eye height in pixels (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    cmd.add_option("--view", options.view, "Viewpoint name of the scene")->capture_default_str();
    cmd.add_option("--seed", options.seed, "Scene seed")->capture_default_str();
    cmd.add_option("--detail", options.detail, "test, low, medium, high or ultra")
        ->capture_default_str();
}

void add_frame_flags(CLI::App& cmd, RenderOptions& options) {
    cmd.add_option("--frames", options.frames, "Frames to measure")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd.add_option("--warmup", options.warmup, "Frames rendered before measuring")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd.add_option("--shadow-resolution", options.shadow_resolution, "Shadow map size in texels")
        ->check(CLI::Range(256, 16384))
        ->capture_default_str();
}

void add_output_flags(CLI::App& cmd, RenderOptions& options) {
    cmd.add_option("--out", options.out, "Output directory")->required();
    cmd.add_flag("--json", options.json, "Print the statistics as JSON on stdout");
    cmd.add_flag("--depth-profile", options.depth_profile,
                 "With --json: add \"depth_profile\", the fractions of the left eye's triangles "
                 "and pixels nearer than each fink2019 mono plane (docs/scenes.md)");
}

// The passes every mode may add, and the head's motion over the frames.
void add_rendering_flags(CLI::App& cmd, RenderOptions& options) {
    cmd.add_flag("--depth-prepass", options.depth_prepass,
                 "A depth-only pass before every forward pass (each visible pixel shaded once; "
                 "off by default: on llvmpipe it costs more than it saves, docs/benchmarks.md)");
    cmd.add_option("--anti-aliasing", options.anti_aliasing,
                   "none, taa (every mode; give it frames to converge, e.g. --warmup 16) or "
                   "msaa2|msaa4|msaa8 (stereo only)")
        ->capture_default_str();
    cmd.add_option("--ssao", options.ssao,
                   "Ambient occlusion: off, per-eye (HBAO+ in each eye) or stereo (papers/002); "
                   "writes ao_left.png, ao_right.png, ao_inconsistency.png and E's mean")
        ->capture_default_str();
    add_lod_flags(cmd, options.lod, false);
    cmd.add_option("--pose-path", options.pose_path,
                   "Head motion over the frames: static, sway, turn or walk")
        ->capture_default_str();
    cmd.add_option("--fps", options.fps, "Frame rate of the pose path (frame n at n / fps s)")
        ->capture_default_str();
}

}  // namespace

void add_render_command(CLI::App& root, const GlobalOptions& global) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = root.add_subcommand("render", "Render one scene in one mode to PNG files");
    cmd->add_option("--scene", options->scene, "beams, landscape or spheres")
        ->capture_default_str();
    add_mode_flags(*cmd, *options);
    add_viewer_flags(*cmd, *options);
    add_frame_flags(*cmd, *options);
    add_output_flags(*cmd, *options);
    add_rendering_flags(*cmd, *options);
    cmd->add_flag("--compare-stereo", options->compare_stereo,
                  "Hybrid and single-pass modes: also render two-pass stereo and write SSIM, the "
                  "largest channel difference and local-SSIM heat maps");
    cmd->callback([options, &global] { run_render(*options, global); });
}

}  // namespace monoplane::app
