// Fuzz target: HMD profiles (hmd/profile.h), the TOML files that describe a headset's frusta.
#include <gtest/gtest.h>

#include <cmath>

#include "hmd/profile.h"
#include "tests/fuzz/fuzz_runner.h"
#include "tests/fuzz/mutator.h"

namespace monoplane {
namespace {

// What parse_hmd_profile promises about a profile it accepts; the rig asserts on these.
std::string broken_promise(const hmd::HmdProfile& p) {
    if (p.name.empty()) return "an empty name";
    if (!(p.ipd >= 0.0 && p.ipd <= 0.1)) return "an IPD outside [0, 0.1]";
    if (p.width < 16 || p.width > 16384 || p.height < 16 || p.height > 16384)
        return "a size outside [16, 16384]";
    for (const rig::Tangents& t : {p.left, p.right}) {
        if (!(t.left < 0.0 && 0.0 < t.right && t.down < 0.0 && 0.0 < t.up))
            return "tangents of the wrong sign";
        for (const double v : {t.left, t.right, t.down, t.up}) {
            if (!(std::abs(v) <= 10.0)) return "a tangent beyond 10";
        }
    }
    for (const double cant : p.cant_deg) {
        if (!(std::abs(cant) <= 45.0)) return "a cant beyond 45 degrees";
    }
    return {};
}

TEST(Fuzz, HmdProfile) {
    const fuzz::FuzzTarget target{
        .name = "hmd_profile",
        .seeds = {fuzz::source_path("hmd/profiles"), fuzz::corpus_path("hmd_profile")},
        .dictionary = fuzz::split_words(R"(name ipd width height [left] [right] left right
            tan_left tan_right tan_down tan_up cant_deg left.tan_up right.cant_deg)"),
        .file_extension = ".toml",
        .iterations = 15000,
        .run = [](const fuzz::FuzzInput& input) {
            const Result<hmd::HmdProfile> profile =
                hmd::parse_hmd_profile(input.bytes, input.file.string());
            if (!profile) return fuzz::rejected(profile.error(), input);
            if (std::string broken = broken_promise(*profile); !broken.empty())
                return fuzz::violation("accepted a profile with " + broken);
            // What every caller does next.
            const rig::RigInputs inputs = hmd::rig_inputs(*profile, 5.0);
            const std::array<double, 2> cant = hmd::cant_radians(*profile);
            if (inputs.eye_width != profile->width || !std::isfinite(cant[0] + cant[1]))
                return fuzz::violation("rig inputs that differ from the profile");
            return fuzz::accepted();
        }};
    fuzz::expect_clean(fuzz::run_fuzz_target(target));
}

}  // namespace
}  // namespace monoplane
