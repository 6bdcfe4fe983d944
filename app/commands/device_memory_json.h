// `"device_memory": {"images_mib", "buffers_mib", "total_mib"}`: the device memory the process
// holds, in MiB, by what the allocations hold, after the renderer's transient images share theirs
// (vk_core::live_device_bytes(MemoryKind)). Written by `render --json` and each run of bench.json.
// Vulkan-free, so that bench.json's plain results (app/bench) can hold the figures.
//
// When may this be called: take the bytes while the renderer being reported is alive and has
// rendered (some images are made on the first frame that needs them).
#pragma once

#include <cstdint>

#include "common/json_writer.h"

namespace monoplane::app {

struct DeviceMemoryFigures {
    double images_mib = 0.0;
    double buffers_mib = 0.0;
    double total_mib = 0.0;

    static DeviceMemoryFigures from_bytes(std::uint64_t image_bytes, std::uint64_t buffer_bytes) {
        constexpr double kMiB = 1024.0 * 1024.0;
        return {static_cast<double>(image_bytes) / kMiB, static_cast<double>(buffer_bytes) / kMiB,
                static_cast<double>(image_bytes + buffer_bytes) / kMiB};
    }
};

inline void write_device_memory_json(JsonWriter& j, const DeviceMemoryFigures& m) {
    j.begin_object("device_memory");
    j.value("images_mib", m.images_mib)
        .value("buffers_mib", m.buffers_mib)
        .value("total_mib", m.total_mib);
    j.end_object();
}

}  // namespace monoplane::app
