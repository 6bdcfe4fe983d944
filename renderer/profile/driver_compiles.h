// Shader compiles inside the Vulkan driver, counted where they can be: a driver that compiles a
// new variant of a shader it already has, because some state or uniform value it keys on changed,
// stalls the frame that needs it (on lavapipe, hundreds of milliseconds). monoplane creates no
// pipeline after warm-up (vk_core::pipelines_created), so any compile after warm-up is such a
// variant: the headset's frame log, `bench --turning-frames` and the tests watch this count.
//
// How: Mesa's LLVM-based drivers (lavapipe/llvmpipe) optimise each shader module with LLVM's
// C entry point LLVMRunPasses and generate its code in LLVMGetPointerToGlobal. The monoplane
// executable defines both (and exports them), so the dynamic linker binds the driver's calls to
// these definitions first; each forwards to the libLLVM the driver loaded, counting modules and
// the time spent. Drivers that compile with their own compiler (NVIDIA, AMD's ACO, ...) never
// call them: there the count is not measurable and stays zero.
// When may this be called: any time, from any thread; the counts only grow.
#pragma once

#include <cstdint>

namespace monoplane::profile {

struct DriverCompiles {
    // The driver compiles through LLVM (it has compiled at least once: lavapipe compiles every
    // pipeline it creates), so the counts below mean something. Reading it costs two loads: it
    // may be read every frame.
    bool measurable = false;
    std::uint64_t modules = 0;  // shader modules the driver compiled, since the process began
    double seconds = 0.0;       // time spent in those compiles, summed over the driver's threads
};

DriverCompiles driver_compiles();

// What happened between two readings (later minus earlier), for a frame or a measurement.
DriverCompiles compiles_between(const DriverCompiles& earlier, const DriverCompiles& later);

}  // namespace monoplane::profile
