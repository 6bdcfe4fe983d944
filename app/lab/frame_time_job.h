// The launcher's frame-time measurement on a worker thread: the probe (frame_time_probe.h) takes
// seconds on a CPU renderer (llvmpipe: 3 to 13 s per preset), so the window keeps drawing, shows
// how far it is and can cancel it, while the probe renders on a device of its own.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "app/lab/frame_time_probe.h"
#include "common/result.h"

namespace monoplane::lab {

// Runs one probe: the app's probe_frame_time with the launcher's context options.
using FrameTimeProbe =
    std::function<Result<FrameTimeEstimate>(const FrameTimeProbeRequest&, const ProbeCallback&)>;

class FrameTimeJob {
  public:
    FrameTimeJob() = default;
    // Cancels a probe still running and waits for it (at most the frame in flight).
    ~FrameTimeJob();
    FrameTimeJob(const FrameTimeJob&) = delete;
    FrameTimeJob& operator=(const FrameTimeJob&) = delete;

    // Starts `probe` on the worker; refused while one runs. `probe` must outlive the job.
    Result<void> start(const FrameTimeProbe& probe, FrameTimeProbeRequest request);
    bool running() const { return running_; }
    // Asks the probe to stop before its next frame; take_result then says it was cancelled.
    void cancel() { cancel_ = true; }
    ProbeProgress progress() const;
    // The probe's outcome once it has ended (the worker joined); none while it runs. Once.
    std::optional<Result<FrameTimeEstimate>> take_result();

  private:
    std::thread worker_;
    mutable std::mutex mutex_;
    ProbeProgress progress_;
    std::optional<Result<FrameTimeEstimate>> result_;
    std::atomic<bool> running_{false};
    std::atomic<bool> cancel_{false};
};

}  // namespace monoplane::lab
