// `monoplane lab` as an experimenter uses it (issue 31, item 5): the launcher runs on a virtual X
// server (ctest starts it under xvfb-run) and is driven by real X key events from xdotool (XTEST),
// never by calls into the program. The day: choose demo.toml, type a participant code, start a
// simulated-headset session that the simulated observer completes, export and analyse; then the
// database, the exported file, the screenshots of each step and the window's own state dump are
// checked. Bad input (an invalid code, a protocol with an error, a missing required variable)
// keeps Start disabled with the message shown. A session started from the launcher with a seed
// is the command's session, row for row (item 3); a session held by another process, and a
// session window closed mid-session, end in a message and a resumable session, never a crash or
// a hang (item 6).
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "study/roster.h"
#include "tests/e2e/lab_driver.h"

namespace monoplane {
namespace {

// Every row of every table of a study database, as text per column name, in rowid order; the
// columns `skip` names (by "table.column" or ".column" for any table) are left out.
using Row = std::map<std::string, std::string>;
std::map<std::string, std::vector<Row>> database_rows(const fs::path& file,
                                                      const std::set<std::string>& skip) {
    std::map<std::string, std::vector<Row>> tables;
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
        ADD_FAILURE() << "cannot open " << file;
        sqlite3_close(db);
        return tables;
    }
    std::vector<std::string> names;
    sqlite3_stmt* list = nullptr;
    sqlite3_prepare_v2(db, "SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY name", -1,
                       &list, nullptr);
    while (sqlite3_step(list) == SQLITE_ROW)
        names.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(list, 0)));
    sqlite3_finalize(list);
    for (const std::string& table : names) {
        std::vector<Row>& rows = tables[table];
        sqlite3_stmt* select = nullptr;
        const std::string sql = "SELECT * FROM \"" + table + "\" ORDER BY rowid";
        if (sqlite3_prepare_v2(db, sql.c_str(), -1, &select, nullptr) != SQLITE_OK) {
            ADD_FAILURE() << sql << ": " << sqlite3_errmsg(db);
            continue;
        }
        while (sqlite3_step(select) == SQLITE_ROW) {
            Row row;
            for (int c = 0; c < sqlite3_column_count(select); ++c) {
                const std::string column = sqlite3_column_name(select, c);
                if (skip.count(table + "." + column) || skip.count("." + column)) continue;
                const int type = sqlite3_column_type(select, c);
                const unsigned char* text = sqlite3_column_text(select, c);
                row[column] = type == SQLITE_NULL ? "NULL"
                                                  : std::to_string(type) + ":" +
                                                        reinterpret_cast<const char*>(text);
            }
            rows.push_back(std::move(row));
        }
        sqlite3_finalize(select);
    }
    sqlite3_close(db);
    return tables;
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
    walk_to_headset_step(lab, "P07");
    ASSERT_FALSE(HasFailure()) << lab.log();
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
    EXPECT_TRUE(wait_for([&] { return has_shot(dir, "summary"); }, 30));
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

// A dense monitor: with the X server's resources saying 192 dpi (Xft.dpi, which GLFW reads as a
// content scale of 2, as desktops set it for HiDPI screens) the launcher draws its 16-pixel text at
// 32 pixels, and says so in its state.
TEST_F(LabWindowTest, TextScalesWithTheMonitorsContentScale) {
    Display* display = XOpenDisplay(nullptr);
    ASSERT_NE(display, nullptr);
    const Atom resources = XInternAtom(display, "RESOURCE_MANAGER", False);
    const std::string dense = "Xft.dpi:\t192\n";
    XChangeProperty(display, DefaultRootWindow(display), resources, XA_STRING, 8, PropModeReplace,
                    reinterpret_cast<const unsigned char*>(dense.data()),
                    static_cast<int>(dense.size()));
    XSync(display, False);
    const fs::path dir = prepare({});
    {
        Lab lab(dir, {});
        EXPECT_TRUE(lab.wait_step("protocol")) << lab.log();
        EXPECT_TRUE(wait_for([&] { return lab.state()["window"]["font_pixels"] == 32.0; }, 30))
            << lab.state().dump(1);
        EXPECT_EQ(lab.state()["window"]["content_scale"], 2.0);
        EXPECT_TRUE(lab.focus()) << lab.log();
        xdo("key ctrl+q");
        EXPECT_EQ(lab.wait_exit(60), 0) << lab.log();
    }
    XDeleteProperty(display, DefaultRootWindow(display), resources);
    XCloseDisplay(display);
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

// Item 3: the launcher's session is the command's. The same protocol file, participant code,
// headset, observer and seed through the window and through `study run` give the same rows in
// every table. Left out: the wall-clock times (*_utc: when it ran, not what was recorded). A
// headless session's event and frame times come from its virtual clock, so they are compared;
// a simulated-headset session would also differ in its frames' measured cpu_ms / gpu_ms /
// missed and pipeline counts, which this headless comparison does not need to leave out.
TEST_F(LabWindowTest, SeededSessionIsTheCommandsSession) {
    const fs::path dir = prepare({});
    Lab lab(dir, {"--headset", "none", "--seed", "4242"});
    walk_to_headset_step(lab, "P07");
    ASSERT_FALSE(HasFailure()) << lab.log();
    const json ready = lab.state();
    ASSERT_EQ(ready["start"]["enabled"], true) << ready.dump(1);
    EXPECT_EQ(ready["headset"]["choice"], "none") << ready.dump(1);
    xdo("key ctrl+Return");
    ASSERT_TRUE(lab.wait_step("summary", 300)) << lab.log();
    ASSERT_TRUE(lab.focus()) << lab.log();
    xdo("key ctrl+q");
    ASSERT_EQ(lab.wait_exit(60), 0) << lab.log();

    ASSERT_EQ(run_monoplane({"study", "run", "--protocol", (dir / "protocols/demo.toml").string(),
                             "--participant", "P07", "--db", (dir / "cli.sqlite").string(),
                             "--headset", "none", "--seed", "4242"},
                            dir / "cli.log"),
              0)
        << file_text(dir / "cli.log");

    // Also left out: what is made new for every session or process (the session's globally
    // unique id, the process id of its run).
    const std::set<std::string> times = {".started_utc",  ".ended_utc",    ".decided_utc",
                                         ".created_utc",  ".answered_utc", ".noted_utc",
                                         ".session_uuid", ".pid"};
    const auto from_lab = database_rows(dir / "lab.sqlite", times);
    const auto from_cli = database_rows(dir / "cli.sqlite", times);
    ASSERT_EQ(from_lab.size(), from_cli.size());
    std::size_t rows = 0;
    for (const auto& [table, lab_rows] : from_lab) {
        ASSERT_TRUE(from_cli.count(table)) << table;
        const std::vector<Row>& cli_rows = from_cli.at(table);
        ASSERT_EQ(lab_rows.size(), cli_rows.size()) << table;
        for (std::size_t i = 0; i < lab_rows.size(); ++i) {
            EXPECT_EQ(lab_rows[i], cli_rows[i]) << table << " row " << i;
            ++rows;
        }
    }
    EXPECT_GT(from_lab.at("trials").size(), 0u);
    EXPECT_GT(from_lab.at("events").size(), 0u);
    std::cout << "compared " << rows << " rows in " << from_lab.size()
              << " tables: the same apart from times\n";
}

// Item 6: the experimenter closes the session window mid-session. The session ends resumable,
// the launcher comes back on the summary, and Resume from the roster completes it.
TEST_F(LabWindowTest, ClosingTheSessionWindowKeepsItResumable) {
    const fs::path dir = prepare({});
    Lab lab(dir, {"--detail", "test", "--resolution-scale", "0.1", "--neutral-s", "0.3", "--end-s",
                  "0", "--sim-rate", "5"});
    walk_to_headset_step(lab, "P03");
    ASSERT_FALSE(HasFailure()) << lab.log();
    xdo("key ctrl+Return");
    ASSERT_TRUE(lab.wait_step("session")) << lab.log();
    ASSERT_TRUE(wait_for(
        [] { return !xdo_output("search --name '^monoplane: experimenter'").empty(); }, 120))
        << lab.log();
    std::this_thread::sleep_for(std::chrono::seconds(3));  // into the session
    ASSERT_GT(close_windows_named("^monoplane: experimenter"), 0);
    ASSERT_TRUE(lab.wait_step("summary", 120)) << lab.log();
    json j = lab.state();
    ASSERT_EQ(j["roster"].size(), 1u) << j.dump(1);
    EXPECT_NE(j["roster"][0]["state"], "completed") << j.dump(1);
    EXPECT_EQ(j["roster"][0]["resume_offered"], true) << j.dump(1);
    EXPECT_NE(j["summary"]["state"], "completed") << j.dump(1);
    // The summary says what the roster says ("interrupted"), not the stored status "running".
    EXPECT_EQ(j["summary"]["state"], j["roster"][0]["state"]) << j.dump(1);
    EXPECT_LT(j["roster"][0]["trials_decided"].get<int>(),
              j["roster"][0]["trials_planned"].get<int>())
        << j.dump(1);

    // Resume by keyboard: the summary focuses Export; Down moves through the roster (its
    // headers, then the one Resume button) and Space presses what has the focus.
    ASSERT_TRUE(lab.focus()) << lab.log();
    bool resumed = false;
    for (int i = 0; i < 6 && !resumed; ++i) {
        xdo("key Down");
        xdo("key space");
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        const json now = lab.state();
        resumed = now.is_object() && now["step"] != "summary";
    }
    ASSERT_TRUE(resumed) << lab.state().dump(1);
    ASSERT_TRUE(wait_for(
        [&] {
            const json now = lab.state();
            return now.is_object() && now["step"] == "summary" && now["roster"].size() == 1 &&
                   now["roster"][0]["state"] == "completed";
        },
        900))
        << lab.state().dump(1) << lab.log();
    ASSERT_TRUE(lab.focus()) << lab.log();
    xdo("key ctrl+q");
    ASSERT_EQ(lab.wait_exit(60), 0) << lab.log();
    const auto roster = study::read_roster({dir / "lab.sqlite"});
    ASSERT_TRUE(roster) << roster.error().message;
    ASSERT_EQ(roster->size(), 1u);
    EXPECT_EQ(roster->front().state(), "completed");
    EXPECT_EQ(roster->front().row.trials_decided, roster->front().row.trials_planned);
}

// Item 6: the database is in use by another session (a paced `study run` in another process).
// The launcher lists it as running with the holder's pid and offers no Resume; a session for
// another participant still runs (SQLite's WAL lets both write); nothing crashes or hangs.
TEST_F(LabWindowTest, SessionHeldByAnotherProcess) {
    const fs::path dir = prepare({});
    const pid_t holder =
        spawn_monoplane({"study", "run", "--protocol", (dir / "protocols/demo.toml").string(),
                         "--participant", "P01", "--db", (dir / "lab.sqlite").string(), "--headset",
                         "none", "--pace-ms", "1000", "--trace"},
                        dir / "holder.log");
    struct Reap {
        pid_t pid;
        ~Reap() {
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
        }
    } reap{holder};
    ASSERT_TRUE(wait_for([&] { return !file_text(dir / "holder.log").empty(); }, 60));

    Lab lab(dir, {"--headset", "none"});
    ASSERT_TRUE(lab.focus()) << lab.log();
    ASSERT_TRUE(lab.wait_step("protocol")) << lab.log();
    json j = lab.state();
    ASSERT_EQ(j["roster"].size(), 1u) << j.dump(1);
    const std::string state = j["roster"][0]["state"];
    EXPECT_NE(state.find(std::to_string(holder)), std::string::npos) << j.dump(1);
    EXPECT_EQ(j["roster"][0]["resume_offered"], false) << j.dump(1);
    EXPECT_FALSE(j["roster"][0]["resume_refusal"].get<std::string>().empty()) << j.dump(1);

    xdo("type --delay 40 demo.toml");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("participant")) << lab.state().dump(1);
    xdo("type --delay 40 P02");
    xdo("key Return");
    ASSERT_TRUE(lab.wait_step("headset")) << lab.state().dump(1);
    xdo("key ctrl+Return");
    ASSERT_TRUE(lab.wait_step("summary", 300)) << lab.log();
    j = lab.state();
    std::cout << "the launcher's session beside a held one: " << j["summary"].dump() << "\n";
    for (const json& line : j["roster"]) {
        if (line["participant"] == "P01") {
            EXPECT_EQ(line["resume_offered"], false) << j.dump(1);
        }
    }
    ASSERT_TRUE(lab.focus()) << lab.log();
    xdo("key ctrl+q");
    ASSERT_EQ(lab.wait_exit(60), 0) << lab.log();
}

// A simxr script for the headset check: a still head, HTC Vive controllers, and `extra`.
fs::path write_check_script(const fs::path& dir, const std::string& extra) {
    const fs::path path = dir / "check.toml";
    std::ofstream(path) << "hmd = \"vive\"\n"
                        << "display_rate_hz = 72\n"
                        << "head_motion = \"still\"\n"
                        << "interaction_profile = \"/interaction_profiles/htc/vive_controller\"\n"
                        << extra;
    return path;
}

// Up to the Headset step of demo.toml with participant `code`; the probed headset's state.
json reach_headset_step(Lab& lab, const std::string& code) {
    walk_to_headset_step(lab, code);
    // The step probed the simulated runtime on entry.
    EXPECT_TRUE(wait_for([&] { return lab.state()["headset"]["runtime_available"] == true; }, 30))
        << lab.state().dump(1) << lab.log();
    return lab.state()["headset"];
}

// Ctrl+H runs the headset check on the simulated headset; the scripted controller's CONFIRM
// (trackpad click at 0.3 s) ends it, and the headset section shows what the runtime measured.
TEST_F(LabWindowTest, HeadsetCheckConfirmedShowsTheRuntimesMeasurements) {
    const fs::path dir = prepare({});
    const fs::path script =
        write_check_script(dir,
                           "[[input]]\nt = 0.3\npath = \"/user/hand/right/input/trackpad/click\"\n"
                           "duration = 0.05\n");
    // --observer none: the script's controller answers, not the simulated observer.
    Lab lab(dir, {"--sim-script", script.string(), "--observer", "none"});
    const json probed = reach_headset_step(lab, "P05");
    EXPECT_EQ(probed["runtime"].get<std::string>().rfind("monoplane simxr ", 0), 0u) << probed;
    EXPECT_GT(probed["width"], 0);
    EXPECT_GT(probed["height"], 0);
    EXPECT_EQ(probed["check"], "");
    EXPECT_EQ(probed["eye_gaze"], "tracked") << probed;  // simxr's eye tracker, before any check
    xdo("key ctrl+h");
    ASSERT_TRUE(wait_for([&] { return lab.state()["headset"]["check"] != ""; }, 120))
        << lab.state().dump(1) << lab.log();
    const json h = lab.state()["headset"];
    EXPECT_EQ(h["check"], "confirmed") << h.dump(1);
    EXPECT_NE(h["check_message"].get<std::string>().find("CONFIRM"), std::string::npos) << h;
    ASSERT_TRUE(h["ipd_m"].is_number()) << h;
    EXPECT_NEAR(h["ipd_m"].get<double>(), 0.064, 1e-6);
    EXPECT_NEAR(h["refresh_hz"].get<double>(), 72.0, 1e-3);
    EXPECT_EQ(h["interaction_profile"], "/interaction_profiles/htc/vive_controller");
    EXPECT_GT(h["check_frames"].get<int>(), 0);
    // simxr's default gaze: tracked, its blinks (0.15 s every 4 s, the first at 2 s) after the
    // check's CONFIRM at 0.3 s, so every frame shown had a valid sample.
    EXPECT_EQ(h["eye_gaze"], "tracked") << h;
    EXPECT_EQ(h["eye_gaze_frames"], h["check_frames"]) << h;
    EXPECT_EQ(lab.state()["step"], "headset");  // the launcher stays where it was
    // The check's panel was shown while it ran.
    bool check_shot = false;
    for (const auto& entry : fs::directory_iterator(dir / "shots")) {
        if (entry.path().stem().string().find("headset-check") == std::string::npos) continue;
        check_shot = true;
        EXPECT_GT(pixel_stddev(entry.path()), 5.0) << entry.path() << " looks blank";
    }
    EXPECT_TRUE(check_shot) << "no screenshot of the check";
    xdo("key ctrl+q");
    ASSERT_EQ(lab.wait_exit(60), 0) << lab.log();
}

// The runtime loses the session mid-check: the launcher shows the message, and goes on.
TEST_F(LabWindowTest, HeadsetCheckRuntimeLostShowsTheMessage) {
    const fs::path dir = prepare({});
    const fs::path script = write_check_script(dir, "lose_session_at_s = 0.2\n");
    Lab lab(dir, {"--sim-script", script.string(), "--observer", "none"});
    reach_headset_step(lab, "P06");
    xdo("key ctrl+h");
    ASSERT_TRUE(wait_for([&] { return lab.state()["headset"]["check"] != ""; }, 120))
        << lab.state().dump(1) << lab.log();
    const json h = lab.state()["headset"];
    EXPECT_EQ(h["check"], "runtime lost") << h.dump(1);
    EXPECT_NE(h["check_message"].get<std::string>().find("lost"), std::string::npos) << h;
    // Still responsive: back to the Participant step and out.
    xdo("key ctrl+Left");
    EXPECT_TRUE(lab.wait_step("participant")) << lab.log();
    xdo("key ctrl+q");
    ASSERT_EQ(lab.wait_exit(60), 0) << lab.log();
}

}  // namespace
}  // namespace monoplane
