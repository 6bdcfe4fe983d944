// Answers from a keyboard or response box in whole sessions on the simulated runtime with NO
// controller bound (simxr's controllers are a profile monoplane suggests no bindings for, as on
// Monado's simulated HMD): the experimenter window's keys, driven by real X key events (xdotool,
// XTEST) under a virtual X server, complete the session and every press is in the database with
// source keyboard; without keys the experimenter is told at once that nobody can answer; an evdev
// response box through a uinput virtual device where the machine has /dev/uinput; and the
// simulated observer's sessions are as before. The OpenXR and Vulkan validation layers are on.
#include <fcntl.h>
#include <linux/uinput.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "study/study_store.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr std::string_view kNoController =
    "no controller bound: the participant cannot answer; connect one or enable keys";

// One scene at one distance, no practice: a session is one trial.
std::string protocol_text(const std::string& responses) {
    return "name = \"keys\"\nscenes = [\"spheres\"]\nmono_planes = [3]\n"
           "alternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 0\n" +
           responses;
}

// simxr's controllers are Microsoft motion controllers, which monoplane suggests nothing for:
// the runtime binds no profile (xrGetCurrentInteractionProfile: XR_NULL_PATH).
std::string unbound_script(double exit_after_s = 0) {
    return "hmd = \"vive\"\ndisplay_rate_hz = 5\n"
           "interaction_profile = \"/interaction_profiles/microsoft/motion_controller\"\n"
           "exit_after_s = " +
           std::to_string(exit_after_s) + "\n";
}

std::string missing_x() {
    if (std::getenv("DISPLAY") == nullptr) return "no X server (DISPLAY unset; run under xvfb-run)";
    if (std::system("xdotool version > /dev/null 2>&1") != 0)
        return "xdotool is not installed (scripts/install-deps.sh installs it)";
    return {};
}

// `monoplane study run` in the background, its output in a log.
class StudyRun {
  public:
    StudyRun(const fs::path& dir, const std::vector<std::string>& extra) : log_(dir / "run.log") {
        std::vector<std::string> args = {MONOPLANE_EXE,
                                         "--validation",
                                         "study",
                                         "run",
                                         "--participant",
                                         "K1",
                                         "--db",
                                         (dir / "k.sqlite").string(),
                                         "--headset",
                                         "simulated",
                                         "--detail",
                                         "test",
                                         "--resolution-scale",
                                         "0.1",
                                         "--neutral-s",
                                         "0.3",
                                         "--end-s",
                                         "0"};
        args.insert(args.end(), extra.begin(), extra.end());
        pid_ = fork();
        if (pid_ == 0) {
            std::freopen(log_.c_str(), "w", stdout);
            dup2(fileno(stdout), STDERR_FILENO);
            std::vector<char*> argv;
            for (std::string& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
    }
    ~StudyRun() {
        if (pid_ > 0 && !status_) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }
    // The exit status once it ended, else none (no wait).
    std::optional<int> exited() {
        if (status_) return status_;
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {
            status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        }
        return status_;
    }
    std::optional<int> wait(std::chrono::seconds limit) {
        const auto until = std::chrono::steady_clock::now() + limit;
        while (!exited() && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(100ms);
        return exited();
    }
    std::string output() const { return read_file(log_); }

  private:
    fs::path log_;
    pid_t pid_ = -1;
    std::optional<int> status_;
};

std::string xdo_output(const std::string& args) {
    std::string text;
    if (FILE* pipe = popen(("xdotool " + args + " 2>/dev/null").c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof buffer, pipe)) text += buffer;
        pclose(pipe);
    }
    return text;
}

class ResponseKeysSession : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
        return dir_ / name;
    }
    std::unique_ptr<study::StudyStore> store() {
        auto opened = study::StudyStore::open(dir_ / "k.sqlite");
        EXPECT_TRUE(opened) << opened.error().message;
        return opened ? std::move(opened).value() : nullptr;
    }
    fs::path dir_;
};

// Presses the answer keys as a participant would until the session ends: switch, then confirm
// (refused until both labels were seen; the next round's switch then shows the other one). Real
// key events (XTEST) into the focused window, as a keyboard's.
void answer_until_done(StudyRun& run, const std::string& switch_key,
                       const std::string& confirm_key) {
    for (int round = 0; round < 40 && !run.exited(); ++round) {
        std::system(("xdotool key " + switch_key).c_str());
        std::this_thread::sleep_for(400ms);
        std::system(("xdotool key " + confirm_key).c_str());
        std::this_thread::sleep_for(400ms);
    }
}

std::string find_window(StudyRun& run) {
    for (int i = 0; i < 300 && !run.exited(); ++i) {
        const std::string ids = xdo_output("search --name 'monoplane: experimenter'");
        if (!ids.empty()) return ids.substr(0, ids.find('\n'));
        std::this_thread::sleep_for(100ms);
    }
    return {};
}

TEST_F(ResponseKeysSession, KeysInTheWindowAnswerWithoutAController) {
    if (const std::string why = missing_x(); !why.empty()) GTEST_SKIP() << why;
    const fs::path protocol =
        write("keys.toml", protocol_text("[responses]\nkeys = { switch = \"Left\", confirm = "
                                         "\"Return\" }\n"));
    const fs::path script = write("unbound.toml", unbound_script());
    StudyRun run(dir_, {"--protocol", protocol.string(), "--observer", "none", "--sim-script",
                        script.string(), "--window", "on"});
    const std::string window = find_window(run);
    ASSERT_FALSE(window.empty()) << run.output();
    ASSERT_EQ(std::system(("xdotool windowfocus --sync " + window).c_str()), 0);
    answer_until_done(run, "Left", "Return");
    ASSERT_EQ(run.wait(60s), 0) << run.output();
    const std::string output = run.output();
    EXPECT_NE(output.find("answers: keys Left switch; Return confirm (experimenter window)"),
              std::string::npos)
        << output;
    EXPECT_EQ(output.find(kNoController), std::string::npos) << output;  // keys answer

    auto db = store();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->session(1)->status, study::SessionStatus::Completed);
    const auto trials = db->trials(1);
    ASSERT_EQ(trials->size(), 1u);
    EXPECT_TRUE((*trials)[0].decided);
    const auto presses = db->presses(1);
    ASSERT_TRUE(presses) << presses.error().message;
    int switches = 0, confirms = 0;
    std::int64_t last = -1;
    for (const study::ResponsePress& p : *presses) {
        EXPECT_EQ(p.source, study::PressSource::Keyboard);
        EXPECT_EQ(p.key, p.action == study::PressAction::Switch ? "Left" : "Return");
        EXPECT_GE(p.time_ns, last);  // on the session's axis, in order
        last = p.time_ns;
        switches += p.action == study::PressAction::Switch;
        confirms += p.action == study::PressAction::Confirm;
    }
    // Label 2 must have been seen before the confirmation that decided the trial counted.
    EXPECT_GE(switches, 1);
    EXPECT_GE(confirms, 1);
    int in_trial = 0;
    for (const study::ResponsePress& p : *presses) in_trial += p.trial_index == 0;
    EXPECT_GE(in_trial, 2);
    // Every switch the trial counts came from a logged key press.
    EXPECT_LE((*trials)[0].outcome.switches, switches);

    // The export shows each press with its source.
    const fs::path csv = dir_ / "presses.csv";
    ASSERT_EQ(std::system((std::string(MONOPLANE_EXE) + " study export --db " +
                           (dir_ / "k.sqlite").string() + " --format presses-csv --out " +
                           csv.string() + " > /dev/null 2>&1")
                              .c_str()),
              0);
    std::ifstream rows(csv);
    std::string line;
    std::getline(rows, line);
    EXPECT_EQ(line, "participant,session,trial,screen,source,action,key,time_ns");
    std::size_t exported = 0;
    while (std::getline(rows, line)) {
        ++exported;
        EXPECT_TRUE(line.starts_with("K1,1,")) << line;
        EXPECT_TRUE(line.find(",keyboard,switch,Left,") != std::string::npos ||
                    line.find(",keyboard,confirm,Return,") != std::string::npos)
            << line;
    }
    EXPECT_EQ(exported, presses->size());
}

TEST_F(ResponseKeysSession, WithoutControllerOrKeysTheExperimenterIsToldAtOnce) {
    if (const std::string why = missing_x(); !why.empty()) GTEST_SKIP() << why;
    const fs::path protocol = write("plain.toml", protocol_text(""));
    // The runtime ends the session after 3 s of its clock (15 frames at 5 Hz).
    const fs::path script = write("unbound.toml", unbound_script(3.0));
    StudyRun run(
        dir_, {"--protocol", protocol.string(), "--observer", "none", "--sim-script",
               script.string(), "--window", "on", "--screenshot", (dir_ / "window.png").string()});
    ASSERT_EQ(run.wait(120s), 1) << run.output();  // the session did not finish
    const std::string output = run.output();
    const std::size_t told = output.find(kNoController);
    ASSERT_NE(told, std::string::npos) << output;
    EXPECT_LT(told, output.find("the OpenXR session ended")) << output;
    EXPECT_TRUE(fs::exists(dir_ / "window.png"));
    auto db = store();
    ASSERT_TRUE(db);
    EXPECT_TRUE(db->presses(1)->empty());
}

TEST_F(ResponseKeysSession, TheSimulatedObserverIsAnsweredAsBefore) {
    // The default script binds simxr's simple controller; the observer answers; nothing is said.
    const fs::path protocol = write("plain.toml", protocol_text(""));
    StudyRun run(dir_, {"--protocol", protocol.string(), "--observer", "default", "--window", "off",
                        "--sim-rate", "5", "--seed", "3"});
    ASSERT_EQ(run.wait(120s), 0) << run.output();
    EXPECT_EQ(run.output().find(kNoController), std::string::npos) << run.output();
    auto db = store();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->session(1)->status, study::SessionStatus::Completed);
    EXPECT_TRUE(db->presses(1)->empty());  // the observer presses no key
}

// A response box: a virtual keyboard made through uinput, read by path with --response-device.
class VirtualKeyboard {
  public:
    // Empty when made; else why not.
    std::string make() {
        fd_ = ::open("/dev/uinput", O_WRONLY | O_NONBLOCK);
        if (fd_ < 0) return "/dev/uinput: " + std::string(std::strerror(errno));
        ioctl(fd_, UI_SET_EVBIT, EV_KEY);
        for (int key : {KEY_LEFT, KEY_RIGHT, KEY_ENTER, KEY_A}) ioctl(fd_, UI_SET_KEYBIT, key);
        uinput_setup setup{};
        setup.id.bustype = BUS_USB;
        std::snprintf(setup.name, sizeof setup.name, "monoplane test response box");
        if (ioctl(fd_, UI_DEV_SETUP, &setup) < 0 || ioctl(fd_, UI_DEV_CREATE) < 0) {
            return "uinput device: " + std::string(std::strerror(errno));
        }
        char sysname[64] = {};
        if (ioctl(fd_, UI_GET_SYSNAME(sizeof sysname), sysname) < 0) return "UI_GET_SYSNAME failed";
        for (const auto& entry :
             fs::directory_iterator(fs::path("/sys/devices/virtual/input") / sysname)) {
            const std::string name = entry.path().filename();
            if (name.rfind("event", 0) == 0) path_ = "/dev/input/" + name;
        }
        std::this_thread::sleep_for(500ms);  // udev makes the node
        if (path_.empty() || !fs::exists(path_)) return "no event node for the uinput device";
        return {};
    }
    ~VirtualKeyboard() {
        if (fd_ >= 0) {
            ioctl(fd_, UI_DEV_DESTROY);
            ::close(fd_);
        }
    }
    void tap(int key) {
        for (int value : {1, 0}) {
            send(EV_KEY, key, value);
            send(EV_SYN, SYN_REPORT, 0);
        }
    }
    const std::string& path() const { return path_; }

  private:
    void send(int type, int code, int value) {
        input_event event{};
        event.type = static_cast<__u16>(type);
        event.code = static_cast<__u16>(code);
        event.value = value;
        static_cast<void>(::write(fd_, &event, sizeof event));
    }
    int fd_ = -1;
    std::string path_;
};

TEST_F(ResponseKeysSession, AResponseBoxAnswersThroughItsEvdevDevice) {
    VirtualKeyboard box;
    if (const std::string why = box.make(); !why.empty()) {
        GTEST_SKIP() << "no uinput virtual device on this machine (" << why
                     << "); the device path is tested through a pipe in window_response_keys_test";
    }
    const fs::path protocol = write("plain.toml", protocol_text(""));
    const fs::path script = write("unbound.toml", unbound_script());
    StudyRun run(dir_, {"--protocol", protocol.string(), "--observer", "none", "--sim-script",
                        script.string(), "--window", "off", "--keys", "switch=Right,confirm=a",
                        "--response-device", box.path()});
    for (int round = 0; round < 60 && !run.exited(); ++round) {
        box.tap(KEY_RIGHT);
        std::this_thread::sleep_for(400ms);
        box.tap(KEY_LEFT);  // not mapped: no press
        box.tap(KEY_A);
        std::this_thread::sleep_for(400ms);
    }
    ASSERT_EQ(run.wait(60s), 0) << run.output();
    auto db = store();
    ASSERT_TRUE(db);
    EXPECT_EQ(db->session(1)->status, study::SessionStatus::Completed);
    for (const study::ResponsePress& p : *db->presses(1)) {
        EXPECT_EQ(p.source, study::PressSource::Device);
        EXPECT_EQ(p.key, p.action == study::PressAction::Switch ? "Right" : "a");
    }
    EXPECT_FALSE(db->presses(1)->empty());
}

TEST_F(ResponseKeysSession, AnUnreadableDeviceStopsBeforeTheHeadsetWithTheFix) {
    const fs::path protocol = write("plain.toml", protocol_text(""));
    StudyRun run(dir_, {"--protocol", protocol.string(), "--observer", "none", "--window", "off",
                        "--response-device", (dir_ / "no-such-event-kbd").string()});
    ASSERT_EQ(run.wait(60s), 1) << run.output();
    EXPECT_NE(run.output().find("cannot read the response device " +
                                (dir_ / "no-such-event-kbd").string() +
                                ": no such device; is it plugged in? (ls -l /dev/input/by-id)"),
              std::string::npos)
        << run.output();
    EXPECT_EQ(run.output().find("OpenXR runtime:"), std::string::npos) << run.output();
}

}  // namespace
}  // namespace monoplane
