// `monoplane lab` on an experimenter's first day (issue 43): each defect found by using the
// launcher as a person does, checked by driving it the same way. The launcher runs under Xvfb,
// keys come from xdotool and clicks land where the window's state dump says it drew the control;
// the window is captured from the X server (XGetImage) and its pixels are checked, and the
// captures are kept in <temp>/monoplane_lab_<suite>_<test>/screens/ for docs/lab.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "app/lab/shell_words.h"
#include "study/roster.h"
#include "study/study_store.h"
#include "tests/e2e/lab_driver.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace monoplane {
namespace {

// The window as the X server shows it, 8-bit RGB.
struct Capture {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;

    std::array<double, 3> mean(double x, double y, double w, double h) const {
        std::array<double, 3> sum{};
        int n = 0;
        for (int j = std::max(0, int(y)); j < std::min(height, int(y + h)); ++j) {
            for (int i = std::max(0, int(x)); i < std::min(width, int(x + w)); ++i) {
                for (int c = 0; c < 3; ++c) sum[c] += rgb[(std::size_t(j) * width + i) * 3 + c];
                ++n;
            }
        }
        for (double& s : sum) s /= std::max(n, 1);
        return sum;
    }
    // Pixels within 40 of `colour` in every channel, in the region.
    int pixels_near(const std::array<int, 3>& colour, double x, double y, double w,
                    double h) const {
        int count = 0;
        for (int j = std::max(0, int(y)); j < std::min(height, int(y + h)); ++j) {
            for (int i = std::max(0, int(x)); i < std::min(width, int(x + w)); ++i) {
                const unsigned char* p = &rgb[(std::size_t(j) * width + i) * 3];
                bool near = true;
                for (int c = 0; c < 3; ++c) near = near && std::abs(p[c] - colour[c]) <= 40;
                count += near ? 1 : 0;
            }
        }
        return count;
    }
    // Pixels drawn in the launcher's error colour (a light red), in the region.
    int error_pixels(double x, double y, double w, double h) const {
        int count = 0;
        for (int j = std::max(0, int(y)); j < std::min(height, int(y + h)); ++j) {
            for (int i = std::max(0, int(x)); i < std::min(width, int(x + w)); ++i) {
                const unsigned char* p = &rgb[(std::size_t(j) * width + i) * 3];
                if (p[0] > 180 && p[1] < 140 && p[2] < 140) ++count;
            }
        }
        return count;
    }
};

int shift_of(unsigned long mask) {
    int shift = 0;
    while (mask != 0 && (mask & 1) == 0) {
        mask >>= 1;
        ++shift;
    }
    return shift;
}

// Captures the window `id` and keeps it as <dir>/screens/<name>.png.
Capture capture(const std::string& id, const fs::path& dir, const std::string& name) {
    Capture c;
    Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) return c;
    const Window window = std::stoul(id);
    XWindowAttributes attributes{};
    XGetWindowAttributes(display, window, &attributes);
    XImage* image =
        XGetImage(display, window, 0, 0, attributes.width, attributes.height, AllPlanes, ZPixmap);
    if (image != nullptr) {
        c.width = image->width;
        c.height = image->height;
        c.rgb.resize(std::size_t(c.width) * c.height * 3);
        const std::array masks{image->red_mask, image->green_mask, image->blue_mask};
        for (int y = 0; y < c.height; ++y) {
            for (int x = 0; x < c.width; ++x) {
                const unsigned long pixel = XGetPixel(image, x, y);
                for (int k = 0; k < 3; ++k) {
                    c.rgb[(std::size_t(y) * c.width + x) * 3 + k] =
                        static_cast<unsigned char>((pixel & masks[k]) >> shift_of(masks[k]));
                }
            }
        }
        XDestroyImage(image);
    }
    XCloseDisplay(display);
    fs::create_directories(dir / "screens");
    stbi_write_png((dir / "screens" / (name + ".png")).c_str(), c.width, c.height, 3, c.rgb.data(),
                   c.width * 3);
    return c;
}

// Dear ImGui's keyboard-focus frame (NavHighlight) and the launcher's green for what went well.
constexpr std::array<int, 3> kFocusFrame{66, 150, 250};
constexpr std::array<int, 3> kGreenText{127, 229, 127};

// A control's rectangle in the state dump, as (x, y, width, height).
std::array<double, 4> rect_of(const json& control) {
    return {control["x"].get<double>(), control["y"].get<double>(), control["width"].get<double>(),
            control["height"].get<double>()};
}

// One scene at one distance and no practice: a session of one trial, so a test can run several.
// What these tests check (the session's arguments, its database row, the Summary) needs no more,
// and the default two practice trials would triple each session's frames.
const std::string kTiny =
    "name = \"tiny\"\nscenes = [\"beams\"]\nmono_planes = [3]\n"
    "alternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 0\n";

std::string with_variable(const std::string& protocol, const std::string& declaration) {
    return protocol + "\n[[variables]]\n" + declaration;
}

// Short simulated-headset sessions (as lab_window_test's day).
const std::vector<std::string> kShortSessions = {
    "--detail", "test", "--resolution-scale", "0.1", "--neutral-s", "0.3",
    "--end-s",  "0",    "--sim-rate",         "5"};

// Types `text` into whatever has the keyboard.
void type(const std::string& text) {
    xdo("type --delay 40 '" + text + "'");
}

// From the Protocol step: `protocol` typed and chosen, then participant `code` typed.
void choose(Lab& lab, const std::string& protocol, const std::string& code) {
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
    ASSERT_TRUE(lab.wait_focused("protocol")) << lab.state().dump(1);
    type(protocol);
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_focused("code")) << lab.state().dump(1);
    type(code);
    ASSERT_TRUE(lab.wait_state([&](const json& j) { return j["participant"]["code"] == code; }))
        << lab.state().dump(1);
}

// Ctrl+Enter, and back on the Summary once the session ended.
void start_and_wait(Lab& lab, int seconds = 600) {
    xdo("key ctrl+Return");
    ASSERT_TRUE(lab.wait_step("session", 60)) << lab.state().dump(1) << lab.log();
    ASSERT_TRUE(lab.wait_step("summary", seconds)) << lab.log();
    ASSERT_TRUE(lab.focus()) << lab.log();
}

void quit(Lab& lab) {
    xdo("key ctrl+q");
    EXPECT_EQ(lab.wait_exit(60), 0) << lab.log();
}

class LabDayTest : public ::testing::Test {
  protected:
    void SetUp() override {
        if (const std::string why = missing_prerequisite(); !why.empty()) GTEST_SKIP() << why;
    }
};

// "6,5" in a number field is refused with "write 6.5", never stored as 65; the message shows in
// red under the field without moving the fields below; "6.5" is stored as 6.5.
TEST_F(LabDayTest, ADecimalCommaIsRefusedNeverStoredAs65) {
    const fs::path dir =
        prepare({{"ipd.toml", with_variable(kTiny,
                                            "name = \"ipd_mm\"\ntype = \"number\"\nmin = 50\n"
                                            "max = 80\nrequired = true\n")}});
    Lab lab(dir, {"--headset", "none"});
    choose(lab, "ipd.toml", "P01");
    ASSERT_FALSE(HasFailure());
    const std::array<double, 4> next_before = rect_of(lab.control("next"));
    ASSERT_TRUE(lab.click("var:ipd_mm")) << lab.state().dump(1);
    type("63,5");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["variables"][0]["value"] == "63,5"; }))
        << lab.state().dump(1);
    json j = lab.state();
    EXPECT_EQ(j["variables"][0]["message"],
              "the 'ipd_mm' field: write 63.5 (the decimal point is '.'; a comma is not read as "
              "one)");
    EXPECT_EQ(j["start"]["enabled"], false);
    // Escape leaves the field and keeps what was typed.
    xdo("key Escape");
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_EQ(lab.state()["variables"][0]["value"], "63,5") << lab.state().dump(1);
    // The message is drawn in red between the field and the Next button, which stayed put.
    const std::array<double, 4> field = rect_of(lab.control("var:ipd_mm"));
    const std::array<double, 4> next = rect_of(lab.control("next"));
    EXPECT_EQ(next, next_before);
    const Capture shot = capture(lab.window(), dir, "decimal-comma");
    EXPECT_GT(shot.error_pixels(0, field[1] + field[3], shot.width, next[1] - field[1] - field[3]),
              50);
    // Corrected: the field's text replaced by the number with a point.
    ASSERT_TRUE(lab.click("var:ipd_mm"));
    xdo("key End");
    for (int i = 0; i < 4; ++i) xdo("key BackSpace");
    type("63.5");
    ASSERT_TRUE(lab.wait_state([](const json& s) { return s["start"]["enabled"] == true; }))
        << lab.state().dump(1);
    EXPECT_EQ(lab.state()["variables"][0]["message"], "");
    start_and_wait(lab, 300);
    ASSERT_FALSE(HasFailure());
    quit(lab);
    auto store = study::StudyStore::open_read_only(dir / "lab.sqlite").value_or_throw();
    const auto participant = store->participant("P01").value_or_throw();
    ASSERT_TRUE(participant.has_value());
    ASSERT_EQ(participant->variables.size(), 1u);
    EXPECT_EQ(participant->variables[0].value, "63.5");
}

// Escape keeps the code being typed; after a session, Next participant gives an empty code and
// form for the same protocol (the next person is never run as the last one's next session).
TEST_F(LabDayTest, NextParticipantClearsTheCodeAndKeepsTheProtocol) {
    const fs::path dir =
        prepare({{"age.toml", with_variable(kTiny, "name = \"age\"\ntype = \"integer\"\n")}});
    Lab lab(dir, {"--headset", "none"});
    choose(lab, "age.toml", "P0");
    ASSERT_FALSE(HasFailure());
    xdo("key Escape");
    ASSERT_TRUE(lab.click("code"));
    xdo("key End");
    type("3");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["participant"]["code"] == "P03"; }))
        << lab.state().dump(1);
    ASSERT_TRUE(lab.click("var:age"));
    type("41");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["start"]["enabled"] == true; }))
        << lab.state().dump(1);
    start_and_wait(lab, 300);
    ASSERT_FALSE(HasFailure());
    ASSERT_TRUE(lab.click("next-participant")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    const json j = lab.state();
    EXPECT_EQ(j["participant"]["code"], "");
    EXPECT_EQ(j["variables"][0]["value"], "");
    ASSERT_TRUE(j["protocol"].is_object()) << j.dump(1);
    EXPECT_EQ(j["protocol"]["name"], "tiny");
    EXPECT_EQ(j["summary"], nullptr);
    EXPECT_EQ(j["start"]["enabled"], false);
    // The protocol's line is drawn on this step too, and the code field has the keyboard.
    EXPECT_TRUE(j["controls"]["protocol-line"].is_object()) << j.dump(1);
    EXPECT_TRUE(wait_for([&] { return lab.control("code")["focused"] == true; }, 10))
        << lab.state()["controls"].dump(1);
    const Capture shot = capture(lab.window(), dir, "next-participant");
    const std::array<double, 4> line = rect_of(j["controls"]["protocol-line"]);
    const std::array<double, 3> text = shot.mean(line[0], line[1], line[2], line[3]);
    EXPECT_GT(text[0] + text[1] + text[2], 3 * 20.0) << "no protocol line drawn";
    quit(lab);
}

// A simxr copy under another manifest is the machine's "real" OpenXR runtime here, with a
// script of its own (another headset profile, and its frames dumped to a folder), so reaching it
// is visible. Simulated, then OpenXR, then simulated again in one launcher run: each probe names
// its runtime's headset, and the OpenXR session's frames go to the real runtime's folder.
TEST_F(LabDayTest, EachSessionReachesTheHeadsetChosenForIt) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    const fs::path simxr_dir = fs::path(MONOPLANE_SIMXR_MANIFEST).parent_path();
    std::ofstream(dir / "real.json")
        << "{\"file_format_version\": \"1.0.0\", \"runtime\": {\"name\": \"the lab's runtime\", "
           "\"library_path\": \""
        << (simxr_dir / "libmonoplane_simxr.so").string() << "\"}}\n";
    std::ofstream(dir / "real.toml") << "hmd = \"symmetric-90\"\ndisplay_rate_hz = 5\n"
                                     << "dump_dir = \"" << (dir / "real-frames").string() << "\"\n";
    LabStart start;
    start.env = {{"XR_RUNTIME_JSON", (dir / "real.json").string()},
                 {"SIMXR_SCRIPT", (dir / "real.toml").string()}};
    std::vector<std::string> options = kShortSessions;
    options.insert(options.end(), {"--observer", "default"});
    Lab lab(dir, options, start);
    const auto probed = [&](const std::string& headset) {
        EXPECT_TRUE(lab.click("headset:" + headset)) << lab.state().dump(1);
        EXPECT_TRUE(lab.wait_state([&](const json& j) {
            return j["headset"]["choice"] == headset && j["headset"]["runtime_available"] == true;
        })) << lab.state().dump(1)
            << lab.log();
        return lab.state()["headset"]["system"].get<std::string>();
    };
    const auto frames = [&] {
        std::error_code ec;
        auto it = fs::directory_iterator(dir / "real-frames", ec);
        return ec ? 0 : static_cast<int>(std::distance(it, fs::directory_iterator()));
    };
    for (const auto& [code, headset] : std::vector<std::pair<std::string, std::string>>{
             {"P01", "simulated"}, {"P02", "openxr"}, {"P03", "simulated"}}) {
        if (code == "P01") {
            choose(lab, "tiny.toml", code);
        } else {
            ASSERT_TRUE(lab.click("next-participant")) << lab.state().dump(1);
            ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
            ASSERT_TRUE(lab.wait_focused("code")) << lab.state().dump(1);
            type(code);
        }
        ASSERT_FALSE(HasFailure());
        xdo("key Return");
        ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
        const std::string system = probed(headset);
        // simxr names its headset's profile: the real runtime's is symmetric, simulated a Vive.
        const bool real = system.find("ymmetric") != std::string::npos;
        EXPECT_EQ(real, headset == "openxr") << headset << ": " << system;
        const int before = frames();
        start_and_wait(lab);
        ASSERT_FALSE(HasFailure());
        const json j = lab.state();
        EXPECT_EQ(j["summary"]["state"], "completed") << j.dump(1) << lab.log();
        if (headset == "openxr")
            EXPECT_GT(frames(), before) << "the OpenXR session did not reach the real runtime";
        else
            EXPECT_EQ(frames(), before) << "the simulated session reached the real runtime";
    }
    quit(lab);
}

// The protocols folder is watched: missing at start, made later, a protocol saved into it is
// listed without a restart; a protocol elsewhere is chosen by its full path.
TEST_F(LabDayTest, TheProtocolsFolderIsWatchedAndAFullPathIsAccepted) {
    const fs::path dir = prepare({});
    fs::create_directories(dir / "elsewhere");
    std::ofstream(dir / "elsewhere" / "far.toml") << "name = \"far\"\n" << kTiny.substr(14);
    Lab lab(dir, {"--db", (dir / "lab.sqlite").string(), "--protocols", (dir / "later").string()},
            LabStart{false, {}});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
    EXPECT_NE(lab.state()["protocols"]["message"], "") << lab.state().dump(1);
    fs::create_directories(dir / "later");
    std::ofstream(dir / "later" / "new.toml") << kTiny;
    ASSERT_TRUE(lab.wait_state([](const json& j) {
        return j["protocols"]["files"].size() == 1 && j["protocols"]["message"] == "";
    })) << lab.state().dump(1);
    // The new file's line is drawn (its text on the background), where the state says.
    const std::array<double, 4> entry = rect_of(lab.control("protocol:new.toml"));
    const Capture listed = capture(lab.window(), dir, "protocol-listed");
    const std::array<double, 3> text = listed.mean(entry[0], entry[1], entry[2] / 4, entry[3]);
    const std::array<double, 3> below =
        listed.mean(entry[0], entry[1] + 3 * entry[3], entry[2] / 4, entry[3]);
    EXPECT_GT(text[0] + text[1] + text[2], below[0] + below[1] + below[2] + 5);
    ASSERT_TRUE(lab.click("protocol:new.toml")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    EXPECT_EQ(lab.state()["protocol"]["name"], "tiny");
    xdo("key ctrl+Left");
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.state().dump(1);
    ASSERT_TRUE(lab.click("protocol"));  // selects the field's text, to be typed over
    type((dir / "elsewhere" / "far.toml").string());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1) << lab.log();
    EXPECT_EQ(lab.state()["protocol"]["name"], "far");
    EXPECT_EQ(lab.state()["protocol"]["path"], (dir / "elsewhere" / "far.toml").string());
    quit(lab);
}

// 41 sessions: the roster scrolls inside the window, the footer stays on it, and the last
// session's Resume is reached by scrolling and clicked. The session resumed from the Protocol
// step leaves its protocol chosen for the next participant, and the summary says what the roster
// says.
TEST_F(LabDayTest, ALongRosterScrollsAndResumeIsReached) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    const std::string db = (dir / "lab.sqlite").string();
    const std::string protocol = (dir / "protocols" / "tiny.toml").string();
    for (int i = 1; i <= 40; ++i) {
        ASSERT_EQ(run_monoplane({"study", "run", "--protocol", protocol, "--participant",
                                 "P" + std::to_string(i), "--db", db, "--headset", "none"},
                                dir / "cli.log"),
                  0)
            << file_text(dir / "cli.log");
    }
    // The 41st is interrupted: its process is killed mid-session (a slow observer).
    const pid_t slow =
        spawn_monoplane({"study", "run", "--protocol", protocol, "--participant", "P41", "--db", db,
                         "--headset", "none", "--pace-ms", "5000", "--trace"},
                        dir / "slow.log");
    ASSERT_TRUE(wait_for([&] { return !file_text(dir / "slow.log").empty(); }, 60));
    std::this_thread::sleep_for(std::chrono::seconds(1));
    kill(slow, SIGKILL);
    waitpid(slow, nullptr, 0);

    Lab lab(dir, {"--headset", "none"});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
    // The footer laid out: its first frames can place it before the roster's height is known.
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["controls"].contains("footer"); }));
    lab.wait_state([](const json& j) { return control_in(j, "footer")["visible"] == true; });
    json j = lab.state();
    ASSERT_EQ(j["roster"].size(), 41u);
    json interrupted;
    for (const json& line : j["roster"])
        if (line["participant"] == "P41") interrupted = line;
    ASSERT_EQ(interrupted["state"], "interrupted") << j["roster"].dump(1);
    const std::string resume = "resume:" + std::to_string(interrupted["session_id"].get<int>());
    const double window_height = j["controls"]["window"]["height"];
    const std::array<double, 4> footer = rect_of(j["controls"]["footer"]);
    EXPECT_LE(footer[1] + footer[3], window_height) << j["controls"].dump(1);
    EXPECT_EQ(j["controls"][resume]["visible"], false) << j["controls"].dump(1);
    // The mouse wheel over the roster scrolls it until the last line shows.
    const std::array<double, 4> first = rect_of(j["controls"]["footer"]);
    xdo("mousemove --window " + lab.window() + " 200 " + std::to_string(int(first[1] - 60)));
    for (int i = 0; i < 40 && lab.control(resume)["visible"] != true; ++i) xdo("click 5");
    ASSERT_EQ(lab.control(resume)["visible"], true) << lab.state()["controls"].dump(1);
    // The Resume button is drawn where the state says, on the roster's scrolled view.
    const std::array<double, 4> button = rect_of(lab.control(resume));
    const Capture scrolled = capture(lab.window(), dir, "roster-scrolled");
    const std::array<double, 3> face = scrolled.mean(button[0], button[1], button[2], button[3]);
    EXPECT_GT(face[2], face[0] + 20) << "no (blue) Resume button at its place";
    EXPECT_EQ(rect_of(lab.control("footer")), footer);  // the footer did not move
    ASSERT_TRUE(lab.click(resume));
    ASSERT_TRUE(lab.wait_step("summary", 300)) << lab.log();
    j = lab.state();
    for (const json& line : j["roster"])
        if (line["participant"] == "P41") {
            EXPECT_EQ(j["summary"]["state"], line["state"]);
        }
    EXPECT_EQ(j["summary"]["state"], "completed") << j.dump(1);
    ASSERT_TRUE(lab.focus());
    ASSERT_TRUE(lab.click("next-participant"));
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    EXPECT_EQ(lab.state()["protocol"]["name"], "tiny") << lab.state().dump(1);
    quit(lab);
}

// Tab walks through every control of the Database step (it no longer stays in the path field)
// and Shift+Tab back; in a choice variable's combo box Enter opens it and Enter picks.
TEST_F(LabDayTest, TabReachesEveryControlAndEnterPicksInACombo) {
    const fs::path dir =
        prepare({{"vision.toml", with_variable(kTiny,
                                               "name = \"vision\"\ntype = \"choice\"\n"
                                               "choices = [\"normal\", \"corrected\"]\n")}});
    Lab lab(dir, {"--protocols", (dir / "protocols").string()}, LabStart{false, {}});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("database")) << lab.log();
    ASSERT_TRUE(wait_for([&] { return lab.control("database")["focused"] == true; }, 10))
        << lab.state()["controls"].dump(1);
    std::vector<std::string> reached;
    for (int i = 0; i < 3; ++i) {
        // Each Tab moves the keyboard on: wait for the dump to show it moved (a loaded machine's
        // frames can take longer than any fixed pause), then read where it went.
        const std::string before = reached.empty() ? "database" : reached.back();
        xdo("key Tab");
        json controls;
        wait_for(
            [&] {
                controls = lab.state()["controls"];
                for (const auto& [name, c] : controls.items())
                    if (c["focused"] == true && name != before) return true;
                return false;
            },
            10);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        for (const auto& [name, c] : controls.items())
            if (c["focused"] == true) reached.push_back(name);
        // The focused button shows Dear ImGui's focus frame around it, the others do not.
        if (reached.size() == 2 && reached.back() == "create") {
            const Capture shot = capture(lab.window(), dir, "tab-create");
            const std::array<double, 4> create = rect_of(controls["create"]);
            const std::array<double, 4> open = rect_of(controls["open"]);
            EXPECT_GT(shot.pixels_near(kFocusFrame, create[0] - 4, create[1] - 4, create[2] + 8,
                                       create[3] + 8),
                      20);
            EXPECT_LT(shot.pixels_near(kFocusFrame, open[0] - 4, open[1] - 4, open[2] + 8, 4), 5);
        }
    }
    EXPECT_EQ(reached, (std::vector<std::string>{"open", "create", "database"}));
    type((dir / "lab.sqlite").string());
    xdo("key Tab");
    xdo("key Tab");
    xdo("key space");  // Create
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_focused("protocol")) << lab.state().dump(1);
    type("vision.toml");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_focused("code")) << lab.state().dump(1);
    type("P01");
    xdo("key Tab");
    ASSERT_TRUE(wait_for([&] { return lab.control("var:vision")["focused"] == true; }, 10))
        << lab.state()["controls"].dump(1);
    xdo("key Return");  // opens the list
    ASSERT_TRUE(wait_for([&] { return lab.control("var:vision")["open"] == true; }, 10))
        << lab.state()["controls"].dump(1);
    xdo("key Down");
    xdo("key Return");  // picks
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["variables"][0]["value"] != ""; }))
        << lab.state().dump(1);
    capture(lab.window(), dir, "combo-picked");
    EXPECT_TRUE(lab.state()["start"]["enabled"]) << lab.state().dump(1);
    quit(lab);
}

// The command line under Start is the session's command with every option the launcher passes,
// shell-quoted; a start that fails is not shown as "Session 0".
TEST_F(LabDayTest, TheShownCommandIsTheSessionsAndAFailedStartSaysSo) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    fs::create_directories(dir / "with space");
    const fs::path script = dir / "with space" / "sim.toml";
    std::ofstream(script) << "hmd = \"vive\"\ndisplay_rate_hz = 5\n";
    std::vector<std::string> options = kShortSessions;
    options.insert(options.end(), {"--sim-script", script.string()});
    Lab lab(dir, options);
    choose(lab, "tiny.toml", "P01");
    ASSERT_FALSE(HasFailure());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["start"]["enabled"] == true; }))
        << lab.state().dump(1);
    const json start = lab.state()["start"];
    const std::vector<std::string> arguments = start["arguments"];
    const std::vector<std::string> tail(arguments.end() - 13, arguments.end());
    // The launcher runs with --validation (as every test): its sessions do too. --detail and
    // --resolution-scale match no preset: they are the "custom" preset's, passed last.
    EXPECT_EQ(tail, (std::vector<std::string>{"--validation", "--neutral-s", "0.3", "--end-s", "0",
                                              "--sim-script", script.string(), "--sim-rate", "5",
                                              "--detail", "test", "--resolution-scale", "0.1"}))
        << start.dump(1);
    EXPECT_EQ(lab.state()["settings"]["preset"], "custom");
    EXPECT_EQ(start["command_line"], lab::shell_command_line(arguments));
    EXPECT_NE(start["command_line"].get<std::string>().find("'" + script.string() + "'"),
              std::string::npos);
    capture(lab.window(), dir, "command-line");
    // The script goes before Start: the session cannot begin.
    fs::remove_all(dir / "with space");
    xdo("key ctrl+Return");
    ASSERT_TRUE(lab.wait_step("summary", 120)) << lab.log();
    const json j = lab.state();
    EXPECT_EQ(j["summary"]["session_id"], 0) << j.dump(1);
    EXPECT_NE(j["summary"]["error"].get<std::string>().find("sim.toml"), std::string::npos)
        << j.dump(1);
    ASSERT_TRUE(lab.focus());
    const Capture shot = capture(lab.window(), dir, "failed-start");
    const std::array<double, 4> line = rect_of(j["controls"]["protocol-line"]);
    EXPECT_GT(shot.error_pixels(0, line[1] + line[3], shot.width, 200), 50)
        << "the error is not shown in red under the summary's first line";
    quit(lab);
}

// With the simulated observer the headset check ends by itself: the observer confirms.
TEST_F(LabDayTest, TheSimulatedObserverAnswersTheHeadsetCheck) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    Lab lab(dir, kShortSessions);
    choose(lab, "tiny.toml", "P01");
    ASSERT_FALSE(HasFailure());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["headset"]["runtime_available"]; }))
        << lab.state().dump(1) << lab.log();
    ASSERT_TRUE(lab.click("check"));
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["headset"]["check"] != ""; }, 180))
        << lab.state().dump(1) << lab.log();
    const json h = lab.state()["headset"];
    EXPECT_EQ(h["check"], "confirmed") << h.dump(1);
    EXPECT_NE(h["check_message"].get<std::string>().find("simulated observer"), std::string::npos)
        << h.dump(1);
    // "Headset check: confirmed ..." is drawn in green under the Check button.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const Capture shot = capture(lab.window(), dir, "check-confirmed");
    const std::array<double, 4> check = rect_of(lab.control("check"));
    EXPECT_GT(shot.pixels_near(kGreenText, 0, check[1] + check[3], shot.width, 3 * check[3]), 30);
    quit(lab);
}

// A required variable left empty and a participant whose sessions are all done are said at the
// Participant step, naming the window's field and what to do there, not command-line options.
TEST_F(LabDayTest, ParticipantProblemsAreSaidWhereTheyAreFixed) {
    const fs::path dir =
        prepare({{"age.toml", with_variable(kTiny,
                                            "name = \"age\"\ntype = \"integer\"\n"
                                            "required = true\nhelp = \"Age in years\"\n")}});
    ASSERT_EQ(run_monoplane({"study", "run", "--protocol", (dir / "protocols/age.toml").string(),
                             "--participant", "P01", "--db", (dir / "lab.sqlite").string(),
                             "--headset", "none", "--var", "age=30"},
                            dir / "cli.log"),
              0)
        << file_text(dir / "cli.log");
    Lab lab(dir, {"--headset", "none"});
    choose(lab, "age.toml", "P02");
    ASSERT_FALSE(HasFailure());
    json j = lab.state();
    ASSERT_EQ(j["participant"]["problems"].size(), 1u) << j.dump(1);
    EXPECT_EQ(j["participant"]["problems"][0],
              "fill in 'age' (Age in years) above: it is required");
    EXPECT_EQ(j["start"]["message"].get<std::string>().find("--var"), std::string::npos);
    const Capture shot = capture(lab.window(), dir, "participant-problem");
    const std::array<double, 4> field = rect_of(j["controls"]["var:age"]);
    const std::array<double, 4> next = rect_of(j["controls"]["next"]);
    EXPECT_GT(shot.error_pixels(0, field[1] + field[3], shot.width, next[1] - field[1] - field[3]),
              50);
    for (int i = 0; i < 3; ++i) xdo("key BackSpace");
    type("P01");
    ASSERT_TRUE(lab.wait_state([](const json& s) { return s["participant"]["known"] == true; }))
        << lab.state().dump(1);
    j = lab.state();
    ASSERT_EQ(j["participant"]["problems"].size(), 1u) << j.dump(1);
    EXPECT_EQ(j["participant"]["problems"][0],
              "P01 has had all 1 session(s) of protocol 'tiny': type another participant code, or "
              "choose another protocol in step 2");
    EXPECT_EQ(j["start"]["message"].get<std::string>().find("study resume"), std::string::npos);
    quit(lab);
}

// No runtime for the chosen headset: Start is disabled and drawn grey, not in the enabled green;
// a refused action's message leaves the footer with the step.
TEST_F(LabDayTest, StartWithoutARuntimeIsDisabledAndLooksIt) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    LabStart start;
    start.env = {{"XR_RUNTIME_JSON", (dir / "no-such-runtime.json").string()}};
    Lab lab(dir, {"--headset", "openxr"}, start);
    choose(lab, "tiny.toml", "P01");
    ASSERT_FALSE(HasFailure());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_state([](const json& j) {
        return j["start"]["message"].get<std::string>().find("no runtime for the openxr") !=
               std::string::npos;
    })) << lab.state().dump(1);
    json j = lab.state();
    EXPECT_EQ(j["start"]["enabled"], false);
    EXPECT_EQ(j["controls"]["start"]["enabled"], false);
    const std::array<double, 4> button = rect_of(j["controls"]["start"]);
    const std::array<double, 3> off = capture(lab.window(), dir, "start-disabled")
                                          .mean(button[0], button[1], button[2], button[3]);
    xdo("key ctrl+Return");  // refused: the footer says why
    ASSERT_TRUE(lab.wait_state([](const json& s) { return s["window"]["message"] != ""; }))
        << lab.state().dump(1);
    ASSERT_TRUE(lab.click("headset:none"));
    ASSERT_TRUE(lab.wait_state([](const json& s) { return s["start"]["enabled"] == true; }))
        << lab.state().dump(1);
    j = lab.state();
    const std::array<double, 4> moved = rect_of(j["controls"]["start"]);
    const std::array<double, 3> on =
        capture(lab.window(), dir, "start-enabled").mean(moved[0], moved[1], moved[2], moved[3]);
    EXPECT_GT(on[1], on[0] + 30) << "enabled Start is green";
    EXPECT_LT(std::abs(off[1] - off[0]), 15) << "disabled Start is grey";
    EXPECT_LT(off[0] + off[1] + off[2], on[0] + on[1] + on[2]);
    xdo("key ctrl+Left");
    ASSERT_TRUE(lab.wait_step("participant"));
    EXPECT_EQ(lab.state()["window"]["message"], "") << "a stale message stayed in the footer";
    quit(lab);
}

// The database and protocols folder are remembered ($XDG_CONFIG_HOME/monoplane/lab.toml): the
// next launch without options opens them.
TEST_F(LabDayTest, TheLastDatabaseAndProtocolsFolderAreRemembered) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    {
        Lab lab(dir, {});
        ASSERT_TRUE(lab.focus()) << lab.log();
        ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
        quit(lab);
    }
    const std::string config = file_text(dir / "config" / "monoplane" / "lab.toml");
    EXPECT_NE(config.find((dir / "lab.sqlite").string()), std::string::npos) << config;
    fs::remove(dir / "state.json");
    Lab again(dir, {}, LabStart{false, {}});
    ASSERT_TRUE(again.focus()) << again.log();
    ASSERT_TRUE(again.wait_step("protocol")) << again.log();
    const json j = again.state();
    EXPECT_EQ(j["database"]["path"], (dir / "lab.sqlite").string());
    EXPECT_EQ(j["protocols"]["folder"], (dir / "protocols").string());
    quit(again);
}

// Short sessions without --detail and --resolution-scale, which the preset chooses.
const std::vector<std::string> kShortPresetSessions = {"--neutral-s", "0.3",        "--end-s",
                                                       "0",           "--sim-rate", "5"};

// The verdict line is drawn in the colour of its verdict: red when the preset cannot reach the
// refresh rate, yellow when only just, green when it does.
void expect_verdict_colour(const Capture& shot, const json& settings, const json& verdict_rect) {
    const std::array<double, 4> r = rect_of(verdict_rect);
    const json v = settings["verdict"];
    if (!v["fits"].get<bool>()) {
        EXPECT_GT(shot.error_pixels(r[0], r[1], shot.width, r[3]), 30) << settings.dump(1);
    } else if (v["tight"].get<bool>()) {
        EXPECT_GT(shot.pixels_near({255, 217, 76}, r[0], r[1], shot.width, r[3]), 30);
    } else {
        EXPECT_GT(shot.pixels_near(kGreenText, r[0], r[1], shot.width, r[3]), 30);
    }
}

// With MONOPLANE_WRITE_DOCS=1, a capture kept in screens/ becomes docs/images/lab-<name>.png.
void write_doc_image(const fs::path& dir, const std::string& capture, const std::string& name) {
    const char* write = std::getenv("MONOPLANE_WRITE_DOCS");
    if (write == nullptr || std::string(write) != "1") return;
    const fs::path to = fs::path(source_dir()) / "docs/images" / ("lab-" + name + ".png");
    fs::copy_file(dir / "screens" / (capture + ".png"), to, fs::copy_options::overwrite_existing);
    // docs/lab.md shows these: each stays small in the repository.
    EXPECT_LT(fs::file_size(to), 150u * 1024u) << to;
}

// Item 3: the Headset step's performance preset. --detail test preselects a "custom" preset;
// the experimenter picks "minimal" in the combo (click, Up, Enter), the command line shows its
// options; Measure runs the probe on a worker while the window keeps drawing, and the estimate
// and the verdict against the refresh rate are shown (in the verdict's colour) and dumped; the
// session then renders at the preset's detail, as stored.
TEST_F(LabDayTest, ThePerformancePresetIsMeasuredAndChoosesTheSessionsSettings) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    std::vector<std::string> options = kShortPresetSessions;
    options.insert(options.end(), {"--detail", "test"});
    Lab lab(dir, options);
    choose(lab, "tiny.toml", "P01");
    ASSERT_FALSE(HasFailure());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["headset"]["runtime_available"]; }))
        << lab.state().dump(1) << lab.log();
    EXPECT_EQ(lab.state()["settings"]["preset"], "custom") << lab.state()["settings"].dump(1);
    ASSERT_TRUE(lab.open_choice("preset")) << lab.state()["controls"].dump(1);
    xdo("key Up");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["settings"]["preset"] == "minimal"; }))
        << lab.state()["settings"].dump(1);
    json j = lab.state();
    const std::vector<std::string> arguments = j["start"]["arguments"];
    const std::vector<std::string> tail(arguments.end() - 4, arguments.end());
    EXPECT_EQ(tail, (std::vector<std::string>{"--detail", "test", "--resolution-scale", "0.25"}))
        << j["start"].dump(1);
    EXPECT_EQ(j["start"]["command_line"], lab::shell_command_line(arguments));
    EXPECT_TRUE(j["settings"]["estimate_ms"].is_null());
    EXPECT_TRUE(j["settings"]["verdict"].is_null());
    ASSERT_TRUE(lab.click("measure"));
    // The window keeps drawing while the probe renders: the state says it is measuring (or,
    // on a fast device, has measured already).
    ASSERT_TRUE(lab.wait_state([](const json& s) {
        return s["settings"]["measurement"]["state"] != "";
    })) << lab.state()["settings"].dump(1);
    ASSERT_TRUE(lab.wait_state(
        [](const json& s) { return s["settings"]["measurement"]["state"] == "done"; }, 300))
        << lab.state()["settings"].dump(1) << lab.log();
    j = lab.state();
    const json settings = j["settings"];
    EXPECT_EQ(settings["measurement"]["preset"], "minimal");
    ASSERT_TRUE(settings["estimate_ms"].is_number()) << settings.dump(1);
    const double ms = settings["estimate_ms"].get<double>();
    EXPECT_GT(ms, 0.0);
    ASSERT_TRUE(settings["verdict"].is_object()) << settings.dump(1);
    // No check yet: the refresh rate is assumed, 90 Hz, and the verdict says so.
    EXPECT_EQ(settings["verdict"]["refresh_hz"], 90.0);
    EXPECT_EQ(settings["verdict"]["fits"].get<bool>(), ms <= 1000.0 / 90.0);
    const std::string text = settings["verdict"]["text"];
    EXPECT_EQ(text.rfind(ms <= 1000.0 / 90.0 ? "" : "cannot reach 90 Hz", 0), 0u) << text;
    EXPECT_NE(text.find("assumed"), std::string::npos) << text;
    for (const json& p : settings["presets"]) {
        if (p["name"] == "minimal")
            EXPECT_EQ(p["estimate_ms"], settings["estimate_ms"]);
        else
            EXPECT_TRUE(p["estimate_ms"].is_null()) << p.dump(1);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const Capture shot = capture(lab.window(), dir, "preset-measured");
    expect_verdict_colour(shot, settings, j["controls"]["verdict"]);
    start_and_wait(lab, 600);
    ASSERT_FALSE(HasFailure());
    j = lab.state();
    EXPECT_EQ(j["summary"]["state"], "completed") << j["summary"].dump(1) << lab.log();
    quit(lab);
    auto store = study::StudyStore::open_read_only(dir / "lab.sqlite").value_or_throw();
    const auto session = store->session(j["summary"]["session_id"].get<std::int64_t>());
    ASSERT_TRUE(session.ok()) << session.error().message;
    EXPECT_EQ(session->render.detail, "test");
}

// The day as docs/lab.md shows it, one capture per step (MONOPLANE_WRITE_DOCS=1 writes them to
// docs/images/lab-*.png): the protocols with a broken one's error in red, the participant's form,
// the Headset step with the "minimal" preset measured and its verdict, and the summary.
TEST_F(LabDayTest, TheDayAsTheDocsShowIt) {
    const fs::path dir =
        prepare({{"tiny.toml", with_variable(kTiny,
                                             "name = \"age\"\ntype = \"integer\"\n"
                                             "required = true\nhelp = \"Age in years\"\n")},
                 {"broken.toml",
                  "name = \"broken\"\nscenes = [\"beams\"]\nmono_planes = [3]\n"
                  "alternatives = [\"stereo\", \"holo\"]\n"}});
    std::vector<std::string> options = kShortPresetSessions;
    options.insert(options.end(), {"--detail", "test"});
    Lab lab(dir, options);
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const Capture protocols = capture(lab.window(), dir, "doc-protocol");
    const std::array<double, 4> broken = rect_of(lab.control("protocol:broken.toml"));
    EXPECT_GT(protocols.error_pixels(0, broken[1], protocols.width, 3 * broken[3]), 50);
    write_doc_image(dir, "doc-protocol", "protocol");
    type("tiny.toml");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_focused("code")) << lab.state().dump(1);
    type("P01");
    ASSERT_TRUE(lab.click("var:age"));
    type("34");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["start"]["enabled"] == true; }))
        << lab.state().dump(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const Capture participant = capture(lab.window(), dir, "doc-participant");
    EXPECT_EQ(participant.error_pixels(0, 0, participant.width, participant.height), 0);
    write_doc_image(dir, "doc-participant", "participant");
    xdo("key ctrl+Right");
    ASSERT_TRUE(lab.wait_state([](const json& j) {
        return j["step"] == "headset" && j["headset"]["runtime_available"] == true;
    })) << lab.state().dump(1);
    ASSERT_TRUE(lab.open_choice("preset")) << lab.state()["controls"].dump(1);
    xdo("key Up");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["settings"]["preset"] == "minimal"; }))
        << lab.state()["settings"].dump(1);
    ASSERT_TRUE(lab.click("measure"));
    ASSERT_TRUE(lab.wait_state(
        [](const json& s) { return s["settings"]["measurement"]["state"] == "done"; }, 300))
        << lab.state()["settings"].dump(1) << lab.log();
    EXPECT_GT(lab.state()["settings"]["estimate_ms"].get<double>(), 0.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const json j = lab.state();
    const Capture headset = capture(lab.window(), dir, "doc-headset");
    expect_verdict_colour(headset, j["settings"], j["controls"]["verdict"]);
    write_doc_image(dir, "doc-headset", "headset");
    start_and_wait(lab, 600);
    ASSERT_FALSE(HasFailure());
    EXPECT_EQ(lab.state()["summary"]["state"], "completed") << lab.log();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const Capture summary = capture(lab.window(), dir, "doc-summary");
    const std::array<double, 4> line = rect_of(lab.control("protocol-line"));
    const std::array<double, 3> text = summary.mean(0, line[1] + line[3], summary.width, 120);
    const std::array<double, 3> empty = summary.mean(0, summary.height - 200, summary.width, 40);
    EXPECT_GT(text[0] + text[1] + text[2], empty[0] + empty[1] + empty[2] + 3);
    write_doc_image(dir, "doc-summary", "summary");
    quit(lab);
}

// Cancel stops a measurement before its next frame; the state says so and Start works again.
TEST_F(LabDayTest, AFrameTimeMeasurementCanBeCancelled) {
    const fs::path dir = prepare({{"tiny.toml", kTiny}});
    Lab lab(dir, kShortPresetSessions);
    choose(lab, "tiny.toml", "P01");
    ASSERT_FALSE(HasFailure());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_state([](const json& j) {
        return j["step"] == "headset" && j["headset"]["runtime_available"] == true;
    })) << lab.state().dump(1);
    EXPECT_EQ(lab.state()["settings"]["preset"], "full");
    ASSERT_TRUE(lab.click("measure"));
    // "full" on a CPU renderer takes seconds a frame: Cancel is there while it runs.
    if (!lab.wait_state([](const json& s) { return s["controls"].contains("cancel-measure"); },
                        10)) {
        GTEST_SKIP() << "the measurement ended before it could be cancelled (a fast device)";
    }
    ASSERT_TRUE(lab.click("cancel-measure"));
    ASSERT_TRUE(lab.wait_state(
        [](const json& s) { return s["settings"]["measurement"]["state"] == "cancelled"; }, 300))
        << lab.state()["settings"].dump(1) << lab.log();
    EXPECT_TRUE(lab.state()["settings"]["estimate_ms"].is_null());
    EXPECT_TRUE(lab.state()["controls"].contains("measure"));
    quit(lab);
}

// A simxr script whose controllers are of a profile the app suggests no bindings for (simxr's
// default, khr/simple_controller, binds), so the runtime binds none: a still head, 72 Hz.
fs::path write_unbound_script(const fs::path& dir) {
    const fs::path path = dir / "unbound.toml";
    std::ofstream(path) << "hmd = \"vive\"\ndisplay_rate_hz = 72\nhead_motion = \"still\"\n"
                        << "interaction_profile = "
                           "\"/interaction_profiles/microsoft/motion_controller\"\n";
    return path;
}

// Item 5: the headset check finds no controller bound, the protocol has no [responses] keys and
// no simulated observer answers (--observer none): the Headset step says at once that the
// participant cannot answer, while the check runs and after it, in red; with a protocol that
// enables keys, nothing is said.
TEST_F(LabDayTest, NoControllerBoundIsSaidAtOnce) {
    const fs::path dir =
        prepare({{"tiny.toml", kTiny},
                 {"keys.toml",
                  kTiny + "\n[responses]\nkeys = { switch = \"Left\", confirm = \"Return\" }\n"}});
    const fs::path script = write_unbound_script(dir);
    std::vector<std::string> options = kShortSessions;
    options.insert(options.end(), {"--sim-script", script.string(), "--observer", "none"});
    Lab lab(dir, options);
    choose(lab, "tiny.toml", "P01");
    ASSERT_FALSE(HasFailure());
    xdo("key Return");
    ASSERT_TRUE(lab.wait_state([](const json& j) {
        return j["step"] == "headset" && j["headset"]["runtime_available"] == true;
    })) << lab.state().dump(1);
    EXPECT_EQ(lab.state()["headset"]["answer_warning"], "");
    xdo("key ctrl+h");
    const std::string message =
        "no controller bound: the participant cannot answer; connect one or enable keys";
    // Said while the check still runs (it has not ended: no CONFIRM can come).
    ASSERT_TRUE(lab.wait_state(
        [&](const json& j) { return j["headset"]["answer_warning"] == message; }, 120))
        << lab.state()["headset"].dump(1) << lab.log();
    EXPECT_EQ(lab.state()["headset"]["check"], "");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const Capture during = capture(lab.window(), dir, "no-controller-during-check");
    EXPECT_GT(during.error_pixels(0, 0, during.width, during.height / 2), 50);
    xdo("key Escape");
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["headset"]["check"] != ""; }, 120))
        << lab.state().dump(1);
    json h = lab.state()["headset"];
    EXPECT_EQ(h["check"], "cancelled") << h.dump(1);
    EXPECT_EQ(h["interaction_profile"], "");
    EXPECT_EQ(h["answer_warning"], message);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const Capture after = capture(lab.window(), dir, "no-controller");
    write_doc_image(dir, "no-controller", "no-controller");
    const std::array<double, 4> line = rect_of(lab.control("answer-warning"));
    EXPECT_GT(after.error_pixels(0, line[1], after.width, line[3]), 30)
        << lab.state()["controls"].dump(1);
    // The same check's finding with a protocol whose keys answer: nothing to say.
    xdo("key ctrl+Left");
    xdo("key ctrl+Left");
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.state().dump(1);
    ASSERT_TRUE(lab.click("protocol:keys.toml"));
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    xdo("key ctrl+Right");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["headset"]["answer_warning"] == ""; }))
        << lab.state()["headset"].dump(1);
    h = lab.state()["headset"];
    EXPECT_EQ(h["check"], "cancelled") << h.dump(1);
    EXPECT_EQ(h["interaction_profile"], "");
    EXPECT_EQ(h["keys_answer"], true);
    // Keys "none" in the window (the third choice: Down, Down, Enter) leaves nobody again, and
    // the session's command says --keys none.
    ASSERT_TRUE(lab.open_choice("keys")) << lab.state()["controls"].dump(1);
    xdo("key Down");
    xdo("key Down");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_state([&](const json& j) {
        return j["headset"]["keys"] == "none" && j["headset"]["answer_warning"] == message;
    })) << lab.state()["headset"].dump(1);
    const std::vector<std::string> arguments = lab.state()["start"]["arguments"];
    const std::vector<std::string> keys_none = {"--keys", "none"};
    EXPECT_NE(std::search(arguments.begin(), arguments.end(), keys_none.begin(), keys_none.end()),
              arguments.end())
        << lab.state()["start"].dump(1);
    quit(lab);
}

// On a 3840 x 2160 screen (its own ctest, with Xvfb at that size) the window opens at three
// quarters of it with text scaled for it (32 pixels), and made as large as the screen it draws
// over all of it: the footer moves to the new bottom.
TEST_F(LabDayTest, TheWindowFitsALargeMonitor) {
    Display* display = XOpenDisplay(nullptr);
    ASSERT_NE(display, nullptr);
    const int screen_width = DisplayWidth(display, DefaultScreen(display));
    const int screen_height = DisplayHeight(display, DefaultScreen(display));
    XCloseDisplay(display);
    if (screen_width < 3840) GTEST_SKIP() << "needs a 3840 x 2160 screen (ctest lab_day_test_4k)";
    const fs::path dir = prepare({});
    Lab lab(dir, {});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_state([](const json& j) { return j["controls"].contains("footer"); }));
    json j = lab.state();
    EXPECT_EQ(j["controls"]["window"]["width"], screen_width * 3 / 4) << j["controls"].dump(1);
    EXPECT_EQ(j["controls"]["window"]["height"], screen_height * 3 / 4);
    EXPECT_EQ(j["window"]["font_pixels"], 32.0);
    xdo("windowsize " + lab.window() + " " + std::to_string(screen_width) + " " +
        std::to_string(screen_height));
    ASSERT_TRUE(lab.wait_state([&](const json& s) {
        return s["controls"]["window"]["width"] == screen_width;
    })) << lab.state()["controls"].dump(1);
    j = lab.state();
    const std::array<double, 4> footer = rect_of(j["controls"]["footer"]);
    EXPECT_GT(footer[1], screen_height * 0.9) << j["controls"].dump(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const Capture shot = capture(lab.window(), dir, "large-monitor");
    EXPECT_EQ(shot.width, screen_width);
    // The footer's text is drawn where the state says: the bottom rows are not all background.
    const std::array<double, 3> bottom = shot.mean(footer[0], footer[1], footer[2], footer[3]);
    const std::array<double, 3> empty = shot.mean(footer[0], footer[1] - 8, footer[2], 4);
    EXPECT_GT(bottom[0] + bottom[1] + bottom[2], empty[0] + empty[1] + empty[2] + 5);
    quit(lab);
}

}  // namespace
}  // namespace monoplane
