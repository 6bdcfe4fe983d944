#include "app/commands/headset_check.h"

#include <array>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

#include "app/commands/validation_report.h"
#include "app/headset/eye_compositor.h"
#include "app/headset/headset_device.h"
#include "app/headset/openxr_headset.h"
#include "app/headset/overlay_text.h"
#include "renderer/vk/context.h"
#include "renderer/vk/frame_ring.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

Result<void> check_headset_name(const std::string& headset) {
    if (headset == "simulated" || headset == "openxr") return Ok{};
    return Error{"headset '" + headset + "': choose simulated or openxr"};
}

// The calibration screen, as directions of view (tangents, +y up): the instruction above the
// grid, whose centre cross is straight ahead, both at infinity like every overlay, so both eyes see
// them at the same place and a blurred or stretched image shows the fit, not the content.
constexpr headset::OverlayPlacement kInstructionPlacement{0.0, 0.48, 0.16};
constexpr headset::OverlayPlacement kGridPlacement{0.0, 0.0, 0.70};

const std::vector<std::string> kInstruction = {"Headset check",
                                               "The text should be sharp and the grid square.",
                                               "Press CONFIRM when it fits."};

// A square grid of 8 x 8 cells with a bolder centre cross: its cells look square, and the cross
// sits straight ahead, when the headset fits and the runtime's calibration is right.
modes::RgbaImage calibration_grid() {
    constexpr std::uint32_t kSize = 480;
    constexpr std::uint32_t kCell = kSize / 8;
    modes::RgbaImage image;
    image.width = kSize;
    image.height = kSize;
    image.pixels.assign(std::size_t(kSize) * kSize * 4, 0);
    const auto on_line = [](std::uint32_t v) { return v % kCell < 2 || v >= kSize - 2; };
    const auto on_cross = [](std::uint32_t v) { return v + 3 >= kSize / 2 && v < kSize / 2 + 3; };
    for (std::uint32_t y = 0; y < kSize; ++y) {
        for (std::uint32_t x = 0; x < kSize; ++x) {
            std::uint8_t level = 40;  // render_text's background
            if (on_line(x) || on_line(y)) level = 170;
            if (on_cross(x) || on_cross(y)) level = 255;
            std::uint8_t* pixel = &image.pixels[(std::size_t(y) * kSize + x) * 4];
            pixel[0] = pixel[1] = pixel[2] = level;
            pixel[3] = 255;
        }
    }
    return image;
}

// The check's frame loop, its state in one place. Each turn: the runtime's events, the window's
// request and the clock, then (while the session runs) one frame: locate the eyes, read the
// controls and the bound profile, draw the calibration screen into both eyes.
class CheckLoop {
  public:
    CheckLoop(const HeadsetCheckOptions& options, headset::OpenXrHeadset& headset,
              const vk_core::Context& ctx, headset::EyeGaze eye_gaze)
        : options_(options), headset_(headset), compositor_(ctx), ring_(ctx) {
        result_.eye_gaze = eye_gaze;
        compositor_.set_overlay("instruction", headset::render_text(kInstruction, {}));
        compositor_.set_overlay("grid", calibration_grid());
    }

    // Turns until the check has ended and the runtime let the session go (or did not answer
    // the request to end it within a few seconds). The result's measurements are the last
    // frame's.
    HeadsetCheck run() {
        start_ = Clock::now();
        for (;;) {
            const Result<bool> alive = headset_.poll_events();
            if (!alive) {
                lost(alive.error().message);
                break;
            }
            if (!*alive) {
                runtime_ended();
                break;
            }
            if (!ended_) ask_window_and_clock();
            if (ended_ && (!headset_.running() || Clock::now() > exit_deadline_)) break;
            if (!headset_.running()) {
                // Waiting for the runtime (READY, or the end after STOPPING): nothing to show.
                std::this_thread::sleep_for(std::chrono::milliseconds(5));
                continue;
            }
            if (const Result<void> shown = frame(); !shown) {
                lost(shown.error().message);
                break;
            }
        }
        return result_;
    }

  private:
    double elapsed_s() const {
        return std::chrono::duration<double>(Clock::now() - start_).count();
    }

    void ask_window_and_clock() {
        CheckRequest request = CheckRequest::Continue;
        if (options_.on_turn) {
            HeadsetCheckProgress progress;
            progress.frames_shown = result_.frames_shown;
            progress.elapsed_s = elapsed_s();
            progress.phase = headset::session_phase_name(headset_.phase());
            progress.refresh_hz = result_.refresh_hz;
            progress.ipd_m = result_.ipd_m;
            progress.interaction_profile = result_.interaction_profile;
            progress.eye_gaze = result_.eye_gaze;
            progress.gaze_frames = result_.gaze_frames;
            request = options_.on_turn(progress);
        }
        if (request == CheckRequest::Confirm) {
            end(CheckEnd::Confirmed, "the experimenter confirmed the fit");
        } else if (request == CheckRequest::Cancel) {
            end(CheckEnd::Cancelled, "the experimenter cancelled the headset check");
        } else if (elapsed_s() > options_.timeout_s) {
            end(CheckEnd::TimedOut,
                "no CONFIRM within " + std::to_string(static_cast<int>(options_.timeout_s)) +
                    " s: check that the controllers are on and tracked, then check again");
        }
    }

    // Ends the check (the first end counts) and asks the runtime to end the session, giving it
    // a few seconds to do so.
    void end(CheckEnd how, std::string message) {
        if (ended_) return;
        ended_ = true;
        result_.end = how;
        result_.message = std::move(message);
        exit_deadline_ = Clock::now() + std::chrono::seconds(3);
        // A runtime that refuses is left behind at the deadline; the session is destroyed then.
        if (headset_.running()) static_cast<void>(headset_.request_exit());
    }

    void runtime_ended() {
        if (headset_.phase() == headset::SessionPhase::LossPending) {
            lost("the session is being lost (loss pending)");
            return;
        }
        end(CheckEnd::RuntimeEnded,
            "the OpenXR runtime ended the session (" +
                std::string(headset::session_phase_name(headset_.phase())) +
                ") before the fit was confirmed: check that the headset is on and the runtime "
                "still running, then check again");
    }

    void lost(const std::string& why) {
        end(CheckEnd::RuntimeLost,
            "the OpenXR runtime was lost mid-check (" + why +
                "): check the headset's cable and power and that the runtime still runs, then "
                "check again; the simulated headset remains available");
    }

    Result<void> frame() {
        const Result<headset::HeadsetFrame> frame = headset_.begin_frame();
        MONOPLANE_TRY(frame);
        measure(*frame);
        const Result<std::vector<headset::ControlPress>> presses = headset_.sync_controls();
        MONOPLANE_TRY(presses);
        for (const headset::ControlPress& press : *presses) {
            if (press.control == headset::Control::Confirm) {
                end(CheckEnd::Confirmed, "the participant pressed CONFIRM: the headset fits");
            }
        }
        const Result<std::string> profile = headset_.interaction_profile();
        MONOPLANE_TRY(profile);
        if (!profile->empty()) result_.interaction_profile = *profile;
        // After sync_controls, which synced the gaze action too.
        const Result<bool> gaze = gaze_valid(*frame);
        MONOPLANE_TRY(gaze);
        if (frame->should_render) {
            MONOPLANE_TRY(draw(*frame));
        }
        MONOPLANE_TRY(headset_.end_frame(*frame));
        if (frame->should_render && frame->views_valid) {
            ++result_.frames_shown;
            if (*gaze) ++result_.gaze_frames;
        }
        return Ok{};
    }

    // Whether the eye tracker had a valid sample for the frame (false without eye gaze).
    Result<bool> gaze_valid(const headset::HeadsetFrame& frame) {
        if (!headset_.tracks_eye_gaze()) return false;
        const Result<std::optional<headset::GazeSample>> sample =
            headset_.locate_gaze(frame.display_time_ns);
        MONOPLANE_TRY(sample);
        return sample->has_value() && (*sample)->valid;
    }

    // What only a running session tells: the display's rate and the eyes' distance.
    void measure(const headset::HeadsetFrame& frame) {
        if (frame.display_period_ns > 0) {
            result_.refresh_hz = 1e9 / static_cast<double>(frame.display_period_ns);
        }
        if (frame.views_valid) {
            result_.ipd_m =
                glm::length(frame.views[1].pose.position - frame.views[0].pose.position);
        }
    }

    // The calibration screen into both eyes' images (the compositor's grey with the overlays),
    // submitted without waiting, as a study's neutral screen is.
    Result<void> draw(const headset::HeadsetFrame& frame) {
        std::array<vk::Image, 2> targets;
        for (int e = 0; e < 2; ++e) {
            const Result<vk::Image> image = headset_.acquire_eye_image(e);
            MONOPLANE_TRY(image);
            targets[e] = *image;
        }
        const std::vector<headset::EyeCompositor::Overlay> overlays = {
            {"grid", kGridPlacement}, {"instruction", kInstructionPlacement}};
        const std::uint32_t slot = ring_.begin();
        for (int e = 0; e < 2; ++e) {
            compositor_.record_eye(ring_.commands(slot), targets[e], headset_.eye_extent(),
                                   frame.views[e].tangents, nullptr, overlays, {});
        }
        ring_.submit(slot);
        return Ok{};
    }

    const HeadsetCheckOptions& options_;
    headset::OpenXrHeadset& headset_;
    headset::EyeCompositor compositor_;
    vk_core::FrameRing ring_;  // after the compositor: its frames finish before the textures go
    HeadsetCheck result_;
    bool ended_ = false;
    Clock::time_point start_;
    Clock::time_point exit_deadline_;
};

// The check on a created headset: its Vulkan device, session and frame loop. The device owns
// the headset, so OpenXR goes before Vulkan on every way out (headset_device.h).
Result<HeadsetCheck> check_on(std::unique_ptr<headset::OpenXrHeadset> created,
                              headset::EyeGaze eye_gaze, const HeadsetCheckOptions& options) {
    Result<headset::HeadsetDevice> opened =
        headset::HeadsetDevice::create(std::move(created), options.global.context_options());
    MONOPLANE_TRY(opened);
    const headset::HeadsetDevice& device = *opened;
    headset::OpenXrHeadset& headset = device.headset();
    const vk_core::Context& ctx = device.vulkan();
    if (Result<void> session = headset.create_session(ctx, options.headset.resolution_scale);
        !session) {
        return Error{"the headset check could not start a session: " + session.error().message};
    }
    HeadsetCheck result;
    {
        CheckLoop loop(options, headset, ctx, eye_gaze);
        result = loop.run();
    }
    result.width = static_cast<int>(headset.eye_extent().width);
    result.height = static_cast<int>(headset.eye_extent().height);
    result.runtime = headset.runtime_name();
    result.system = headset.system_name();
    // Here rather than in the destructor: what the validation layers say of it counts below.
    headset.destroy_session();
    try {
        fail_on_validation_messages(ctx, headset.validation_messages(), options.global);
    } catch (const UserError& e) {
        return Error{std::string("the headset check: ") + e.what()};
    }
    return result;
}

}  // namespace

const char* check_end_name(CheckEnd end) {
    switch (end) {
        case CheckEnd::Confirmed:
            return "confirmed";
        case CheckEnd::Cancelled:
            return "cancelled";
        case CheckEnd::TimedOut:
            return "timed out";
        case CheckEnd::RuntimeEnded:
            return "runtime ended the session";
        case CheckEnd::RuntimeLost:
            return "runtime lost";
    }
    return "invalid";
}

Result<headset::HeadsetProbe> probe_headset(bool simulated, const HeadsetStudyOptions& simulation,
                                            bool validation) {
    HeadsetStudyOptions options = simulation;
    options.headset = simulated ? "simulated" : "openxr";
    try {
        RuntimeSelection selection(options);
        return headset::probe_runtime(validation);
    } catch (const UserError& e) {
        return Error{e.what()};
    }
}

Result<HeadsetCheck> run_headset_check(const HeadsetCheckOptions& options) {
    MONOPLANE_TRY(check_headset_name(options.headset.headset));
    try {
        RuntimeSelection selection(options.headset);
        // Eye gaze asked for wherever the runtime offers it, to report whether the headset
        // tracks the eyes (and sees them during the check); nothing of it is stored.
        Result<std::unique_ptr<headset::OpenXrHeadset>> created =
            headset::OpenXrHeadset::create(options.global.validation, false, /*eye_gaze=*/true);
        selection.instance_created();
        MONOPLANE_TRY(created);
        const headset::EyeGaze eye_gaze = headset::eye_gaze_support(**created);
        return check_on(std::move(created).value(), eye_gaze, options);
    } catch (const std::exception& e) {
        // A Vulkan failure (a lost device) or a bad simulated script: a message, not a crash.
        return Error{std::string("the headset check failed: ") + e.what()};
    }
}

}  // namespace monoplane::app
