// Every interaction profile of the OpenXR 1.0 core specification (section 6.4 "Interaction
// Profile Paths") with its top-level user paths and components, as full paths
// ("/user/hand/right/input/select/click", "/user/gamepad/output/haptic_left"). A conformant
// runtime must accept suggested bindings for all of them, even for hardware it does not have.
// Shared by the script parser (which checks `interaction_profile` and `[[input]]` paths) and the
// runtime (which checks suggested bindings). No Vulkan, no OpenXR headers.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace monoplane::simxr {

enum class ComponentKind {
    boolean,  // .../click, .../touch: 0 or 1
    scalar,   // .../value, .../force, .../x, .../y: 0 to 1 (x, y: -1 to 1)
    pose,     // .../pose
    haptic,   // .../output/haptic, .../output/haptic_left, ...
};

struct Component {
    std::string path;
    ComponentKind kind;
};

struct InteractionProfile {
    std::string path;                     // "/interaction_profiles/khr/simple_controller"
    std::string name;                     // "Khronos Simple Controller" (the spec's heading)
    std::vector<std::string> user_paths;  // spec "Valid for user paths": "/user/hand/left", ...
    std::vector<Component> components;
};

// The profiles of the 1.0 core specification, in its order.
std::span<const InteractionProfile> interaction_profiles();

// The profile with this path, or nullptr.
const InteractionProfile* find_interaction_profile(std::string_view path);

// XR_EXT_eye_gaze_interaction's profile, valid only where the application enabled the extension:
// /user/eyes_ext with its one component, input/gaze_ext/pose.
constexpr std::string_view kEyeGazeProfilePath = "/interaction_profiles/ext/eye_gaze_interaction";
constexpr std::string_view kEyesUserPath = "/user/eyes_ext";
const InteractionProfile& eye_gaze_interaction_profile();

// What an action of each type reads (spec 11.4, suggested bindings: the rules differ by type).
enum class ActionUse { boolean, scalar, vector2, pose, vibration };

// Whether a suggested binding to `path` is valid for the profile (spec 11.4: the runtime must
// accept every binding in the interaction profile's allowlist): one of its components, or an
// input identifier with components (".../input/trigger", ".../input/thumbstick"). Any action type
// may be suggested for a valid path; what it binds is bound_components' business.
bool is_binding_path(const InteractionProfile& profile, std::string_view path);

// The components a valid binding path binds for an action of type `use`, by spec 11.4: a
// boolean reads a click or a thresholded value (an identifier: its click, else its value); a
// float reads a value or a click (an identifier: its value, else its click); a vector2f reads an
// identifier's x and y; a pose reads a pose (an identifier: its pose); a vibration, an output.
// Empty when the input cannot be converted to the action's type (the spec leaves it unbound).
std::vector<const Component*> bound_components(const InteractionProfile& profile,
                                               std::string_view path, ActionUse use);

// The top-level user path ("/user/hand/left") a component path starts with, or "".
std::string_view user_path_of(const InteractionProfile& profile, std::string_view path);

// xrGetInputSourceLocalizedName's text for a component path of the profile: the parts asked for,
// in the order user path ("Left Hand"), profile ("Khronos Simple Controller"), component
// ("Select Click"), separated by spaces.
std::string localized_source_name(const InteractionProfile& profile, std::string_view path,
                                  bool user_part, bool profile_part, bool component_part);

}  // namespace monoplane::simxr
