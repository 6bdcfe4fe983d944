// What HeadsetLoop shows the eyes: the trial's scene through its renderer, or the compositor's
// grey with the screen's overlays (label, pause panel, questionnaire item, page), and each eye's
// depth beside its colour.
#include "app/commands/study_headset_loop.h"
#include "app/headset/overlay_text.h"

namespace monoplane::app {
namespace {

using study::ScreenKind;

// Where the overlays sit, as directions of view (tangents, +y up): the label low and small, in
// the lower periphery; the questionnaire straight ahead.
constexpr headset::OverlayPlacement kLabelPlacement{0.0, -0.55, 0.05};
constexpr headset::OverlayPlacement kPanelPlacement{0.0, 0.05, 0.45};

std::vector<std::string> questionnaire_lines(const study::Protocol& protocol, int question,
                                             int selection) {
    const study::Questionnaire& q = protocol.questionnaire;
    const study::HeadsetPrompts& prompts = protocol.day.prompts;
    std::string scale;
    for (int v = 1; v <= q.scale_points; ++v) {
        scale += v == selection ? "[" + std::to_string(v) + "] " : " " + std::to_string(v) + "  ";
    }
    const std::pair<std::string_view, std::string> counts[] = {
        {"question", std::to_string(question + 1)},
        {"questions", std::to_string(q.items.size())},
        {"points", std::to_string(q.scale_points)}};
    return {study::fill_prompt(prompts.question, counts),
            q.items[static_cast<std::size_t>(question)],
            "",
            study::fill_prompt(prompts.scale, counts),
            scale,
            "",
            prompts.answer};
}

}  // namespace

HeadsetLoop::Rendered HeadsetLoop::render(const headset::HeadsetFrame& frame,
                                          const LocatedHead& located,
                                          const study::LiveScreen& screen, const rig::Pose& head) {
    std::array<vk::Image, 2> targets;
    std::array<vk::Image, 2> depth_targets;
    for (int e = 0; e < 2; ++e) {
        const std::optional<vk::Image> image = unless_lost(headset_.acquire_eye_image(e));
        std::optional<vk::Image> depth_image = vk::Image{};
        if (image && depth_writer_) depth_image = unless_lost(headset_.acquire_eye_depth_image(e));
        if (!image || !depth_image) return Rendered{};  // lost: nothing is drawn or shown
        targets[e] = *image;
        depth_targets[e] = *depth_image;
    }
    charge(headset::FrameStep::kOpenXrBegin);
    Rendered rendered;
    rendered.shown = true;
    modes::FrameInputs inputs;
    const std::vector<headset::EyeCompositor::Overlay> overlays = screen_overlays(screen, frame);
    if (screen.kind == ScreenKind::Trial && !screen.paused && frame.views_valid) {
        const study::ScheduledTrial& trial = *screen.trial;
        rendered.renderer = &renderers_.renderer(trial.scene, screen.mode);
        inputs.views = view_inputs(frame, located, head, renderers_.seat(trial.scene), protocol_);
        inputs.mono_plane = trial.mono_plane;
        rendered.trial_view = TrialView{trial.scene, inputs.views, trial.mono_plane};
        // hybrid-auto: the trial's distance is the nearest plane its chooser may take.
        inputs.nearest_auto_plane = trial.mono_plane;
    }
    const modes::ModeRenderer* renderer = rendered.renderer;
    const auto record_eyes = [&](const vk::raii::CommandBuffer& cmd) {
        for (int e = 0; e < 2; ++e) {
            const auto eye = static_cast<modes::Eye>(e);
            headset::EyeCompositor::MirrorRecorder mirror;
            if (experimenter_ && e == 0) {
                mirror = [this](const vk::raii::CommandBuffer& c, vk::Image image,
                                vk::ImageLayout layout, vk::Extent2D size) {
                    experimenter_->record_mirror(c, image, layout, size);
                };
            }
            compositor_.record_eye(cmd, targets[e], extent_, frame.views[e].tangents,
                                   renderer ? &renderer->display_image(eye) : nullptr, overlays,
                                   mirror);
            if (depth_writer_) {
                record_depth(cmd, e, depth_targets[e], frame.views[e].tangents,
                             inputs.views.cant[e], renderer, overlays);
            }
        }
    };
    charge(headset::FrameStep::kSession);
    if (rendered.renderer) {
        rendered.renderer->submit_frame(inputs, record_eyes);
        rendered.completed = rendered.renderer->take_completed();
        for (const profile::FrameStats& stats : rendered.completed) {
            times_.add_gpu_ms(stats.gpu_frame_ms);
        }
    } else {
        const std::uint32_t slot = compositor_frames_.begin();
        record_eyes(compositor_frames_.commands(slot));
        compositor_frames_.submit(slot);
    }
    charge(headset::FrameStep::kRender);
    return rendered;
}

void HeadsetLoop::record_depth(const vk::raii::CommandBuffer& cmd, int e, vk::Image target,
                               const rig::Tangents& tangents, double cant,
                               const modes::ModeRenderer* renderer,
                               const std::vector<headset::EyeCompositor::Overlay>& overlays) {
    std::optional<headset::EyeDepthSource> source;
    if (renderer) {
        source.emplace();
        source->linear_depth = renderer->eye_linear_depth_image(static_cast<modes::Eye>(e));
        source->tangents = tangents;
        // The renderer turns the eye by R_y(cant) in the head's frame (view_setup.cpp), its
        // position on the eyes' plane: head -> eye undoes the turn.
        source->head_to_eye = glm::mat3_cast(glm::angleAxis(-cant, glm::dvec3(0.0, 1.0, 0.0)));
    }
    depth_writer_->record(cmd, target, extent_, source ? &*source : nullptr, protocol_.near,
                          compositor_.overlay_rects(overlays, tangents, extent_));
}

std::vector<headset::EyeCompositor::Overlay> HeadsetLoop::screen_overlays(
    const study::LiveScreen& screen, const headset::HeadsetFrame& f) {
    if (is_page_screen(screen.kind)) {
        return {pages_.overlay(screen, compositor_, {f.views[0].tangents, f.views[1].tangents},
                               extent_)};
    }
    if (screen.kind == ScreenKind::Trial && screen.paused) {
        return {{"paused", kPanelPlacement}};
    }
    if (screen.kind == ScreenKind::Trial) {
        return {{screen.label == 1 ? "label1" : "label2", kLabelPlacement}};
    }
    if (screen.kind != ScreenKind::Questionnaire) return {};
    const std::string key =
        "question" + std::to_string(screen.question) + "-" + std::to_string(screen.selection);
    if (!compositor_.has_overlay(key)) {
        compositor_.set_overlay(
            key,
            headset::render_text(questionnaire_lines(protocol_, screen.question, screen.selection),
                                 headset::TextStyle{.font = protocol_.day.font}));
    }
    return {{key, kPanelPlacement}};
}

}  // namespace monoplane::app
