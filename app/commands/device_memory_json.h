// `"device_memory": {"images_mib", "buffers_mib", "total_mib"}`: the device memory the process
// holds, in MiB, by what the allocations hold, after the renderer's transient images share theirs
// (vk_core::live_device_bytes). Written by `render --json` and each run of bench.json.
//
// When may this be called: take a snapshot while the renderer being reported is alive and has
// rendered (some images are made on the first frame that needs them).
#pragma once

#include "common/json_writer.h"
#include "renderer/vk/memory.h"

namespace monoplane::app {

struct DeviceMemoryFigures {
    double images_mib = 0.0;
    double buffers_mib = 0.0;
    double total_mib = 0.0;
};

inline DeviceMemoryFigures device_memory_now() {
    constexpr double kMiB = 1024.0 * 1024.0;
    const auto images = vk_core::live_device_bytes(vk_core::MemoryKind::kImage);
    const auto buffers = vk_core::live_device_bytes(vk_core::MemoryKind::kBuffer);
    return {static_cast<double>(images) / kMiB, static_cast<double>(buffers) / kMiB,
            static_cast<double>(images + buffers) / kMiB};
}

inline void write_device_memory_json(JsonWriter& j, const DeviceMemoryFigures& m) {
    j.begin_object("device_memory");
    j.value("images_mib", m.images_mib)
        .value("buffers_mib", m.buffers_mib)
        .value("total_mib", m.total_mib);
    j.end_object();
}

}  // namespace monoplane::app
