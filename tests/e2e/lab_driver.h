// The end-to-end tests' driver of `monoplane lab` (lab_window_test, lab_day_test): the launcher
// runs on a virtual X server and is driven by real X input from xdotool (XTEST), keys and mouse
// clicks at the places the window's state dump gives for its controls, never by calls into the
// program; its state file, screenshots and database are what the tests read.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

// Last: Xlib defines macros (None, Bool, Status) that other headers use as names.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#undef None
#undef Bool
#undef Status

namespace monoplane {
// The tests' own helpers (inline: each test file uses some of them).
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

inline std::string source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir ? dir : ".";
}

inline fs::path test_folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir =
        fs::temp_directory_path() /
        ("monoplane_lab_" + std::string(info->test_suite_name()) + "_" + info->name());
    return dir;
}

// Why the test cannot run here; empty when it can.
inline std::string missing_prerequisite() {
    if (std::getenv("DISPLAY") == nullptr) return "no X server (DISPLAY unset; run under xvfb-run)";
    if (std::system("xdotool version > /dev/null 2>&1") != 0)
        return "xdotool is not installed (scripts/install-deps.sh installs it)";
    return {};
}

inline std::string xdo_output(const std::string& args) {
    std::string text;
    if (FILE* pipe = popen(("xdotool " + args + " 2>/dev/null").c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof buffer, pipe)) text += buffer;
        pclose(pipe);
    }
    return text;
}

inline void xdo(const std::string& args) {
    ASSERT_EQ(std::system(("xdotool " + args).c_str()), 0) << "xdotool " << args;
    // The launcher draws at about 60 frames a second: a few frames for each event to land.
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
}

inline bool wait_for(const std::function<bool()>& done, int seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (std::chrono::steady_clock::now() < until) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return done();
}

// The control `name` of a state dump; null when the dump has no such control (a const json's
// operator[] must not be asked for a key it lacks).
inline json control_in(const json& state, const std::string& name) {
    if (!state.is_object() || !state.contains("controls")) return json();
    const json& controls = state.at("controls");
    if (!controls.is_object() || !controls.contains(name)) return json();
    return controls.at(name);
}

// The launcher process, its window and its state file.
// How a test starts the launcher: its own options after the state file and screenshots, and
// its environment's changes.
struct LabStart {
    bool db_and_protocols = true;  // --db DIR/lab.sqlite --protocols DIR/protocols
    std::vector<std::pair<std::string, std::string>> env;  // set ("" value: unset)
};

class Lab {
  public:
    Lab(const fs::path& dir, const std::vector<std::string>& extra, const LabStart& start = {})
        : dir_(dir) {
        // The validation layer on, as in every test: any message fails the launcher.
        std::vector<std::string> args = {MONOPLANE_EXE, "--validation", "lab"};
        if (start.db_and_protocols) {
            args.insert(args.end(), {"--db", (dir / "lab.sqlite").string(), "--protocols",
                                     (dir / "protocols").string()});
        }
        args.insert(args.end(), {"--state-file", state_file().string(), "--screenshot-dir",
                                 (dir / "shots").string()});
        args.insert(args.end(), extra.begin(), extra.end());
        pid_ = fork();
        if (pid_ == 0) {
            const std::string log = (dir / "lab.log").string();
            std::freopen(log.c_str(), "a", stdout);
            dup2(fileno(stdout), STDERR_FILENO);
            // What the launcher remembers stays in the test's folder, never in the user's.
            setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1);
            for (const auto& [name, value] : start.env) {
                if (value.empty())
                    unsetenv(name.c_str());
                else
                    setenv(name.c_str(), value.c_str(), 1);
            }
            std::vector<char*> argv;
            for (std::string& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
    }
    ~Lab() {
        if (pid_ > 0 && !exited_) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }

    fs::path state_file() const { return dir_ / "state.json"; }
    const std::string& window() const { return window_; }

    // Clicks the middle of the control `name` where the state dump says the window drew it;
    // false when the state names no such control within `seconds`. A control shows in the dump
    // a frame or more after the step that draws it, which on a loaded machine can be a while:
    // the click waits for the control (visible, where the dump says so) instead of racing it.
    bool click(const std::string& name, int seconds = 30) {
        json c;
        wait_for(
            [&] {
                c = state()["controls"][name];
                return c.is_object() && c.value("visible", true);
            },
            seconds);
        if (!c.is_object()) return false;
        const int x = static_cast<int>(c["x"].get<double>() + c["width"].get<double>() / 2);
        const int y = static_cast<int>(c["y"].get<double>() + c["height"].get<double>() / 2);
        xdo("mousemove --window " + window_ + " " + std::to_string(x) + " " + std::to_string(y));
        xdo("click 1");
        return true;
    }
    // Clicks the combo box `name` and waits until its list is open: keys sent before then would
    // reach the window behind it (frames are slow on a loaded machine).
    bool open_choice(const std::string& name, int seconds = 30) {
        if (!click(name, seconds)) return false;
        return wait_state([&](const json& j) { return control_in(j, name)["open"] == true; },
                          seconds);
    }
    // Waits until the control `name` has the keyboard. A step's field takes it a frame or more
    // after the step shows (slow frames on a loaded machine): keys typed before then are lost.
    bool wait_focused(const std::string& name, int seconds = 30) {
        return wait_state([&](const json& j) { return control_in(j, name)["focused"] == true; },
                          seconds);
    }
    // The control `name` of the state dump (null when it is not drawn).
    json control(const std::string& name) { return state()["controls"][name]; }
    bool wait_state(const std::function<bool(const json&)>& done, int seconds = 30) {
        return wait_for(
            [&] {
                const json j = state();
                return j.is_object() && done(j);
            },
            seconds);
    }

    // Finds the launcher's window (a new one after each session) and gives it the keyboard.
    bool focus() {
        window_.clear();
        wait_for(
            [&] {
                std::istringstream ids(xdo_output("search --name '^monoplane lab$'"));
                return static_cast<bool>(ids >> window_);
            },
            120);
        if (window_.empty()) return false;
        xdo("windowfocus --sync " + window_);
        xdo("mousemove --window " + window_ + " 4 4");
        return true;
    }

    // The state file as last written; null before the first.
    json state() {
        std::ifstream in(state_file());
        if (!in) return json();
        json j = json::parse(in, nullptr, false);
        if (j.is_discarded()) return json();
        if (j.contains("step")) steps_seen_.insert(j["step"].get<std::string>());
        return j;
    }
    bool wait_step(const std::string& step, int seconds = 60) {
        return wait_for(
            [&] {
                const json j = state();
                return j.is_object() && j["step"] == step;
            },
            seconds);
    }
    const std::set<std::string>& steps_seen() const { return steps_seen_; }

    // Waits for the process to end; its exit status (-1: still running after `seconds`).
    int wait_exit(int seconds) {
        int status = 0;
        const bool ended =
            wait_for([&] { return waitpid(pid_, &status, WNOHANG) == pid_; }, seconds);
        if (!ended) return -1;
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    const fs::path& dir() const { return dir_; }

    std::string log() const {
        std::ifstream in(dir_ / "lab.log");
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }

  private:
    fs::path dir_;
    pid_t pid_ = -1;
    bool exited_ = false;
    std::string window_;
    std::set<std::string> steps_seen_;
};

// Runs `monoplane ARGS` in the background with stdout and stderr into `log`; its pid.
inline pid_t spawn_monoplane(std::vector<std::string> args, const fs::path& log) {
    args.insert(args.begin(), MONOPLANE_EXE);
    const pid_t pid = fork();
    if (pid == 0) {
        std::freopen(log.c_str(), "w", stdout);
        dup2(fileno(stdout), STDERR_FILENO);
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    return pid;
}

// Runs `monoplane ARGS` to its end; its exit status.
inline int run_monoplane(const std::vector<std::string>& args, const fs::path& log) {
    const pid_t pid = spawn_monoplane(args, log);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

inline std::string file_text(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Asks the top-level windows named `name` to close as a window manager's close button does: a
// WM_DELETE_WINDOW client message (xdotool's windowclose destroys the window instead, which no
// experimenter can do). The number of windows asked.
inline int close_windows_named(const std::string& name) {
    Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) return 0;
    const Atom protocols = XInternAtom(display, "WM_PROTOCOLS", False);
    const Atom delete_window = XInternAtom(display, "WM_DELETE_WINDOW", False);
    int asked = 0;
    std::istringstream ids(xdo_output("search --name '" + name + "'"));
    for (unsigned long id = 0; ids >> id;) {
        XEvent event{};
        event.xclient.type = ClientMessage;
        event.xclient.window = id;
        event.xclient.message_type = protocols;
        event.xclient.format = 32;
        event.xclient.data.l[0] = static_cast<long>(delete_window);
        event.xclient.data.l[1] = CurrentTime;
        if (XSendEvent(display, id, False, NoEventMask, &event) != 0) ++asked;
    }
    XFlush(display);
    XCloseDisplay(display);
    return asked;
}

inline fs::path prepare(const std::vector<std::pair<std::string, std::string>>& protocols) {
    const fs::path dir = test_folder();
    fs::remove_all(dir);
    fs::create_directories(dir / "protocols");
    fs::copy_file(fs::path(source_dir()) / "protocols/demo.toml", dir / "protocols/demo.toml");
    for (const auto& [file, text] : protocols) std::ofstream(dir / "protocols" / file) << text;
    return dir;
}

// A screenshot that shows something: its pixels vary (a blank window is one colour).
inline double pixel_stddev(const fs::path& png) {
    int width = 0, height = 0, channels = 0;
    unsigned char* data = stbi_load(png.c_str(), &width, &height, &channels, 1);
    if (data == nullptr) return 0.0;
    const std::size_t n = std::size_t(width) * height;
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sum += data[i];
        sum2 += double(data[i]) * data[i];
    }
    stbi_image_free(data);
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
}

// Whether the window has saved its screenshot of a step ("NN-<step>.png"): it takes it on the
// step's third frame, so a test that moves on at once could outrun it on a loaded machine.
inline bool has_shot(const fs::path& dir, const std::string& step) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir / "shots", ec)) {
        const std::string name = entry.path().stem().string();
        if (name.substr(name.find('-') + 1) == step) return true;
    }
    return false;
}

// From the launcher's start to the Headset step of demo.toml with participant `code`, waiting on
// each step for its screenshot before moving on.
inline void walk_to_headset_step(Lab& lab, const std::string& code) {
    EXPECT_TRUE(lab.focus()) << lab.log();
    EXPECT_TRUE(lab.wait_step("protocol")) << lab.log();  // --db opened it: Database is done
    EXPECT_TRUE(wait_for([&] { return has_shot(lab.dir(), "protocol"); }, 30));
    xdo("type --delay 40 demo.toml");
    xdo("key Return");
    EXPECT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    EXPECT_TRUE(wait_for([&] { return has_shot(lab.dir(), "participant"); }, 30));
    xdo("type --delay 40 " + code);
    xdo("key Return");
    EXPECT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    EXPECT_TRUE(wait_for([&] { return has_shot(lab.dir(), "headset"); }, 30));
}

}  // namespace
}  // namespace monoplane
