// The launcher's model (app/lab/launcher_model.h): protocols listed with their `protocol check`
// verdict, the participant code and variables validated as typed with the study library's own
// messages, Start enabled exactly when study::plan_session accepts, the roster with its resume
// verdicts, the request Start produces (the options of `study run`), and the state dump.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "app/lab/lab_config.h"
#include "app/lab/launcher_model.h"
#include "app/lab/shell_words.h"
#include "study/file_digest.h"
#include "study/participant_variables.h"
#include "study/session_hold.h"
#include "study/session_start.h"
#include "study/study_store.h"

namespace monoplane::lab {
namespace {

namespace fs = std::filesystem;
using study::SessionStatus;

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// demo.toml with two required variables and an optional one.
std::string with_variables(const std::string& demo) {
    return demo + R"(
[[variables]]
name = "age"
type = "integer"
min = 18
max = 99
required = true
help = "Age in years"

[[variables]]
name = "vision"
type = "choice"
choices = ["normal", "corrected"]
required = true

[[variables]]
name = "remarks"
type = "text"
)";
}

class LauncherModelTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "lab_model_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        protocols_ = dir_ / "protocols";
        fs::create_directory(protocols_);
        const char* source = std::getenv("MONOPLANE_SOURCE_DIR");
        ASSERT_NE(source, nullptr) << "ctest sets MONOPLANE_SOURCE_DIR";
        demo_text_ = read_text(fs::path(source) / "protocols" / "demo.toml");
        ASSERT_FALSE(demo_text_.empty());
        write_text(protocols_ / "demo.toml", demo_text_);
        write_text(protocols_ / "broken.toml",
                   "name = \"broken\"\nscenes = [\"beams\"]\nmono_planes = [3, 8]\n"
                   "alternatives = [\"stereo\", \"hybrid\"]\ncolour = 3\n");
        write_text(protocols_ / "vars.toml", with_variables(demo_text_));
        write_text(protocols_ / "notes.txt", "not a protocol");
        db_ = dir_ / "study.sqlite";
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A model with the database open and `protocol` chosen, as the window's first two steps.
    LauncherModel ready(const std::string& protocol) {
        LauncherModel m(LauncherSettings{db_, protocols_});
        EXPECT_TRUE(m.database_open()) << m.database_message();
        const Result<void> chosen = m.select_protocol(protocols_ / protocol);
        EXPECT_TRUE(chosen.ok()) << chosen.error().message;
        return m;
    }

    // A session as `study run` begins it, through the same library calls.
    std::int64_t begin(const std::string& protocol, const std::string& code,
                       std::vector<std::string> variables, SessionStatus status,
                       std::vector<study::SceneFileRecord> scene_files = {}) {
        auto store = study::StudyStore::open(db_).value_or_throw();
        const study::Protocol p = study::load_protocol(protocols_ / protocol).value_or_throw();
        study::SessionRequest request;
        request.participant_code = code;
        request.variables = std::move(variables);
        request.seed = 7;
        study::SessionStart start = study::plan_session(store.get(), p, request).value_or_throw();
        start.info.runtime = "none";
        start.info.device = "none";
        start.info.scene_files = std::move(scene_files);
        const std::int64_t id = store->begin_session(start.info, start.schedule).value_or_throw();
        if (status != SessionStatus::Running) store->set_status(id, status).value_or_throw();
        return id;
    }

    fs::path dir_, protocols_, db_;
    std::string demo_text_;
};

TEST_F(LauncherModelTest, ListsTheFolderSortedWithEachProtocolCheckVerdict) {
    const auto listed = list_protocols(protocols_);
    ASSERT_TRUE(listed.ok()) << listed.error().message;
    ASSERT_EQ(listed->size(), 3u);  // notes.txt is no protocol
    EXPECT_EQ((*listed)[0].file, "broken.toml");
    EXPECT_EQ((*listed)[1].file, "demo.toml");
    EXPECT_EQ((*listed)[2].file, "vars.toml");
    EXPECT_FALSE((*listed)[0].valid);
    // The problem as `protocol check` prints it: file, line and column, the key.
    EXPECT_TRUE(contains((*listed)[0].message, "broken.toml:5:1: key 'colour'"))
        << (*listed)[0].message;
    EXPECT_EQ((*listed)[0].message,
              study::load_protocol(protocols_ / "broken.toml").error().message);
    EXPECT_TRUE((*listed)[1].valid);
    EXPECT_EQ((*listed)[1].name, "demo");
    EXPECT_TRUE((*listed)[1].message.empty());

    const auto missing = list_protocols(dir_ / "nowhere");
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(contains(missing.error().message, "--protocols DIR")) << missing.error().message;
}

TEST_F(LauncherModelTest, StepsFollowTheDayAndABrokenProtocolCannotBeChosen) {
    LauncherModel m(LauncherSettings{{}, protocols_});
    EXPECT_EQ(m.step(), LauncherStep::Database);
    EXPECT_FALSE(m.go_to(LauncherStep::Protocol).ok());
    const Result<void> absent = m.open_database(db_, false);
    ASSERT_FALSE(absent.ok());
    EXPECT_TRUE(contains(absent.error().message, "choose Create")) << absent.error().message;
    EXPECT_FALSE(fs::exists(db_));
    ASSERT_TRUE(m.open_database(db_, true).ok()) << m.database_message();
    EXPECT_TRUE(fs::exists(db_));
    ASSERT_TRUE(m.go_to(LauncherStep::Protocol).ok());
    const Result<void> to_participant = m.go_to(LauncherStep::Participant);
    ASSERT_FALSE(to_participant.ok());
    EXPECT_EQ(to_participant.error().message, "choose a valid protocol first");

    const Result<void> broken = m.select_protocol(protocols_ / "broken.toml");
    ASSERT_FALSE(broken.ok());
    EXPECT_TRUE(contains(broken.error().message, "broken.toml:5:1")) << broken.error().message;
    EXPECT_EQ(m.protocol(), nullptr);
    EXPECT_FALSE(m.start_enabled());
    EXPECT_EQ(m.start_message(), "choose a valid protocol first");

    ASSERT_TRUE(m.select_protocol(protocols_ / "demo.toml").ok());
    ASSERT_TRUE(m.go_to(LauncherStep::Participant).ok());
    EXPECT_FALSE(m.go_to(LauncherStep::Headset).ok());  // no code yet
    EXPECT_FALSE(m.go_to(LauncherStep::Session).ok());  // only Start begins a session
    m.set_participant_code("P01");
    ASSERT_TRUE(m.go_to(LauncherStep::Headset).ok());
    ASSERT_TRUE(m.go_to(LauncherStep::Database).ok());  // back is always open
}

TEST_F(LauncherModelTest, TheCodeIsValidatedAsTyped) {
    LauncherModel m = ready("demo.toml");
    EXPECT_EQ(m.code_message(), "");
    EXPECT_EQ(m.start_message(), "enter the participant code");
    m.set_participant_code("P 01");
    EXPECT_EQ(m.code_message(), study::check_participant_code("P 01").error().message);
    EXPECT_TRUE(contains(m.code_message(), "letters, digits, '_' or '-'")) << m.code_message();
    EXPECT_FALSE(m.start_enabled());
    m.set_participant_code(std::string(65, 'a'));
    EXPECT_TRUE(contains(m.code_message(), "1 to 64")) << m.code_message();
    EXPECT_FALSE(m.start_enabled());
    m.set_participant_code("P01");
    EXPECT_EQ(m.code_message(), "");
    EXPECT_FALSE(m.participant().has_value());
    EXPECT_EQ(m.next_session_number(), 1);
    EXPECT_TRUE(m.start_enabled()) << m.start_message();
}

TEST_F(LauncherModelTest, AVariableOutOfRangeShowsTheLibrarysMessageAndKeepsStartDisabled) {
    LauncherModel m = ready("vars.toml");
    ASSERT_EQ(m.variables().size(), 3u);
    EXPECT_EQ(m.variables()[0].declaration.name, "age");
    EXPECT_TRUE(m.variables()[0].declaration.required);
    EXPECT_EQ(m.variables()[1].declaration.choices,
              (std::vector<std::string>{"normal", "corrected"}));
    m.set_participant_code("P01");
    ASSERT_TRUE(m.set_variable("age", "17").ok());
    ASSERT_TRUE(m.set_variable("vision", "normal").ok());
    const std::string expected =
        study::check_variable_value(m.variables()[0].declaration, "17").error().message;
    EXPECT_EQ(m.variables()[0].message, expected);
    EXPECT_TRUE(contains(expected, "age")) << expected;
    EXPECT_FALSE(m.start_enabled());
    EXPECT_TRUE(contains(m.start_message(), expected)) << m.start_message();
    EXPECT_FALSE(m.start().ok());
    EXPECT_EQ(m.step(), LauncherStep::Protocol);

    ASSERT_TRUE(m.set_variable("age", "30").ok());
    EXPECT_EQ(m.variables()[0].message, "");
    EXPECT_TRUE(m.start_enabled()) << m.start_message();
    EXPECT_FALSE(m.set_variable("height", "180").ok());
}

TEST_F(LauncherModelTest, AMissingRequiredVariableKeepsStartDisabledWithTheMessage) {
    LauncherModel m = ready("vars.toml");
    m.set_participant_code("P01");
    ASSERT_TRUE(m.set_variable("age", "30").ok());
    EXPECT_EQ(m.variables()[1].message, "");  // an empty field is not yet an error...
    EXPECT_FALSE(m.start_enabled());          // ...but Start says what is missing
    // In the Participant step's words, where the field is: not `study run`'s --var advice.
    const std::string expected = "fill in 'vision' above: it is required";
    EXPECT_EQ(m.start_message(), expected);
    EXPECT_EQ(m.participant_problems(), std::vector<std::string>{expected});
    EXPECT_FALSE(contains(m.start_message(), "--var")) << m.start_message();
    const Result<LaunchRequest> refused = m.start();
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message, expected);
}

TEST_F(LauncherModelTest, AKnownParticipantShowsTheirSessionsAndRecordedVariables) {
    const std::int64_t first =
        begin("vars.toml", "P01", {"age=30", "vision=corrected"}, SessionStatus::Completed);
    LauncherModel m = ready("vars.toml");
    m.set_participant_code("P01");
    ASSERT_TRUE(m.participant().has_value());
    ASSERT_EQ(m.participant()->sessions.size(), 1u);
    EXPECT_EQ(m.participant()->sessions[0], std::make_pair(1, first));
    EXPECT_EQ(m.next_session_number(), 2);
    EXPECT_EQ(m.variables()[0].text, "30");
    EXPECT_TRUE(m.variables()[0].recorded);
    EXPECT_EQ(m.variables()[1].text, "corrected");
    EXPECT_FALSE(m.set_variable("age", "31").ok());
    // demo.toml-like protocols have sessions = 1: a second session is refused, as by the command.
    EXPECT_FALSE(m.start_enabled());
    EXPECT_TRUE(contains(m.start_message(), "P01 has had all 1 session(s) of protocol"))
        << m.start_message();
    EXPECT_FALSE(contains(m.start_message(), "study resume")) << m.start_message();
    m.set_session_number(1);
    EXPECT_TRUE(contains(m.start_message(), "already has session 1")) << m.start_message();
}

// One live session per participant, in the launcher as on the command line: Start stays off
// with the library's message while the participant's earlier session is interrupted or running;
// and opening the database, reading its roster and the participant's form write nothing.
TEST_F(LauncherModelTest, StartStaysOffForAParticipantsUnfinishedSessionAndOpenWritesNothing) {
    write_text(protocols_ / "two.toml", "sessions = 2\n" + demo_text_);
    const std::int64_t interrupted = begin("two.toml", "P01", {}, SessionStatus::Running);
    const std::int64_t held = begin("two.toml", "P02", {}, SessionStatus::Running);
    Result<study::SessionHold> hold = study::SessionHold::acquire(db_, held);
    ASSERT_TRUE(hold.ok()) << hold.error().message;
    const std::string before = read_text(db_);
    ASSERT_FALSE(fs::exists(db_.string() + "-wal"));

    LauncherModel m = ready("two.toml");
    m.set_participant_code("P01");
    EXPECT_FALSE(m.start_enabled());
    EXPECT_TRUE(contains(m.start_message(), "P01's session 1 was interrupted (0 of "))
        << m.start_message();
    EXPECT_TRUE(contains(m.start_message(), "press Resume on its line")) << m.start_message();
    EXPECT_FALSE(contains(m.start_message(), "study resume")) << m.start_message();
    m.set_participant_code("P02");
    EXPECT_FALSE(m.start_enabled());
    EXPECT_TRUE(
        contains(m.start_message(), "is running (process " + std::to_string(::getpid()) + " on "))
        << m.start_message();
    m.set_participant_code("P03");  // a new participant starts beside them
    EXPECT_TRUE(m.start_enabled()) << m.start_message();
    EXPECT_EQ(read_text(db_), before);
    EXPECT_FALSE(fs::exists(db_.string() + "-wal"));
    EXPECT_FALSE(fs::exists(db_.string() + "-shm"));
    (void)interrupted;
}

TEST_F(LauncherModelTest, TheRosterSaysWhichSessionsResumeAndWhyNot) {
    begin("demo.toml", "P01", {}, SessionStatus::Completed);
    const std::int64_t interrupted = begin("demo.toml", "P02", {}, SessionStatus::Running);
    const std::int64_t held = begin("demo.toml", "P03", {}, SessionStatus::Running);
    Result<study::SessionHold> hold = study::SessionHold::acquire(db_, held);
    ASSERT_TRUE(hold.ok()) << hold.error().message;

    LauncherModel m = ready("demo.toml");
    ASSERT_EQ(m.roster().size(), 3u);
    EXPECT_EQ(m.roster()[0].state, "completed");
    EXPECT_FALSE(m.roster()[0].resume_offered);
    EXPECT_EQ(m.roster()[0].resume_refusal, "");
    EXPECT_EQ(m.roster()[1].state, "interrupted");
    EXPECT_TRUE(m.roster()[1].resume_offered);
    EXPECT_TRUE(m.roster()[2].state.starts_with("running (process " + std::to_string(::getpid())))
        << m.roster()[2].state;
    EXPECT_FALSE(m.roster()[2].resume_offered);
    EXPECT_TRUE(contains(m.roster()[2].resume_refusal, "process " + std::to_string(::getpid())))
        << m.roster()[2].resume_refusal;

    const Result<LaunchRequest> refused = m.resume(held, false);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(contains(refused.error().message, "is being run by")) << refused.error().message;
    ASSERT_TRUE(m.set_headset("none").ok());
    const Result<LaunchRequest> resumed = m.resume(interrupted, false);
    ASSERT_TRUE(resumed.ok()) << resumed.error().message;
    EXPECT_EQ(m.step(), LauncherStep::Session);
    EXPECT_EQ(resumed->arguments(),
              (std::vector<std::string>{"study", "resume", "--db", db_.string(), "--session-id",
                                        std::to_string(interrupted), "--headset", "none"}));
    EXPECT_FALSE(m.go_to(LauncherStep::Database).ok());  // not while the session runs
    ASSERT_TRUE(m.session_ended("").ok());
    EXPECT_EQ(m.step(), LauncherStep::Summary);
    ASSERT_TRUE(m.summary().has_value());
    EXPECT_EQ(m.summary()->session_id, interrupted);
    EXPECT_EQ(m.summary()->participant, "P02");
}

TEST_F(LauncherModelTest, AChangedSceneFileRefusesResumeUnlessAccepted) {
    const fs::path scene = protocols_ / "room.gltf";
    write_text(scene, R"({"asset":{"version":"2.0"}})");
    std::string text = demo_text_;
    text.replace(text.find("\"spheres\"]"), 10, "\"room.gltf\"]");
    write_text(protocols_ / "gltf.toml", text);
    const study::FileDigest digest = study::digest_file(scene).value_or_throw();
    const std::int64_t id =
        begin("gltf.toml", "P01", {}, SessionStatus::Running,
              {study::SceneFileRecord{"room.gltf", 0, fs::absolute(scene), digest}});
    write_text(scene, R"({"asset":{"version":"2.0"},"scenes":[]})");

    LauncherModel m = ready("gltf.toml");
    ASSERT_EQ(m.roster().size(), 1u);
    EXPECT_FALSE(m.roster()[0].resume_offered);
    EXPECT_TRUE(m.roster()[0].scene_files_changed);
    EXPECT_TRUE(contains(m.roster()[0].resume_refusal, "room.gltf"))
        << m.roster()[0].resume_refusal;
    EXPECT_FALSE(m.resume(id, false).ok());
    const Result<LaunchRequest> accepted = m.resume(id, true);
    ASSERT_TRUE(accepted.ok()) << accepted.error().message;
    EXPECT_TRUE(accepted->accept_changed_scenes);
    EXPECT_TRUE(contains(m.state_json(), "\"scene_files_changed\": true"));
}

// What `study run` gets from StudyOptions (study_session.cpp's plan()): the same fields.
study::SessionRequest as_the_command_builds_it(const LaunchRequest& r) {
    study::SessionRequest s;
    s.participant_code = r.participant;
    s.session_number = r.session_number;
    s.participant_number = r.participant_number;
    s.variables = r.variables;
    s.seed = *r.seed;
    return s;
}

TEST_F(LauncherModelTest, StartProducesTheCommandsRequest) {
    LauncherModel m = ready("vars.toml");
    m.set_participant_code("P05");
    ASSERT_TRUE(m.set_variable("age", "41").ok());
    ASSERT_TRUE(m.set_variable("vision", "normal").ok());
    ASSERT_TRUE(m.set_headset("none").ok());
    EXPECT_FALSE(m.set_observer("nobody").ok());  // study::make_observer's refusal
    ASSERT_TRUE(m.set_observer("chance").ok());
    m.set_seed(1234);
    const Result<LaunchRequest> r = m.start();
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(m.step(), LauncherStep::Session);
    EXPECT_EQ(r->command, LaunchRequest::Command::Run);
    EXPECT_EQ(r->protocol, (protocols_ / "vars.toml").string());
    EXPECT_EQ(r->db, db_.string());
    EXPECT_EQ(r->participant, "P05");
    EXPECT_EQ(r->variables, (std::vector<std::string>{"age=41", "vision=normal"}));
    EXPECT_FALSE(r->session_number.has_value());  // the command's default: their next
    EXPECT_FALSE(r->participant_number.has_value());
    EXPECT_EQ(r->seed, 1234u);
    const std::vector<std::string> args = r->arguments();
    EXPECT_EQ(args, (std::vector<std::string>{"study", "run", "--protocol", r->protocol,
                                              "--participant", "P05", "--db", db_.string(), "--var",
                                              "age=41", "--var", "vision=normal", "--headset",
                                              "none", "--observer", "chance", "--seed", "1234"}));

    // The command, given these arguments, stores the session the request plans.
    auto store = study::StudyStore::open(db_).value_or_throw();
    const study::SessionStart planned =
        study::plan_session(store.get(), *m.protocol(), as_the_command_builds_it(*r))
            .value_or_throw();
#ifdef MONOPLANE_EXECUTABLE
    if (!fs::exists(MONOPLANE_EXECUTABLE)) GTEST_SKIP() << MONOPLANE_EXECUTABLE << " not built";
    std::string command = "'" + std::string(MONOPLANE_EXECUTABLE) + "'";
    for (const std::string& a : args) command += " '" + a + "'";
    ASSERT_EQ(std::system((command + " > /dev/null 2>&1").c_str()), 0) << command;
    ASSERT_TRUE(m.session_ended("").ok());
    const auto id = store->find_session("P05", 1).value_or_throw();
    ASSERT_TRUE(id.has_value());
    const study::SessionInfo stored = store->session(*id).value_or_throw();
    EXPECT_EQ(stored.seed, planned.info.seed);
    EXPECT_EQ(stored.variables, planned.info.variables);
    EXPECT_EQ(stored.participant_number, planned.info.participant_number);
    EXPECT_EQ(stored.observer, "chance");
    const study::Schedule schedule = store->load_schedule(*id).value_or_throw();
    ASSERT_EQ(schedule.trials.size(), planned.schedule.trials.size());
    EXPECT_EQ(schedule.block_order, planned.schedule.block_order);
    for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
        const study::ScheduledTrial& a = schedule.trials[i];
        const study::ScheduledTrial& b = planned.schedule.trials[i];
        EXPECT_EQ(std::tie(a.practice, a.block, a.scene, a.mono_plane, a.label1_alternative),
                  std::tie(b.practice, b.block, b.scene, b.mono_plane, b.label1_alternative))
            << "trial " << i;
    }
    ASSERT_TRUE(m.summary().has_value());
    EXPECT_EQ(m.summary()->state, "completed");
    EXPECT_EQ(m.summary()->trials_decided, m.summary()->trials_planned);
    EXPECT_EQ(m.next_session_number(), 2);
#else
    GTEST_SKIP() << "no monoplane executable in this build (MONOPLANE_VULKAN=OFF)";
#endif
}

TEST_F(LauncherModelTest, TheStateDumpNamesWhatEachStepShows) {
    begin("demo.toml", "P01", {}, SessionStatus::Running);
    LauncherModel m = ready("vars.toml");
    ASSERT_TRUE(m.go_to(LauncherStep::Participant).ok());
    m.set_participant_code("P02");
    ASSERT_TRUE(m.set_variable("age", "150").ok());
    const nlohmann::json j = nlohmann::json::parse(m.state_json());
    EXPECT_EQ(j["step"], "participant");
    EXPECT_EQ(j["database"]["path"], db_.string());
    EXPECT_EQ(j["database"]["open"], true);
    ASSERT_EQ(j["protocols"]["files"].size(), 3u);
    EXPECT_EQ(j["protocols"]["files"][0]["valid"], false);
    EXPECT_TRUE(contains(j["protocols"]["files"][0]["message"], "broken.toml:5:1"));
    EXPECT_EQ(j["protocol"]["name"], "demo");
    EXPECT_EQ(j["participant"]["code"], "P02");
    EXPECT_EQ(j["participant"]["known"], false);
    EXPECT_EQ(j["participant"]["next_session_number"], 1);
    EXPECT_TRUE(j["participant"]["session_number"].is_null());
    ASSERT_EQ(j["variables"].size(), 3u);
    EXPECT_EQ(j["variables"][0]["name"], "age");
    EXPECT_EQ(j["variables"][0]["type"], "integer");
    EXPECT_EQ(j["variables"][0]["min"], 18);
    EXPECT_EQ(j["variables"][0]["max"], 99);
    EXPECT_EQ(j["variables"][0]["required"], true);
    EXPECT_EQ(j["variables"][0]["help"], "Age in years");
    EXPECT_EQ(j["variables"][0]["value"], "150");
    EXPECT_EQ(j["variables"][0]["message"], m.variables()[0].message);
    EXPECT_FALSE(m.variables()[0].message.empty());
    EXPECT_EQ(j["variables"][1]["choices"], nlohmann::json({"normal", "corrected"}));
    EXPECT_EQ(j["start"]["enabled"], false);
    EXPECT_EQ(j["start"]["message"], m.start_message());
    EXPECT_EQ(j["start"]["arguments"][1], "run");
    EXPECT_EQ(j["headset"]["choice"], "simulated");
    ASSERT_EQ(j["roster"].size(), 1u);
    EXPECT_EQ(j["roster"][0]["participant"], "P01");
    EXPECT_EQ(j["roster"][0]["state"], "interrupted");
    EXPECT_EQ(j["roster"][0]["resume_offered"], true);
    EXPECT_TRUE(j["summary"].is_null());
}

// The headset step's report (the window probes and checks; the model shows it as is), including
// how the last headset check ended.
TEST_F(LauncherModelTest, StateJsonShowsTheHeadsetReportAndTheCheck) {
    LauncherModel m(LauncherSettings{});
    HeadsetReport report;
    report.runtime_available = true;
    report.runtime = "monoplane simxr 0.1.0";
    report.system = "monoplane simxr: HTC Vive";
    report.width = 1080;
    report.height = 1200;
    report.refresh_hz = 72.0;
    report.ipd_m = 0.064;
    report.interaction_profile = "/interaction_profiles/htc/vive_controller";
    report.check = "runtime lost";
    report.check_message = "the runtime lost the session";
    report.check_frames = 14;
    m.set_headset_report(report);
    const nlohmann::json h = nlohmann::json::parse(m.state_json())["headset"];
    EXPECT_EQ(h["runtime_available"], true);
    EXPECT_EQ(h["runtime"], "monoplane simxr 0.1.0");
    EXPECT_EQ(h["system"], "monoplane simxr: HTC Vive");
    EXPECT_EQ(h["width"], 1080);
    EXPECT_EQ(h["height"], 1200);
    EXPECT_DOUBLE_EQ(h["refresh_hz"].get<double>(), 72.0);
    EXPECT_DOUBLE_EQ(h["ipd_m"].get<double>(), 0.064);
    EXPECT_EQ(h["interaction_profile"], "/interaction_profiles/htc/vive_controller");
    EXPECT_EQ(h["message"], "");
    EXPECT_EQ(h["check"], "runtime lost");
    EXPECT_EQ(h["check_message"], "the runtime lost the session");
    EXPECT_EQ(h["check_frames"], 14);

    m.set_headset_report(HeadsetReport{});  // no runtime probed, no check yet
    const nlohmann::json none = nlohmann::json::parse(m.state_json())["headset"];
    EXPECT_EQ(none["runtime_available"], false);
    EXPECT_TRUE(none["ipd_m"].is_null());
    EXPECT_EQ(none["check"], "");
    EXPECT_EQ(none["check_frames"], 0);
}

// A decimal comma is refused with the number written with a point, in the launcher as by
// `study run --var` (which refuses it too): "6,5" is never stored as 65 or 6.5 unseen.
TEST_F(LauncherModelTest, ADecimalCommaIsRefusedWithTheNumberWrittenWithAPoint) {
    write_text(protocols_ / "ipd.toml", demo_text_ + R"(
[[variables]]
name = "ipd_mm"
type = "number"
min = 50
max = 80
required = true
)");
    LauncherModel m(LauncherSettings{db_, protocols_, launcher_request_names()});
    ASSERT_TRUE(m.select_protocol(protocols_ / "ipd.toml").ok());
    m.set_participant_code("P01");
    ASSERT_TRUE(m.set_variable("ipd_mm", "63,5").ok());
    EXPECT_EQ(m.variables()[0].message,
              "the 'ipd_mm' field: write 63.5 (the decimal point is '.'; a comma is not read as "
              "one)");
    EXPECT_FALSE(m.start_enabled());
    // The command refuses the same text.
    EXPECT_FALSE(study::check_variable_value(m.variables()[0].declaration, "63,5").ok());
    ASSERT_TRUE(m.set_variable("ipd_mm", "63.5").ok());
    EXPECT_EQ(m.variables()[0].message, "");
    EXPECT_TRUE(m.start_enabled()) << m.start_message();
    EXPECT_EQ(m.request().variables, std::vector<std::string>{"ipd_mm=63.5"});
    // Not a number in any reading: the library's message, in the window's names.
    ASSERT_TRUE(m.set_variable("ipd_mm", "6,5,1").ok());
    EXPECT_TRUE(contains(m.variables()[0].message, "the 'ipd_mm' field: not a number"))
        << m.variables()[0].message;
}

TEST_F(LauncherModelTest, NextParticipantClearsTheCodeAndFormAndKeepsTheProtocol) {
    LauncherModel m = ready("vars.toml");
    m.set_participant_code("P03");
    ASSERT_TRUE(m.set_variable("age", "30").ok());
    ASSERT_TRUE(m.set_variable("vision", "normal").ok());
    m.set_session_number(1);
    ASSERT_TRUE(m.go_to(LauncherStep::Headset).ok());
    ASSERT_TRUE(m.next_participant().ok());
    EXPECT_EQ(m.step(), LauncherStep::Participant);
    EXPECT_EQ(m.participant_code(), "");
    EXPECT_FALSE(m.session_number().has_value());
    ASSERT_NE(m.protocol(), nullptr);
    EXPECT_EQ(m.protocol_path(), protocols_ / "vars.toml");
    for (const VariableField& field : m.variables())
        EXPECT_EQ(field.text, "") << field.declaration.name;
    EXPECT_FALSE(m.start_enabled());
}

TEST_F(LauncherModelTest, TheProtocolsFolderIsListedAgainWhenItChanges) {
    const fs::path later = dir_ / "later";
    LauncherModel m(LauncherSettings{db_, later});
    EXPECT_TRUE(m.protocols().empty());
    EXPECT_TRUE(contains(m.protocols_message(), "does not exist")) << m.protocols_message();
    EXPECT_FALSE(m.rescan_protocols_if_changed());  // still missing: nothing new
    fs::create_directory(later);
    write_text(later / "demo.toml", demo_text_);
    EXPECT_TRUE(m.rescan_protocols_if_changed());
    ASSERT_EQ(m.protocols().size(), 1u);
    EXPECT_TRUE(m.protocols()[0].valid) << m.protocols()[0].message;
    EXPECT_EQ(m.protocols_message(), "");
    EXPECT_FALSE(m.rescan_protocols_if_changed());
    write_text(later / "x.toml", "name = \"x\"\nscenes = [\"beams\"]\n");  // saved meanwhile
    EXPECT_TRUE(m.rescan_protocols_if_changed());
    EXPECT_EQ(m.protocols().size(), 2u);
    // A protocol kept outside the folder is chosen by its full path.
    EXPECT_TRUE(m.select_protocol(protocols_ / "vars.toml").ok());
    EXPECT_EQ(m.protocol_path(), protocols_ / "vars.toml");
    EXPECT_FALSE(m.select_protocol(dir_ / "none.toml").ok());
}

TEST_F(LauncherModelTest, TheCommandLineHasEverySessionOptionShellQuoted) {
    LauncherSettings settings{db_, protocols_};
    settings.session_arguments = {"--detail", "test", "--sim-script", "/tmp/a b/it's.toml"};
    LauncherModel m(settings);
    ASSERT_TRUE(m.select_protocol(protocols_ / "demo.toml").ok());
    m.set_participant_code("P01");
    const std::vector<std::string> a = m.request().arguments();
    ASSERT_GE(a.size(), 4u);
    EXPECT_EQ(std::vector<std::string>(a.end() - 4, a.end()), settings.session_arguments);
    EXPECT_EQ(shell_quoted("/tmp/a b/it's.toml"), "'/tmp/a b/it'\\''s.toml'");
    EXPECT_EQ(shell_quoted("--var"), "--var");
    EXPECT_EQ(shell_quoted("age=30"), "age=30");
    EXPECT_EQ(shell_quoted(""), "''");
    EXPECT_EQ(shell_command_line({"study", "run", "--var", "note=a b"}),
              "monoplane study run --var 'note=a b'");
}

TEST_F(LauncherModelTest, StartIsDisabledWhenTheChosenHeadsetHasNoRuntime) {
    LauncherModel m = ready("demo.toml");
    m.set_participant_code("P01");
    ASSERT_TRUE(m.set_headset("openxr").ok());
    EXPECT_TRUE(m.start_enabled()) << m.start_message();  // not probed yet: the session says
    HeadsetReport none;
    none.message = "no OpenXR runtime is active";
    m.set_headset_report(none);
    EXPECT_FALSE(m.start_enabled());
    EXPECT_TRUE(contains(m.start_message(), "no runtime for the openxr headset"))
        << m.start_message();
    EXPECT_TRUE(contains(m.start_message(), "no OpenXR runtime is active")) << m.start_message();
    ASSERT_TRUE(m.set_headset("none").ok());
    EXPECT_TRUE(m.start_enabled()) << m.start_message();
}

TEST_F(LauncherModelTest, TheLastDatabaseAndProtocolsFolderAreRemembered) {
    const fs::path file = dir_ / "config" / "monoplane" / "lab.toml";
    Result<LabConfig> none = read_lab_config(file);
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->db.empty());
    ASSERT_TRUE(write_lab_config(file, LabConfig{db_, protocols_}).ok());
    Result<LabConfig> read = read_lab_config(file);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->db, db_);
    EXPECT_EQ(read->protocols, protocols_);
    write_text(file, "db = [\n");
    EXPECT_FALSE(read_lab_config(file).ok());
    ::setenv("XDG_CONFIG_HOME", (dir_ / "config").c_str(), 1);
    EXPECT_EQ(lab_config_file(), file);
    ::unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace monoplane::lab
