#include "app/headset/response_device.h"

#include <fcntl.h>
#include <linux/input.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace monoplane::headset {

std::string response_device_error(const std::string& path, int error) {
    const std::string what = "cannot read the response device " + path + ": ";
    if (error == EACCES || error == EPERM) {
        return what +
               "permission denied; add your user to the device's group (usually 'input': "
               "sudo usermod -aG input $USER, then log in again) or give it a udev rule";
    }
    if (error == ENOENT || error == ENODEV || error == ENXIO) {
        return what + "no such device; is it plugged in? (ls -l /dev/input/by-id)";
    }
    return what + std::strerror(error);
}

Result<ResponseDevice> ResponseDevice::open(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return Error{response_device_error(path, errno)};
    // Event times on the clock the runtime converts (XR_KHR_convert_timespec_time), not the
    // wall clock the kernel stamps by default.
    int clock = CLOCK_MONOTONIC;
    static_cast<void>(::ioctl(fd, EVIOCSCLOCKID, &clock));
    return ResponseDevice(fd, path);
}

ResponseDevice ResponseDevice::adopt(int fd, std::string path) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    return ResponseDevice(fd, std::move(path));
}

ResponseDevice::ResponseDevice(ResponseDevice&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), path_(std::move(other.path_)) {}

ResponseDevice& ResponseDevice::operator=(ResponseDevice&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
        path_ = std::move(other.path_);
    }
    return *this;
}

ResponseDevice::~ResponseDevice() {
    if (fd_ >= 0) ::close(fd_);
}

Result<std::vector<DeviceKeyPress>> ResponseDevice::take_presses() {
    std::vector<DeviceKeyPress> presses;
    input_event events[64];
    for (;;) {
        const ssize_t n = ::read(fd_, events, sizeof events);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;  // nothing more now
        if (n < 0) return Error{response_device_error(path_, errno)};
        if (n == 0) break;  // a pipe's writer closed (tests); a device never ends
        // The kernel hands out whole events only.
        for (std::size_t i = 0; i < static_cast<std::size_t>(n) / sizeof(input_event); ++i) {
            const input_event& e = events[i];
            if (e.type != EV_KEY || e.value != 1) continue;
            presses.push_back({e.code, timespec{e.input_event_sec, e.input_event_usec * 1000}});
        }
    }
    return presses;
}

}  // namespace monoplane::headset
