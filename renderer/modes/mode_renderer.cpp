#include "renderer/modes/mode_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "common/programming_error.h"
#include "common/result.h"
#include "renderer/modes/frustum_culling.h"
#include "renderer/modes/mode_renderer_internals.h"
#include "renderer/passes/culling/cull_constants.h"
#include "renderer/passes/pass_units.h"
#include "rig/temporal_jitter.h"

namespace monoplane::modes {
namespace {

// The region whose shadows are computed: the scene, clipped to a box around the viewer, snapped
// to a coarse grid so small head motion does not invalidate the shadow map.
scenes::Aabb shadow_region(const scenes::Scene& scene, const glm::dvec3& head, float radius) {
    const double snap = radius / 4.0;
    const glm::dvec3 centre = glm::round(head / snap) * snap;
    scenes::Aabb region = scene.bounds;
    region.min = glm::max(region.min, glm::vec3(centre - glm::dvec3(radius)));
    region.max = glm::min(region.max, glm::vec3(centre + glm::dvec3(radius)));
    region.max = glm::max(region.max, region.min);
    return region;
}

glm::dvec3 to_world(const rig::Pose& head, const glm::dvec3& in_head) {
    return glm::dvec3(rig::to_matrix(head) * glm::dvec4(in_head, 1.0));
}

}  // namespace

vk::SampleCountFlagBits msaa_samples(plan::AntiAliasing aa) {
    switch (aa) {
        case plan::AntiAliasing::kMsaa2:
            return vk::SampleCountFlagBits::e2;
        case plan::AntiAliasing::kMsaa4:
            return vk::SampleCountFlagBits::e4;
        case plan::AntiAliasing::kMsaa8:
            return vk::SampleCountFlagBits::e8;
        default:
            return vk::SampleCountFlagBits::e1;
    }
}

namespace {

// Refuses shared scene resources made for other shadow parameters than the renderer's.
std::shared_ptr<SceneResources> checked(std::shared_ptr<SceneResources> resources,
                                        const RendererOptions& options) {
    if (!(resources->shadow_params() == options.shadow)) {
        throw UserError(
            "a renderer's shadow parameters differ from those its scene's shared "
            "resources were made with: make one SceneResources per shadow setting");
    }
    return resources;
}

// Refuses option combinations the renderer does not implement, with the reason.
const RendererOptions& checked(const vk_core::Context& ctx, plan::Mode mode,
                               const RendererOptions& options) {
    const vk::SampleCountFlagBits samples = msaa_samples(options.anti_aliasing);
    if (samples != vk::SampleCountFlagBits::e1) {
        if (mode != plan::Mode::kStereo) {
            throw UserError("MSAA (" + plan::anti_aliasing_name(options.anti_aliasing) +
                            ") is available in stereo mode only: in the hybrid modes C's image "
                            "is mapped into the eyes after the resolve would have happened "
                            "(papers/000 Sect. 4.5; docs/hybrid.md). Use --anti-aliasing taa.");
        }
        const vk::PhysicalDeviceLimits limits = ctx.physical_device().getProperties().limits;
        const vk::SampleCountFlags supported =
            limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
        if (!(supported & samples)) {
            throw UserError(plan::anti_aliasing_name(options.anti_aliasing) +
                            " is not supported by " + ctx.device_info().name);
        }
    }
    if (options.read_back_ao && !options.ssao) {
        throw UserError("reading back ambient occlusion needs SSAO switched on");
    }
    if (options.auto_mono_plane && mode == plan::Mode::kStereo) {
        throw UserError("--mono-plane auto needs a hybrid mode: stereo has no mono plane");
    }
    return options;
}

// The recorders of every unit a frame of this renderer may run (an executed pass of one of
// `plans`), made with the renderer for all the passes it may record, so that their pipelines are
// never compiled mid-run: a session's frames compile nothing, and its frame log counts what they
// do. A debug view's unit is left until a frame shows it (record_unit makes a recorder on its
// first pass).
void make_unit_recorders(const vk_core::Context& ctx, const passes::UnitScene& scene,
                         const passes::UnitSettings& settings,
                         const std::vector<plan::FramePlan>& plans,
                         const std::vector<plan::PassUnitDeclaration>& units,
                         std::map<std::string, std::unique_ptr<passes::UnitRecorder>>& recorders) {
    std::map<std::string, passes::UnitPasses> unit_passes;
    for (const plan::FramePlan& plan : plans) {
        for (const plan::PlannedPass* pass : plan.executed()) {
            const auto unit = std::find_if(
                units.begin(), units.end(),
                [&](const plan::PassUnitDeclaration& u) { return u.name == pass->unit; });
            if (unit == units.end() || unit->debug_view) continue;
            unit_passes[pass->unit].passes.emplace_back(&plan, pass);
        }
    }
    for (const auto& [unit, passes] : unit_passes) {
        recorders[unit] = passes::make_unit_recorder(unit, ctx, scene, passes, settings);
    }
}

}  // namespace

ModeRenderer::ModeRenderer(const vk_core::Context& ctx, const scenes::Scene& scene, plan::Mode mode,
                           vk::Extent2D eye_extent, const RendererOptions& options,
                           double nearest_mono_plane)
    : ModeRenderer(ctx, std::make_shared<SceneResources>(ctx, scene, options.shadow), mode,
                   eye_extent, options, nearest_mono_plane) {}

ModeRenderer::ModeRenderer(const vk_core::Context& ctx, std::shared_ptr<SceneResources> resources,
                           plan::Mode mode, vk::Extent2D eye_extent, const RendererOptions& options,
                           double nearest_mono_plane)
    : ctx_(ctx),
      resources_(checked(std::move(resources), options)),
      scene_(resources_->scene()),
      mode_(mode),
      eye_extent_(eye_extent),
      options_(checked(ctx, mode, options)),
      nearest_mono_plane_(nearest_mono_plane),
      blended_chunks_(resources_->alpha_classes()[MONOPLANE_CLASS_BLENDED] > 0),
      culling_(ctx, scene_, resources_->chunk_table(), resources_->level_table()),
      pyramid_(ctx, eye_extent),
      units_(passes::pass_unit_declarations()),
      profiler_(ctx),
      ring_(ctx) {
    const bool taa = options.anti_aliasing == plan::AntiAliasing::kTaa;
    const ViewFeatures eye_features{taa, taa, msaa_samples(options.anti_aliasing)};
    if (options.stereo_pass != plan::StereoPass::kTwoPasses) {
        eye_layers_ = std::make_unique<ForwardImages>(ctx, eye_extent, eye_features, 2);
        eye_pair_constants_.emplace(ctx, 2 * sizeof(passes::ViewConstants),
                                    vk::BufferUsageFlagBits::eUniformBuffer,
                                    vk_core::MemoryUse::kDeviceLocal);
    }
    // The plans every frame of this renderer may run: what its transient images are placed by.
    possible_plans_ = possible_plans(
        plan_options_of(mode, options, blended_chunks_, options.auto_mono_plane.has_value()),
        plan::PlanDevice{ctx.capabilities().conditional_rendering,
                         ctx.capabilities().independent_blend},
        units_);
    unit_scene_ = resources_->unit_scene();
    make_unit_recorders(ctx, unit_scene_, unit_settings(), possible_plans_, units_,
                        unit_recorders_);
    if (!eye_layers_) {
        eye_memory_ = View::eye_memory(ctx, eye_extent, eye_features, possible_plans_);
    }
    for (std::uint32_t e = 0; e < 2; ++e) {
        auto& eye = eyes_[e];
        // Two passes draw into images of each eye's own: lavapipe (Mesa 22.3) does not resolve
        // MSAA into a layer other than 0 of a layered image.
        eye = eye_layers_ ? std::make_unique<View>(ctx, *eye_layers_, e, eye_features)
                          : std::make_unique<View>(ctx, eye_extent, eye_features, eye_memory_.get(),
                                                   plan::eye_view(static_cast<int>(e)));
        if (options.ssao) eye->ssao = std::make_unique<passes::SsaoImages>(ctx, eye_extent);
    }
    if (options.auto_mono_plane) {
        auto_mono_plane_ = std::make_unique<AutoMonoPlane>(ctx, scene_, *options.auto_mono_plane);
    }
}

void ModeRenderer::ensure_pyramid() {
    if (pyramid_.fits(mono_->extent)) return;
    // The old pyramid and the sets naming it may be in use by a frame in flight.
    drain_frames();
    // The blocks stay: they are the eyes' size.
    executor_.forget(pyramid_.pyramid().range());
    pyramid_.resize(mono_->extent);
}

ModeRenderer::~ModeRenderer() {
    // Nothing a submitted frame uses may go before it has completed.
    try {
        ring_.wait_all();
    } catch (const vk::SystemError&) {
        // The device is lost: nothing in flight will complete, and nothing waits for it.
    }
}

void ModeRenderer::ensure_mono_view(int width, int height) {
    const vk::Extent2D needed(static_cast<std::uint32_t>(width),
                              static_cast<std::uint32_t>(height));
    if (mono_ && mono_->extent.width >= needed.width && mono_->extent.height >= needed.height) {
        return;
    }
    // Allocated once for the nearest m in normal use (eq. 8); grown only if a frame needs more,
    // after the frames in flight that use the old images.
    drain_frames();
    if (mono_) forget_images(*mono_);
    mono_.reset();
    const bool taa = options_.anti_aliasing == plan::AntiAliasing::kTaa;
    mono_ = std::make_unique<MonoView>(ctx_, needed, ViewFeatures{taa, false}, possible_plans_);
    if (options_.ssao) mono_->ssao = std::make_unique<passes::SsaoImages>(ctx_, needed);
}

void ModeRenderer::update_view(View& view, const glm::dmat4& view_proj,
                               const glm::dmat4& unjittered, const glm::dvec3& position,
                               const FrameInputs& inputs, const glm::dvec3& mono_position,
                               double blend_band, const glm::dmat4& light_view_proj,
                               double hidden_depth_threshold) {
    const scenes::Lighting& lighting = scene_.lighting;
    const rig::Pose& head = inputs.views.head;
    passes::ViewConstants c{};
    c.view_proj = glm::mat4(view_proj);
    c.inv_view_proj = glm::mat4(glm::inverse(view_proj));
    c.light_view_proj = glm::mat4(light_view_proj);
    c.camera_position = glm::vec4(glm::vec3(position), 1.0f);
    c.sun_direction = glm::vec4(glm::normalize(lighting.sun_direction), 0.0f);
    c.sun_radiance = glm::vec4(lighting.sun_radiance, 0.0f);
    c.sky_zenith = glm::vec4(lighting.sky_zenith, 0.0f);
    c.sky_horizon = glm::vec4(lighting.sky_horizon, 0.0f);
    c.ground_albedo = glm::vec4(lighting.ground_albedo, 0.0f);
    c.shadow_params = glm::vec4(resources_->shadow().texel_size(), 0.0f, 0.0f, 0.0f);
    c.head_position = glm::vec4(glm::vec3(head.position), 1.0f);
    c.head_forward =
        glm::vec4(glm::vec3(glm::normalize(head.orientation * glm::dvec3(0.0, 0.0, -1.0))), 0.0f);
    c.mono_camera_position = glm::vec4(glm::vec3(mono_position), 1.0f);
    c.view_blend = glm::vec4(static_cast<float>(inputs.mono_plane), static_cast<float>(blend_band),
                             static_cast<float>(hidden_depth_threshold), 0.0f);
    c.velocity_view_proj = glm::mat4(unjittered);
    // A restarted history has no previous frame: zero velocity.
    const bool continues = history_valid_ && view.has_previous;
    c.prev_view_proj = glm::mat4(continues ? view.previous_unjittered : unjittered);
    uploads_.stage(view.constants, &c, sizeof(c));
    view.written_constants = c;
    view.previous_unjittered = unjittered;
    view.has_previous = true;
    view.geometry = {view_proj, position};
}

void ModeRenderer::decide_routing(const FrameInputs& inputs, passes::CullFrame& cull) const {
    if (!rig_ || rig_->mono_skipped) return;  // stereo draws everything in the eyes
    const scenes::ChunkRouting& routing = scene_.routing;
    const glm::dvec3 head = inputs.views.head.position;
    const double m = inputs.mono_plane;
    // Force-mono geometry lies outside a vertical cylinder of radius R: from an eye it is at
    // least R - |eye_xz| away, and at most the frustum's widest angle theta off the view axis,
    // so its depth in front of the eyes is at least (R - |eye_xz|) cos(theta). Honoured only when
    // that is beyond m: C, starting at m - eps, then draws every pixel of it the eyes would have.
    if (routing.force_mono_outside_radius > 0.0f) {
        // Measured from the head's forward axis, so a canted eye's turn counts: the widest
        // corner ray of either eye, turned into the head frame.
        double cos_widest = 1.0;
        for (int e : {rig::kLeft, rig::kRight}) {
            const rig::Tangents& t = rig_->inputs.eyes[e];
            const glm::dmat3 turn = rig::eye_rotation(rig_->inputs, e);
            for (double tan_x : {t.left, t.right}) {
                for (double tan_y : {t.down, t.up}) {
                    const glm::dvec3 ray = turn * glm::dvec3(tan_x, tan_y, -1.0);
                    cos_widest = std::min(cos_widest, -ray.z / glm::length(ray));
                }
            }
        }
        const double clearance = routing.force_mono_outside_radius -
                                 glm::length(glm::dvec2(head.x, head.z)) - 0.5 * inputs.views.ipd;
        cull.honour_force_mono = clearance * cos_widest >= m;
    }
    // Force-stereo geometry lies inside a sphere: at most |head - centre| + r from the head, so
    // nearer than C's near plane m - eps when that bound is.
    if (routing.force_stereo_inside_radius > 0.0f) {
        const double reach = glm::length(head - glm::dvec3(routing.force_stereo_centre)) +
                             routing.force_stereo_inside_radius + 0.5 * inputs.views.ipd;
        cull.honour_force_stereo = reach <= m - rig_->overlap;
    }
}

ModeRenderer::FrameState ModeRenderer::prepare_frame(const FrameInputs& inputs) {
    FrameState frame;
    frame.inputs = &inputs;
    const StereoViewInputs& views = inputs.views;

    // TAA: this frame's jitter, and whether the history continues (consecutive frames of the
    // same configuration; a study switching between renderers restarts it).
    frame.taa = options_.anti_aliasing == plan::AntiAliasing::kTaa;
    const std::uint64_t frame_index = inputs.frame_index.value_or(next_frame_index_);
    history_valid_ = frame.taa && frame_index == next_frame_index_ && frame_index > 0 &&
                     history_continues_at(inputs.mono_plane);
    next_frame_index_ = frame_index + 1;
    history_mono_plane_ = inputs.mono_plane;
    frame.jitter_px = frame.taa ? rig::halton_jitter(frame_index) : glm::dvec2(0.0);
    frame.eye_jitter =
        rig::jitter_matrix(frame.jitter_px, glm::dvec2(eye_extent_.width, eye_extent_.height));

    const scenes::Aabb region =
        shadow_region(scene_, views.head.position, options_.shadow.region_radius_m);
    frame.light_view_proj =
        passes::fit_light_view_proj(glm::dvec3(scene_.lighting.sun_direction), region);
    frame.shadow_needed = resources_->shadow_needed(frame.light_view_proj);
    frame.predicated = ctx_.capabilities().conditional_rendering;

    build_frame_rig(inputs, frame);
    resolve_variant(inputs, frame);
    update_plan(inputs, frame);
    update_frame_views(inputs, frame);
    return frame;
}

const FrameInputs& ModeRenderer::resolve_mono_plane(const FrameInputs& inputs) {
    if (!auto_mono_plane_) return inputs;
    auto_inputs_ = inputs;
    auto_inputs_.mono_plane =
        auto_mono_plane_->choose(inputs.views, eye_extent_, inputs.nearest_auto_plane).mono_plane;
    return auto_inputs_;
}

bool ModeRenderer::history_continues_at(double mono_plane) const {
    // A fixed m that changes is another configuration (a study switching alternatives). The
    // chooser's m moves by at most a sub-pixel step per frame, which the history absorbs as it
    // absorbs head motion; only a jump the error budget forced restarts it.
    if (auto_mono_plane_) return !auto_mono_plane_->last().jumped;
    return history_mono_plane_ == mono_plane;
}

void ModeRenderer::resolve_variant(const FrameInputs& inputs, FrameState& frame) {
    frame.mono_culling = inputs.mono_culling;
    if (inputs.mono_culling != plan::MonoCulling::kAuto) return;
    // Only monoplane's hybrid drawing C has variants to tell apart.
    if (mode_ != plan::Mode::kHybrid || !frame.use_mono) {
        frame.mono_culling = plan::MonoCulling::kNoOpt;
        return;
    }
    // Another m changes what the pyramid saves: measure again. Under --mono-plane auto m moves a
    // little every frame; only a move beyond the chooser's hysteresis is another m.
    const double tolerance = auto_mono_plane_ ? options_.auto_mono_plane->hysteresis : 0.0;
    if (!(std::abs(std::log(inputs.mono_plane / variant_mono_plane_)) <= tolerance)) {
        variant_chooser_.reset();
        variant_mono_plane_ = inputs.mono_plane;
    }
    frame.mono_culling = variant_chooser_.next();
    frame.measuring_variant = true;
}

void ModeRenderer::build_frame_rig(const FrameInputs& inputs, FrameState& frame) {
    // The rig (hybrid modes). m >= f leaves C out and hybrid records the stereo pass list.
    rig_.reset();
    if (mode_ == plan::Mode::kStereo) return;
    const StereoViewInputs& views = inputs.views;
    rig::RigInputs rig_inputs = rig_inputs_for(views, static_cast<int>(eye_extent_.width),
                                               static_cast<int>(eye_extent_.height));
    rig_inputs.mono_plane = inputs.mono_plane;
    rig_inputs.overlap_k = inputs.overlap_k;
    rig_inputs.grazing_angle = inputs.grazing_angle;
    if (nearest_mono_plane_ > 0.0 && nearest_mono_plane_ <= inputs.mono_plane) {
        rig_inputs.nearest_mono_plane = nearest_mono_plane_;
    }
    rig_ = rig::build_rig(rig_inputs).value_or_throw();
    frame.use_mono = !rig_->mono_skipped;
    if (frame.use_mono && mode_ == plan::Mode::kHybridFarfield) {
        if (rig::is_canted(rig_inputs)) {
            // papers/003's copy moves C's pixels by one constant offset per eye, which only eyes
            // parallel to C allow; a canted eye needs the projective mapping of `hybrid`.
            throw UserError(
                "hybrid-farfield cannot render canted displays: its constant pixel-offset copy "
                "needs eyes parallel to the far-field camera; use --mode hybrid, whose "
                "plane-induced mapping handles canted eyes");
        }
        frame.farfield =
            build_farfield_rig(rig_inputs.eyes, rig_inputs.eye_width, rig_inputs.eye_height,
                               views.ipd, inputs.mono_plane, views.far);
    }
}

void ModeRenderer::update_frame_views(const FrameInputs& inputs, FrameState& frame) {
    const StereoViewInputs& views = inputs.views;
    const bool use_mono = frame.use_mono;
    const auto& farfield = frame.farfield;
    // C's work saved by the merged depth pyramid: the plan decides.
    const bool depth_tested = last_plan_.runs(plan::PassKind::kDepthPyramid);
    passes::CullFrame cull;
    // Hybrid: C draws the blended chunks wholly beyond m, the eyes the others.
    cull.split_blended = use_mono;
    // Instanced stereo draws each chunk of the both-eyes list once per eye, as two instances.
    cull.both_eyes_instances = options_.stereo_pass == plan::StereoPass::kInstanced ? 2u : 1u;
    const glm::dvec3 mono_in_head = farfield || !use_mono ? glm::dvec3(0.0) : rig_->mono_position;
    const glm::dvec3 mono_position = to_world(views.head, mono_in_head);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const int e = static_cast<int>(eye);
        const glm::dvec3 offset = eye_offset(eye, views.ipd);
        // eye_view includes the eye's cant, as the rig's eye_from_head does.
        const glm::dmat4 view_proj =
            use_mono ? rig_->eye_projection[e] * eye_view(views, eye) : eye_view_proj(views, eye);
        const double band = use_mono && !farfield ? inputs.view_blend_band : 0.0;
        update_view(*eyes_[e], frame.eye_jitter * view_proj, view_proj,
                    to_world(views.head, offset), inputs, mono_position, band,
                    frame.light_view_proj);
        cull.view_proj[e] = view_proj;  // a sub-pixel jitter changes no chunk's visibility
        cull.lod_views[e] = plan::lod_view_of(view_proj, to_world(views.head, offset),
                                              glm::dvec2(eye_extent_.width, eye_extent_.height));
    }
    if (options_.lod.enabled) cull.lod_error_px = options_.lod.error_px;
    if (use_mono) {
        glm::dmat4 mono_view_proj;
        if (farfield) {
            ensure_mono_view(farfield->width, farfield->height);
            mono_->area = mono_->extent;
            mono_view_proj = farfield->projection * rig::view_matrix(views.head, mono_in_head);
        } else {
            ensure_mono_view(rig_->mono.allocated_width, rig_->mono.allocated_height);
            mono_->area = vk::Extent2D(static_cast<std::uint32_t>(rig_->mono.viewport_width),
                                       static_cast<std::uint32_t>(rig_->mono.viewport_height));
            mono_view_proj = rig_->mono_projection * rig::view_matrix(views.head, mono_in_head);
        }
        // The eyes' reversed-Z depth of m - eps (Sect. 4.4: z_m): a pyramid value above it
        // means every eye pixel reading that part of C shows nearer content. A canted eye's
        // depth of that plane varies over its field: the largest is the safe bound.
        const double threshold =
            rig::nearest_eye_depth_of_plane(*rig_, inputs.mono_plane - rig_->overlap);
        // The same jitter in C's pixels (Sect. 4.5).
        frame.mono_jitter =
            rig::jitter_matrix(frame.jitter_px, glm::dvec2(mono_->area.width, mono_->area.height));
        update_view(*mono_, frame.mono_jitter * mono_view_proj, mono_view_proj, mono_position,
                    inputs, mono_position, 0.0, frame.light_view_proj, threshold);
        cull.view_proj[MONOPLANE_CULL_MONO] = mono_view_proj;
        cull.mono_viewport = glm::dvec2(mono_->area.width, mono_->area.height);
        // C's own pixels (eq. 8): its viewport over its field.
        cull.lod_views[MONOPLANE_CULL_MONO] =
            plan::lod_view_of(mono_view_proj, mono_position, cull.mono_viewport);
        cull.hidden_depth_threshold = threshold;
        decide_routing(inputs, cull);
        if (depth_tested) {
            ensure_pyramid();
            cull.pyramid_mips = pyramid_.mips();
        }
    }
    // Nearest chunks first, blended ones farthest first (one order for every view: the eyes and C
    // look from the head), sorted and uploaded again only when the head has moved.
    if (draw_order_viewer_ != views.head.position) {
        culling_.set_draw_order(draw_order(scene_, views.head.position), uploads_);
        draw_order_viewer_ = views.head.position;
    }
    culling_.set_frame(cull, uploads_);
    if (eye_pair_constants_) {
        // view_block.glsl's views[2]: left, then right (std140 arrays of this struct are packed).
        const std::array pair = {eyes_[0]->written_constants, eyes_[1]->written_constants};
        uploads_.stage(*eye_pair_constants_, pair.data(), sizeof(pair));
    }
}

void ModeRenderer::update_plan(const FrameInputs& inputs, const FrameState& frame) {
    const plan::PlanOptions options =
        plan_options_of(mode_, options_, blended_chunks_, auto_mono_plane_ != nullptr);
    plan::PlanFrame planned;
    planned.mono_skipped = !frame.use_mono;
    planned.mono_culling = frame.mono_culling;
    planned.debug = inputs.debug;
    planned.unit_debug_view = inputs.unit_debug_view;
    planned.shadow_needed = frame.shadow_needed;
    const plan::PlanDevice device{frame.predicated, ctx_.capabilities().independent_blend};
    // Consecutive frames of one configuration share their plan: make it only when that changes.
    const PlanInputs key{options, planned, device};
    if (last_plan_inputs_ == key) return;
    last_plan_ = plan::plan_frame(options, planned, device, units_);
    last_plan_inputs_ = key;
    executor_.plan_changed();
}

void ModeRenderer::submit_frame(
    const FrameInputs& inputs,
    const std::function<void(const vk::raii::CommandBuffer&)>& record_after) {
    // The slot's previous frame first: its results, then its command buffer, are reused.
    complete_frame(ring_.next_slot());
    const auto cpu_start = std::chrono::steady_clock::now();
    FrameState frame = prepare_frame(resolve_mono_plane(inputs));
    frame.slot = ring_.begin();
    frame.unit_values = unit_frame_values(frame);
    const vk::raii::CommandBuffer& cmd = ring_.commands(frame.slot);
    uploads_.record(cmd);
    profiler_.begin_frame(cmd, frame.slot);
    executor_.begin_frame(last_plan_, bind_resources());
    for (std::size_t p = 0; p < last_plan_.passes.size(); ++p) {
        if (!last_plan_.passes[p].skipped) record_pass(cmd, p, frame);
    }
    executor_.end_frame(cmd);
    const double record_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpu_start)
            .count();
    if (record_after) record_after(cmd);
    ring_.submit(frame.slot);
    PendingFrame pending{record_ms, frame.measuring_variant};
    pending.depth_histogram = last_plan_.runs(plan::PassKind::kDepthHistogram);
    if (mode_ != plan::Mode::kStereo) pending.mono_plane = frame.inputs->mono_plane;
    if (auto_mono_plane_) pending.mono_plane_reason = auto_mono_plane_->last().reason;
    pending_[frame.slot] = std::move(pending);
    mono_rendered_ = frame.use_mono && options_.read_back;
    if (frame.taa) history_parity_ = 1 - history_parity_;
    last_variant_ = frame.mono_culling;
    last_slot_ = frame.slot;
    // --variant auto times each frame before it picks the next frame's variant.
    if (frame.measuring_variant) drain_frames();
}

void ModeRenderer::complete_frame(std::uint32_t slot) {
    if (!ring_.in_flight(slot)) return;
    ring_.wait(slot);
    const PendingFrame pending = *pending_[slot];
    pending_[slot].reset();
    profile::FrameStats stats = collect_frame(slot, pending.record_ms);
    stats.mono_plane = pending.mono_plane;
    stats.mono_plane_reason = pending.mono_plane_reason;
    if (pending.measuring_variant) variant_chooser_.record(stats.gpu_frame_ms);
    if (auto_mono_plane_) auto_mono_plane_->complete(slot, pending.depth_histogram, stats);
    completed_.push_back(std::move(stats));
}

void ModeRenderer::drain_frames() {
    // Oldest first: the ring's next slot holds the oldest frame of a full ring.
    for (std::uint32_t i = 0; i < vk_core::FrameRing::kFramesInFlight; ++i) {
        complete_frame((ring_.next_slot() + i) % vk_core::FrameRing::kFramesInFlight);
    }
}

std::vector<profile::FrameStats> ModeRenderer::take_completed() {
    std::vector<profile::FrameStats> taken = std::move(completed_);
    completed_.clear();
    return taken;
}

std::vector<profile::FrameStats> ModeRenderer::finish_frames() {
    drain_frames();
    read_back_last_frame();
    return take_completed();
}

profile::FrameStats ModeRenderer::render_frame(
    const FrameInputs& inputs,
    const std::function<void(const vk::raii::CommandBuffer&)>& record_after) {
    submit_frame(inputs, record_after);
    return finish_frames().back();
}

plan::PlanOptions plan_options_of(plan::Mode mode, const RendererOptions& options,
                                  bool blended_chunks, bool depth_histogram) {
    plan::PlanOptions plan;
    plan.mode = mode;
    plan.stereo_pass = options.stereo_pass;
    plan.anti_aliasing = options.anti_aliasing;
    plan.ssao = options.ssao.has_value();
    plan.ssao_stereo = options.ssao == passes::SsaoVariant::kStereoConsistent;
    plan.depth_prepass = options.depth_prepass;
    plan.read_back = options.read_back;
    plan.read_back_depth = options.read_back_depth;
    plan.read_back_ao = options.read_back_ao;
    plan.read_back_draw_lists = options.read_back_draw_lists;
    plan.depth_histogram = depth_histogram;
    plan.separate_tonemap = options.separate_tonemap;
    plan.blended = blended_chunks;
    return plan;
}

}  // namespace monoplane::modes
