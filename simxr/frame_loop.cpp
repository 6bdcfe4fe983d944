// The frame loop on a virtual clock (docs/simxr.md): xrWaitFrame never sleeps; the n-th call of
// a session (n from 0) predicts display time base + n * period. Script events (exit_after_s,
// lose_session_at_s, lose_instance_at_s) fire at the first xrWaitFrame whose predicted time
// reaches them.
#include <cmath>
#include <cstdio>

#include "simxr/entry_points.h"
#include "simxr/frame_dump.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

// spec 10.5: at least 16 composition layers must be accepted; simxr accepts exactly that many.
constexpr uint32_t kMaxLayers = 16;

bool reached(const Session& session, XrTime time, double seconds) {
    return seconds > 0.0 && time - session.base_time >= std::llround(seconds * 1e9);
}

void fire_script_events(Session& session, XrTime time) {
    const Script& script = session.instance->script;
    if (!session.exit_requested && reached(session, time, script.exit_after_s)) {
        begin_exit(session);
    }
    if (!session.loss_pending && reached(session, time, script.lose_session_at_s)) {
        session.loss_pending = true;
        queue_state_change(session, XR_SESSION_STATE_LOSS_PENDING, time);
    }
    if (!session.instance->lost && reached(session, time, script.lose_instance_at_s)) {
        lose_instance(*session.instance, time);
    }
}

XrResult check_sub_image(const Session& session, const XrSwapchainSubImage& sub_image) {
    const Swapchain* swapchain = lookup<Swapchain>(sub_image.swapchain);
    if (swapchain == nullptr || swapchain->session != &session) return XR_ERROR_HANDLE_INVALID;
    // spec (xrEndFrame): a layer whose swapchain has no released image is XR_ERROR_LAYER_INVALID.
    if (!swapchain->last_released) return XR_ERROR_LAYER_INVALID;
    const XrRect2Di& rect = sub_image.imageRect;
    if (rect.offset.x < 0 || rect.offset.y < 0 || rect.extent.width <= 0 ||
        rect.extent.height <= 0 ||
        static_cast<int64_t>(rect.offset.x) + rect.extent.width > swapchain->info.width ||
        static_cast<int64_t>(rect.offset.y) + rect.extent.height > swapchain->info.height) {
        return XR_ERROR_SWAPCHAIN_RECT_INVALID;
    }
    if (sub_image.imageArrayIndex >= swapchain->info.arraySize) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    return XR_SUCCESS;
}

// A projection view's XR_KHR_composition_layer_depth structure, or nullptr. spec (fundamentals,
// next chains): a runtime must ignore structures of extensions the instance did not enable, so
// without the extension a chained depth structure is neither checked nor dumped.
const XrCompositionLayerDepthInfoKHR* depth_info(const Session& session,
                                                 const XrCompositionLayerProjectionView& view) {
    if (!session.instance->composition_layer_depth) return nullptr;
    return static_cast<const XrCompositionLayerDepthInfoKHR*>(
        find_in_chain(view.next, XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR));
}

// XrCompositionLayerDepthInfoKHR's rules (XR_KHR_composition_layer_depth, revision 6).
XrResult check_depth_info(const Session& session, const XrCompositionLayerDepthInfoKHR& depth) {
    // The sub-image follows xrEndFrame's rules for every swapchain a layer names.
    if (XrResult r = check_sub_image(session, depth.subImage); r != XR_SUCCESS) return r;
    // subImage "identifies the depth image": a colour swapchain there is a malformed structure.
    if (!lookup<Swapchain>(depth.subImage.swapchain)->depth) return XR_ERROR_VALIDATION_FAILURE;
    // minDepth < maxDepth, both in [0, 1]; nearZ and farZ in (0, +inf] and not equal (nearZ >
    // farZ is reversed depth). Written as positive tests so that NaN fails them.
    const bool depth_range =
        depth.minDepth >= 0.0f && depth.minDepth < depth.maxDepth && depth.maxDepth <= 1.0f;
    const bool planes = depth.nearZ > 0.0f && depth.farZ > 0.0f && depth.nearZ != depth.farZ;
    return depth_range && planes ? XR_SUCCESS : XR_ERROR_VALIDATION_FAILURE;
}

// A projection view: its pose, colour sub-image and, with the extension, depth.
XrResult check_projection_view(const Session& session,
                               const XrCompositionLayerProjectionView& view) {
    if (view.type != XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_unit_quaternion(view.pose.orientation)) return XR_ERROR_POSE_INVALID;
    if (XrResult r = check_sub_image(session, view.subImage); r != XR_SUCCESS) return r;
    // The extension asks for depth on every view of a layer but does not make a view without it
    // an error, so each view is checked on its own.
    if (const auto* depth = depth_info(session, view)) return check_depth_info(session, *depth);
    return XR_SUCCESS;
}

XrResult check_quad(const Session& session, const XrCompositionLayerQuad& quad) {
    if (!is_unit_quaternion(quad.pose.orientation)) return XR_ERROR_POSE_INVALID;
    return check_sub_image(session, quad.subImage);
}

XrResult check_layer(const Session& session, const XrCompositionLayerBaseHeader* layer) {
    if (layer == nullptr) return XR_ERROR_LAYER_INVALID;
    const Space* space = lookup<Space>(layer->space);
    if (space == nullptr || space->session != &session) return XR_ERROR_HANDLE_INVALID;
    if (layer->type == XR_TYPE_COMPOSITION_LAYER_PROJECTION) {
        const auto* projection = reinterpret_cast<const XrCompositionLayerProjection*>(layer);
        // spec: viewCount must equal the view configuration's view count.
        if (projection->viewCount != 2 || projection->views == nullptr) {
            return XR_ERROR_VALIDATION_FAILURE;
        }
        for (uint32_t i = 0; i < 2; ++i) {
            if (XrResult r = check_projection_view(session, projection->views[i]);
                r != XR_SUCCESS) {
                return r;
            }
        }
        return XR_SUCCESS;
    }
    if (layer->type == XR_TYPE_COMPOSITION_LAYER_QUAD) {
        return check_quad(session, *reinterpret_cast<const XrCompositionLayerQuad*>(layer));
    }
    return XR_ERROR_LAYER_INVALID;
}

// spec 9.3: a running session leaves READY for SYNCHRONIZED once the application's frame loop
// is synchronized with the runtime, which simxr takes to be its first submitted frame
// (OpenXR-CTS "Session State": no change before a frame is submitted). simxr shows the
// application's frames and gives it input at once, so VISIBLE and FOCUSED follow at the same
// time: frame 0 is not rendered (shouldRender false in READY), every later one is.
void synchronize(Session& session) {
    queue_state_change(session, XR_SESSION_STATE_SYNCHRONIZED, session.now());
    queue_state_change(session, XR_SESSION_STATE_VISIBLE, session.now());
    queue_state_change(session, XR_SESSION_STATE_FOCUSED, session.now());
}

XrResult dump_frame(Session& session, std::int64_t frame, const XrFrameEndInfo& info) {
    const Script& script = session.instance->script;
    if (script.dump_dir.empty() || frame % script.dump_every != 0) return XR_SUCCESS;
    for (uint32_t l = 0; l < info.layerCount; ++l) {
        if (info.layers[l]->type != XR_TYPE_COMPOSITION_LAYER_PROJECTION) continue;
        const auto* projection =
            reinterpret_cast<const XrCompositionLayerProjection*>(info.layers[l]);
        std::error_code error;
        std::filesystem::create_directories(script.dump_dir, error);
        for (uint32_t eye = 0; eye < 2; ++eye) {
            char name[64];
            std::snprintf(name, sizeof(name), "frame_%06lld_%s", static_cast<long long>(frame),
                          eye == 0 ? "left" : "right");
            const std::filesystem::path stem = script.dump_dir / name;
            const XrCompositionLayerProjectionView& view = projection->views[eye];
            if (!dump_sub_image(session, view.subImage, stem.string() + ".png")) {
                return XR_ERROR_RUNTIME_FAILURE;
            }
            // The depth that goes with these colours: the same layer's, not another's.
            const XrCompositionLayerDepthInfoKHR* depth = depth_info(session, view);
            if (depth != nullptr &&
                !dump_depth_sub_image(session, *depth, stem.string() + "_depth.pfm")) {
                return XR_ERROR_RUNTIME_FAILURE;
            }
        }
        return XR_SUCCESS;  // the first projection layer is what the eyes see
    }
    return XR_SUCCESS;
}

}  // namespace

XrResult XRAPI_CALL xrWaitFrame(XrSession handle, const XrFrameWaitInfo* info,
                                XrFrameState* state) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if ((info != nullptr && info->type != XR_TYPE_FRAME_WAIT_INFO) ||
        !has_type(state, XR_TYPE_FRAME_STATE)) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    // After LOSS_PENDING the next xrWaitFrame fails; the frame in flight may still be finished.
    if (session->loss_pending) return XR_ERROR_SESSION_LOST;
    if (!session->running) return XR_ERROR_SESSION_NOT_RUNNING;
    // A real runtime blocks a second xrWaitFrame until xrBeginFrame; simxr never blocks, so it
    // simply lets the waits queue up.
    const std::int64_t frame = session->frames_waited++;
    const XrTime time = session->predicted_display_time(frame);
    session->latest_wait_time = time;
    session->waited_not_begun.push_back(frame);
    state->predictedDisplayTime = time;
    state->predictedDisplayPeriod = session->period;
    state->shouldRender =
        session->state == XR_SESSION_STATE_VISIBLE || session->state == XR_SESSION_STATE_FOCUSED;
    fire_script_events(*session, time);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrBeginFrame(XrSession handle, const XrFrameBeginInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info != nullptr && info->type != XR_TYPE_FRAME_BEGIN_INFO) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (!session->running) return XR_ERROR_SESSION_NOT_RUNNING;
    // spec: xrBeginFrame without a preceding xrWaitFrame is XR_ERROR_CALL_ORDER_INVALID.
    if (session->waited_not_begun.empty()) return XR_ERROR_CALL_ORDER_INVALID;
    const std::int64_t frame = session->waited_not_begun.front();
    session->waited_not_begun.pop_front();
    // spec: a frame begun while another was never ended discards the earlier one.
    const XrResult result = session->begun_frame ? XR_FRAME_DISCARDED : XR_SUCCESS;
    session->begun_frame = frame;
    return result;
}

XrResult XRAPI_CALL xrEndFrame(XrSession handle, const XrFrameEndInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_FRAME_END_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (!session->running) return XR_ERROR_SESSION_NOT_RUNNING;
    // spec: xrEndFrame without a matching xrBeginFrame is XR_ERROR_CALL_ORDER_INVALID.
    if (!session->begun_frame) return XR_ERROR_CALL_ORDER_INVALID;
    const std::int64_t frame = *session->begun_frame;
    // spec (xrEndFrame): displayTime should be computed from xrWaitFrame's prediction, but the
    // runtime must be robust against pipelined applications, so only a time that is no time
    // (<= 0) is XR_ERROR_TIME_INVALID. The frame keeps its index (dumps) whatever the time.
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE) {
        return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
    }
    if (info->layerCount > kMaxLayers) return XR_ERROR_LAYER_LIMIT_EXCEEDED;
    if (info->layerCount > 0 && info->layers == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (uint32_t i = 0; i < info->layerCount; ++i) {
        if (XrResult result = check_layer(*session, info->layers[i]); result != XR_SUCCESS) {
            return result;
        }
    }
    const XrResult dumped = dump_frame(*session, frame, *info);
    session->begun_frame.reset();
    if (session->queued_state == XR_SESSION_STATE_READY) synchronize(*session);
    return dumped;
}

}  // namespace monoplane::simxr
