// `monoplane lab` as an experimenter uses it (issue 31, item 5): the launcher runs on a virtual X
// server (ctest starts it under xvfb-run) and is driven by real X key events from xdotool (XTEST),
// never by calls into the program. The day: choose demo.toml, type a participant code, start a
// simulated-headset session that the simulated observer completes, export and analyse; then the
// database, the exported file, the screenshots of each step and the window's own state dump are
// checked. Bad input (an invalid code, a protocol with an error, a missing required variable)
// keeps Start disabled with the message shown.
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
#include <vector>

#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include "study/roster.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir ? dir : ".";
}

fs::path test_folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir =
        fs::temp_directory_path() /
        ("monoplane_lab_" + std::string(info->test_suite_name()) + "_" + info->name());
    return dir;
}

// Why the test cannot run here; empty when it can.
std::string missing_prerequisite() {
    if (std::getenv("DISPLAY") == nullptr) return "no X server (DISPLAY unset; run under xvfb-run)";
    if (std::system("xdotool version > /dev/null 2>&1") != 0)
        return "xdotool is not installed (scripts/install-deps.sh installs it)";
    return {};
}

std::string xdo_output(const std::string& args) {
    std::string text;
    if (FILE* pipe = popen(("xdotool " + args + " 2>/dev/null").c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof buffer, pipe)) text += buffer;
        pclose(pipe);
    }
    return text;
}

void xdo(const std::string& args) {
    ASSERT_EQ(std::system(("xdotool " + args).c_str()), 0) << "xdotool " << args;
    // The launcher draws at about 60 frames a second: a few frames for each event to land.
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
}

bool wait_for(const std::function<bool()>& done, int seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (std::chrono::steady_clock::now() < until) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return done();
}

// The launcher process, its window and its state file.
class Lab {
  public:
    Lab(const fs::path& dir, const std::vector<std::string>& extra) : dir_(dir) {
        std::vector<std::string> args = {MONOPLANE_EXE,
                                         "lab",
                                         "--db",
                                         (dir / "lab.sqlite").string(),
                                         "--protocols",
                                         (dir / "protocols").string(),
                                         "--state-file",
                                         state_file().string(),
                                         "--screenshot-dir",
                                         (dir / "shots").string()};
        args.insert(args.end(), extra.begin(), extra.end());
        pid_ = fork();
        if (pid_ == 0) {
            const std::string log = (dir / "lab.log").string();
            std::freopen(log.c_str(), "w", stdout);
            dup2(fileno(stdout), STDERR_FILENO);
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

fs::path prepare(const std::vector<std::pair<std::string, std::string>>& protocols) {
    const fs::path dir = test_folder();
    fs::remove_all(dir);
    fs::create_directories(dir / "protocols");
    fs::copy_file(fs::path(source_dir()) / "protocols/demo.toml", dir / "protocols/demo.toml");
    for (const auto& [file, text] : protocols) std::ofstream(dir / "protocols" / file) << text;
    return dir;
}

// A screenshot that shows something: its pixels vary (a blank window is one colour).
double pixel_stddev(const fs::path& png) {
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

class LabWindowTest : public ::testing::Test {
  protected:
    void SetUp() override {
        if (const std::string why = missing_prerequisite(); !why.empty()) GTEST_SKIP() << why;
    }
};

TEST_F(LabWindowTest, DayFromProtocolToExport) {
    const fs::path dir = prepare({});
    // Small sessions: the observer's dwell times are real, the frames few and tiny.
    Lab lab(dir, {"--detail", "test", "--resolution-scale", "0.1", "--neutral-s", "0.3", "--end-s",
                  "0", "--sim-rate", "5"});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();  // --db opened it: Database is done
    xdo("type --delay 40 demo.toml");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    xdo("type --delay 40 P07");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    const json ready = lab.state();
    EXPECT_EQ(ready["start"]["enabled"], true) << ready.dump(1);
    xdo("key ctrl+Return");
    ASSERT_TRUE(lab.wait_step("summary", 900)) << lab.log();
    ASSERT_TRUE(lab.focus()) << lab.log();
    xdo("key ctrl+e");
    EXPECT_TRUE(wait_for([&] { return fs::exists(dir / "lab.csv"); }, 60)) << lab.log();
    xdo("key ctrl+r");
    EXPECT_TRUE(wait_for([&] { return fs::exists(dir / "lab-analysis/report.html"); }, 180))
        << lab.log();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the summary's screenshot
    xdo("key ctrl+q");
    ASSERT_EQ(lab.wait_exit(60), 0) << lab.log();

    // The database: one completed session of P07, as `study list` reads it.
    const auto roster = study::read_roster({dir / "lab.sqlite"});
    ASSERT_TRUE(roster) << roster.error().message;
    ASSERT_EQ(roster->size(), 1u);
    EXPECT_EQ(roster->front().row.participant_code, "P07");
    EXPECT_EQ(roster->front().state(), "completed");
    EXPECT_EQ(roster->front().row.trials_decided, roster->front().row.trials_planned);
    std::ifstream csv(dir / "lab.csv");
    std::string header;
    ASSERT_TRUE(std::getline(csv, header));
    EXPECT_NE(header.find("participant"), std::string::npos) << header;

    // Each step's screenshot shows something; the state dump named each step.
    std::set<std::string> shot_steps;
    for (const auto& entry : fs::directory_iterator(dir / "shots")) {
        const std::string name = entry.path().stem().string();
        shot_steps.insert(name.substr(name.find('-') + 1));
        EXPECT_GT(pixel_stddev(entry.path()), 5.0) << entry.path() << " looks blank";
    }
    for (const char* step : {"protocol", "participant", "headset", "summary"}) {
        EXPECT_TRUE(shot_steps.count(step)) << "no screenshot of " << step;
        EXPECT_TRUE(lab.steps_seen().count(step)) << "the state file never named " << step;
    }
}

TEST_F(LabWindowTest, BadInputKeepsStartDisabled) {
    const fs::path dir = prepare({
        {"broken.toml", "name = \"broken\"\nscenes = [\"beams\"]\nmono_planes = \"eight\"\n"},
        {"vars.toml",
         "name = \"vars\"\nscenes = [\"beams\"]\nmono_planes = [3]\n"
         "alternatives = [\"stereo\", \"hybrid\"]\n\n[[variables]]\nname = \"age\"\n"
         "type = \"integer\"\nrequired = true\nhelp = \"Age in years\"\n"},
    });
    Lab lab(dir, {});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
    // A protocol with an error: refused in place, with its file and line; no Start.
    xdo("type --delay 40 broken.toml");
    xdo("key Return");
    std::this_thread::sleep_for(std::chrono::seconds(1));
    json j = lab.state();
    EXPECT_EQ(j["step"], "protocol") << j.dump(1);
    EXPECT_EQ(j["start"]["enabled"], false);
    EXPECT_NE(j.dump().find("broken.toml:3"), std::string::npos) << j.dump(1);
    // The refused name stays selected in the field: typing replaces it.
    xdo("type --delay 40 vars.toml");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    // An invalid code: its message, no Start.
    xdo("type --delay 40 'bad code!'");
    std::this_thread::sleep_for(std::chrono::seconds(1));
    j = lab.state();
    EXPECT_FALSE(j["participant"]["message"].get<std::string>().empty()) << j.dump(1);
    EXPECT_EQ(j["start"]["enabled"], false);
    // A valid code but the required variable missing: still no Start, and why.
    for (int i = 0; i < 9; ++i) xdo("key BackSpace");
    xdo("type --delay 40 P1");
    ASSERT_TRUE(wait_for(
        [&] {
            j = lab.state();
            return j["participant"]["code"] == "P1" &&
                   j["participant"]["message"].get<std::string>().empty();
        },
        20))
        << j.dump(1);
    EXPECT_EQ(j["start"]["enabled"], false) << j.dump(1);
    EXPECT_NE(j["start"]["message"].get<std::string>().find("age"), std::string::npos) << j.dump(1);
    // Start refused by key too: no session begins (Enter in the code field may still move on to
    // the headset step, where Start stays disabled with the same message).
    xdo("key ctrl+Return");
    std::this_thread::sleep_for(std::chrono::seconds(1));
    j = lab.state();
    EXPECT_NE(j["step"], "session") << j.dump(1);
    EXPECT_EQ(j["start"]["enabled"], false) << j.dump(1);
    EXPECT_TRUE(j["roster"].empty()) << j.dump(1);
    xdo("key ctrl+q");
    EXPECT_EQ(lab.wait_exit(60), 0) << lab.log();
}

}  // namespace
}  // namespace monoplane
