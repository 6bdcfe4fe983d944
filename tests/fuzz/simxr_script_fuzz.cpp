// Fuzz target: simxr scripts (simxr/script.h), the TOML that drives the simulated
// OpenXR runtime, and the timeline functions that turn its seconds into nanoseconds.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "simxr/interaction_profiles.h"
#include "simxr/script.h"
#include "hmd/profile.h"
#include "tests/fuzz/fuzz_runner.h"
#include "tests/fuzz/mutator.h"

namespace monoplane {
namespace {

// What parse_script promises about a script it accepts (script.h).
std::string broken_promise(const simxr::Script& s) {
    if (!(s.display_rate_hz > 0.0 && s.display_rate_hz <= 1000.0)) return "a bad display rate";
    if (s.dump_every < 1 || s.missed_slot_every < 0 || s.missed_slot_every == 1)
        return "a bad frame count";
    if (!(s.exit_after_s >= 0.0) || !(s.lose_session_at_s >= 0.0)) return "a negative time";
    if (simxr::find_interaction_profile(s.interaction_profile) == nullptr)
        return "an unknown interaction profile";
    for (std::size_t i = 0; i < s.poses.size(); ++i) {
        if (!(s.poses[i].t >= 0.0) || (i > 0 && !(s.poses[i - 1].t < s.poses[i].t)))
            return "keyframes out of order";
    }
    for (const simxr::InputPress& press : s.inputs) {
        if (!(press.t >= 0.0 && press.duration > 0.0)) return "a bad press window";
    }
    return {};
}

// The runtime asks for poses and presses at frame times in int64 nanoseconds; every keyframe and
// press edge is a boundary where that arithmetic could overflow (UBSan reports it).
void walk_the_timeline(const simxr::Script& s) {
    std::vector<double> times = {-1.0, 0.0, 1e6};
    for (const simxr::PoseKeyframe& k : s.poses) times.insert(times.end(), {k.t, k.t + 1e-3});
    for (const double t : times) static_cast<void>(simxr::head_pose_at(s, t));
    for (const simxr::InputPress& press : s.inputs) {
        for (const double t : {press.t, press.t + press.duration, 0.0}) {
            static_cast<void>(simxr::input_pressed_at(s, press.path, std::llround(t * 1e9)));
        }
    }
}

TEST(Fuzz, SimxrScript) {
    // `hmd = "profile.toml"` in the seeds resolves against the script's folder.
    std::filesystem::copy_file(fuzz::source_path("hmd/profiles/symmetric-90.toml"),
                               fuzz::work_folder("simxr_script") / "profile.toml",
                               std::filesystem::copy_options::overwrite_existing);
    std::vector<std::string> dictionary = fuzz::split_words(R"(
hmd display_rate_hz missed_slot_every physical_device interaction_profile dump_dir
dump_every exit_after_s lose_session_at_s [[pose]] [[input]] [pose] t position
yaw_pitch_roll_deg path duration "profile.toml"
)");
    for (const std::string& name : hmd::builtin_hmd_names()) dictionary.push_back('"' + name + '"');
    for (const simxr::InteractionProfile& profile : simxr::interaction_profiles()) {
        dictionary.push_back('"' + profile.path + '"');
        for (const simxr::Component& component : profile.components)
            dictionary.push_back('"' + component.path + '"');
    }

    const fuzz::FuzzTarget target{
        .name = "simxr_script",
        .seeds = {fuzz::corpus_path("simxr_script")},
        .dictionary = dictionary,
        .file_extension = ".toml",
        .iterations = 15000,
        .run = [](const fuzz::FuzzInput& input) {
            const Result<simxr::Script> script = simxr::parse_script(input.bytes, input.file);
            if (!script) return fuzz::rejected(script.error(), input);
            if (std::string broken = broken_promise(*script); !broken.empty())
                return fuzz::violation("accepted a script with " + broken);
            if (script->frame_period_ns() <= 0)
                return fuzz::violation("a frame period of " +
                                       std::to_string(script->frame_period_ns()) + " ns");
            walk_the_timeline(*script);
            return fuzz::accepted();
        }};
    fuzz::expect_clean(fuzz::run_fuzz_target(target));
}

}  // namespace
}  // namespace monoplane
