// simxr's interaction-profile tables against the OpenXR 1.0 specification, section 6.4
// "Interaction Profile Paths" (the expected lists below are copied from the spec text, not from
// the tables), and the binding rules of section 11.4 "Suggested Bindings".
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "simxr/interaction_profiles.h"

namespace monoplane::simxr {
namespace {

bool has_component(const InteractionProfile& profile, const std::string& path) {
    return std::ranges::any_of(profile.components,
                               [&](const Component& c) { return c.path == path; });
}

const InteractionProfile& profile(const std::string& vendor_and_name) {
    const InteractionProfile* found =
        find_interaction_profile("/interaction_profiles/" + vendor_and_name);
    EXPECT_NE(found, nullptr) << vendor_and_name;
    static const InteractionProfile none;
    return found != nullptr ? *found : none;
}

// The nine profiles of 6.4.1 to 6.4.9, their "Valid for user paths" and how many components the
// spec lists for each (per user path, summed; the Touch controller's x/y/menu are left only and
// its a/b/system right only).
TEST(SimxrProfiles, EveryCoreProfileWithItsUserPathsAndComponentCount) {
    const std::vector<std::string> hands = {"/user/hand/left", "/user/hand/right"};
    struct Expected {
        std::string name;
        std::vector<std::string> users;
        std::size_t components;
    };
    const std::vector<Expected> expected = {
        {"khr/simple_controller", hands, 5 * 2},
        {"google/daydream_controller", hands, 7 * 2},
        {"htc/vive_controller", hands, 12 * 2},
        {"htc/vive_pro", {"/user/head"}, 4},
        {"microsoft/motion_controller", hands, 13 * 2},
        {"microsoft/xbox_controller", {"/user/gamepad"}, 24},
        {"oculus/go_controller", hands, 9 * 2},
        {"oculus/touch_controller", hands, 5 + 5 + 11 * 2},
        {"valve/index_controller", hands, 22 * 2},
    };
    ASSERT_EQ(interaction_profiles().size(), expected.size());
    for (const Expected& e : expected) {
        const InteractionProfile& p = profile(e.name);
        EXPECT_EQ(p.user_paths, e.users) << e.name;
        EXPECT_EQ(p.components.size(), e.components) << e.name;
        for (const Component& c : p.components) {
            EXPECT_FALSE(user_path_of(p, c.path).empty()) << c.path;
        }
    }
    EXPECT_EQ(find_interaction_profile("/interaction_profiles/acme/stick"), nullptr);
}

TEST(SimxrProfiles, ComponentsMatchTheSpec) {
    const InteractionProfile& motion = profile("microsoft/motion_controller");
    for (const char* path :
         {"/user/hand/left/input/thumbstick/x", "/user/hand/left/input/thumbstick/y",
          "/user/hand/right/input/thumbstick/click", "/user/hand/left/input/squeeze/click",
          "/user/hand/right/input/trackpad/touch", "/user/hand/left/input/trigger/value",
          "/user/hand/right/input/menu/click", "/user/hand/left/output/haptic"}) {
        EXPECT_TRUE(has_component(motion, path)) << path;
    }
    // The motion controller's trigger has a value only, its thumbstick no touch.
    EXPECT_FALSE(has_component(motion, "/user/hand/left/input/trigger/click"));
    EXPECT_FALSE(has_component(motion, "/user/hand/left/input/thumbstick/touch"));

    const InteractionProfile& xbox = profile("microsoft/xbox_controller");
    for (const char* path :
         {"/user/gamepad/input/a/click", "/user/gamepad/input/view/click",
          "/user/gamepad/input/dpad_left/click", "/user/gamepad/input/trigger_right/value",
          "/user/gamepad/input/thumbstick_left/y", "/user/gamepad/output/haptic_left",
          "/user/gamepad/output/haptic_right_trigger"}) {
        EXPECT_TRUE(has_component(xbox, path)) << path;
    }
    EXPECT_FALSE(has_component(xbox, "/user/hand/left/input/a/click"));

    const InteractionProfile& vive_pro = profile("htc/vive_pro");
    EXPECT_TRUE(has_component(vive_pro, "/user/head/input/system/click"));
    EXPECT_TRUE(has_component(vive_pro, "/user/head/input/mute_mic/click"));

    const InteractionProfile& touch = profile("oculus/touch_controller");
    EXPECT_TRUE(has_component(touch, "/user/hand/left/input/x/touch"));
    EXPECT_TRUE(has_component(touch, "/user/hand/left/input/menu/click"));
    EXPECT_FALSE(has_component(touch, "/user/hand/right/input/x/click"));
    EXPECT_TRUE(has_component(touch, "/user/hand/right/input/system/click"));
    EXPECT_FALSE(has_component(touch, "/user/hand/left/input/system/click"));
    EXPECT_TRUE(has_component(touch, "/user/hand/right/input/thumbrest/touch"));

    EXPECT_TRUE(has_component(profile("oculus/go_controller"), "/user/hand/left/input/back/click"));
    EXPECT_TRUE(has_component(profile("google/daydream_controller"),
                              "/user/hand/right/input/trackpad/click"));
    EXPECT_FALSE(has_component(profile("google/daydream_controller"),
                               "/user/hand/right/output/haptic"));  // no haptics listed
    EXPECT_TRUE(
        has_component(profile("valve/index_controller"), "/user/hand/right/input/trackpad/force"));
}

TEST(SimxrProfiles, ComponentKindsFollowTheirNames) {
    std::map<std::string, ComponentKind> kinds;
    for (const Component& c : profile("microsoft/xbox_controller").components)
        kinds[c.path] = c.kind;
    EXPECT_EQ(kinds["/user/gamepad/input/a/click"], ComponentKind::boolean);
    EXPECT_EQ(kinds["/user/gamepad/input/trigger_left/value"], ComponentKind::scalar);
    EXPECT_EQ(kinds["/user/gamepad/input/thumbstick_right/x"], ComponentKind::scalar);
    EXPECT_EQ(kinds["/user/gamepad/output/haptic_left_trigger"], ComponentKind::haptic);
    for (const Component& c : profile("khr/simple_controller").components) kinds[c.path] = c.kind;
    EXPECT_EQ(kinds["/user/hand/left/input/aim/pose"], ComponentKind::pose);
}

TEST(SimxrProfiles, BindingPathsAreComponentsOrTheirIdentifiers) {
    const InteractionProfile& vive = profile("htc/vive_controller");
    EXPECT_TRUE(is_binding_path(vive, "/user/hand/left/input/trigger/value"));
    EXPECT_TRUE(is_binding_path(vive, "/user/hand/left/input/trigger"));
    EXPECT_TRUE(is_binding_path(vive, "/user/hand/right/input/trackpad"));
    EXPECT_TRUE(is_binding_path(vive, "/user/hand/right/output/haptic"));
    EXPECT_FALSE(is_binding_path(vive, "/user/hand/right/input"));
    EXPECT_FALSE(is_binding_path(vive, "/user/hand/right/input/thumbstick"));
    EXPECT_FALSE(is_binding_path(vive, "/user/hand/right/input/trigger/force"));
    EXPECT_FALSE(is_binding_path(vive, "/user/head/input/trigger/value"));
    EXPECT_FALSE(is_binding_path(vive, "/user/hand/right"));
}

std::vector<std::string> bound(const std::string& profile_name, const std::string& path,
                               ActionUse use) {
    std::vector<std::string> paths;
    for (const Component* c : bound_components(profile(profile_name), path, use)) {
        paths.push_back(c->path);
    }
    return paths;
}

// spec 11.4: an identifier binds click then value for booleans, value then click for floats,
// x and y for vector2f, pose for poses; an input the action cannot read stays unbound.
TEST(SimxrProfiles, IdentifiersBindTheComponentTheActionTypeReads) {
    using V = std::vector<std::string>;
    const std::string trigger = "/user/hand/left/input/trigger";
    EXPECT_EQ(bound("htc/vive_controller", trigger, ActionUse::boolean), V{trigger + "/click"});
    EXPECT_EQ(bound("htc/vive_controller", trigger, ActionUse::scalar), V{trigger + "/value"});
    // The Touch trigger has no click: a boolean reads its value (thresholded).
    EXPECT_EQ(bound("oculus/touch_controller", trigger, ActionUse::boolean), V{trigger + "/value"});
    // The simple controller's select has no value: a float reads its click.
    EXPECT_EQ(bound("khr/simple_controller", "/user/hand/left/input/select", ActionUse::scalar),
              V{"/user/hand/left/input/select/click"});
    const std::string stick = "/user/hand/right/input/thumbstick";
    EXPECT_EQ(bound("microsoft/motion_controller", stick, ActionUse::vector2),
              (V{stick + "/x", stick + "/y"}));
    EXPECT_EQ(bound("microsoft/motion_controller", stick, ActionUse::boolean), V{stick + "/click"});
    EXPECT_EQ(bound("microsoft/motion_controller", stick + "/x", ActionUse::vector2), V{});
    EXPECT_EQ(bound("khr/simple_controller", "/user/hand/left/input/grip", ActionUse::pose),
              V{"/user/hand/left/input/grip/pose"});
    EXPECT_EQ(bound("khr/simple_controller", "/user/hand/left/input/grip/pose", ActionUse::boolean),
              V{});
    EXPECT_EQ(bound("khr/simple_controller", "/user/hand/left/output/haptic", ActionUse::vibration),
              V{"/user/hand/left/output/haptic"});
    EXPECT_EQ(
        bound("khr/simple_controller", "/user/hand/left/input/menu/click", ActionUse::vibration),
        V{});
}

TEST(SimxrProfiles, LocalizedNamesHaveTheRequestedParts) {
    const InteractionProfile& simple = profile("khr/simple_controller");
    EXPECT_EQ(localized_source_name(simple, "/user/hand/left/input/select/click", true, true, true),
              "Left Hand Khronos Simple Controller Select Click");
    EXPECT_EQ(localized_source_name(simple, "/user/hand/right/input/aim/pose", true, false, false),
              "Right Hand");
    EXPECT_EQ(localized_source_name(simple, "/user/hand/right/input/aim/pose", false, false, true),
              "Aim Pose");
    EXPECT_EQ(localized_source_name(profile("microsoft/xbox_controller"),
                                    "/user/gamepad/input/dpad_up/click", true, false, true),
              "Gamepad Dpad Up Click");
}

}  // namespace
}  // namespace monoplane::simxr
