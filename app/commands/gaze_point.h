// Where a participant's gaze rests in the scene and hybrid's error there (docs/gaze.md): the gaze
// ray from the eyes' midpoint, cast on the CPU against the scene's surfaces (SceneRayCaster), and
// the rig's error at the point it meets (rig::angular_error_at_point), or at infinity along the
// ray where it meets nothing. Derived as each frame is logged: no GPU pass is added.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <glm/ext/vector_double3.hpp>

#include "app/commands/gaze_point_cost.h"
#include "common/result.h"
#include "rig/pose.h"
#include "rig/rig.h"
#include "scenes/scene.h"
#include "scenes/scene_ray_cast.h"
#include "study/frame_record.h"

namespace monoplane::app {

// The gaze point for a head at `head_in_scene` (the eyes' midpoint and the head's orientation in
// the scene's frame), looking along `gaze_in_head` (unit, head frame, -z ahead), with the frame's
// rig at the trial's mono plane. None for a gaze that does not point ahead of the eyes' plane
// (gaze_in_head.z >= 0) and meets nothing: no error is defined there. Pure.
std::optional<study::GazePointRecord> gaze_point(const scenes::SceneRayCaster& scene,
                                                 const rig::Pose& head_in_scene,
                                                 const rig::Rig& rig,
                                                 const glm::dvec3& gaze_in_head);

// A session's gaze points: one ray caster per scene, built when the session begins (only when
// it records gaze), and the rig of the last frame asked about, kept while its inputs stay the
// same (they change with the trial's m or the runtime's views, not with the head's motion).
class GazePointFinder {
  public:
    // scenes: by the protocol's name; they need not outlive the finder.
    static Result<std::unique_ptr<GazePointFinder>> build(
        const std::map<std::string, const scenes::Scene*>& scenes);

    // A trial frame of `scene` whose gaze sample was valid: the head placed in the scene, and
    // the rig's inputs for the frame's views (modes::rig_inputs_for) at the trial's m. None where
    // the trial has no m yet (NaN), the rig refuses the inputs, or gaze_point gives none.
    std::optional<study::GazePointRecord> find(const std::string& scene,
                                               const rig::Pose& head_in_scene,
                                               const rig::RigInputs& rig_inputs,
                                               const glm::dvec3& gaze_in_head);

    // What the build and the lookups so far cost (each find() is timed).
    const GazePointCost& cost() const { return cost_; }

  private:
    std::optional<study::GazePointRecord> find_untimed(const std::string& scene,
                                                       const rig::Pose& head_in_scene,
                                                       const rig::RigInputs& rig_inputs,
                                                       const glm::dvec3& gaze_in_head);

    GazePointCost cost_;
    std::map<std::string, std::unique_ptr<scenes::SceneRayCaster>> casters_;
    std::optional<rig::RigInputs> rig_inputs_;
    std::optional<rig::Rig> rig_;
};

}  // namespace monoplane::app
