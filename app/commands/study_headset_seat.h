// Where the participant's head is in the scene on a headset: the seat the first tracked frame
// sets, the head located from the two eyes the runtime reports (with their cant), and the
// renderer's viewer from both.
#pragma once

#include <array>

#include <glm/gtc/quaternion.hpp>

#include "app/headset/openxr_headset.h"
#include "renderer/modes/mode_renderer.h"
#include "rig/pose.h"
#include "study/protocol.h"

namespace monoplane::app {

// The participant's seat: the head pose of the first tracked frame, turned about the vertical
// only, is where the scene's viewpoint is. LOCAL space puts its origin near the starting head on
// most runtimes but not all (some at floor level, simxr at 1.6 m); recentring on the first frame
// makes every runtime start the participant exactly at the viewpoint, looking along it, while
// later head motion (and the head's own pitch and roll) is kept.
class SeatAnchor {
  public:
    // The head pose relative to the anchor, setting the anchor from the first call.
    rig::Pose relative(const rig::Pose& head);

  private:
    bool set_ = false;
    glm::dvec3 origin_{0.0};
    glm::dquat inverse_yaw_{1.0, 0.0, 0.0, 0.0};
};

// The head from the two located eyes: their midpoint, and the orientation halfway between
// theirs. Canted views differ from it by a yaw each, their cant; a
// runtime whose views differ otherwise (a pitch or roll between the eyes) is refused, because
// the rig models displays turned about the head's vertical axis only.
struct LocatedHead {
    rig::Pose head;
    std::array<double, 2> cant = {0.0, 0.0};  // radians, positive turning the eye left
};

// For a frame whose views are valid; throws UserError when they differ by more than a yaw.
LocatedHead located_head(const headset::HeadsetFrame& frame);

// The renderer's viewer: the head relative to the seat, placed at the scene's viewpoint, with
// the runtime's eye distance and calibrated frusta.
modes::StereoViewInputs view_inputs(const headset::HeadsetFrame& frame, const LocatedHead& located,
                                    const rig::Pose& head, const rig::Pose& seat,
                                    const study::Protocol& protocol);

}  // namespace monoplane::app
