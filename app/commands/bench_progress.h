// `monoplane bench`'s progress: one line on stderr per step, with the time left.
#pragma once

#include <chrono>
#include <string>

namespace monoplane::app::bench {

// One line of progress on stderr, rewritten in place on a terminal.
class Progress {
  public:
    // Starts the clock; `total`: the steps the sweep makes.
    explicit Progress(int total);

    // Any time: `done` of the total steps are done, `what` is under way.
    void show(int done, const std::string& what) const;

  private:
    int total_;
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
};

}  // namespace monoplane::app::bench
