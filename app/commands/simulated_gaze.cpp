#include "app/commands/simulated_gaze.h"

#include <cmath>

#include "app/commands/gaze_point.h"
#include "scenes/generate.h"
#include "simxr/gaze.h"

namespace monoplane::app {
namespace {

// Apart from every other stream drawn from a session's seed (schedule, observer).
constexpr std::uint64_t kGazeStream = 0x6A2E'0000'0000'0000ull;

// splitmix64's finaliser: one trial's gaze seed from the session's seed and the trial's index.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

}  // namespace

Result<std::unique_ptr<SimulatedGaze>> SimulatedGaze::build(const study::Protocol& protocol,
                                                            const hmd::HmdProfile& hmd) {
    auto gaze = std::unique_ptr<SimulatedGaze>(new SimulatedGaze());
    const std::optional<scenes::Detail> detail = scenes::parse_detail(protocol.render.detail);
    if (!detail) return Error{"unknown scene detail '" + protocol.render.detail + "'"};
    for (const std::string& name : protocol.scenes) {
        const std::optional<scenes::SceneId> id = scenes::parse_scene_id(name);
        if (!id) {
            return Error{"scene '" + name +
                         "' names a file: simulated gaze knows the built-in scenes only (beams, "
                         "landscape, spheres)"};
        }
        const scenes::Scene scene = scenes::generate_scene(*id, *detail);
        Result<std::unique_ptr<scenes::SceneRayCaster>> caster =
            scenes::SceneRayCaster::build(scene);
        MONOPLANE_TRY(caster);
        gaze->scenes_[name] = {std::move(caster).value(), scene.find_viewpoint("default")->head};
    }
    for (const double m : protocol.mono_planes) {
        rig::RigInputs inputs = hmd::rig_inputs(hmd, m);
        inputs.near = protocol.near;
        inputs.far = protocol.far;
        Result<rig::Rig> rig = rig::build_rig(inputs);
        MONOPLANE_TRY(rig);
        gaze->rigs_.emplace(m, std::move(rig).value());
    }
    return gaze;
}

double SimulatedGaze::error_at_gaze(const study::ScheduledTrial& trial, std::uint64_t seed) const {
    // A NaN key would find some plane: std::map's order holds no NaN apart.
    if (!std::isfinite(trial.mono_plane)) return 0.0;
    const auto scene = scenes_.find(trial.scene);
    const auto rig = rigs_.find(trial.mono_plane);
    if (scene == scenes_.end() || rig == rigs_.end()) return 0.0;
    simxr::GazeScript script;
    script.seed = mix(seed ^ (kGazeStream + static_cast<std::uint64_t>(trial.index)));
    double sum = 0.0;
    int samples = 0;
    const int count = static_cast<int>(kViewingS * kSampleHz);
    for (int i = 0; i < count; ++i) {
        // The default looks about the view's centre whatever the head does: a still head.
        const simxr::GazeSample sample = simxr::gaze_at(script, i / kSampleHz, rig::Pose{});
        if (!sample.valid) continue;
        const std::optional<study::GazePointRecord> point =
            gaze_point(*scene->second.caster, scene->second.seat, rig->second, sample.direction);
        if (!point) continue;
        sum += point->error_arcmin;
        ++samples;
    }
    return samples > 0 ? sum / samples : 0.0;
}

}  // namespace monoplane::app
