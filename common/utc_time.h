// The wall-clock time as the study database and its lock files record it: UTC to the second,
// ISO 8601 with a Z ("2026-12-05T11:00:26Z"), so that times sort as text and read the same on
// every lab PC whatever its time zone.
#pragma once

#include <ctime>
#include <string>

namespace monoplane {

// Now, in UTC; reads the system clock. Any time, from any thread (gmtime_r keeps no shared
// state).
inline std::string utc_now_iso8601() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

}  // namespace monoplane
