// A lost OpenXR runtime is an ordinary end (issue 42, item 6): when the runtime loses the instance
// (XR_ERROR_INSTANCE_LOST, as Monado's client says when its service died) or the session
// (LOSS_PENDING) at trial 2, `study run` tears OpenXR down before Vulkan, prints one message saying
// where the session stood and how to resume it, exits 3, keeps every decided trial, leaves the
// session interrupted in `study list`, and `study resume` completes it. simxr loses both on cue
// (lose_instance_at_s, lose_session_at_s); a real Monado service is killed mid-session where one
// runs (MONOPLANE_MONADO_SERVICE_PIDFILE).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "study/study_store.h"
#include "tests/e2e/child_process.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

struct Finished {     // a command that ran to its end
    int status = -1;  // the exit status; -1: killed by a signal
    int signal = 0;   // the signal that killed it
    std::string out, err;
};

// Runs a shell command line with stdout and stderr kept apart (the one message is on stderr).
Finished run(const std::string& command) {
    const fs::path out = test_folder() / "stdout.log";
    const fs::path err = test_folder() / "stderr.log";
    const int status =
        std::system((command + " > " + out.string() + " 2> " + err.string()).c_str());
    Finished r;
    if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
    // std::system runs sh -c: a child killed by a signal shows as 128 + the signal.
    if (r.status > 128) r.signal = r.status - 128;
    r.out = read_file(out);
    r.err = read_file(err);
    return r;
}

// The controller's script (HTC Vive controllers: trigger switches, trackpad confirms): a switch
// every 0.5 s and a confirmation 0.25 s after each, as tests/e2e/headset_session_test.cpp. At 20 Hz
// with a 0.3 s neutral screen, the demo's instruction page is confirmed at 0.35 s, practice trial
// 1 is decided at 1.35 s, and trial 2 shows from 1.7 s to its decision at 2.35 s (seed 5).
std::string controller_script(const std::string& loss) {
    std::ostringstream s;
    s << loss << "\nhmd = \"vive\"\ndisplay_rate_hz = 20\n"
      << "interaction_profile = \"/interaction_profiles/htc/vive_controller\"\n";
    for (int k = 0; k < 80; ++k) {
        s << "[[input]]\nt = " << 0.5 * k + 0.1
          << "\npath = \"/user/hand/right/input/trigger/click\"\nduration = 0.1\n";
        s << "[[input]]\nt = " << 0.5 * k + 0.35
          << "\npath = \"/user/hand/right/input/trackpad/click\"\nduration = 0.1\n";
    }
    return s.str();
}

// Within trial 2, after its first switch and before its confirmation.
constexpr double kTrialTwoS = 2.2;

class RuntimeLostTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        db_ = dir_ / "lost.sqlite";
    }

    std::string study(const std::string& command, const fs::path& script) const {
        return std::string(MONOPLANE_EXE) + " --validation study " + command + " --db " +
               db_.string() + " --headset simulated --observer none --sim-script " +
               script.string() + " --window off --detail test --resolution-scale 0.1 " +
               "--neutral-s 0.3";
    }

    Finished run_until_lost(const std::string& loss) const {
        const fs::path script = dir_ / "lossy.toml";
        std::ofstream(script) << controller_script(loss);
        return run(study(
            "run --protocol " + source_dir() + "/protocols/demo.toml --participant LOST --seed 5",
            script));
    }

    // What a lost runtime leaves: exit 3, one message naming trial 2 and the resume line, the
    // decided trial stored and trial 2 undecided, the session interrupted.
    void expect_interrupted_at_trial_two(const Finished& lost) const {
        EXPECT_EQ(lost.status, 3) << lost.err;
        const std::string message =
            "monoplane: the OpenXR runtime was lost at trial 2 of session 1; every decided trial "
            "is kept; resume with `monoplane study resume --db " +
            db_.string() + " --participant LOST --session 1 --headset simulated`";
        EXPECT_EQ(count(lost.err, message), 1) << lost.err;
        EXPECT_EQ(count(lost.err, "was lost"), 1) << lost.err;
        EXPECT_EQ(count(lost.err, "monoplane: "), 1) << lost.err;  // no other error
        // The frame log was flushed as on any end of a session.
        EXPECT_NE(lost.err.find("builds while frames ran"), std::string::npos) << lost.err;

        auto store = study::StudyStore::open(db_);
        ASSERT_TRUE(store) << store.error().message;
        EXPECT_EQ((*store)->session(1)->status, study::SessionStatus::Running);
        const auto trials = (*store)->trials(1);
        ASSERT_TRUE(trials);
        ASSERT_EQ(trials->size(), 7u);
        EXPECT_TRUE((*trials)[0].decided);
        for (std::size_t i = 1; i < trials->size(); ++i) EXPECT_FALSE((*trials)[i].decided) << i;
        const auto events = (*store)->events(1);
        ASSERT_TRUE(events);
        int trial_two_switches = 0;
        for (const auto& e : *events)
            trial_two_switches += e.trial_index == 1 && e.kind == study::EventKind::Switched;
        EXPECT_GT(trial_two_switches, 0) << "the loss came after trial 2's first switch";
        const auto frames = (*store)->frames(1);
        ASSERT_TRUE(frames);
        EXPECT_GT(frames->size(), 30u);

        const Finished list = run(std::string(MONOPLANE_EXE) + " study list --db " + db_.string());
        EXPECT_EQ(list.status, 0) << list.err;
        EXPECT_NE(list.out.find("interrupted"), std::string::npos) << list.out;
    }

    void expect_resume_completes() const {
        const fs::path fresh = dir_ / "fresh.toml";
        std::ofstream(fresh) << controller_script("");
        const Finished resumed = run(study("resume --participant LOST --session 1", fresh));
        ASSERT_EQ(resumed.status, 0) << resumed.err;
        auto store = study::StudyStore::open(db_);
        ASSERT_TRUE(store);
        EXPECT_EQ((*store)->session(1)->status, study::SessionStatus::Completed);
        const auto trials = (*store)->trials(1);
        ASSERT_TRUE(trials);
        for (const auto& t : *trials) EXPECT_TRUE(t.decided) << "trial " << t.trial.index;
    }

    fs::path dir_;
    fs::path db_;
};

// XR_ERROR_INSTANCE_LOST in the middle of a frame (simxr's xrBeginFrame), with the loss-pending
// event queued: a runtime whose service died.
TEST_F(RuntimeLostTest, InstanceLostAtTrialTwoIsAnInterruptionThatResumes) {
    const Finished lost = run_until_lost("lose_instance_at_s = " + std::to_string(kTrialTwoS));
    expect_interrupted_at_trial_two(lost);
    expect_resume_completes();
}

// LOSS_PENDING: the runtime says the session is being lost (a headset unplugged).
TEST_F(RuntimeLostTest, SessionLostAtTrialTwoIsAnInterruptionThatResumes) {
    const Finished lost = run_until_lost("lose_session_at_s = " + std::to_string(kTrialTwoS));
    expect_interrupted_at_trial_two(lost);
    expect_resume_completes();
}

// Monado's out-of-process service killed mid-session, as when it crashes or is quit: its client
// answers XR_ERROR_INSTANCE_LOST. Before issue 42 monoplane died of SIGSEGV here every time (the
// Vulkan device went before the swapchains). Runs where a service is up: export the variables
// `monado-service start` prints (XR_RUNTIME_JSON, XDG_RUNTIME_DIR, DISPLAY) and
// MONOPLANE_MONADO_SERVICE_PIDFILE, the file holding the service's pid. The session is resumed on
// simxr (the service is gone).
TEST_F(RuntimeLostTest, KilledMonadoServiceIsAnInterruptionThatResumes) {
    const char* pidfile = std::getenv("MONOPLANE_MONADO_SERVICE_PIDFILE");
    if (pidfile == nullptr || *pidfile == '\0') {
        GTEST_SKIP() << "set MONOPLANE_MONADO_SERVICE_PIDFILE (and the variables monado-service "
                        "start prints) to run against a Monado service";
    }
    pid_t service = 0;
    std::ifstream(pidfile) >> service;
    ASSERT_GT(service, 0) << pidfile;
    ASSERT_EQ(kill(service, 0), 0) << "no Monado service runs as pid " << service;
    // Monado's simulated HMD has no controllers: the default observer answers. The service is
    // killed once trial 2 (index 1) has shown.
    const std::vector<std::string> args = {MONOPLANE_EXE,
                                           "study",
                                           "run",
                                           "--protocol",
                                           source_dir() + "/protocols/demo.toml",
                                           "--participant",
                                           "LOST",
                                           "--db",
                                           db_.string(),
                                           "--headset",
                                           "openxr",
                                           "--observer",
                                           "default",
                                           "--window",
                                           "off",
                                           "--detail",
                                           "test",
                                           "--resolution-scale",
                                           "0.2",
                                           "--neutral-s",
                                           "0.3",
                                           "--seed",
                                           "5",
                                           "--trace"};
    auto [pid, fd] = spawn(args, dir_.string());
    ASSERT_GT(pid, 0);
    std::string output;
    bool killed = false;
    char buffer[4096];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) {
        output.append(buffer, static_cast<std::size_t>(n));
        if (!killed && output.find("committed trial 1 shown") != std::string::npos) {
            kill(service, SIGKILL);
            killed = true;
        }
    }
    close(fd);
    int status = 0;
    waitpid(pid, &status, 0);
    const std::string err = read_file(dir_ / "stderr.log");
    ASSERT_TRUE(killed) << output << err;
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << "\n" << err;
    EXPECT_EQ(WEXITSTATUS(status), 3) << err;
    EXPECT_EQ(count(err,
                    "monoplane: the OpenXR runtime was lost at trial 2 of session 1; every "
                    "decided trial is kept; resume with `monoplane study resume --db " +
                        db_.string() + " --participant LOST --session 1 --headset openxr`"),
              1)
        << err;
    auto store = study::StudyStore::open(db_);
    ASSERT_TRUE(store) << store.error().message;
    const auto trials = (*store)->trials(1);
    ASSERT_TRUE(trials);
    EXPECT_TRUE((*trials)[0].decided);
    const Finished list = run(std::string(MONOPLANE_EXE) + " study list --db " + db_.string());
    EXPECT_NE(list.out.find("interrupted"), std::string::npos) << list.out;

    const fs::path fresh = dir_ / "fresh.toml";
    // 5 Hz: the observer looks for seconds per trial on the virtual clock; fewer frames to draw.
    std::ofstream(fresh) << "hmd = \"vive\"\ndisplay_rate_hz = 5\n";
    const Finished resumed =
        run("env -u XR_RUNTIME_JSON " + std::string(MONOPLANE_EXE) + " study resume --db " +
            db_.string() +
            " --participant LOST --session 1 --headset simulated --observer "
            "default --sim-script " +
            fresh.string() + " --window off --detail test --resolution-scale 0.1 --neutral-s 0.3");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    store = study::StudyStore::open(db_);
    ASSERT_TRUE(store);
    EXPECT_EQ((*store)->session(1)->status, study::SessionStatus::Completed);
}

}  // namespace
}  // namespace monoplane
