// A response box (or any keyboard) read directly from its evdev device, /dev/input/event* or a
// /dev/input/by-id/...-event-kbd link ([responses] device, docs/study.md): key presses whatever
// window has the focus, so the experimenter's keyboard stays the experimenter's. Non-blocking:
// the session's frame loop polls it once a frame.
#pragma once

#include <ctime>
#include <string>
#include <vector>

#include "common/result.h"

namespace monoplane::headset {

// A key going down on the device: its code (KEY_*) and the kernel's time of the event, on
// CLOCK_MONOTONIC (asked for when the device is opened; a descriptor that is no evdev device
// keeps what its writer put there).
struct DeviceKeyPress {
    int code = 0;
    timespec time{};
};

class ResponseDevice {
  public:
    // Opens `path` for reading, non-blocking. The error is one line that names the path and what
    // to do: no such device (is it plugged in? ls -l /dev/input/by-id), or permission denied (the
    // user must be in the device's group, usually `input`: sudo usermod -aG input $USER, then log
    // in again, or a udev rule). Any time.
    static Result<ResponseDevice> open(const std::string& path);
    // Reads from a descriptor already open (tests: a pipe), taking it over; non-blocking is set.
    static ResponseDevice adopt(int fd, std::string path);

    ResponseDevice(ResponseDevice&& other) noexcept;
    ResponseDevice& operator=(ResponseDevice&& other) noexcept;
    ResponseDevice(const ResponseDevice&) = delete;
    ResponseDevice& operator=(const ResponseDevice&) = delete;
    ~ResponseDevice();

    // The keys pressed since the last call, in order: EV_KEY events with value 1; releases (0)
    // and autorepeats (2) are not presses. An error (the device was unplugged) names the path.
    // Once a frame, from the thread that opened it.
    Result<std::vector<DeviceKeyPress>> take_presses();

    const std::string& path() const { return path_; }

  private:
    ResponseDevice(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
    int fd_ = -1;
    std::string path_;
};

// The one-line error of a device that cannot be opened: `error` is open(2)'s errno. Pure.
std::string response_device_error(const std::string& path, int error);

}  // namespace monoplane::headset
