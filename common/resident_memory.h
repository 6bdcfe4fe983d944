// The process's resident memory (RSS), as the kernel counts it: what a long session or benchmark
// must keep bounded. Linux only (/proc/self/statm); none elsewhere or when it cannot be read.
// When may this be called: any time, from any thread.
#pragma once

#include <cstdint>
#include <fstream>
#include <optional>

#include <unistd.h>

namespace monoplane {

inline std::optional<std::uint64_t> resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t total_pages = 0;
    std::uint64_t resident_pages = 0;
    if (!(statm >> total_pages >> resident_pages)) return std::nullopt;
    const long page = sysconf(_SC_PAGESIZE);
    if (page <= 0) return std::nullopt;
    return resident_pages * static_cast<std::uint64_t>(page);
}

}  // namespace monoplane
