#include "app/commands/study_headset.h"

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include <glm/gtc/quaternion.hpp>

#include "app/commands/headset_frame_log.h"
#include "app/commands/image_quality_options.h"
#include "app/commands/validation_report.h"
#include "app/headset/eye_compositor.h"
#include "app/headset/frame_times.h"
#include "app/headset/openxr_headset.h"
#include "app/headset/overlay_text.h"
#include "app/window/experimenter_window.h"
#include "common/result.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/modes/scene_resources.h"
#include "renderer/vk/frame_ring.h"
#include "renderer/vk/memory.h"
#include "scenes/generate.h"
#include "study/live_session.h"
#include "study/observer_input.h"

#ifndef MONOPLANE_SIMXR_MANIFEST
#error "MONOPLANE_SIMXR_MANIFEST must name the simulated runtime's manifest"
#endif

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;
using study::LiveInput;
using study::ScreenKind;

// Where the overlays sit, as directions of view (tangents, +y up): the label low and small, in
// the lower periphery; the questionnaire straight ahead.
constexpr headset::OverlayPlacement kLabelPlacement{0.0, -0.55, 0.05};
constexpr headset::OverlayPlacement kPanelPlacement{0.0, 0.05, 0.45};

// The participant's seat: the head pose of the first tracked frame, turned about the vertical
// only, is where the scene's viewpoint is. LOCAL space puts its origin near the starting head on
// most runtimes but not all (some at floor level, simxr at 1.6 m); recentring on the first frame
// makes every runtime start the participant exactly at the viewpoint, looking along it, while
// later head motion (and the head's own pitch and roll) is kept.
class SeatAnchor {
  public:
    // The head pose relative to the anchor, setting the anchor from the first call.
    rig::Pose relative(const rig::Pose& head) {
        if (!set_) {
            const glm::dvec3 forward = head.orientation * glm::dvec3(0.0, 0.0, -1.0);
            const double yaw = std::atan2(-forward.x, -forward.z);
            inverse_yaw_ = glm::angleAxis(-yaw, glm::dvec3(0.0, 1.0, 0.0));
            origin_ = head.position;
            set_ = true;
        }
        rig::Pose pose;
        pose.position = inverse_yaw_ * (head.position - origin_);
        pose.orientation = inverse_yaw_ * head.orientation;
        return pose;
    }

  private:
    bool set_ = false;
    glm::dvec3 origin_{0.0};
    glm::dquat inverse_yaw_{1.0, 0.0, 0.0, 0.0};
};

// The head from the two located eyes: their midpoint and common orientation. The rig assumes
// parallel eyes (DESIGN.md section 4): canted views are refused.
rig::Pose located_head(const headset::HeadsetFrame& frame) {
    const rig::Pose& l = frame.views[0].pose;
    const rig::Pose& r = frame.views[1].pose;
    const double cant =
        2.0 * std::acos(std::min(1.0, std::abs(glm::dot(l.orientation, r.orientation))));
    if (cant > 0.2 * 3.14159265358979 / 180.0) {
        throw UserError("the headset's views are canted by " +
                        std::to_string(cant * 180.0 / 3.14159265358979) +
                        " degrees; monoplane's rig supports parallel eye views only");
    }
    rig::Pose head;
    head.position = 0.5 * (l.position + r.position);
    head.orientation = l.orientation;
    return head;
}

// The renderer's viewer: the head relative to the seat, placed at the scene's viewpoint, with
// the runtime's eye distance and calibrated frusta.
modes::StereoViewInputs view_inputs(const headset::HeadsetFrame& frame, const rig::Pose& head,
                                    const rig::Pose& seat, const study::Protocol& protocol) {
    modes::StereoViewInputs inputs;
    inputs.head.position = seat.position + seat.orientation * head.position;
    inputs.head.orientation = seat.orientation * head.orientation;
    inputs.ipd = glm::length(frame.views[1].pose.position - frame.views[0].pose.position);
    inputs.left = frame.views[0].tangents;
    inputs.right = frame.views[1].tangents;
    inputs.near = protocol.near;
    inputs.far = protocol.far;
    return inputs;
}

// The renderer's mode and stereo pass for a protocol's mode name (stereo-multiview and stereo-gs
// are stereo drawn in one pass).
modes::RenderModeChoice renderer_mode(study::RenderMode mode) {
    const auto parsed = modes::parse_render_mode(std::string(study::render_mode_name(mode)));
    if (!parsed) {
        throw UserError("render mode " + std::string(study::render_mode_name(mode)) +
                        " is not implemented; use stereo, stereo-multiview, stereo-gs, hybrid or "
                        "hybrid-farfield");
    }
    return *parsed;
}

// The scenes and a renderer per (scene, mode) of the protocol, made before the first trial so
// that no trial waits for one.
class StudyRenderers {
  public:
    StudyRenderers(const vk_core::Context& ctx, const study::Protocol& protocol,
                   vk::Extent2D extent, const study::RenderSettings& render) {
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
        std::cerr << "rendering with anti-aliasing " << render.anti_aliasing << ", SSAO "
                  << render.ssao << ", detail " << render.detail << "\n";
        const std::uint64_t bytes_before = vk_core::live_device_bytes();
        std::uint64_t scene_bytes = 0;
        for (const std::string& name : protocol.scenes) {
            std::cerr << "preparing " << name << "\n";
            auto scene = std::make_unique<scenes::Scene>(
                scenes::generate_scene(*scenes::parse_scene_id(name), *detail));
            // Geometry, chunk table and shadow map once per scene, for all its alternatives.
            const std::uint64_t before_scene = vk_core::live_device_bytes();
            auto resources = std::make_shared<modes::SceneResources>(ctx, *scene, options.shadow);
            scene_bytes += vk_core::live_device_bytes() - before_scene;
            for (study::RenderMode mode : protocol.alternatives) {
                const auto key = std::make_pair(name, mode);
                if (renderers_.count(key)) continue;
                const modes::RenderModeChoice choice = renderer_mode(mode);
                modes::RendererOptions mode_options = options;
                mode_options.stereo_pass = choice.stereo_pass;
                renderers_[key] = std::make_unique<modes::ModeRenderer>(
                    ctx, resources, choice.mode, extent, mode_options, nearest);
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
    modes::ModeRenderer& renderer(const std::string& scene, study::RenderMode mode) {
        return *renderers_.at({scene, mode});
    }
    // Every renderer, e.g. to finish their frames in flight at the end of a session.
    template <class F>
    void for_each(F f) {
        for (auto& [key, renderer] : renderers_) f(*renderer);
    }
    const rig::Pose& seat(const std::string& scene) const {
        const scenes::Viewpoint* v = scenes_.at(scene)->find_viewpoint("default");
        return v->head;
    }

  private:
    std::map<std::string, std::unique_ptr<scenes::Scene>> scenes_;  // outlive the renderers
    std::map<std::pair<std::string, study::RenderMode>, std::unique_ptr<modes::ModeRenderer>>
        renderers_;
};

window::Phase window_phase(const study::LiveScreen& screen) {
    switch (screen.kind) {
        case ScreenKind::Neutral:
            return window::Phase::Neutral;
        case ScreenKind::Trial:
            return screen.paused ? window::Phase::Paused : window::Phase::Trial;
        case ScreenKind::Questionnaire:
            return window::Phase::Questionnaire;
        case ScreenKind::Finished:
            return window::Phase::Finished;
        case ScreenKind::Aborted:
            return window::Phase::Aborted;
    }
    return window::Phase::Starting;
}

std::vector<std::string> questionnaire_lines(const study::Protocol& protocol, int question,
                                             int selection) {
    const study::Questionnaire& q = protocol.questionnaire;
    std::string scale;
    for (int v = 1; v <= q.scale_points; ++v) {
        scale += v == selection ? "[" + std::to_string(v) + "] " : " " + std::to_string(v) + "  ";
    }
    return {"Question " + std::to_string(question + 1) + " of " + std::to_string(q.items.size()),
            q.items[static_cast<std::size_t>(question)],
            "",
            "1 = disagree ... " + std::to_string(q.scale_points) + " = agree",
            scale,
            "",
            "trigger: next value    confirm button: choose"};
}

bool has_display() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

}  // namespace

void select_simulated_runtime(const HeadsetStudyOptions& options) {
    // The simulated runtime, whatever runtime the machine has active: a dry run must never
    // reach a real headset.
    setenv("XR_RUNTIME_JSON", MONOPLANE_SIMXR_MANIFEST, 1);
    if (!options.sim_script.empty()) {
        if (!fs::exists(options.sim_script)) {
            throw UserError("--sim-script " + options.sim_script + ": no such file");
        }
        setenv("SIMXR_SCRIPT", fs::absolute(options.sim_script).c_str(), 1);
        return;
    }
    // A built-in profile name stays a name; a file is made absolute, as the script's relative
    // paths are read against the script's folder.
    std::string hmd = options.hmd;
    if (fs::exists(hmd) && fs::is_regular_file(hmd)) hmd = fs::absolute(hmd).string();
    const fs::path script =
        fs::temp_directory_path() / ("monoplane-simxr-" + std::to_string(getpid()) + ".toml");
    std::ofstream out(script);
    out << "# written by monoplane study run --headset simulated\n";
    out << "hmd = \"" << hmd << "\"\n";
    out << "display_rate_hz = " << options.sim_rate_hz << "\n";
    if (!options.dump_frames.empty()) {
        fs::create_directories(options.dump_frames);
        out << "dump_dir = \"" << fs::absolute(options.dump_frames).string() << "\"\n";
    }
    if (!out) throw UserError("cannot write the simulated runtime's script " + script.string());
    setenv("SIMXR_SCRIPT", script.c_str(), 1);
}

study::SessionStatus run_headset_session(
    const HeadsetStudyOptions& options, const GlobalOptions& global, study::StudyStore& store,
    const study::Protocol& protocol, study::Observer* observer,
    const std::function<double(const study::ScheduledTrial&)>& trial_error_px,
    const std::function<std::int64_t(const std::string&, const std::string&)>& begin) {
    if (options.headset == "simulated") select_simulated_runtime(options);
    auto headset = headset::OpenXrHeadset::create().value_or_throw();
    std::cerr << "OpenXR runtime: " << headset->runtime_name() << ", system "
              << headset->system_name() << "\n";

    vk_core::ContextOptions context_options = global.context_options();
    context_options.hooks = headset->vulkan_hooks();
    bool want_window = options.window == "on" || (options.window == "auto" && has_display());
    if (want_window) {
        auto extensions = window::required_instance_extensions();
        if (!extensions) {
            if (options.window == "on") throw UserError(extensions.error().message);
            std::cerr << "no experimenter window: " << extensions.error().message << "\n";
            want_window = false;
        } else {
            context_options.instance_extensions = *extensions;
            context_options.device_extensions = window::required_device_extensions();
        }
    }
    auto ctx = vk_core::Context::create(context_options).value_or_throw();
    std::cerr << "device: " << ctx->device_info().name << "\n";
    headset->create_session(*ctx, options.resolution_scale).value_or_throw();
    const vk::Extent2D extent = headset->eye_extent();
    std::cerr << "eye swapchains: " << extent.width << " x " << extent.height << "\n";

    std::unique_ptr<window::ExperimenterWindow> experimenter;
    if (want_window) {
        experimenter = window::ExperimenterWindow::create(*ctx, {}, extent).value_or_throw();
    }
    const std::int64_t session_id = begin(headset->runtime_name(), ctx->device_info().name);
    const study::SessionInfo info = store.session(session_id).value_or_throw();
    // Sessions of schema version 1 recorded no detail: they rendered at the default, low.
    study::RenderSettings render = info.render;
    if (render.detail.empty()) render.detail = "low";
    StudyRenderers renderers(*ctx, protocol, extent, render);
    headset::EyeCompositor compositor(*ctx);
    headset::TextStyle label_style;
    label_style.scale = 2;
    label_style.padding = 2;
    compositor.set_overlay("label1", headset::render_text({"1"}, label_style));
    compositor.set_overlay("label2", headset::render_text({"2"}, label_style));
    compositor.set_overlay("paused", headset::render_text({"Paused"}, {}));

    std::deque<std::string> log_tail;
    study::LiveOptions live_options;
    live_options.neutral_ns = static_cast<std::int64_t>(options.neutral_s * 1e9);
    live_options.on_committed = [&](const std::string& what) {
        if (options.trace) {
            std::printf("committed %s\n", what.c_str());
            std::fflush(stdout);
        }
        log_tail.push_back(what);
        if (log_tail.size() > 200) log_tail.pop_front();
    };
    auto live =
        study::LiveSession::open(store, session_id, protocol, live_options).value_or_throw();
    std::optional<study::ObserverInput> observer_input;
    if (observer) observer_input.emplace(*observer, protocol, trial_error_px);

    // Frames without a scene (neutral screen, questionnaire) are the compositor's alone; scene
    // frames ride in their renderer's ring. Neither waits for the GPU after submitting.
    vk_core::FrameRing compositor_frames(*ctx);
    headset::FrameTimes times;
    HeadsetFrameLog frame_log(store, session_id);
    using Clock = std::chrono::steady_clock;
    auto step_start = Clock::now();
    // Charges the time since the last step to `step`.
    const auto charge = [&](headset::FrameStep step) {
        const auto now = Clock::now();
        times.add(step, std::chrono::duration<double, std::milli>(now - step_start).count());
        step_start = now;
    };
    std::vector<window::Command> window_commands;
    std::vector<int> window_answers(protocol.questionnaire.items.size(), 0);
    bool unblinded = false;
    bool exit_requested = false;
    bool screenshot_saved = false;
    SeatAnchor anchor;
    std::int64_t first_frame_ns = -1;
    int last_reported_trial = -1;
    auto request = [&](LiveInput input, std::int64_t time_ns) {
        const std::string what = live->request(input, time_ns).value_or_throw();
        if (options.trace)
            std::printf("request %s: %s\n", std::string(study::live_input_name(input)).c_str(),
                        what.c_str());
    };

    for (;;) {
        if (!headset->poll_events().value_or_throw()) break;
        if (live->finished() && !exit_requested) {
            headset->request_exit().value_or_throw();
            exit_requested = true;
        }
        if (!headset->running()) {
            // Waiting for the runtime (READY, or EXITING after the end): no frames to render.
            if (experimenter) experimenter->frame({});
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            continue;
        }
        const auto frame_start = Clock::now();
        step_start = frame_start;
        const headset::HeadsetFrame frame = headset->begin_frame().value_or_throw();
        const std::int64_t now = frame.display_time_ns;
        if (first_frame_ns < 0) first_frame_ns = now;
        rig::Pose head;
        if (frame.views_valid) head = anchor.relative(located_head(frame));

        // Input: the controller, then the experimenter's window, then a simulated observer.
        const std::vector<headset::ControlPress> presses =
            headset->sync_controls().value_or_throw();
        charge(headset::FrameStep::kOpenXrBegin);
        for (const headset::ControlPress& press : presses) {
            if (press.control == headset::Control::Switch)
                request(LiveInput::Switch, press.time_ns);
            if (press.control == headset::Control::Confirm)
                request(LiveInput::Confirm, press.time_ns);
            if (press.control == headset::Control::Pause) {
                request(live->screen().paused ? LiveInput::Resume : LiveInput::Pause,
                        press.time_ns);
            }
        }
        for (const window::Command& c : window_commands) {
            using Kind = window::Command::Kind;
            switch (c.kind) {
                case Kind::Switch:
                    request(LiveInput::Switch, now);
                    break;
                case Kind::Confirm:
                    request(LiveInput::Confirm, now);
                    break;
                case Kind::Pause:
                    request(LiveInput::Pause, now);
                    break;
                case Kind::Resume:
                    request(LiveInput::Resume, now);
                    break;
                case Kind::Abort:
                    request(LiveInput::Abort, now);
                    break;
                case Kind::Unblind:
                    unblinded = c.value != 0;
                    break;
                case Kind::Answer:
                    if (c.item >= 0 && c.item < static_cast<int>(window_answers.size()))
                        window_answers[static_cast<std::size_t>(c.item)] = c.value;
                    break;
                case Kind::SubmitAnswers:
                    for (std::size_t i = 0; i < window_answers.size(); ++i) {
                        if (live->screen().kind != ScreenKind::Questionnaire) break;
                        if (window_answers[i] > 0)
                            live->answer(static_cast<int>(i), window_answers[i]).value_or_throw();
                    }
                    break;
            }
        }
        window_commands.clear();
        if (observer_input) {
            for (LiveInput input : observer_input->poll(live->screen(), live->progress(), now)) {
                request(input, now);
            }
        }

        const study::LiveScreen screen = live->screen();
        bool rendered = false;
        bool scene_frame = false;
        std::optional<rig::Pose> rendered_head;
        modes::ModeRenderer* scene_renderer = nullptr;
        std::vector<profile::FrameStats> completed;
        if (frame.should_render) {
            std::array<vk::Image, 2> targets;
            for (int e = 0; e < 2; ++e) targets[e] = headset->acquire_eye_image(e).value_or_throw();
            charge(headset::FrameStep::kOpenXrBegin);
            std::vector<headset::EyeCompositor::Overlay> overlays;
            modes::ModeRenderer* renderer = nullptr;
            modes::FrameInputs inputs;
            if (screen.kind == ScreenKind::Trial && !screen.paused && frame.views_valid) {
                const study::ScheduledTrial& trial = *screen.trial;
                renderer = &renderers.renderer(trial.scene, screen.mode);
                inputs.views = view_inputs(frame, head, renderers.seat(trial.scene), protocol);
                inputs.mono_plane = trial.mono_plane;
                overlays.push_back({screen.label == 1 ? "label1" : "label2", kLabelPlacement});
            } else if (screen.kind == ScreenKind::Trial && screen.paused) {
                overlays.push_back({"paused", kPanelPlacement});
            } else if (screen.kind == ScreenKind::Questionnaire) {
                const std::string key = "question" + std::to_string(screen.question) + "-" +
                                        std::to_string(screen.selection);
                if (!compositor.has_overlay(key)) {
                    compositor.set_overlay(
                        key,
                        headset::render_text(
                            questionnaire_lines(protocol, screen.question, screen.selection), {}));
                }
                overlays.push_back({key, kPanelPlacement});
            }
            const auto record_eyes = [&](const vk::raii::CommandBuffer& cmd) {
                for (int e = 0; e < 2; ++e) {
                    const auto eye = static_cast<modes::Eye>(e);
                    headset::EyeCompositor::MirrorRecorder mirror;
                    if (experimenter && e == 0) {
                        mirror = [&](const vk::raii::CommandBuffer& c, vk::Image image,
                                     vk::ImageLayout layout, vk::Extent2D size) {
                            experimenter->record_mirror(c, image, layout, size);
                        };
                    }
                    compositor.record_eye(cmd, targets[e], extent, frame.views[e].tangents,
                                          renderer ? &renderer->display_image(eye) : nullptr,
                                          overlays, mirror);
                }
            };
            charge(headset::FrameStep::kSession);
            // The eyes' copies ride in the renderer's submission: one submission per frame, and
            // no wait for it (the ring waits only for the frame two before).
            if (renderer) {
                renderer->submit_frame(inputs, record_eyes);
                completed = renderer->take_completed();
                for (const profile::FrameStats& stats : completed) {
                    times.add_gpu_ms(stats.gpu_frame_ms);
                }
                scene_frame = true;
                scene_renderer = renderer;
                rendered_head = inputs.views.head;
            } else {
                const std::uint32_t slot = compositor_frames.begin();
                record_eyes(compositor_frames.commands(slot));
                compositor_frames.submit(slot);
            }
            charge(headset::FrameStep::kRender);
            rendered = true;
        }
        headset->end_frame(frame).value_or_throw();
        charge(headset::FrameStep::kOpenXrEnd);
        // What the participant sees changes only with a frame that was shown.
        if (rendered) {
            const double cpu_ms =
                std::chrono::duration<double, std::milli>(Clock::now() - frame_start).count();
            frame_log.displayed(frame, screen, rendered_head, cpu_ms, scene_renderer);
            // After displayed(): a renderer that waited may return this very frame's time.
            frame_log.completed(scene_renderer, completed);
            live->frame_presented(frame.index, now).value_or_throw();
        }
        charge(headset::FrameStep::kLog);

        const study::LiveProgress progress = live->progress();
        if (progress.trial_number != last_reported_trial && screen.kind == ScreenKind::Trial) {
            last_reported_trial = progress.trial_number;
            std::cerr << "trial " << progress.trial_number << "/" << progress.trial_count << ": "
                      << screen.trial->scene << " m = " << screen.trial->mono_plane
                      << (screen.trial->practice ? " (practice)" : "") << "\n";
        }
        if (experimenter) {
            window::ExperimenterView view;
            view.participant = info.participant_code;
            view.protocol = protocol.name;
            view.headset = headset->runtime_name();
            view.hmd = headset->system_name();
            view.device = ctx->device_info().name;
            view.trial_number = progress.trial_number;
            view.trial_count = progress.trial_count;
            view.phase = window_phase(screen);
            view.elapsed_s = static_cast<double>(now - first_frame_ns) * 1e-9;
            if (screen.trial) {
                view.practice = screen.trial->practice;
                view.scene = screen.trial->scene;
                view.mono_plane = screen.trial->mono_plane;
                view.label_modes = {
                    std::string(study::render_mode_name(screen.trial->label1_mode)),
                    std::string(study::render_mode_name(screen.trial->label2_mode))};
                if (progress.trial_started_ns >= 0) {
                    view.trial_elapsed_s =
                        static_cast<double>(now - progress.trial_started_ns) * 1e-9;
                }
            }
            view.visible_label = progress.visible_label;
            view.switches = progress.switches;
            view.both_seen = progress.both_seen;
            view.unblinded = unblinded;
            view.log_tail.assign(
                log_tail.end() -
                    std::min<std::ptrdiff_t>(40, static_cast<std::ptrdiff_t>(log_tail.size())),
                log_tail.end());
            view.questionnaire_items = protocol.questionnaire.items;
            view.scale_points = protocol.questionnaire.scale_points;
            view.answers = window_answers;
            view.frame_index = static_cast<std::uint64_t>(frame.index);
            view.frame_ms = std::chrono::duration<double, std::milli>(
                                std::chrono::steady_clock::now() - frame_start)
                                .count();
            view.status_line = std::string("session ") +
                               std::string(headset::session_phase_name(headset->phase()));
            window_commands = experimenter->frame(view);
            if (!options.screenshot.empty() && frame.index == options.screenshot_frame) {
                experimenter->save_screenshot(options.screenshot).value_or_throw();
                std::cerr << "wrote " << options.screenshot << "\n";
                screenshot_saved = true;
            }
            charge(headset::FrameStep::kWindow);
            if (experimenter->close_requested() && !live->finished()) {
                std::cerr << "the experimenter window was closed: ending the session (resume "
                             "it with `monoplane study resume`)\n";
                headset->request_exit().value_or_throw();
                exit_requested = true;
            }
        }
        times.end_frame(scene_frame);
    }
    if (experimenter && !options.screenshot.empty() && !screenshot_saved) {
        experimenter->save_screenshot(options.screenshot).value_or_throw();
        std::cerr << "wrote " << options.screenshot << "\n";
    }
    if (times.scene_frames() > 0) std::cerr << times.summary();
    renderers.for_each([&](modes::ModeRenderer& r) { frame_log.completed(&r, r.finish_frames()); });
    frame_log.flush();
    ctx->device().waitIdle();
    experimenter.reset();
    headset->destroy_session();
    fail_on_validation_messages(*ctx, global);
    const study::SessionInfo end = store.session(session_id).value_or_throw();
    if (!live->finished()) {
        // Not an error of the study's data (everything decided is stored), but the session did
        // not finish: the exit status says so, for scripts that run sessions.
        throw UserError("the OpenXR session ended (" +
                        std::string(headset::session_phase_name(headset->phase())) +
                        ") before the study did; `monoplane study resume --db ...` continues at "
                        "the first undecided trial");
    }
    return end.status;
}

}  // namespace monoplane::app
