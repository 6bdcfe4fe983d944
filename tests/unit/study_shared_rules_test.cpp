// Rules that several parts of the study take from one home, so that they cannot drift apart: a
// participant code (participant_code.h) refused by the store and by plan_session with the same
// words, a variable name (check_variable_name) refused by the store and by the protocol parser
// with the same words, one UTC clock (common/utc_time.h) for the store and the session holds, and
// names read both ways from one table each.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "common/utc_time.h"
#include "study/live_session.h"
#include "study/participant_code.h"
#include "study/protocol.h"
#include "study/protocol_study_day.h"
#include "study/session_hold.h"
#include "study/session_log.h"
#include "study/session_start.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

bool is_utc_second(const std::string& text) {
    static const std::regex kIso8601(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}Z)");
    return std::regex_match(text, kIso8601);
}

// Two data trials on one scene, nothing a store would refuse.
Schedule two_trials() {
    Schedule s;
    s.seed = 7;
    s.block_order = {"beams"};
    for (int i = 0; i < 2; ++i) {
        ScheduledTrial t;
        t.index = i;
        t.block = 0;
        t.scene = "beams";
        t.mono_plane = i == 0 ? 1.6 : 8.0;
        t.label1_mode = RenderMode::Stereo;
        t.label2_mode = RenderMode::Hybrid;
        s.trials.push_back(t);
    }
    return s;
}

SessionInfo info_for(const std::string& code) {
    SessionInfo info;
    info.participant_code = code;
    info.protocol_name = "rules";
    info.protocol_text = "name = \"rules\"\n";
    info.software_version = "0.1.0";
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "lab-pc";
    info.observer = "default";
    return info;
}

class StudySharedRulesTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "study_rules_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        Result<std::unique_ptr<StudyStore>> opened = StudyStore::open(dir_ / "rules.sqlite");
        ASSERT_TRUE(opened.ok()) << opened.error().message;
        store_ = std::move(opened).value();
    }
    void TearDown() override {
        store_.reset();
        fs::remove_all(dir_);
    }

    fs::path dir_;
    std::unique_ptr<StudyStore> store_;
};

TEST_F(StudySharedRulesTest, TheStoreAndThePlannerRefuseABadParticipantCodeInTheSameWords) {
    for (const std::string& code :
         std::vector<std::string>{"P 07", "", std::string(65, 'a'), "Anna/Schmidt"}) {
        const Result<void> rule = check_participant_code(code);
        ASSERT_FALSE(rule.ok()) << code;
        EXPECT_NE(rule.error().message.find("participant code '" + code + "'"), std::string::npos);
        EXPECT_NE(rule.error().message.find("never a name"), std::string::npos);

        const Result<std::int64_t> stored = store_->begin_session(info_for(code), two_trials());
        ASSERT_FALSE(stored.ok()) << code;
        EXPECT_EQ(stored.error().message, rule.error().message);

        SessionRequest request;
        request.participant_code = code;
        const Result<SessionStart> planned = plan_session(nullptr, Protocol{}, request);
        ASSERT_FALSE(planned.ok()) << code;
        EXPECT_EQ(planned.error().message, rule.error().message);
    }
    EXPECT_TRUE(check_participant_code(std::string(64, 'a')).ok());
    EXPECT_TRUE(check_participant_code("P07_b-2").ok());
}

TEST_F(StudySharedRulesTest, TheStoreAndTheProtocolRefuseABadVariableNameInTheSameWords) {
    for (const std::string& name :
         std::vector<std::string>{"Age", "1st", "with space", std::string(33, 'a')}) {
        const Result<void> rule = check_variable_name(name);
        ASSERT_FALSE(rule.ok()) << name;
        EXPECT_EQ(rule.error().message.rfind("'" + name + "' is not a variable name", 0), 0u)
            << rule.error().message;

        SessionInfo info = info_for("P01");
        info.variables = {{name, VariableType::Integer, "3"}};
        const Result<std::int64_t> stored = store_->begin_session(info, two_trials());
        ASSERT_FALSE(stored.ok()) << name;
        EXPECT_EQ(stored.error().message,
                  "cannot store the participant's variables: " + rule.error().message);

        const Result<Protocol> parsed = parse_protocol(
            "name = \"rules\"\nscenes = [\"beams\"]\nmono_planes = [3, 8]\n"
            "alternatives = [\"stereo\", \"hybrid\"]\n\n[[variables]]\nname = \"" +
                name + "\"\ntype = \"integer\"\n",
            "rules.toml");
        ASSERT_FALSE(parsed.ok()) << name;
        EXPECT_NE(parsed.error().message.find("key 'variables.name': " + rule.error().message),
                  std::string::npos)
            << parsed.error().message;
    }
    EXPECT_TRUE(check_variable_name("age").ok());
    EXPECT_TRUE(check_variable_name(std::string(32, 'a')).ok());
    EXPECT_TRUE(check_variable_name("ipd_mm2").ok());
}

TEST_F(StudySharedRulesTest, TheStoreAndTheSessionHoldsKeepOneClock) {
    EXPECT_TRUE(is_utc_second(utc_now_iso8601())) << utc_now_iso8601();

    SessionInfo info = info_for("P01");  // no start time given: the store's clock
    const Result<std::int64_t> id = store_->begin_session(info, two_trials());
    ASSERT_TRUE(id.ok()) << id.error().message;
    const Result<SessionInfo> stored = store_->session(*id);
    ASSERT_TRUE(stored.ok()) << stored.error().message;
    EXPECT_TRUE(is_utc_second(stored->started_utc)) << stored->started_utc;

    Result<SessionHold> hold = SessionHold::acquire(store_->path(), *id);
    ASSERT_TRUE(hold.ok()) << hold.error().message;
    const Result<std::optional<SessionHolder>> holder = SessionHold::holder(store_->path(), *id);
    ASSERT_TRUE(holder.ok()) << holder.error().message;
    ASSERT_TRUE(holder->has_value());
    EXPECT_TRUE(is_utc_second((*holder)->since_utc)) << (*holder)->since_utc;
}

TEST(StudyNameTables, EveryNameReadsBackAsItsValue) {
    for (SessionStatus status : {SessionStatus::Running, SessionStatus::Paused,
                                 SessionStatus::Completed, SessionStatus::Aborted})
        EXPECT_EQ(parse_session_status(session_status_name(status)), status);
    EXPECT_EQ(session_status_name(SessionStatus::Completed), "completed");
    EXPECT_FALSE(parse_session_status("Completed"));

    for (VariableType type :
         {VariableType::Integer, VariableType::Number, VariableType::Choice, VariableType::Text})
        EXPECT_EQ(parse_variable_type(variable_type_name(type)), type);
    EXPECT_FALSE(parse_variable_type("int"));

    std::set<std::string_view> inputs;
    for (LiveInput input : {LiveInput::Switch, LiveInput::Confirm, LiveInput::Pause,
                            LiveInput::Resume, LiveInput::Abort})
        EXPECT_TRUE(inputs.insert(live_input_name(input)).second) << live_input_name(input);
    EXPECT_EQ(live_input_name(LiveInput::Switch), "switch");

    std::set<std::string_view> screens;
    for (ScreenKind kind : {ScreenKind::Neutral, ScreenKind::Trial, ScreenKind::Questionnaire,
                            ScreenKind::Finished, ScreenKind::Aborted, ScreenKind::Instructions,
                            ScreenKind::Ready, ScreenKind::Break, ScreenKind::End})
        EXPECT_TRUE(screens.insert(screen_kind_name(kind)).second) << screen_kind_name(kind);
    EXPECT_EQ(screen_kind_name(ScreenKind::Questionnaire), "questionnaire");
    EXPECT_FALSE(screens.contains("invalid"));
}

}  // namespace
}  // namespace monoplane::study
