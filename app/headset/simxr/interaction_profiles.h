// The interaction profiles simxr simulates (OpenXR 1.0 spec, section 6.4 "Interaction Profile
// Paths") and their components, as full paths ("/user/hand/right/input/select/click"). Shared
// by the script parser (which checks `interaction_profile` and `[[input]]` paths) and the
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
    haptic,   // .../haptic (output)
};

struct Component {
    std::string path;
    ComponentKind kind;
};

struct InteractionProfile {
    std::string path;  // "/interaction_profiles/khr/simple_controller"
    std::vector<Component> components;
};

// The profiles simxr knows, in a stable order.
std::span<const InteractionProfile> interaction_profiles();

// The profile with this path, or nullptr.
const InteractionProfile* find_interaction_profile(std::string_view path);

// The component a binding path names: the path itself, or for an identifier without a component
// (".../input/trigger") the component the spec lets a runtime pick (click, then value, then pose).
// nullptr if the profile has no such component.
const Component* resolve_binding_path(const InteractionProfile& profile, std::string_view path);

}  // namespace monoplane::simxr
