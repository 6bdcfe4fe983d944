#include "app/commands/study_headset_seat.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/result.h"

namespace monoplane::app {

rig::Pose SeatAnchor::relative(const rig::Pose& head) {
    if (!set_) {
        const glm::dvec3 forward = head.orientation * glm::dvec3(0.0, 0.0, -1.0);
        const double yaw = std::atan2(-forward.x, -forward.z);
        inverse_yaw_ = glm::angleAxis(-yaw, glm::dvec3(0.0, 1.0, 0.0));
        origin_ = head.position;
        set_ = true;
    }
    rig::Pose pose;
    pose.position = inverse_yaw_ * (head.position - origin_);
    pose.orientation = inverse_yaw_ * head.orientation;
    return pose;
}

LocatedHead located_head(const headset::HeadsetFrame& frame) {
    const rig::Pose& l = frame.views[0].pose;
    const rig::Pose& r = frame.views[1].pose;
    LocatedHead located;
    located.head.position = 0.5 * (l.position + r.position);
    const glm::dquat right =
        glm::dot(l.orientation, r.orientation) < 0.0 ? -r.orientation : r.orientation;
    located.head.orientation = glm::normalize(glm::slerp(l.orientation, right, 0.5));
    constexpr double kTolerance = 0.2 * 3.14159265358979 / 180.0;
    for (int e : {0, 1}) {
        glm::dquat relative =
            glm::inverse(located.head.orientation) * frame.views[e].pose.orientation;
        if (relative.w < 0.0) relative = -relative;
        // A pure yaw is (cos a/2, 0, sin a/2, 0).
        const double off_axis = 2.0 * std::asin(std::min(1.0, std::hypot(relative.x, relative.z)));
        if (off_axis > kTolerance) {
            throw UserError("the headset's " + std::string(e == 0 ? "left" : "right") +
                            " view is turned by " +
                            std::to_string(off_axis * 180.0 / 3.14159265358979) +
                            " degrees about an axis other than the head's vertical; monoplane's "
                            "rig supports parallel views and views canted by a yaw "
                            "(docs/headsets.md, \"Canted headsets\")");
        }
        located.cant[e] = 2.0 * std::atan2(relative.y, relative.w);
    }
    return located;
}

modes::StereoViewInputs view_inputs(const headset::HeadsetFrame& frame, const LocatedHead& located,
                                    const rig::Pose& head, const rig::Pose& seat,
                                    const study::Protocol& protocol) {
    modes::StereoViewInputs inputs;
    inputs.head.position = seat.position + seat.orientation * head.position;
    inputs.head.orientation = seat.orientation * head.orientation;
    inputs.ipd = glm::length(frame.views[1].pose.position - frame.views[0].pose.position);
    inputs.left = frame.views[0].tangents;
    inputs.right = frame.views[1].tangents;
    inputs.cant = located.cant;
    inputs.near = protocol.near;
    inputs.far = protocol.far;
    return inputs;
}

}  // namespace monoplane::app
