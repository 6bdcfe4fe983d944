// The values of `monoplane bench`'s flags, as the user gave them, and the flags that fill them in.
// Checking them is bench_sweep.h's.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands/auto_mono_plane_options.h"
#include "app/commands/lod_flags.h"
#include "scenes/generate.h"

namespace monoplane::app::bench {

// The ten distances of protocols/fink2019.toml (papers/000 Sect. 6) and the far plane.
inline constexpr const char* kDefaultMonoPlanes = "1.6,3,5,8,12,16,20,25,31,39.5,far";

struct BenchOptions {
    std::string scenes = "beams,landscape,spheres";
    std::string modes = "stereo,hybrid,hybrid-farfield";
    std::string variants = "no-opt,discard,occlusion-cull";
    std::string mono_planes = kDefaultMonoPlanes;
    std::string protocol;  // takes the mono planes from a protocol (plus far)
    std::string hmd = "vive";
    int width = 0;
    int height = 0;
    std::string detail = "low";
    std::string view = "default";
    std::uint64_t seed = scenes::kDefaultSeed;
    int frames = 10;
    int warmup = 3;
    bool accuracy = true;
    std::string anti_aliasing = "none";
    std::string ssao = "off";
    std::string stereo_pass = "two";
    std::uint32_t vertex_work = 0;
    double grazing_deg = 1.0;  // rig::RigInputs::grazing_angle, degrees
    bool depth_prepass = false;
    bool separate_tonemap = false;  // RendererOptions::separate_tonemap in every run
    AutoMonoPlaneFlags auto_flags;  // the "auto" entry of --mono-planes
    int auto_warmup = 40;           // extra warm-up frames for auto to settle on its m
    int turning_frames = 0;         // pairs of still and turning-head frames per run (0: none)
    LodFlags lod;                   // a sweep: "off,auto"
    std::string out;
};

// Adds bench's flags to `cmd`, in the order --help lists them; `options` must outlive `cmd`.
void add_bench_options(CLI::App& cmd, BenchOptions& options);

}  // namespace monoplane::app::bench
