// A headset session from its start to its end: the answer keys, the runtime with its Vulkan
// device, the eyes' swapchains, the experimenter window and the renderers; the frames in between
// are HeadsetLoop's (study_headset_loop.h).
#include "app/commands/study_headset.h"

#include <cstdlib>
#include <iostream>
#include <memory>

#include "app/commands/runtime_lost.h"
#include "app/commands/study_headset_loop.h"
#include "app/commands/validation_report.h"
#include "app/commands/window_bridge.h"
#include "app/headset/headset_device.h"

namespace monoplane::app {
namespace {

bool has_display() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

// The experimenter window when wanted and possible, and the instance and device extensions it
// needs added to the context's.
bool want_window(const HeadsetStudyOptions& options, vk_core::ContextOptions& context_options) {
    if (!(options.window == "on" || (options.window == "auto" && has_display()))) return false;
    auto extensions = window::required_instance_extensions();
    if (!extensions) {
        if (options.window == "on") throw UserError(extensions.error().message);
        std::cerr << "no experimenter window: " << extensions.error().message << "\n";
        return false;
    }
    context_options.instance_extensions = *extensions;
    context_options.device_extensions = window::required_device_extensions();
    return true;
}

// The runtime `options.headset` names (simxr, written a script, for simulated) with the Vulkan
// device it makes from `context_options`.
headset::HeadsetDevice open_headset(const HeadsetStudyOptions& options, const GlobalOptions& global,
                                    const vk_core::ContextOptions& context_options, bool eye_gaze) {
    RuntimeSelection selection(options);
    auto created =
        headset::OpenXrHeadset::create(global.validation, options.layer_depth != "off", eye_gaze);
    // simxr has read its script (in xrCreateInstance): the environment goes back as it was, so
    // the launcher's next session reaches the runtime it chooses.
    selection.instance_created();
    std::unique_ptr<headset::OpenXrHeadset> openxr = std::move(created).value_or_throw();
    std::cerr << "OpenXR runtime: " << openxr->runtime_name() << ", system "
              << openxr->system_name() << "\n";
    return headset::HeadsetDevice::create(std::move(openxr), context_options).value_or_throw();
}

}  // namespace

study::SessionStatus run_headset_session(
    const HeadsetStudyOptions& options, const GlobalOptions& global, study::StudyStore& store,
    const study::Protocol& protocol, ImportedStudyScenes imported, study::Observer* observer,
    const std::function<double(const study::ScheduledTrial&)>& trial_error_px,
    const std::function<std::int64_t(const std::string&, const std::string&)>& begin) {
    // The answer keys first: a bad option or an unreadable device stops before the headset.
    const study::ResponseSettings responses =
        resolve_responses(protocol.responses, options.keys, options.response_device);
    vk_core::ContextOptions context_options = global.context_options();
    const bool window = want_window(options, context_options);
    ParticipantAnswers answers(responses, window, observer != nullptr);
    if (responses.enabled) {
        std::cerr << "answers: " << study::describe_responses(responses) << "\n";
        if (!window && responses.device.empty()) {
            std::cerr << "the answer keys are read from the experimenter window, and there is "
                         "none (--window off, or no display): only the controller answers\n";
        }
    }
    // OpenXR goes before Vulkan on every way out (headset_device.h); what renders is declared
    // after the device, so it goes before both.
    const headset::HeadsetDevice device =
        open_headset(options, global, context_options, protocol.gaze.record);
    headset::OpenXrHeadset& headset = device.headset();
    // [gaze] record on a runtime without an eye tracker: said now, and noted with the session.
    const bool gaze_missing = protocol.gaze.record && !headset.tracks_eye_gaze();
    const std::string no_gaze = "no eye gaze on this runtime (" + headset.runtime_name() +
                                "): the protocol asks for gaze ([gaze] record), none is recorded";
    if (gaze_missing) std::cerr << no_gaze << "\n";
    if (protocol.gaze.record && !gaze_missing) std::cerr << "eye gaze: recorded per frame\n";
    const vk_core::Context& ctx = device.vulkan();
    std::cerr << "device: " << ctx.device_info().name << "\n";
    headset.create_session(ctx, options.resolution_scale).value_or_throw();
    const vk::Extent2D extent = headset.eye_extent();
    std::cerr << "eye swapchains: " << extent.width << " x " << extent.height << "\n";
    std::unique_ptr<window::ExperimenterWindow> experimenter;
    if (window) experimenter = window::ExperimenterWindow::create(ctx, {}, extent).value_or_throw();
    if (experimenter) experimenter->set_response_keys(window_bindings(responses));

    const std::int64_t session_id = begin(headset.runtime_name(), ctx.device_info().name);
    if (gaze_missing) store.add_session_note(session_id, no_gaze).value_or_throw();
    // Sessions of schema version 1 recorded no detail: they rendered at the default, low.
    study::RenderSettings render = store.session(session_id).value_or_throw().render;
    if (render.detail.empty()) render.detail = "low";
    StudyRenderers renderers(ctx, protocol, extent, render, std::move(imported));
    bool finished = false;
    std::string loss;  // the lost runtime's message; empty if it was not lost
    {
        HeadsetLoop loop(options, protocol, store, session_id, headset, ctx, experimenter.get(),
                         renderers, observer, trial_error_px, answers);
        loop.run();
        finished = loop.finished();
        if (headset.lost()) loss = loop.loss_message();
        ctx.device().waitIdle();
    }
    experimenter.reset();
    // Here rather than in the destructor: what the validation layers say of it counts below.
    headset.destroy_session();
    fail_on_validation_messages(ctx, headset.validation_messages(), global);
    const study::SessionInfo end = store.session(session_id).value_or_throw();
    // A runtime lost after the session completed took nothing from it.
    if (!finished && !loss.empty()) throw RuntimeLost(loss);
    if (!finished) {
        // Not an error of the study's data (everything decided is stored), but the session did
        // not finish: the exit status says so, for scripts that run sessions.
        throw UserError("the OpenXR session ended (" +
                        std::string(headset::session_phase_name(headset.phase())) +
                        ") before the study did; `monoplane study resume --db ...` continues at "
                        "the first undecided trial");
    }
    return end.status;
}

}  // namespace monoplane::app
