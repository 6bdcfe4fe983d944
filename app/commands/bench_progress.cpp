#include "app/commands/bench_progress.h"

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace monoplane::app::bench {

Progress::Progress(int total)
    : total_(total), start_(std::chrono::steady_clock::now()), terminal_(isatty(2) != 0) {}

void Progress::show(int done, const std::string& what) const {
    constexpr int kWidth = 24;
    const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::ostringstream line;
    line << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kWidth - filled), '-') << "] " << done << "/"
         << total_ << " " << what;
    if (done > 0 && done < total_) {
        const double remaining = elapsed / done * (total_ - done);
        line << "  about " << static_cast<int>(remaining / 60) << " min "
             << static_cast<int>(std::fmod(remaining, 60.0)) << " s left";
    }
    // A terminal gets one line rewritten in place; a log file one line per step.
    if (terminal_) {
        std::cerr << std::left << std::setw(110) << line.str() << std::flush;
    } else {
        std::cerr << line.str().substr(1) << "\n";
    }
}

}  // namespace monoplane::app::bench
