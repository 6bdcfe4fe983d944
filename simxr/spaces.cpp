// Reference spaces, action spaces and view location. LOCAL and STAGE are the same space: the
// script's head positions are given in it, so a standing height is part of the keyframes
// (y = 1.6). VIEW is the head. Eyes sit at -ipd/2 and +ipd/2 along the head's x axis. The
// simulated controllers are held still in front of the head (hand_in_head).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "simxr/entry_points.h"
#include "simxr/interaction_profiles.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

rig::Pose from_xr(const XrPosef& pose) {
    return {
        {pose.position.x, pose.position.y, pose.position.z},
        glm::dquat(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z)};
}

XrPosef to_xr(const rig::Pose& pose) {
    const glm::dquat q = glm::normalize(pose.orientation);
    return {{static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z),
             static_cast<float>(q.w)},
            {static_cast<float>(pose.position.x), static_cast<float>(pose.position.y),
             static_cast<float>(pose.position.z)}};
}

// a ∘ b: b expressed in the space a is given in.
rig::Pose compose(const rig::Pose& a, const rig::Pose& b) {
    return {a.position + a.orientation * b.position, a.orientation * b.orientation};
}

rig::Pose inverse(const rig::Pose& pose) {
    const glm::dquat inverse_rotation = glm::conjugate(pose.orientation);
    return {-(inverse_rotation * pose.position), inverse_rotation};
}

rig::Pose head_at(const Session& session, XrTime time) {
    return head_pose_at(session.instance->script, session.script_time(time));
}

// Nothing tracks simxr's controllers, so each hand's pose components (grip and aim alike) ride
// rigidly with the head: 20 cm to its side, 30 cm below and 40 cm in front of the eyes'
// midpoint, oriented like the head. An application sees its hands where a seated user holds
// them, and hello_xr draws its hand cubes.
std::optional<rig::Pose> hand_in_head(std::string_view component) {
    const glm::dquat identity(1.0, 0.0, 0.0, 0.0);
    if (component.starts_with("/user/hand/left/")) return rig::Pose{{-0.2, -0.3, -0.4}, identity};
    if (component.starts_with("/user/hand/right/")) return rig::Pose{{0.2, -0.3, -0.4}, identity};
    return std::nullopt;
}

// XR_EXT_eye_gaze_interaction's gaze pose in the head's frame at `time`: from the midpoint
// between the eyes (the head's origin), its -z along the script's gaze; nullopt during a blink
// (the eye tracker has no sample: the space is not located).
std::optional<rig::Pose> gaze_in_head(const Session& session, XrTime time) {
    const Script& script = session.instance->script;
    const double t = session.script_time(time);
    const GazeSample sample = gaze_at(script.gaze, t, head_pose_at(script, t));
    if (!sample.valid) return std::nullopt;
    const glm::dvec3 ahead(0.0, 0.0, -1.0);
    const glm::dvec3 axis = glm::cross(ahead, sample.direction);
    const double sine = glm::length(axis);
    glm::dquat orientation(1.0, 0.0, 0.0, 0.0);
    if (sine > 1e-12) {
        orientation =
            glm::angleAxis(std::atan2(sine, glm::dot(ahead, sample.direction)), axis / sine);
    } else if (sample.direction.z > 0.0) {
        orientation = glm::angleAxis(glm::pi<double>(), glm::dvec3(0.0, 1.0, 0.0));
    }
    return rig::Pose{glm::dvec3(0.0), orientation};
}

// The pose a bound pose component has in the head's frame: a hand's, or the eyes' gaze.
std::optional<rig::Pose> component_in_head(const Session& session, std::string_view component,
                                           XrTime time) {
    if (component.starts_with(kEyesUserPath)) return gaze_in_head(session, time);
    return hand_in_head(component);
}

// The pose source an action space follows (spec 11.5.1: a single one, the first bound that
// matches its subaction path), or nullptr while it is unlocatable (spec 7.2.1: only while its
// action set was active in the latest xrSyncActions).
const std::string* pose_source(const Session& session, const Space& space) {
    if (space.action == nullptr ||
        std::ranges::find(session.synced_sets, space.action->set) == session.synced_sets.end()) {
        return nullptr;
    }
    std::string prefix;
    if (space.subaction_path != XR_NULL_PATH) {
        prefix = *session.instance->paths.find(space.subaction_path) + "/";
    }
    for (const auto& [action, component] : session.bindings) {
        if (action == space.action && component.starts_with(prefix)) return &component;
    }
    return nullptr;
}

// Where a space is in LOCAL at `time`; nullopt for an action space that cannot be located.
std::optional<rig::Pose> space_in_local(const Session& session, const Space& space, XrTime time) {
    const rig::Pose offset = from_xr(space.pose_in_reference);
    if (space.action_space) {
        const std::string* source = pose_source(session, space);
        const std::optional<rig::Pose> hand =
            source == nullptr ? std::nullopt : component_in_head(session, *source, time);
        if (!hand) return std::nullopt;
        return compose(compose(head_at(session, time), *hand), offset);
    }
    const rig::Pose origin =
        space.type == XR_REFERENCE_SPACE_TYPE_VIEW ? head_at(session, time) : rig::Pose{};
    return compose(origin, offset);
}

constexpr XrSpaceLocationFlags kFullyTracked =
    XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
    XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;

XrFovf fov_of(const rig::Tangents& tangents) {
    return {
        static_cast<float>(std::atan(tangents.left)), static_cast<float>(std::atan(tangents.right)),
        static_cast<float>(std::atan(tangents.up)), static_cast<float>(std::atan(tangents.down))};
}

}  // namespace

bool is_unit_quaternion(const XrQuaternionf& q) {
    const double length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    // Slightly unnormalized is fine (applications' float maths); NaN fails the comparison.
    return std::abs(length - 1.0) <= 1e-2;
}

XrResult XRAPI_CALL xrEnumerateReferenceSpaces(XrSession handle, uint32_t capacity, uint32_t* count,
                                               XrReferenceSpaceType* spaces) {
    std::lock_guard lock(runtime_mutex());
    if (lookup<Session>(handle) == nullptr) return XR_ERROR_HANDLE_INVALID;
    return fill_array<XrReferenceSpaceType>(
        capacity, count, spaces,
        {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
         XR_REFERENCE_SPACE_TYPE_STAGE});
}

XrResult XRAPI_CALL xrCreateReferenceSpace(XrSession handle, const XrReferenceSpaceCreateInfo* info,
                                           XrSpace* space_handle) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_REFERENCE_SPACE_CREATE_INFO) || space_handle == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_VIEW &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_STAGE) {
        return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    }
    if (!is_unit_quaternion(info->poseInReferenceSpace.orientation)) return XR_ERROR_POSE_INVALID;
    auto space = std::make_unique<Space>();
    space->session = session;
    space->type = info->referenceSpaceType;
    space->pose_in_reference = info->poseInReferenceSpace;
    session->spaces.push_back(space.get());
    *space_handle = register_object<XrSpace>(std::move(space));
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetReferenceSpaceBoundsRect(XrSession handle, XrReferenceSpaceType type,
                                                  XrExtent2Df* bounds) {
    std::lock_guard lock(runtime_mutex());
    if (lookup<Session>(handle) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (bounds == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (type != XR_REFERENCE_SPACE_TYPE_VIEW && type != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        type != XR_REFERENCE_SPACE_TYPE_STAGE) {
        return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    }
    // spec: without known bounds the extent is zero and the result XR_SPACE_BOUNDS_UNAVAILABLE.
    *bounds = {0.0f, 0.0f};
    return XR_SPACE_BOUNDS_UNAVAILABLE;
}

XrResult XRAPI_CALL xrCreateActionSpace(XrSession handle, const XrActionSpaceCreateInfo* info,
                                        XrSpace* space_handle) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_ACTION_SPACE_CREATE_INFO) || space_handle == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const Action* action = lookup<Action>(info->action);
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (action->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (XrResult r = check_subaction_path(*session->instance, *action, info->subactionPath);
        r != XR_SUCCESS) {
        return r;
    }
    if (!is_unit_quaternion(info->poseInActionSpace.orientation)) return XR_ERROR_POSE_INVALID;
    auto space = std::make_unique<Space>();
    space->session = session;
    space->action_space = true;
    space->action = action;
    space->subaction_path = info->subactionPath;
    space->pose_in_reference = info->poseInActionSpace;
    session->spaces.push_back(space.get());
    *space_handle = register_object<XrSpace>(std::move(space));
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrDestroySpace(XrSpace handle) {
    std::lock_guard lock(runtime_mutex());
    Space* space = lookup<Space>(handle);
    if (space == nullptr) return XR_ERROR_HANDLE_INVALID;
    std::erase(space->session->spaces, space);
    unregister_object(space);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrLocateSpace(XrSpace space_handle, XrSpace base_handle, XrTime time,
                                  XrSpaceLocation* location) {
    std::lock_guard lock(runtime_mutex());
    const Space* space = lookup<Space>(space_handle);
    const Space* base = lookup<Space>(base_handle);
    if (space == nullptr || base == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(location, XR_TYPE_SPACE_LOCATION) || space->session != base->session) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    if (auto* velocity = static_cast<XrSpaceVelocity*>(
            const_cast<void*>(find_in_chain(location->next, XR_TYPE_SPACE_VELOCITY)))) {
        velocity->velocityFlags = 0;
    }
    const Session& session = *space->session;
    const std::optional<rig::Pose> space_pose = space_in_local(session, *space, time);
    const std::optional<rig::Pose> base_pose = space_in_local(session, *base, time);
    // XR_EXT_eye_gaze_interaction: when the gaze sample was taken (now, or none).
    if (auto* sample_time = static_cast<XrEyeGazeSampleTimeEXT*>(
            const_cast<void*>(find_in_chain(location->next, XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT)))) {
        sample_time->time = space_pose && base_pose ? time : 0;
    }
    if (space_pose && base_pose) {
        location->pose = to_xr(compose(inverse(*base_pose), *space_pose));
        location->locationFlags = kFullyTracked;
        return XR_SUCCESS;
    }
    // spec 7.4: two spaces on the same entity (two action spaces of one action and subaction
    // path) are located relative to each other even while the entity is not.
    if (space->action_space && base->action_space && space->action != nullptr &&
        space->action == base->action && space->subaction_path == base->subaction_path) {
        location->pose = to_xr(
            compose(inverse(from_xr(base->pose_in_reference)), from_xr(space->pose_in_reference)));
        location->locationFlags = kFullyTracked;
        return XR_SUCCESS;
    }
    // spec 7.2.1: an unlocatable action space has no position or orientation.
    location->locationFlags = 0;
    location->pose = {{0, 0, 0, 1}, {0, 0, 0}};
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrLocateViews(XrSession handle, const XrViewLocateInfo* info,
                                  XrViewState* view_state, uint32_t capacity, uint32_t* count,
                                  XrView* views) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_VIEW_LOCATE_INFO) || !has_type(view_state, XR_TYPE_VIEW_STATE) ||
        count == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) {
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    }
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    const Space* space = lookup<Space>(info->space);
    if (space == nullptr || space->session != session) return XR_ERROR_HANDLE_INVALID;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    if (views == nullptr || views[0].type != XR_TYPE_VIEW || views[1].type != XR_TYPE_VIEW) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const std::optional<rig::Pose> space_pose = space_in_local(*session, *space, info->displayTime);
    if (!space_pose) {  // spec 7.2.1: an unlocatable action space locates no views
        view_state->viewStateFlags = 0;
        return XR_SUCCESS;
    }
    const hmd::HmdProfile& hmd = session->instance->script.hmd;
    const rig::Pose head = head_at(*session, info->displayTime);
    const rig::Pose local_to_space = inverse(*space_pose);
    for (int eye = 0; eye < 2; ++eye) {
        const double x = (eye == 0 ? -0.5 : 0.5) * hmd.ipd;
        // A canted profile turns the view by its cant_deg about the head's +y; XrFovf stays
        // relative to the turned view, as the spec defines it.
        const double cant = hmd::cant_radians(hmd)[eye];
        const rig::Pose eye_in_head{{x, 0.0, 0.0}, glm::angleAxis(cant, glm::dvec3(0.0, 1.0, 0.0))};
        views[eye].pose = to_xr(compose(local_to_space, compose(head, eye_in_head)));
        views[eye].fov = fov_of(eye == 0 ? hmd.left : hmd.right);
    }
    view_state->viewStateFlags =
        XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
        XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
