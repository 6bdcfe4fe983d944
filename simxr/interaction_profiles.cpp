#include "simxr/interaction_profiles.h"

#include <array>

namespace monoplane::simxr {
namespace {

constexpr std::string_view kLeft = "/user/hand/left";
constexpr std::string_view kRight = "/user/hand/right";
// spec 6.3.1: the top-level user paths a profile can be valid for.
constexpr std::array<std::string_view, 2> kHands = {kLeft, kRight};
constexpr std::array<std::string_view, 1> kHead = {"/user/head"};
constexpr std::array<std::string_view, 1> kGamepad = {"/user/gamepad"};

struct ComponentSpec {
    std::string_view subpath;    // "input/select/click", relative to a user path
    std::string_view only_on{};  // set: the one user path that has it (Touch: x/y left, a/b right)
};

ComponentKind kind_of(std::string_view subpath) {
    // spec 6.3.2: outputs are haptics (the Xbox controller names four of them).
    if (subpath.starts_with("output/")) return ComponentKind::haptic;
    if (subpath.ends_with("/click") || subpath.ends_with("/touch")) return ComponentKind::boolean;
    if (subpath.ends_with("/pose")) return ComponentKind::pose;
    return ComponentKind::scalar;
}

// The component lists of the OpenXR 1.0 spec, section 6.4, in its order (subsections 6.4.1 to
// 6.4.9), relative to each of the profile's user paths. "system/click (may not be available for
// application use)" is listed: a runtime must still accept a binding to it.

constexpr ComponentSpec kSimpleController[] = {{"input/select/click"},
                                               {"input/menu/click"},
                                               {"input/grip/pose"},
                                               {"input/aim/pose"},
                                               {"output/haptic"}};

constexpr ComponentSpec kDaydreamController[] = {
    {"input/select/click"},   {"input/trackpad/x"}, {"input/trackpad/y"}, {"input/trackpad/click"},
    {"input/trackpad/touch"}, {"input/grip/pose"},  {"input/aim/pose"}};

constexpr ComponentSpec kViveController[] = {
    {"input/system/click"},  {"input/squeeze/click"},  {"input/menu/click"},
    {"input/trigger/click"}, {"input/trigger/value"},  {"input/trackpad/x"},
    {"input/trackpad/y"},    {"input/trackpad/click"}, {"input/trackpad/touch"},
    {"input/grip/pose"},     {"input/aim/pose"},       {"output/haptic"}};

constexpr ComponentSpec kVivePro[] = {{"input/system/click"},
                                      {"input/volume_up/click"},
                                      {"input/volume_down/click"},
                                      {"input/mute_mic/click"}};

constexpr ComponentSpec kMixedRealityController[] = {
    {"input/menu/click"},     {"input/squeeze/click"}, {"input/trigger/value"},
    {"input/thumbstick/x"},   {"input/thumbstick/y"},  {"input/thumbstick/click"},
    {"input/trackpad/x"},     {"input/trackpad/y"},    {"input/trackpad/click"},
    {"input/trackpad/touch"}, {"input/grip/pose"},     {"input/aim/pose"},
    {"output/haptic"}};

constexpr ComponentSpec kXboxController[] = {{"input/menu/click"},
                                             {"input/view/click"},
                                             {"input/a/click"},
                                             {"input/b/click"},
                                             {"input/x/click"},
                                             {"input/y/click"},
                                             {"input/dpad_down/click"},
                                             {"input/dpad_right/click"},
                                             {"input/dpad_up/click"},
                                             {"input/dpad_left/click"},
                                             {"input/shoulder_left/click"},
                                             {"input/shoulder_right/click"},
                                             {"input/thumbstick_left/click"},
                                             {"input/thumbstick_right/click"},
                                             {"input/trigger_left/value"},
                                             {"input/trigger_right/value"},
                                             {"input/thumbstick_left/x"},
                                             {"input/thumbstick_left/y"},
                                             {"input/thumbstick_right/x"},
                                             {"input/thumbstick_right/y"},
                                             {"output/haptic_left"},
                                             {"output/haptic_right"},
                                             {"output/haptic_left_trigger"},
                                             {"output/haptic_right_trigger"}};

constexpr ComponentSpec kGoController[] = {
    {"input/system/click"},   {"input/trigger/click"}, {"input/back/click"},
    {"input/trackpad/x"},     {"input/trackpad/y"},    {"input/trackpad/click"},
    {"input/trackpad/touch"}, {"input/grip/pose"},     {"input/aim/pose"}};

constexpr ComponentSpec kTouchController[] = {{"input/x/click", kLeft},
                                              {"input/x/touch", kLeft},
                                              {"input/y/click", kLeft},
                                              {"input/y/touch", kLeft},
                                              {"input/menu/click", kLeft},
                                              {"input/a/click", kRight},
                                              {"input/a/touch", kRight},
                                              {"input/b/click", kRight},
                                              {"input/b/touch", kRight},
                                              {"input/system/click", kRight},
                                              {"input/squeeze/value"},
                                              {"input/trigger/value"},
                                              {"input/trigger/touch"},
                                              {"input/thumbstick/x"},
                                              {"input/thumbstick/y"},
                                              {"input/thumbstick/click"},
                                              {"input/thumbstick/touch"},
                                              {"input/thumbrest/touch"},
                                              {"input/grip/pose"},
                                              {"input/aim/pose"},
                                              {"output/haptic"}};

constexpr ComponentSpec kIndexController[] = {
    {"input/system/click"},   {"input/system/touch"},     {"input/a/click"},
    {"input/a/touch"},        {"input/b/click"},          {"input/b/touch"},
    {"input/squeeze/value"},  {"input/squeeze/force"},    {"input/trigger/click"},
    {"input/trigger/value"},  {"input/trigger/touch"},    {"input/thumbstick/x"},
    {"input/thumbstick/y"},   {"input/thumbstick/click"}, {"input/thumbstick/touch"},
    {"input/trackpad/x"},     {"input/trackpad/y"},       {"input/trackpad/force"},
    {"input/trackpad/touch"}, {"input/grip/pose"},        {"input/aim/pose"},
    {"output/haptic"}};

struct ProfileSpec {
    std::string_view vendor_and_name;  // "khr/simple_controller", under /interaction_profiles/
    std::string_view name;             // the spec's heading
    std::span<const std::string_view> user_paths;
    std::span<const ComponentSpec> components;
};

constexpr ProfileSpec kProfiles[] = {
    {"khr/simple_controller", "Khronos Simple Controller", kHands, kSimpleController},
    {"google/daydream_controller", "Google Daydream Controller", kHands, kDaydreamController},
    {"htc/vive_controller", "HTC Vive Controller", kHands, kViveController},
    {"htc/vive_pro", "HTC Vive Pro", kHead, kVivePro},
    {"microsoft/motion_controller", "Microsoft Mixed Reality Motion Controller", kHands,
     kMixedRealityController},
    {"microsoft/xbox_controller", "Microsoft Xbox Controller", kGamepad, kXboxController},
    {"oculus/go_controller", "Oculus Go Controller", kHands, kGoController},
    {"oculus/touch_controller", "Oculus Touch Controller", kHands, kTouchController},
    {"valve/index_controller", "Valve Index Controller", kHands, kIndexController},
};

// A profile's full component paths: every component under every user path it is valid for,
// grouped by component in the spec's order.
InteractionProfile make_profile(const ProfileSpec& spec) {
    InteractionProfile profile{"/interaction_profiles/" + std::string(spec.vendor_and_name),
                               std::string(spec.name),
                               {},
                               {}};
    for (std::string_view user : spec.user_paths) profile.user_paths.emplace_back(user);
    for (const ComponentSpec& component : spec.components) {
        for (std::string_view user : spec.user_paths) {
            if (!component.only_on.empty() && component.only_on != user) continue;
            profile.components.push_back({std::string(user) + "/" + std::string(component.subpath),
                                          kind_of(component.subpath)});
        }
    }
    return profile;
}

std::vector<InteractionProfile> build_profiles() {
    std::vector<InteractionProfile> profiles;
    for (const ProfileSpec& spec : kProfiles) profiles.push_back(make_profile(spec));
    return profiles;
}

}  // namespace

std::span<const InteractionProfile> interaction_profiles() {
    static const std::vector<InteractionProfile> profiles = build_profiles();
    return profiles;
}

const InteractionProfile& eye_gaze_interaction_profile() {
    static const InteractionProfile profile{
        std::string(kEyeGazeProfilePath),
        "Eye Gaze Interaction",
        {std::string(kEyesUserPath)},
        {{std::string(kEyesUserPath) + "/input/gaze_ext/pose", ComponentKind::pose}}};
    return profile;
}

const InteractionProfile* find_interaction_profile(std::string_view path) {
    for (const InteractionProfile& profile : interaction_profiles()) {
        if (profile.path == path) return &profile;
    }
    return nullptr;
}

namespace {

const Component* find_component(const InteractionProfile& profile, std::string_view path) {
    for (const Component& component : profile.components) {
        if (component.path == path) return &component;
    }
    return nullptr;
}

// An identifier's component ("/click" under ".../input/trigger"), or nullptr.
const Component* child(const InteractionProfile& profile, std::string_view identifier,
                       std::string_view component) {
    return find_component(profile, std::string(identifier) + "/" + std::string(component));
}

std::string title_case(std::string_view words) {
    std::string text;
    bool start = true;
    for (char c : words) {
        if (c == '/' || c == '_') {
            text += ' ';
            start = true;
        } else {
            text += start && c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
            start = false;
        }
    }
    return text;
}

}  // namespace

bool is_binding_path(const InteractionProfile& profile, std::string_view path) {
    if (find_component(profile, path) != nullptr) return true;
    // spec 6.3.2: an input source path is /input/<identifier>[_<location>][/<component>]; only the
    // component may be left out, so an identifier is a component path less its last segment.
    for (const Component& component : profile.components) {
        const std::string_view full = component.path;
        if (full.size() > path.size() && full.starts_with(path) && full[path.size()] == '/' &&
            full.find('/', path.size() + 1) == std::string_view::npos &&
            path.find("/input/") != std::string_view::npos) {
            return true;
        }
    }
    return false;
}

std::vector<const Component*> bound_components(const InteractionProfile& profile,
                                               std::string_view path, ActionUse use) {
    if (const Component* exact = find_component(profile, path)) {
        const bool fits = [&] {
            switch (use) {
                case ActionUse::boolean:
                case ActionUse::scalar:
                    return exact->kind == ComponentKind::boolean ||
                           exact->kind == ComponentKind::scalar;
                case ActionUse::vector2:
                    return false;  // spec: a vector2f binds an identifier, never its x or y alone
                case ActionUse::pose:
                    return exact->kind == ComponentKind::pose;
                case ActionUse::vibration:
                    return exact->kind == ComponentKind::haptic;
            }
            return false;
        }();
        if (!fits) return {};
        return {exact};
    }
    auto first_of = [&](std::string_view a, std::string_view b) -> std::vector<const Component*> {
        if (const Component* found = child(profile, path, a)) return {found};
        if (const Component* found = b.empty() ? nullptr : child(profile, path, b)) return {found};
        return {};
    };
    switch (use) {
        case ActionUse::boolean:
            return first_of("click", "value");
        case ActionUse::scalar:
            return first_of("value", "click");
        case ActionUse::vector2: {
            const Component* x = child(profile, path, "x");
            const Component* y = child(profile, path, "y");
            if (x == nullptr || y == nullptr) return {};
            return {x, y};
        }
        case ActionUse::pose:
            return first_of("pose", "");
        case ActionUse::vibration:
            return {};
    }
    return {};
}

std::string_view user_path_of(const InteractionProfile& profile, std::string_view path) {
    for (const std::string& user : profile.user_paths) {
        if (path.starts_with(user) && path.size() > user.size() && path[user.size()] == '/') {
            return user;
        }
    }
    return {};
}

std::string localized_source_name(const InteractionProfile& profile, std::string_view path,
                                  bool user_part, bool profile_part, bool component_part) {
    const std::string_view user = user_path_of(profile, path);
    std::vector<std::string> parts;
    if (user_part && !user.empty()) {
        if (user == kLeft) {
            parts.emplace_back("Left Hand");
        } else if (user == kRight) {
            parts.emplace_back("Right Hand");
        } else if (user == kEyesUserPath) {
            parts.emplace_back("Eyes");
        } else {
            parts.push_back(title_case(user.substr(user.rfind('/') + 1)));  // "Head", "Gamepad"
        }
    }
    if (profile_part) parts.push_back(profile.name);
    if (component_part && !user.empty()) {
        std::string_view rest = path.substr(user.size() + 1);  // "input/select/click"
        if (rest.starts_with("input/")) rest.remove_prefix(6);
        parts.push_back(title_case(rest));  // "Select Click", "Haptic Left"
    }
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : " ") + part;
    return text;
}

}  // namespace monoplane::simxr
