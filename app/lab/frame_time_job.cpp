#include "app/lab/frame_time_job.h"

#include <exception>
#include <string>
#include <utility>

namespace monoplane::lab {

FrameTimeJob::~FrameTimeJob() {
    cancel_ = true;
    if (worker_.joinable()) worker_.join();
}

Result<void> FrameTimeJob::start(const FrameTimeProbe& probe, FrameTimeProbeRequest request) {
    if (running_) return Error{"the frame time is being measured: wait for it or cancel it"};
    if (worker_.joinable()) worker_.join();
    cancel_ = false;
    {
        std::lock_guard lock(mutex_);
        progress_ = {};
        result_.reset();
    }
    running_ = true;
    worker_ = std::thread([this, &probe, request = std::move(request)] {
        const ProbeCallback report = [this](const ProbeProgress& p) {
            std::lock_guard lock(mutex_);
            progress_ = p;
            return !cancel_.load();
        };
        // An exception must not end the launcher: it is the measurement's failure.
        Result<FrameTimeEstimate> estimate = Error{"the frame-time probe did not run"};
        try {
            estimate = probe(request, report);
        } catch (const std::exception& e) {
            estimate = Error{std::string("the frame-time probe stopped: ") + e.what()};
        }
        std::lock_guard lock(mutex_);
        result_ = std::move(estimate);
        running_ = false;
    });
    return Ok{};
}

ProbeProgress FrameTimeJob::progress() const {
    std::lock_guard lock(mutex_);
    return progress_;
}

std::optional<Result<FrameTimeEstimate>> FrameTimeJob::take_result() {
    if (running_) return std::nullopt;
    if (worker_.joinable()) worker_.join();
    std::lock_guard lock(mutex_);
    return std::exchange(result_, std::nullopt);
}

}  // namespace monoplane::lab
