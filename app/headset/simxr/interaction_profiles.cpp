#include "app/headset/simxr/interaction_profiles.h"

#include <array>

namespace monoplane::simxr {
namespace {

struct ComponentSpec {
    std::string_view hands;  // "lr": both hands, "l", "r": one
    std::string_view subpath;
};

ComponentKind kind_of(std::string_view subpath) {
    if (subpath.ends_with("/click") || subpath.ends_with("/touch")) return ComponentKind::boolean;
    if (subpath.ends_with("/pose")) return ComponentKind::pose;
    if (subpath.ends_with("/haptic")) return ComponentKind::haptic;
    return ComponentKind::scalar;
}

InteractionProfile make_profile(std::string_view vendor_and_name,
                                std::initializer_list<ComponentSpec> specs) {
    InteractionProfile profile{"/interaction_profiles/" + std::string(vendor_and_name), {}};
    for (const ComponentSpec& spec : specs) {
        for (char hand : spec.hands) {
            const std::string user = hand == 'l' ? "/user/hand/left/" : "/user/hand/right/";
            profile.components.push_back({user + std::string(spec.subpath), kind_of(spec.subpath)});
        }
    }
    return profile;
}

// Component lists from the OpenXR 1.0 spec, section 6.4.
std::vector<InteractionProfile> build_profiles() {
    std::vector<InteractionProfile> profiles;
    profiles.push_back(make_profile("khr/simple_controller", {{"lr", "input/select/click"},
                                                              {"lr", "input/menu/click"},
                                                              {"lr", "input/grip/pose"},
                                                              {"lr", "input/aim/pose"},
                                                              {"lr", "output/haptic"}}));
    profiles.push_back(make_profile("htc/vive_controller", {{"lr", "input/system/click"},
                                                            {"lr", "input/squeeze/click"},
                                                            {"lr", "input/menu/click"},
                                                            {"lr", "input/trigger/click"},
                                                            {"lr", "input/trigger/value"},
                                                            {"lr", "input/trackpad/x"},
                                                            {"lr", "input/trackpad/y"},
                                                            {"lr", "input/trackpad/click"},
                                                            {"lr", "input/trackpad/touch"},
                                                            {"lr", "input/grip/pose"},
                                                            {"lr", "input/aim/pose"},
                                                            {"lr", "output/haptic"}}));
    profiles.push_back(
        make_profile("valve/index_controller",
                     {{"lr", "input/system/click"},     {"lr", "input/system/touch"},
                      {"lr", "input/a/click"},          {"lr", "input/a/touch"},
                      {"lr", "input/b/click"},          {"lr", "input/b/touch"},
                      {"lr", "input/squeeze/value"},    {"lr", "input/squeeze/force"},
                      {"lr", "input/trigger/click"},    {"lr", "input/trigger/value"},
                      {"lr", "input/trigger/touch"},    {"lr", "input/thumbstick/x"},
                      {"lr", "input/thumbstick/y"},     {"lr", "input/thumbstick/click"},
                      {"lr", "input/thumbstick/touch"}, {"lr", "input/trackpad/x"},
                      {"lr", "input/trackpad/y"},       {"lr", "input/trackpad/force"},
                      {"lr", "input/trackpad/touch"},   {"lr", "input/grip/pose"},
                      {"lr", "input/aim/pose"},         {"lr", "output/haptic"}}));
    profiles.push_back(
        make_profile("oculus/touch_controller",
                     {{"l", "input/x/click"},           {"l", "input/x/touch"},
                      {"l", "input/y/click"},           {"l", "input/y/touch"},
                      {"l", "input/menu/click"},        {"r", "input/a/click"},
                      {"r", "input/a/touch"},           {"r", "input/b/click"},
                      {"r", "input/b/touch"},           {"r", "input/system/click"},
                      {"lr", "input/squeeze/value"},    {"lr", "input/trigger/value"},
                      {"lr", "input/trigger/touch"},    {"lr", "input/thumbstick/x"},
                      {"lr", "input/thumbstick/y"},     {"lr", "input/thumbstick/click"},
                      {"lr", "input/thumbstick/touch"}, {"lr", "input/thumbrest/touch"},
                      {"lr", "input/grip/pose"},        {"lr", "input/aim/pose"},
                      {"lr", "output/haptic"}}));
    return profiles;
}

}  // namespace

std::span<const InteractionProfile> interaction_profiles() {
    static const std::vector<InteractionProfile> profiles = build_profiles();
    return profiles;
}

const InteractionProfile* find_interaction_profile(std::string_view path) {
    for (const InteractionProfile& profile : interaction_profiles()) {
        if (profile.path == path) return &profile;
    }
    return nullptr;
}

const Component* resolve_binding_path(const InteractionProfile& profile, std::string_view path) {
    auto find = [&](std::string_view full) -> const Component* {
        for (const Component& component : profile.components) {
            if (component.path == full) return &component;
        }
        return nullptr;
    };
    if (const Component* exact = find(path)) return exact;
    // spec 6.3.2: a binding to an identifier without a component lets the runtime choose one.
    for (std::string_view suffix : {"/click", "/value", "/pose"}) {
        if (const Component* implied = find(std::string(path) + std::string(suffix)))
            return implied;
    }
    return nullptr;
}

}  // namespace monoplane::simxr
