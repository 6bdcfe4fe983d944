#include "app/commands/gaze_point.h"

#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "rig/angular_error.h"

namespace monoplane::app {

std::optional<study::GazePointRecord> gaze_point(const scenes::SceneRayCaster& scene,
                                                 const rig::Pose& head_in_scene,
                                                 const rig::Rig& rig,
                                                 const glm::dvec3& gaze_in_head) {
    const glm::dvec3 direction = head_in_scene.orientation * gaze_in_head;
    const std::optional<scenes::RayHit> hit = scene.cast(head_in_scene.position, direction);
    study::GazePointRecord point;
    point.mono_plane_m = rig.inputs.mono_plane;
    if (!hit) {
        if (!(gaze_in_head.z < 0.0)) return std::nullopt;
        point.error_arcmin = rig::angular_error_in_direction(rig, gaze_in_head).larger_arcmin();
        return point;
    }
    // The point in the head's frame: its depth is the distance in front of the eyes' plane.
    const glm::dvec3 in_head =
        glm::inverse(head_in_scene.orientation) * (hit->point - head_in_scene.position);
    point.depth_m = -in_head.z;
    point.error_arcmin = rig::angular_error_at_point(rig, in_head).larger_arcmin();
    return point;
}

Result<std::unique_ptr<GazePointFinder>> GazePointFinder::build(
    const std::map<std::string, const scenes::Scene*>& scenes) {
    const auto start = std::chrono::steady_clock::now();
    auto finder = std::make_unique<GazePointFinder>();
    for (const auto& [name, scene] : scenes) {
        Result<std::unique_ptr<scenes::SceneRayCaster>> caster =
            scenes::SceneRayCaster::build(*scene);
        MONOPLANE_TRY(caster);
        finder->casters_[name] = std::move(caster).value();
    }
    finder->cost_.built(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    return finder;
}

std::optional<study::GazePointRecord> GazePointFinder::find(const std::string& scene,
                                                            const rig::Pose& head_in_scene,
                                                            const rig::RigInputs& inputs,
                                                            const glm::dvec3& gaze_in_head) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<study::GazePointRecord> point =
        find_untimed(scene, head_in_scene, inputs, gaze_in_head);
    cost_.found(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                    .count());
    return point;
}

std::optional<study::GazePointRecord> GazePointFinder::find_untimed(
    const std::string& scene, const rig::Pose& head_in_scene, const rig::RigInputs& inputs,
    const glm::dvec3& gaze_in_head) {
    const auto caster = casters_.find(scene);
    if (caster == casters_.end() || !std::isfinite(inputs.mono_plane)) return std::nullopt;
    if (rig_inputs_ != inputs) {
        Result<rig::Rig> rig = rig::build_rig(inputs);
        if (!rig.ok()) return std::nullopt;  // the renderer refused these views too
        rig_ = std::move(rig).value();
        rig_inputs_ = inputs;
    }
    return gaze_point(*caster->second, head_in_scene, *rig_, gaze_in_head);
}

}  // namespace monoplane::app
