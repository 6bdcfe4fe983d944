// One frame of an OpenXR session: xrWaitFrame, xrBeginFrame and the located eyes, then the
// released images and the projection layer (with the eyes' depth where written) at xrEndFrame.
#include <cmath>
#include <limits>

#include "app/headset/openxr_headset_impl.h"

namespace monoplane::headset {
namespace {

rig::Pose to_pose(const XrPosef& p) {
    rig::Pose pose;
    pose.position = {p.position.x, p.position.y, p.position.z};
    pose.orientation =
        glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
    return pose;
}

rig::Tangents to_tangents(const XrFovf& fov) {
    rig::Tangents t;
    t.left = std::tan(static_cast<double>(fov.angleLeft));
    t.right = std::tan(static_cast<double>(fov.angleRight));
    t.up = std::tan(static_cast<double>(fov.angleUp));
    t.down = std::tan(static_cast<double>(fov.angleDown));
    return t;
}

}  // namespace

Result<HeadsetFrame> OpenXrHeadset::begin_frame() {
    Impl& x = *impl_;
    XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO};
    XrFrameState state{XR_TYPE_FRAME_STATE};
    MONOPLANE_TRY(x.check("xrWaitFrame", xrWaitFrame(x.session, &wait, &state)));
    XrFrameBeginInfo begin{XR_TYPE_FRAME_BEGIN_INFO};
    MONOPLANE_TRY(x.check("xrBeginFrame", xrBeginFrame(x.session, &begin)));

    HeadsetFrame frame;
    frame.index = ++x.frame_index;
    frame.display_time_ns = state.predictedDisplayTime;
    frame.display_period_ns = state.predictedDisplayPeriod;
    frame.should_render = state.shouldRender == XR_TRUE;
    XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO};
    locate.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    locate.displayTime = state.predictedDisplayTime;
    locate.space = x.local;
    XrViewState view_state{XR_TYPE_VIEW_STATE};
    std::uint32_t count = 0;
    for (auto& v : x.views) v = {XR_TYPE_VIEW};
    MONOPLANE_TRY(x.check("xrLocateViews", xrLocateViews(x.session, &locate, &view_state, 2, &count,
                                                         x.views.data())));
    const XrViewStateFlags needed =
        XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT;
    frame.views_valid = count == 2 && (view_state.viewStateFlags & needed) == needed;
    x.views_located = frame.views_valid;
    for (int e = 0; e < 2; ++e) {
        frame.views[e].pose = to_pose(x.views[e].pose);
        frame.views[e].tangents = to_tangents(x.views[e].fov);
    }
    return frame;
}

Result<void> OpenXrHeadset::end_frame(const HeadsetFrame& frame,
                                      const std::optional<DepthEncoding>& depth) {
    Impl& x = *impl_;
    // Releases the acquired images of two swapchains; true if both were acquired.
    const auto release = [&x](std::array<Impl::Swapchain, 2>& pair) -> Result<bool> {
        bool both = true;
        for (Impl::Swapchain& swapchain : pair) {
            if (!swapchain.acquired) {
                both = false;
                continue;
            }
            XrSwapchainImageReleaseInfo info{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
            MONOPLANE_TRY(x.check("xrReleaseSwapchainImage",
                                  xrReleaseSwapchainImage(swapchain.handle, &info)));
            swapchain.acquired = false;
        }
        return both;
    };
    Result<bool> rendered = release(x.swapchains);
    MONOPLANE_TRY(rendered);
    Result<bool> depth_written = release(x.depth_swapchains);
    MONOPLANE_TRY(depth_written);
    // XR_KHR_composition_layer_depth (XrCompositionLayerDepthInfoKHR): depth goes "to the next
    // chain for all XrCompositionLayerProjectionView structures in the given layer", here with
    // the colour's rectangle on the depth swapchain. minDepth and maxDepth are the window depths
    // of the near and far planes, nearZ and farZ their distances, in (0, +inf] and unequal. The
    // encoding d = near / distance puts infinity at window depth 0 and `near` at 1: minDepth 0
    // with nearZ = +inf, maxDepth 1 with farZ = near (nearZ > farZ is reversed depth).
    const bool with_depth = *depth_written && depth.has_value();
    std::array<XrCompositionLayerDepthInfoKHR, 2> depth_infos{};
    std::array<XrCompositionLayerProjectionView, 2> views{};
    XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    const XrCompositionLayerBaseHeader* layers[] = {
        reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
    for (int e = 0; e < 2; ++e) {
        views[e] = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
        views[e].pose = x.views[e].pose;
        views[e].fov = x.views[e].fov;
        views[e].subImage.swapchain = x.swapchains[e].handle;
        views[e].subImage.imageRect.extent = {static_cast<std::int32_t>(eye_extent_.width),
                                              static_cast<std::int32_t>(eye_extent_.height)};
        if (!with_depth) continue;
        XrCompositionLayerDepthInfoKHR& info = depth_infos[e];
        info = {XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR};
        info.subImage = views[e].subImage;
        info.subImage.swapchain = x.depth_swapchains[e].handle;
        info.minDepth = 0.0f;
        info.maxDepth = 1.0f;
        info.nearZ = std::numeric_limits<float>::infinity();
        info.farZ = static_cast<float>(depth->near);
        views[e].next = &info;
    }
    layer.space = x.local;
    layer.viewCount = 2;
    layer.views = views.data();
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = frame.display_time_ns;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    // Nothing is submitted for a frame the runtime said not to render, or without tracking.
    const bool submit = *rendered && frame.should_render && x.views_located;
    end.layerCount = submit ? 1 : 0;
    end.layers = submit ? layers : nullptr;
    return x.check("xrEndFrame", xrEndFrame(x.session, &end));
}

}  // namespace monoplane::headset
