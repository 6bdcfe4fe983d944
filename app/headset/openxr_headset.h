// An OpenXR session over Vulkan (XR_KHR_vulkan_enable2; docs/headsets.md): the runtime
// creates the Vulkan instance and device on the physical device it names, one swapchain per eye
// receives the rendered views, xrLocateViews feeds each frame's eye poses and calibrated
// asymmetric frusta to the rig, and the participant's controller drives switch, confirm and pause
// through actions bound for khr/simple_controller, HTC Vive, Valve Index and Oculus Touch.
//
// The session life cycle follows the specification: READY -> xrBeginSession, STOPPING ->
// xrEndSession, EXITING or LOSS_PENDING -> the session is over (the study stays resumable).
// Works with any conformant runtime: SteamVR, Monado, Meta's, and monoplane's own simulated one
// (simxr, chosen through XR_RUNTIME_JSON).
#pragma once

#include <array>
#include <cstdint>
#include <ctime>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/result.h"
#include "renderer/vk/context.h"
#include "rig/pose.h"
#include "rig/tangents.h"

namespace monoplane::headset {

enum class SessionPhase {
    None,  // no session yet
    Idle,
    Ready,
    Synchronized,
    Visible,
    Focused,
    Stopping,
    LossPending,
    Exiting,
};
const char* session_phase_name(SessionPhase phase);

// One eye as the runtime located it for a frame, in the LOCAL reference space.
struct EyeView {
    rig::Pose pose;
    rig::Tangents tangents;  // tan of XrFovf's angles: the calibrated, asymmetric frustum
};

// The eye tracker's sample for a frame's display time (XR_EXT_eye_gaze_interaction's gaze pose,
// located in the VIEW space): valid when the runtime tracked the gaze then (orientation valid
// and tracked); direction: a unit vector in the head's space (-z ahead), from the midpoint
// between the eyes, meaningful only when valid.
struct GazeSample {
    bool valid = false;
    glm::dvec3 direction{0.0, 0.0, -1.0};
};

struct HeadsetFrame {
    std::int64_t index = 0;              // 0-based count of xrWaitFrame calls in this session
    std::int64_t display_time_ns = 0;    // predicted display time (XrTime, runtime's clock)
    std::int64_t display_period_ns = 0;  // the runtime's predicted display period
    bool should_render = false;
    bool views_valid = false;  // orientation and position tracked
    std::array<EyeView, 2> views;
    // With eye gaze (create's eye_gaze, a runtime that tracks the eyes): the frame's sample,
    // once locate_gaze filled it; none otherwise.
    std::optional<GazeSample> gaze;
};

enum class Control { Switch, Confirm, Pause };
const char* control_name(Control control);

struct ControlPress {
    Control control = Control::Switch;
    std::int64_t time_ns = 0;  // when the runtime saw the button go down (XrTime)
};

// How the eyes' depth images were written (app/headset/eye_depth_writer.h), for the projection
// views' XrCompositionLayerDepthInfoKHR: reversed Z with the far plane at infinity, window depth
// d = near / distance along the eye's axis, in [0, 1] (1 at `near`, 0 at infinity).
struct DepthEncoding {
    double near = 0.1;  // metres
};

class OpenXrHeadset {
  public:
    // Creates the XrInstance with XR_KHR_vulkan_enable2 and finds the HMD. Errors say what to do:
    // no runtime installed or active, no headset connected, no Vulkan support. With `validation`,
    // the OpenXR core validation layer watches every call (app/headset/xr_validation.h); it is
    // an error if it is not installed. With `layer_depth`, XR_KHR_composition_layer_depth is
    // enabled when the runtime offers it (the eyes' depth is then submitted with their colour).
    // With `eye_gaze`, XR_EXT_eye_gaze_interaction is enabled when the runtime offers it, and
    // the session binds the gaze pose if the system tracks the eyes (tracks_eye_gaze).
    static Result<std::unique_ptr<OpenXrHeadset>> create(bool validation = false,
                                                         bool layer_depth = true,
                                                         bool eye_gaze = false);
    ~OpenXrHeadset();
    OpenXrHeadset(const OpenXrHeadset&) = delete;
    OpenXrHeadset& operator=(const OpenXrHeadset&) = delete;

    const std::string& runtime_name() const { return runtime_name_; }
    // Whether eye gaze was asked for and the runtime offers it with a system that tracks the
    // eyes: then each session binds the gaze and locate_gaze samples it.
    bool tracks_eye_gaze() const;
    // Whether eye gaze was asked for and the runtime offers XR_EXT_eye_gaze_interaction, whether
    // or not its system tracks the eyes.
    bool offers_eye_gaze() const;
    // The gaze at a frame's display time (the runtime's XrTime), after the frame's
    // sync_controls (which syncs the gaze action too); none without eye gaze.
    Result<std::optional<GazeSample>> locate_gaze(std::int64_t display_time_ns);
    const std::string& system_name() const { return system_name_; }
    // What the OpenXR validation layer reported (nothing unless created with validation).
    const vk_core::ValidationMessages& validation_messages() const;

    // The runtime's recommended size of each eye's image (xrEnumerateViewConfigurationViews,
    // primary stereo): known from the system alone, so it may be called any time after create(),
    // with or without a session (the launcher shows it before any Vulkan device exists).
    Result<vk::Extent2D> recommended_eye_extent() const;

    // Hooks for vk_core::Context::create: the runtime creates the instance and device and names
    // the physical device (after its graphics requirements are queried, as the spec demands).
    vk_core::ContextCreationHooks vulkan_hooks();

    // Creates the session on the Context's device, the LOCAL space, the actions and one swapchain
    // per eye at the runtime's recommended size times resolution_scale; with the depth extension
    // enabled, one depth swapchain per eye of the same size too (depth_format()).
    Result<void> create_session(const vk_core::Context& ctx, double resolution_scale);
    vk::Extent2D eye_extent() const { return eye_extent_; }
    vk::Format swapchain_format() const { return swapchain_format_; }
    // The eyes' depth swapchains' format (one of eye_depth_formats()), or eUndefined when no
    // depth is submitted (extension not offered or not wanted, or no format in common).
    vk::Format depth_format() const { return depth_format_; }

    // Handles queued events, beginning and ending the session as its state asks. Returns false
    // once the session is over (EXITING, LOSS_PENDING, or the instance is lost).
    Result<bool> poll_events();
    SessionPhase phase() const { return phase_; }
    bool running() const { return running_; }  // between xrBeginSession and xrEndSession
    // Whether the runtime is gone for this session: a call answered XR_ERROR_INSTANCE_LOST or
    // XR_ERROR_SESSION_LOST (Monado's client answers so when its service died: a broken IPC
    // connection), or an instance- or session-loss-pending event arrived. From then on every
    // call may fail: the session can only be destroyed. Any time.
    bool lost() const;

    // xrWaitFrame, xrBeginFrame and xrLocateViews. Only while running().
    Result<HeadsetFrame> begin_frame();
    // The button presses since the last call (xrSyncActions; nothing unless FOCUSED).
    Result<std::vector<ControlPress>> sync_controls();
    // The eye's swapchain image for this frame, acquired and waited: it is in
    // COLOR_ATTACHMENT_OPTIMAL and must be left so. Only between begin_frame and end_frame.
    Result<vk::Image> acquire_eye_image(int eye);
    // The eye's depth swapchain image for this frame (only with a depth_format()), acquired and
    // waited: it is in DEPTH_STENCIL_ATTACHMENT_OPTIMAL and must be left so.
    Result<vk::Image> acquire_eye_depth_image(int eye);
    // Releases the acquired images and submits the projection layer (none if nothing was
    // rendered). The images' writes must have completed (the caller waited for its queue).
    // With `depth` and both eyes' depth images acquired, each view carries its depth
    // (XR_KHR_composition_layer_depth), else none does.
    Result<void> end_frame(const HeadsetFrame& frame,
                           const std::optional<DepthEncoding>& depth = std::nullopt);
    // The interaction profile the runtime bound to the participant's hands
    // (xrGetCurrentInteractionProfile, left hand first), or "" while none is: runtimes bind one
    // in an xrSyncActions of the running session. Only between create_session and
    // destroy_session.
    Result<std::string> interaction_profile() const;
    // The runtime's time (XrTime) of a CLOCK_MONOTONIC time, through
    // XR_KHR_convert_timespec_time (enabled when the runtime offers it: Monado and SteamVR do,
    // simxr does not); none without it or once the runtime is lost. Any time after create().
    std::optional<std::int64_t> runtime_time(const timespec& monotonic) const;
    // Asks the runtime to end the session (it answers with STOPPING).
    Result<void> request_exit();
    // Ends the session (unless the runtime is lost) and destroys it with its swapchains, after
    // waiting for the session's Vulkan device to finish with their images. Call while that
    // device lives (HeadsetDevice, app/headset/headset_device.h, owns both in that order); the
    // destructor calls it too. Any time; again, nothing happens.
    void destroy_session();

  private:
    struct Impl;
    explicit OpenXrHeadset(std::unique_ptr<Impl> impl);

    std::unique_ptr<Impl> impl_;
    std::string runtime_name_;
    std::string system_name_;
    vk::Extent2D eye_extent_;
    vk::Format swapchain_format_ = vk::Format::eUndefined;
    vk::Format depth_format_ = vk::Format::eUndefined;
    SessionPhase phase_ = SessionPhase::None;
    bool running_ = false;
};

// The controller mapping (docs/headsets.md): for each interaction profile, the component paths
// bound to each control. Pure data, shown by `monoplane study run --help` and tested.
struct ControlBinding {
    Control control;
    const char* path;
};
struct ProfileBindings {
    const char* profile;
    std::vector<ControlBinding> bindings;
};
const std::vector<ProfileBindings>& controller_bindings();

}  // namespace monoplane::headset
