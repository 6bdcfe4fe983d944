// The error at gaze of a simulated participant (docs/gaze.md, "The gaze observer"): where simxr's
// default gaze model (simxr/gaze.h: about 3 fixations a second, centre-biased within 12 degrees of
// the view axis, blinks every 4 s) rests during a trial, cast into the trial's scene from its seat
// with the head still, and hybrid's error there at the trial's m (gaze_point.h). The gaze
// observer (`--observer gaze:...`) decides on it; `simulate --predictor gaze-error` regresses the
// simulated choices on it, as the report does on a session's recorded gaze.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "common/result.h"
#include "hmd/profile.h"
#include "rig/rig.h"
#include "scenes/scene.h"
#include "scenes/scene_ray_cast.h"
#include "study/protocol.h"
#include "study/schedule.h"

namespace monoplane::app {

class SimulatedGaze {
  public:
    // How long the participant is taken to look at the test alternative in a trial, and how
    // often the gaze is sampled meanwhile.
    static constexpr double kViewingS = 2.0;
    static constexpr double kSampleHz = 30.0;

    // Generates the protocol's built-in scenes at its [render] detail and builds their ray
    // casters. A scene that names a glTF file is refused (the simulation knows the built-in scenes
    // only), as is an HMD whose rig cannot be built at the protocol's distances.
    static Result<std::unique_ptr<SimulatedGaze>> build(const study::Protocol& protocol,
                                                        const hmd::HmdProfile& hmd);

    // The mean error at gaze, arcmin, over the trial's viewing of the test alternative: the gaze
    // of a participant whose session seed is `seed` (each trial draws its own stream). 0 for a
    // trial whose m is not set (NaN) or where no sample was valid. Deterministic; any thread
    // that does not share the object with a writer (it is not written after build).
    double error_at_gaze(const study::ScheduledTrial& trial, std::uint64_t seed) const;

  private:
    struct SceneGaze {
        std::unique_ptr<scenes::SceneRayCaster> caster;
        rig::Pose seat;
    };
    std::map<std::string, SceneGaze> scenes_;
    std::map<double, rig::Rig> rigs_;  // per m of the protocol
};

}  // namespace monoplane::app
