// What finding the gaze points costs a session (docs/gaze.md, "Cost"): the ray casters' build
// when the session begins, and each frame's lookup on the CPU, kept as a histogram of 1 us bins so
// that a session of any length keeps the same few kilobytes. The session's summary prints it.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace monoplane::app {

class GazePointCost {
  public:
    void built(double milliseconds) { build_ms_ = milliseconds; }
    void found(double microseconds);

    std::int64_t lookups() const { return lookups_; }
    // The q-quantile (0 < q < 1) of the lookups' times, microseconds, to the bin (1 us; the last
    // bin holds everything from kBins - 1 us on); 0 before any lookup.
    double quantile_us(double q) const;
    // "gaze points: 9346 lookups, 11 us each (median), 25 us (99th percentile); ray casting
    // prepared in 85 ms when the session began".
    std::string summary() const;

  private:
    static constexpr int kBins = 10'000;
    std::array<std::int32_t, kBins> bins_{};
    std::int64_t lookups_ = 0;
    double build_ms_ = 0.0;
};

}  // namespace monoplane::app
