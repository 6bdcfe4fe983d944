// The live session: a study session driven frame by frame by a display and
// live input, and the simulated observer at its controls. Every test drives a virtual 90 Hz
// display: frame n is presented at n * kPeriod; at each frame the requests due are applied first
// (with the frame's time), then frame_presented(n, t). Expected frames, times and outcomes are
// derived from the rules: a requested change becomes visible with the next frame presented (a
// trial started by frame n shows label 1 at frame n + 1), the neutral screen lasts neutral_ns from
// its first frame (or from the decision), a confirmation is refused until both labels were seen.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "study/live_session.h"
#include "study/observer.h"
#include "study/observer_input.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_log.h"
#include "study/session_screens.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kPeriod = 1'000'000'000 / 90;  // 11'111'111 ns
constexpr std::int64_t kMs = 1'000'000;

std::int64_t at(std::int64_t frame) {
    return frame * kPeriod;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// 2 scenes x 2 distances, in the listed order, after `practice` practice trials.
std::string protocol_text(bool require_both_viewed, int scale_points, int items, int practice = 1) {
    std::string text = R"(name = "live"
scenes = ["beams", "spheres"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
order = "fixed"
first_scene = "fixed"
)";
    text += std::string("require_both_viewed = ") + (require_both_viewed ? "true" : "false") + "\n";
    text += "practice_trials = " + std::to_string(practice) + "\n";
    if (items > 0) {
        text += "\n[questionnaire]\nscale_points = " + std::to_string(scale_points) + "\nitems = [";
        for (int i = 0; i < items; ++i) {
            text +=
                std::string(i > 0 ? ", " : "") + "\"Item " + std::string(1, char('A' + i)) + "\"";
        }
        text += "]\n";
    }
    return text;
}

Protocol make_protocol(bool require_both_viewed = true, int scale_points = 5, int items = 2,
                       int practice = 1) {
    Result<Protocol> p =
        parse_protocol(protocol_text(require_both_viewed, scale_points, items, practice), "test");
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().message);
    return p.ok() ? std::move(p).value() : Protocol{};
}

void expect_event(const TrialEvent& e, EventKind kind, int trial, int label, std::int64_t time_ns,
                  std::int64_t frame) {
    EXPECT_EQ(e.kind, kind) << event_kind_name(e.kind);
    EXPECT_EQ(e.trial_index, trial) << event_kind_name(e.kind);
    EXPECT_EQ(e.label, label) << event_kind_name(e.kind);
    EXPECT_EQ(e.time_ns, time_ns) << event_kind_name(e.kind);
    EXPECT_EQ(e.frame, frame) << event_kind_name(e.kind);
}

class LiveSessionTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "live_session_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        db_ = dir_ / "study.db";
        Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_);
        ASSERT_TRUE(store.ok()) << store.error().message;
        store_ = std::move(store).value();
    }
    void TearDown() override {
        store_.reset();
        fs::remove_all(dir_);
    }

    std::int64_t begin(const Protocol& protocol, std::uint64_t seed = 7,
                       const std::string& code = "P01") {
        // The store requires the next participant's Latin square row.
        Result<int> index = store_->participant_count();
        EXPECT_TRUE(index.ok());
        schedule_ = make_schedule(protocol, seed, index.ok() ? *index : 0);
        SessionInfo info;
        info.participant_code = code;
        info.protocol_name = protocol.name;
        info.protocol_hash = protocol.text_hash;
        info.protocol_text = protocol.text;
        info.seed = seed;
        info.software_version = "0.1.0";
        info.hmd = "vive";
        info.runtime = "simulated";
        info.device = "test";
        Result<std::int64_t> id = store_->begin_session(info, schedule_);
        EXPECT_TRUE(id.ok()) << id.error().message;
        return id.ok() ? *id : -1;
    }

    std::unique_ptr<LiveSession> open(std::int64_t id, const Protocol& protocol,
                                      std::int64_t neutral_ns) {
        LiveOptions options;
        options.neutral_ns = neutral_ns;
        options.on_committed = [this](const std::string& line) { committed_.push_back(line); };
        Result<std::unique_ptr<LiveSession>> s = LiveSession::open(*store_, id, protocol, options);
        EXPECT_TRUE(s.ok()) << s.error().message;
        return s.ok() ? std::move(s).value() : nullptr;
    }

    static void present(LiveSession& s, std::int64_t frame) {
        const Result<void> ok = s.frame_presented(frame, at(frame));
        ASSERT_TRUE(ok.ok()) << ok.error().message;
    }

    static std::string request(LiveSession& s, LiveInput input, std::int64_t frame) {
        Result<std::string> r = s.request(input, at(frame));
        EXPECT_TRUE(r.ok()) << r.error().message;
        return r.ok() ? *r : std::string();
    }

    std::vector<TrialEvent> events(std::int64_t id) {
        Result<std::vector<TrialEvent>> e = store_->events(id);
        EXPECT_TRUE(e.ok()) << e.error().message;
        return e.ok() ? *e : std::vector<TrialEvent>{};
    }

    std::vector<TrialRecord> trials(std::int64_t id) {
        Result<std::vector<TrialRecord>> t = store_->trials(id);
        EXPECT_TRUE(t.ok()) << t.error().message;
        return t.ok() ? *t : std::vector<TrialRecord>{};
    }

    SessionStatus status(std::int64_t id) {
        Result<SessionInfo> info = store_->session(id);
        EXPECT_TRUE(info.ok()) << info.error().message;
        return info.ok() ? info->status : SessionStatus::Running;
    }

    // The session's stored questionnaire answers, by item.
    std::vector<QuestionnaireAnswer> answers(std::int64_t id) {
        Result<std::vector<QuestionnaireAnswer>> stored = store_->answers(id);
        EXPECT_TRUE(stored.ok()) << stored.error().message;
        return stored.ok() ? *stored : std::vector<QuestionnaireAnswer>{};
    }

    // From frame `frame` on, presents frames until a trial's label is visible; returns the next
    // frame to present.
    static std::int64_t until_visible(LiveSession& s, std::int64_t frame) {
        for (int i = 0; i < 10'000 && s.progress().visible_label == 0; ++i) present(s, frame++);
        EXPECT_NE(s.progress().visible_label, 0);
        return frame;
    }

    // Decides the current or next trial by hand: label 1 shows, a switch 3 frames later, a
    // confirmation of label 2 3 frames after that. Returns the next frame to present.
    static std::int64_t decide_trial(LiveSession& s, std::int64_t frame) {
        // Presents past a neutral screen and until the trial's first label shows.
        while (s.screen().kind == ScreenKind::Neutral || s.progress().visible_label == 0 ||
               s.screen().kind != ScreenKind::Trial) {
            present(s, frame++);
            if (frame > 100'000) {
                ADD_FAILURE() << "no trial started";
                return frame;
            }
        }
        frame += 3;
        request(s, LiveInput::Switch, frame);
        present(s, frame++);
        frame += 3;
        EXPECT_TRUE(contains(request(s, LiveInput::Confirm, frame), "decided: label 2"));
        present(s, frame++);
        return frame;
    }

    fs::path dir_;
    fs::path db_;
    std::unique_ptr<StudyStore> store_;
    Schedule schedule_;
    std::vector<std::string> committed_;
};

// 1. The neutral screen lasts neutral_ns from the first frame; the trial starts at the frame whose
// time reaches it and label 1 becomes visible at the frame after.
TEST_F(LiveSessionTest, NeutralScreenLastsFromTheFirstFrameThenLabel1ShowsAtTheNextFrame) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    ASSERT_EQ(schedule_.trials.size(), 5u);  // 1 practice + 2 x 2
    EXPECT_TRUE(schedule_.trials[0].practice);
    auto s = open(id, protocol, 100 * kMs);
    ASSERT_TRUE(s);
    EXPECT_EQ(status(id), SessionStatus::Running);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    EXPECT_EQ(s->progress().trial_number, 0);
    EXPECT_EQ(s->progress().trial_count, 5);

    // The first frame is frame 4 (4P); (n - 4) * 11'111'111 >= 100'000'000 first holds at n = 14
    // (9 frames later is 99'999'999 ns: just short).
    for (std::int64_t n = 4; n <= 13; ++n) {
        present(*s, n);
        EXPECT_EQ(s->screen().kind, ScreenKind::Neutral) << "frame " << n;
        EXPECT_EQ(s->screen().trial, nullptr);
    }
    EXPECT_TRUE(events(id).empty());
    present(*s, 14);
    LiveScreen screen = s->screen();
    ASSERT_EQ(screen.kind, ScreenKind::Trial);
    ASSERT_NE(screen.trial, nullptr);
    EXPECT_EQ(screen.trial->index, 0);
    EXPECT_EQ(screen.label, 1);
    EXPECT_EQ(screen.mode, schedule_.trials[0].label1_mode);
    EXPECT_FALSE(screen.paused);
    LiveProgress p = s->progress();
    EXPECT_EQ(p.trial_number, 1);
    EXPECT_EQ(p.visible_label, 0);  // drawn from this frame on, visible with the next
    EXPECT_EQ(p.trial_started_ns, -1);
    EXPECT_TRUE(events(id).empty());

    present(*s, 15);
    const std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Shown, 0, 1, at(15), 15);
    p = s->progress();
    EXPECT_EQ(p.visible_label, 1);
    EXPECT_EQ(p.trial_started_ns, at(15));
    EXPECT_EQ(p.switches, 0);
    EXPECT_FALSE(p.both_seen);
    EXPECT_NE(std::find(committed_.begin(), committed_.end(),
                        "trial 0 shown label 1 t " + std::to_string(at(15)) + " frame 15"),
              committed_.end());
    present(*s, 16);
    EXPECT_EQ(events(id).size(), 1u);  // nothing changed
}

// 2. A switch is drawn at once and logged with the frame that shows it.
TEST_F(LiveSessionTest, SwitchIsDrawnAtOnceAndLoggedWithTheFrameThatShowsIt) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    present(*s, 0);  // neutral_ns 0: the trial starts with the first frame
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    // Nothing visible yet: a switch would show label 2 first.
    EXPECT_TRUE(contains(request(*s, LiveInput::Switch, 1), "no label is visible"));
    EXPECT_EQ(s->screen().label, 1);
    present(*s, 1);
    ASSERT_EQ(events(id).size(), 1u);

    EXPECT_EQ(request(*s, LiveInput::Switch, 5), "switch");
    EXPECT_EQ(s->screen().label, 2);
    EXPECT_EQ(s->screen().mode, schedule_.trials[0].label2_mode);
    EXPECT_EQ(s->progress().visible_label, 1);
    EXPECT_EQ(s->progress().switches, 0);
    EXPECT_EQ(events(id).size(), 1u);  // not visible yet, not logged
    present(*s, 5);
    std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 2u);
    expect_event(e[1], EventKind::Switched, 0, 2, at(5), 5);
    EXPECT_EQ(s->progress().switches, 1);
    EXPECT_EQ(s->progress().visible_label, 2);
    EXPECT_TRUE(s->progress().both_seen);

    // Two switches before one frame cancel: never seen, neither logged nor counted.
    request(*s, LiveInput::Switch, 8);
    request(*s, LiveInput::Switch, 8);
    EXPECT_EQ(s->screen().label, 2);
    present(*s, 8);
    EXPECT_EQ(events(id).size(), 2u);
    EXPECT_EQ(s->progress().switches, 1);

    request(*s, LiveInput::Switch, 9);
    present(*s, 9);
    e = events(id);
    ASSERT_EQ(e.size(), 3u);
    expect_event(e[2], EventKind::Switched, 0, 1, at(9), 9);
    EXPECT_EQ(s->progress().switches, 2);
    EXPECT_EQ(s->screen().mode, schedule_.trials[0].label1_mode);
}

// 3. Confirmation refused until both were seen; then the decision with every outcome field.
TEST_F(LiveSessionTest, ConfirmIsRefusedUntilBothWereSeenThenDecides) {
    const Protocol protocol = make_protocol();
    ASSERT_TRUE(protocol.require_both_viewed);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 50 * kMs);
    ASSERT_TRUE(s);
    // n * P >= 50 ms first at n = 5 (4.5 frames): the trial starts at 5, label 1 shows at 6.
    for (std::int64_t n = 0; n <= 4; ++n) present(*s, n);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    present(*s, 5);
    EXPECT_EQ(s->screen().kind, ScreenKind::Trial);
    present(*s, 6);
    EXPECT_EQ(s->progress().trial_started_ns, at(6));

    const std::string refused = request(*s, LiveInput::Confirm, 10);
    EXPECT_TRUE(contains(refused, "both labels must be viewed")) << refused;
    std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 2u);
    expect_event(e[1], EventKind::Refused, 0, 1, at(10), -1);
    EXPECT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_FALSE(trials(id)[0].decided);
    present(*s, 10);

    request(*s, LiveInput::Switch, 20);
    present(*s, 20);
    for (std::int64_t n = 21; n < 47; ++n) present(*s, n);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 47), "trial 0 decided: label 2");
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    e = events(id);
    ASSERT_EQ(e.size(), 4u);
    expect_event(e[2], EventKind::Switched, 0, 2, at(20), 20);
    expect_event(e[3], EventKind::Confirmed, 0, 2, at(47), -1);

    std::vector<TrialRecord> t = trials(id);
    ASSERT_EQ(t.size(), 5u);
    ASSERT_TRUE(t[0].decided);
    EXPECT_EQ(t[0].outcome.choice, 2);
    EXPECT_EQ(t[0].outcome.chosen_mode, schedule_.trials[0].label2_mode);
    EXPECT_TRUE(t[0].outcome.valid);
    EXPECT_EQ(t[0].outcome.switches, 1);
    EXPECT_EQ(t[0].outcome.decision_time_ns, at(47) - at(6));
    EXPECT_EQ(t[0].outcome.time_on_label_ns[0], at(20) - at(6));
    EXPECT_EQ(t[0].outcome.time_on_label_ns[1], at(47) - at(20));
    EXPECT_FALSE(t[1].decided);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 47), "confirm ignored on the neutral screen");

    // The next neutral screen runs 50 ms from the decision: (n - 47) * P >= 50 ms at n = 52.
    for (std::int64_t n = 48; n <= 51; ++n) {
        present(*s, n);
        EXPECT_EQ(s->screen().kind, ScreenKind::Neutral) << "frame " << n;
    }
    present(*s, 52);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 1);
    EXPECT_EQ(s->screen().label, 1);
    EXPECT_EQ(s->progress().trial_number, 2);
    EXPECT_EQ(s->progress().switches, 0);
    present(*s, 53);
    expect_event(events(id).back(), EventKind::Shown, 1, 1, at(53), 53);

    // Back and forth, then label 1.
    request(*s, LiveInput::Switch, 60);
    present(*s, 60);
    request(*s, LiveInput::Switch, 70);
    present(*s, 70);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 80), "trial 1 decided: label 1");
    t = trials(id);
    ASSERT_TRUE(t[1].decided);
    EXPECT_EQ(t[1].outcome.choice, 1);
    EXPECT_EQ(t[1].outcome.chosen_mode, schedule_.trials[1].label1_mode);
    EXPECT_EQ(t[1].outcome.chosen_mode,
              protocol.alternatives[schedule_.trials[1].label1_alternative]);
    EXPECT_TRUE(t[1].outcome.valid);
    EXPECT_EQ(t[1].outcome.switches, 2);
    EXPECT_EQ(t[1].outcome.decision_time_ns, at(80) - at(53));
    EXPECT_EQ(t[1].outcome.time_on_label_ns[0], (at(60) - at(53)) + (at(80) - at(70)));
    EXPECT_EQ(t[1].outcome.time_on_label_ns[1], at(70) - at(60));
}

// Without require_both_viewed, label 1 may be confirmed unseen the other: an invalid decision.
TEST_F(LiveSessionTest, WithoutRequireBothViewedAnUnseenOtherLabelGivesAnInvalidDecision) {
    const Protocol protocol = make_protocol(false);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    present(*s, 0);
    present(*s, 1);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 30), "trial 0 decided: label 1");
    const std::vector<TrialRecord> t = trials(id);
    ASSERT_TRUE(t[0].decided);
    EXPECT_EQ(t[0].outcome.choice, 1);
    EXPECT_EQ(t[0].outcome.chosen_mode, schedule_.trials[0].label1_mode);
    EXPECT_FALSE(t[0].outcome.valid);
    EXPECT_EQ(t[0].outcome.switches, 0);
    EXPECT_EQ(t[0].outcome.decision_time_ns, at(29));
    const std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 2u);
    expect_event(e[1], EventKind::Confirmed, 0, 1, at(30), -1);
}

// 4. The neutral screen ignores input (abort aside) and logs nothing.
TEST_F(LiveSessionTest, RequestsOnTheNeutralScreenAreIgnored) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 100 * kMs);
    ASSERT_TRUE(s);
    for (std::int64_t n = 0; n <= 9; ++n) {
        EXPECT_EQ(request(*s, LiveInput::Switch, n), "switch ignored on the neutral screen");
        EXPECT_EQ(request(*s, LiveInput::Confirm, n), "confirm ignored on the neutral screen");
        EXPECT_EQ(request(*s, LiveInput::Pause, n), "pause ignored on the neutral screen");
        EXPECT_EQ(request(*s, LiveInput::Resume, n), "resume ignored on the neutral screen");
        EXPECT_FALSE(s->answer(0, 3).ok());  // no questionnaire yet
        present(*s, n);
        EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    }
    EXPECT_TRUE(events(id).empty());
    EXPECT_FALSE(trials(id)[0].decided);
    EXPECT_EQ(status(id), SessionStatus::Running);
    // 10 * P = 111 ms >= 100 ms: the trial starts on schedule, unaffected by the ignored input.
    present(*s, 10);
    EXPECT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().label, 1);
}

// 5. Pause and resume: nothing changes while paused and the pause is left out of all times; abort
// ends the session.
TEST_F(LiveSessionTest, PauseResumeAndAbort) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    present(*s, 0);
    present(*s, 1);  // label 1 visible at 1P

    EXPECT_EQ(request(*s, LiveInput::Pause, 5), "pause");
    EXPECT_TRUE(s->screen().paused);
    EXPECT_EQ(s->screen().kind, ScreenKind::Trial);
    std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 2u);
    expect_event(e[1], EventKind::Paused, 0, 0, at(5), -1);
    present(*s, 5);
    // While paused the participant's input does not apply, and a confirmation refused for that
    // reason is no Refused event.
    EXPECT_TRUE(contains(request(*s, LiveInput::Switch, 6), "not being viewed"));
    EXPECT_TRUE(contains(request(*s, LiveInput::Confirm, 6), "not being viewed"));
    EXPECT_TRUE(contains(request(*s, LiveInput::Pause, 6), "not being viewed"));
    EXPECT_EQ(s->screen().label, 1);
    for (std::int64_t n = 6; n < 20; ++n) present(*s, n);
    EXPECT_EQ(events(id).size(), 2u);

    EXPECT_EQ(request(*s, LiveInput::Resume, 20), "resume");
    EXPECT_FALSE(s->screen().paused);
    expect_event(events(id).back(), EventKind::Resumed, 0, 0, at(20), -1);
    present(*s, 20);
    EXPECT_TRUE(contains(request(*s, LiveInput::Resume, 21), "not paused"));
    present(*s, 21);
    request(*s, LiveInput::Switch, 25);
    present(*s, 25);
    expect_event(events(id).back(), EventKind::Switched, 0, 2, at(25), 25);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 30), "trial 0 decided: label 2");
    std::vector<TrialRecord> t = trials(id);
    ASSERT_TRUE(t[0].decided);
    // First visible 1P, confirmed 30P, paused 5P..20P.
    EXPECT_EQ(t[0].outcome.decision_time_ns, (at(30) - at(1)) - (at(20) - at(5)));
    EXPECT_EQ(t[0].outcome.time_on_label_ns[0], (at(5) - at(1)) + (at(25) - at(20)));
    EXPECT_EQ(t[0].outcome.time_on_label_ns[1], at(30) - at(25));
    EXPECT_EQ(t[0].outcome.switches, 1);

    // Trial 1, aborted while viewed.
    present(*s, 31);
    present(*s, 32);
    expect_event(events(id).back(), EventKind::Shown, 1, 1, at(32), 32);
    EXPECT_FALSE(s->finished());
    EXPECT_EQ(request(*s, LiveInput::Abort, 40), "session aborted");
    EXPECT_TRUE(s->finished());
    EXPECT_EQ(s->screen().kind, ScreenKind::Aborted);
    EXPECT_EQ(status(id), SessionStatus::Aborted);
    expect_event(events(id).back(), EventKind::Aborted, 1, 0, at(40), -1);
    t = trials(id);
    EXPECT_TRUE(t[0].decided);
    EXPECT_FALSE(t[1].decided);
    const std::size_t logged = events(id).size();
    EXPECT_EQ(request(*s, LiveInput::Switch, 41), "switch ignored on the aborted screen");
    EXPECT_EQ(request(*s, LiveInput::Abort, 41), "abort ignored on the aborted screen");
    present(*s, 41);
    present(*s, 42);
    EXPECT_EQ(events(id).size(), logged);
    EXPECT_EQ(status(id), SessionStatus::Aborted);
}

TEST_F(LiveSessionTest, AbortWhilePausedLogsTheTrialsAbort) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    present(*s, 0);
    present(*s, 1);
    request(*s, LiveInput::Pause, 3);
    present(*s, 3);
    EXPECT_EQ(request(*s, LiveInput::Abort, 9), "session aborted");
    expect_event(events(id).back(), EventKind::Aborted, 0, 0, at(9), -1);
    EXPECT_EQ(status(id), SessionStatus::Aborted);
    EXPECT_TRUE(s->finished());
}

TEST_F(LiveSessionTest, AbortOnTheNeutralScreenEndsTheSessionWithoutATrialEvent) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 100 * kMs);
    ASSERT_TRUE(s);
    present(*s, 0);
    EXPECT_EQ(request(*s, LiveInput::Abort, 1), "session aborted");
    EXPECT_TRUE(s->finished());
    EXPECT_EQ(s->screen().kind, ScreenKind::Aborted);
    EXPECT_EQ(status(id), SessionStatus::Aborted);
    EXPECT_TRUE(events(id).empty());
    for (std::int64_t n = 1; n < 30; ++n) present(*s, n);  // no trial starts after an abort
    EXPECT_EQ(s->screen().kind, ScreenKind::Aborted);
    EXPECT_TRUE(events(id).empty());
}

// 6. The questionnaire on the scale: switch cycles the selection, confirm accepts it.
TEST_F(LiveSessionTest, QuestionnaireAfterTheLastTrial) {
    const Protocol protocol = make_protocol(true, 5, 2);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    std::int64_t n = 0;
    for (int trial = 0; trial < 5; ++trial) {
        n = decide_trial(*s, n);
        EXPECT_TRUE(trials(id)[trial].decided);
        // With neutral_ns 0 the frame after the decision already starts the next trial.
        EXPECT_EQ(s->progress().trial_number, std::min(trial + 2, 5));
    }
    for (const TrialRecord& t : trials(id)) EXPECT_TRUE(t.decided) << t.trial.index;
    EXPECT_FALSE(s->finished());
    // The decision's frame was presented with neutral_ns 0 already past: the questionnaire.
    LiveScreen screen = s->screen();
    ASSERT_EQ(screen.kind, ScreenKind::Questionnaire);
    EXPECT_EQ(screen.trial, nullptr);
    EXPECT_EQ(screen.question, 0);
    EXPECT_EQ(screen.selection, 3);  // (5 + 1) / 2
    EXPECT_EQ(status(id), SessionStatus::Running);

    const int expected[] = {4, 5, 1, 2, 3, 4};
    for (int value : expected) {
        EXPECT_EQ(request(*s, LiveInput::Switch, n),
                  "questionnaire selection " + std::to_string(value));
        EXPECT_EQ(s->screen().selection, value);
        present(*s, n++);
    }
    EXPECT_EQ(request(*s, LiveInput::Pause, n), "pause ignored during the questionnaire");
    EXPECT_EQ(request(*s, LiveInput::Confirm, n), "answered item 1");
    present(*s, n++);
    {
        const auto stored = answers(id);
        ASSERT_EQ(stored.size(), 1u);
        EXPECT_EQ(stored[0].item, 0);
        EXPECT_EQ(stored[0].answer, 4);
        EXPECT_EQ(stored[0].text, "Item A");
    }
    screen = s->screen();
    EXPECT_EQ(screen.kind, ScreenKind::Questionnaire);
    EXPECT_EQ(screen.question, 1);
    EXPECT_EQ(screen.selection, 3);  // back to the middle for the next item

    // The experimenter's window: out-of-range items and values are errors and change nothing.
    EXPECT_FALSE(s->answer(1, 0).ok());
    EXPECT_FALSE(s->answer(1, 6).ok());
    EXPECT_FALSE(s->answer(2, 3).ok());
    EXPECT_FALSE(s->answer(-1, 3).ok());
    EXPECT_EQ(s->screen().question, 1);
    EXPECT_EQ(answers(id).size(), 1u);
    const Result<void> ok = s->answer(1, 5);
    ASSERT_TRUE(ok.ok()) << ok.error().message;
    EXPECT_TRUE(s->finished());
    EXPECT_EQ(s->screen().kind, ScreenKind::Finished);
    EXPECT_EQ(status(id), SessionStatus::Completed);
    {
        const auto stored = answers(id);
        ASSERT_EQ(stored.size(), 2u);
        EXPECT_EQ(stored[1].item, 1);
        EXPECT_EQ(stored[1].answer, 5);
        EXPECT_EQ(stored[1].text, "Item B");
    }
    EXPECT_EQ(request(*s, LiveInput::Confirm, n), "confirm ignored on the finished screen");
    EXPECT_FALSE(s->answer(0, 1).ok());
    present(*s, n++);
    EXPECT_EQ(status(id), SessionStatus::Completed);
}

// The experimenter may answer out of order; the screen asks the first unanswered item. An even
// scale starts at (4 + 1) / 2 = 2.
TEST_F(LiveSessionTest, QuestionnaireAnsweredOutOfOrderFromTheWindow) {
    const Protocol protocol = make_protocol(true, 4, 3, 0);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    std::int64_t n = 0;
    for (int trial = 0; trial < 4; ++trial) n = decide_trial(*s, n);
    ASSERT_EQ(s->screen().kind, ScreenKind::Questionnaire);
    EXPECT_EQ(s->screen().selection, 2);
    EXPECT_EQ(request(*s, LiveInput::Switch, n), "questionnaire selection 3");
    ASSERT_TRUE(s->answer(1, 4).ok());
    EXPECT_EQ(s->screen().question, 0);
    EXPECT_EQ(s->screen().selection, 2);
    EXPECT_EQ(request(*s, LiveInput::Switch, n), "questionnaire selection 3");
    EXPECT_EQ(request(*s, LiveInput::Switch, n), "questionnaire selection 4");
    EXPECT_EQ(request(*s, LiveInput::Switch, n), "questionnaire selection 1");
    EXPECT_EQ(request(*s, LiveInput::Confirm, n), "answered item 1");
    EXPECT_EQ(s->screen().question, 2);  // item 1 (0-based) was answered already
    EXPECT_FALSE(s->finished());
    EXPECT_EQ(request(*s, LiveInput::Confirm, n), "answered item 3");
    EXPECT_TRUE(s->finished());
    EXPECT_EQ(status(id), SessionStatus::Completed);
    const auto stored = answers(id);
    ASSERT_EQ(stored.size(), 3u);
    EXPECT_EQ(stored[0].answer, 1);
    EXPECT_EQ(stored[1].answer, 4);
    EXPECT_EQ(stored[2].answer, 2);
}

TEST_F(LiveSessionTest, WithoutQuestionnaireTheLastDecisionCompletesTheSession) {
    const Protocol protocol = make_protocol(true, 7, 0);
    ASSERT_TRUE(protocol.questionnaire.items.empty());
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    std::int64_t n = 0;
    for (int trial = 0; trial < 5; ++trial) n = decide_trial(*s, n);
    EXPECT_TRUE(s->finished());
    EXPECT_EQ(s->screen().kind, ScreenKind::Finished);
    EXPECT_EQ(status(id), SessionStatus::Completed);
}

// 7. A resumed session continues at its first undecided trial; decided trials stay as they were.
// The trial the crash cut short starts over with label 1, and its outcome counts both runs: the
// switch before the crash, and the time each label was visible up to the last event of it.
TEST_F(LiveSessionTest, ResumedSessionStartsAtTheFirstUndecidedTrial) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    std::vector<TrialRecord> before;
    {
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        std::int64_t n = 0;
        n = decide_trial(*s, n);
        n = decide_trial(*s, n);
        // Trial 2 starts and is seen; the process dies before a decision.
        n = until_visible(*s, n);
        ASSERT_EQ(s->screen().trial->index, 2);
        request(*s, LiveInput::Switch, n);
        present(*s, n++);
        before = trials(id);
    }
    ASSERT_TRUE(store_->set_status(id, SessionStatus::Paused).ok());
    const std::size_t logged = events(id).size();

    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    EXPECT_EQ(status(id), SessionStatus::Running);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    EXPECT_EQ(s->progress().trial_number, 2);  // the last trial decided
    std::int64_t n = 1000;
    present(*s, n++);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 2);
    EXPECT_EQ(s->screen().label, 1);  // the trial starts over with label 1
    EXPECT_EQ(s->progress().trial_number, 3);
    EXPECT_EQ(s->progress().switches, 1);  // the earlier run's
    present(*s, n);
    std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), logged + 1);
    expect_event(e.back(), EventKind::Shown, 2, 1, at(n), n);
    ++n;
    for (int trial = 2; trial < 5; ++trial) n = decide_trial(*s, n);
    const std::vector<TrialRecord> after = trials(id);
    ASSERT_EQ(after.size(), 5u);
    for (const TrialRecord& t : after) EXPECT_TRUE(t.decided) << t.trial.index;
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(after[i].outcome.choice, before[i].outcome.choice);
        EXPECT_EQ(after[i].outcome.decision_time_ns, before[i].outcome.decision_time_ns);
        EXPECT_EQ(after[i].outcome.switches, before[i].outcome.switches);
    }
    // Trial 2's events: shown and switched before the crash, shown, switched and confirmed after.
    std::vector<TrialEvent> trial2;
    for (const TrialEvent& event : events(id))
        if (event.trial_index == 2) trial2.push_back(event);
    ASSERT_EQ(trial2.size(), 5u);
    EXPECT_EQ(trial2[2].kind, EventKind::Shown);
    const TrialOutcome& o = after[2].outcome;
    EXPECT_EQ(o.runs, 2);
    EXPECT_EQ(o.switches, 2);
    EXPECT_EQ(o.time_on_label_ns[0],
              (trial2[1].time_ns - trial2[0].time_ns) + (trial2[3].time_ns - trial2[2].time_ns));
    EXPECT_EQ(o.time_on_label_ns[1], trial2[4].time_ns - trial2[3].time_ns);
    EXPECT_EQ(o.decision_time_ns, o.time_on_label_ns[0] + o.time_on_label_ns[1]);
    for (int i = 0; i < 2; ++i) EXPECT_EQ(after[i].outcome.runs, 1);
    ASSERT_EQ(s->screen().kind, ScreenKind::Questionnaire);
}

TEST_F(LiveSessionTest, ResumedSessionWithAllTrialsDecidedGoesToTheQuestionnaire) {
    const Protocol protocol = make_protocol();
    const std::int64_t id = begin(protocol);
    {
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        std::int64_t n = 0;
        for (int trial = 0; trial < 5; ++trial) n = decide_trial(*s, n);
        ASSERT_EQ(s->screen().kind, ScreenKind::Questionnaire);
    }
    auto s = open(id, protocol, 20 * kMs);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->progress().trial_number, 5);
    present(*s, 0);
    present(*s, 1);  // 11 ms < 20 ms
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    present(*s, 2);
    EXPECT_EQ(s->screen().kind, ScreenKind::Questionnaire);
    EXPECT_EQ(s->screen().question, 0);
    EXPECT_EQ(s->screen().selection, 3);
}

// --- The protocol's screens: instructions, ready, breaks, end ----------------------------------

// 2 scenes x 3 distances in the listed order, no practice: data trials 0-2 in block 0 (beams),
// 3-5 in block 1 (spheres).
Protocol six_trial_protocol() {
    const std::string text = R"(name = "screens"
scenes = ["beams", "spheres"]
mono_planes = [3, 8, 16]
alternatives = ["stereo", "hybrid"]
order = "fixed"
first_scene = "fixed"
practice_trials = 0
)";
    Result<Protocol> p = parse_protocol(text, "screens.toml");
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().message);
    return p.ok() ? std::move(p).value() : Protocol{};
}

BreakSettings break_settings(int every_trials, bool between_blocks, double min_s) {
    BreakSettings b;
    b.every_trials = every_trials;
    b.between_blocks = between_blocks;
    b.min_s = min_s;
    b.text = "Take a short break.";
    return b;
}

void expect_screen_event(const TrialEvent& e, EventKind kind, int page, std::int64_t time_ns,
                         std::int64_t frame) {
    EXPECT_EQ(e.kind, kind) << event_kind_name(e.kind);
    EXPECT_EQ(e.trial_index, -1) << event_kind_name(e.kind);
    EXPECT_EQ(e.label, 0) << event_kind_name(e.kind);
    EXPECT_EQ(e.page, page) << event_kind_name(e.kind);
    EXPECT_EQ(e.time_ns, time_ns) << event_kind_name(e.kind);
    EXPECT_EQ(e.frame, frame) << event_kind_name(e.kind);
}

// Sessions in memory (MemorySessionLog, as `simulate` runs them): the events are exactly what
// the session logged, with nothing read back.
class ScreenSessionTest : public LiveSessionTest {
  protected:
    std::unique_ptr<LiveSession> begin_in_memory(const Protocol& protocol, std::int64_t neutral_ns,
                                                 int first_trial = 0,
                                                 const std::vector<TrialRecord>& history = {},
                                                 const std::vector<TrialEvent>& events = {}) {
        schedule_ = make_schedule(protocol, 7, 0);
        LiveOptions options;
        options.neutral_ns = neutral_ns;
        options.on_committed = [this](const std::string& line) { committed_.push_back(line); };
        Result<std::unique_ptr<LiveSession>> s =
            LiveSession::begin(log_, 1, protocol, options, schedule_, first_trial, history, events);
        EXPECT_TRUE(s.ok()) << s.error().message;
        return s.ok() ? std::move(s).value() : nullptr;
    }

    // A participant who confirms each screen at the frame after it shows and decides each trial
    // in three frames (label 1 shows, switch, confirm label 2), until the session ends.
    static std::int64_t play(LiveSession& s, std::int64_t frame) {
        for (const std::int64_t last = frame + 100'000; !s.finished() && frame < last; ++frame) {
            const LiveScreen screen = s.screen();
            const LiveProgress p = s.progress();
            if (screen.kind == ScreenKind::Trial && p.visible_label == 1 && p.switches == 0) {
                request(s, LiveInput::Switch, frame);
            } else if (screen.kind == ScreenKind::Trial && p.visible_label == 2) {
                request(s, LiveInput::Confirm, frame);
            } else if (screen.kind != ScreenKind::Trial && screen.kind != ScreenKind::Neutral) {
                request(s, LiveInput::Confirm, frame);
            }
            present(s, frame);
        }
        EXPECT_TRUE(s.finished());
        return frame;
    }

    // The trials a break came before, from the log: each break_started's next trial event.
    std::vector<int> breaks_before() const {
        std::vector<int> before;
        bool in_break = false;
        for (const TrialEvent& e : log_.events()) {
            if (e.kind == EventKind::BreakStarted) in_break = true;
            if (in_break && !is_screen_event(e.kind)) {
                before.push_back(e.trial_index);
                in_break = false;
            }
        }
        return before;
    }

    static TrialRecord decided(const ScheduledTrial& trial) {
        TrialRecord r;
        r.trial = trial;
        r.decided = true;
        r.outcome.choice = 1;
        r.outcome.chosen_mode = trial.label1_mode;
        return r;
    }

    MemorySessionLog log_;
};

// Three pages, back once, then the practice trial, the ready screen and the first data trial:
// each page's appearance is logged with the frame that showed it, each confirmation with its
// time.
TEST_F(ScreenSessionTest, InstructionsWithBackThenPracticeThenReady) {
    Protocol protocol = make_protocol(true, 5, 0, 1);
    protocol.day.instructions = {{"Page one"}, {"Page two"}, {"Page three"}};
    protocol.day.ready = ScreenPage{"Practice is over. Press CONFIRM to begin."};
    auto s = begin_in_memory(protocol, 100 * kMs);
    ASSERT_TRUE(s);
    LiveScreen screen = s->screen();
    ASSERT_EQ(screen.kind, ScreenKind::Instructions);
    EXPECT_EQ(screen.page, 0);
    EXPECT_EQ(screen.page_count, 3);
    ASSERT_NE(screen.text, nullptr);
    EXPECT_EQ(*screen.text, "Page one");
    EXPECT_EQ(screen.trial, nullptr);
    EXPECT_FALSE(s->finished());
    // Not yet on screen: a confirmation would answer a page nobody saw.
    EXPECT_EQ(request(*s, LiveInput::Confirm, 0),
              "confirm ignored on the instructions screen: not visible yet");
    EXPECT_EQ(request(*s, LiveInput::Pause, 0), "pause ignored on the instructions screen");
    present(*s, 0);
    for (std::int64_t n = 1; n <= 4; ++n) present(*s, n);
    EXPECT_EQ(request(*s, LiveInput::Switch, 5), "switch ignored on the instructions screen");
    EXPECT_EQ(request(*s, LiveInput::Confirm, 5), "instructions page 2");
    EXPECT_EQ(*s->screen().text, "Page two");
    EXPECT_EQ(s->screen().page, 1);
    present(*s, 5);
    EXPECT_EQ(request(*s, LiveInput::Switch, 8), "instructions page 1");  // back
    EXPECT_EQ(*s->screen().text, "Page one");
    present(*s, 8);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 10), "instructions page 2");
    present(*s, 10);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 12), "instructions page 3");
    present(*s, 12);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 14), "instructions read");
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    EXPECT_EQ(s->screen().text, nullptr);
    // The neutral screen runs 100 ms from the last confirmation: (n - 14) * P >= 100 ms at 24.
    for (std::int64_t n = 14; n <= 23; ++n) {
        present(*s, n);
        EXPECT_EQ(s->screen().kind, ScreenKind::Neutral) << n;
    }
    present(*s, 24);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_TRUE(s->screen().trial->practice);
    present(*s, 25);
    request(*s, LiveInput::Switch, 28);
    present(*s, 28);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 31), "trial 0 decided: label 2");
    screen = s->screen();
    ASSERT_EQ(screen.kind, ScreenKind::Ready);  // after practice, before the first data trial
    EXPECT_EQ(*screen.text, "Practice is over. Press CONFIRM to begin.");
    present(*s, 31);
    EXPECT_EQ(request(*s, LiveInput::Switch, 33), "switch ignored on the ready screen");
    EXPECT_EQ(request(*s, LiveInput::Confirm, 35), "ready confirmed");
    for (std::int64_t n = 35; n <= 44; ++n) present(*s, n);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    present(*s, 45);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 1);
    present(*s, 46);

    const std::vector<TrialEvent>& e = log_.events();
    ASSERT_EQ(e.size(), 15u);
    expect_screen_event(e[0], EventKind::InstructionsShown, 0, at(0), 0);
    expect_screen_event(e[1], EventKind::InstructionsConfirmed, 0, at(5), -1);
    expect_screen_event(e[2], EventKind::InstructionsShown, 1, at(5), 5);
    expect_screen_event(e[3], EventKind::InstructionsShown, 0, at(8), 8);
    expect_screen_event(e[4], EventKind::InstructionsConfirmed, 0, at(10), -1);
    expect_screen_event(e[5], EventKind::InstructionsShown, 1, at(10), 10);
    expect_screen_event(e[6], EventKind::InstructionsConfirmed, 1, at(12), -1);
    expect_screen_event(e[7], EventKind::InstructionsShown, 2, at(12), 12);
    expect_screen_event(e[8], EventKind::InstructionsConfirmed, 2, at(14), -1);
    expect_event(e[9], EventKind::Shown, 0, 1, at(25), 25);
    expect_event(e[10], EventKind::Switched, 0, 2, at(28), 28);
    expect_event(e[11], EventKind::Confirmed, 0, 2, at(31), -1);
    expect_screen_event(e[12], EventKind::ReadyShown, -1, at(31), 31);
    expect_screen_event(e[13], EventKind::ReadyConfirmed, -1, at(35), -1);
    expect_event(e[14], EventKind::Shown, 1, 1, at(46), 46);
    EXPECT_EQ(e[9].page, -1);
    // Every screen event went through the log's committed lines.
    EXPECT_EQ(committed_.front(), "screen instructions_shown page 0 t 0 frame 0");
    EXPECT_NE(std::find(committed_.begin(), committed_.end(),
                        "screen ready_confirmed page -1 t " + std::to_string(at(35)) + " frame -1"),
              committed_.end());
    EXPECT_EQ(log_.outcomes().size(), 1u);
}

// Without practice the ready screen follows the instructions directly.
TEST_F(ScreenSessionTest, WithoutPracticeTheReadyScreenFollowsTheInstructions) {
    Protocol protocol = make_protocol(true, 5, 0, 0);
    protocol.day.instructions = {{"Only page"}};
    protocol.day.ready = ScreenPage{"Ready?"};
    auto s = begin_in_memory(protocol, 0);
    ASSERT_TRUE(s);
    present(*s, 0);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 3), "instructions read");
    EXPECT_EQ(s->screen().kind, ScreenKind::Ready);
    present(*s, 3);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 6), "ready confirmed");
    present(*s, 6);  // neutral_ns 0: the first data trial starts
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_FALSE(s->screen().trial->practice);
    present(*s, 7);
    const std::vector<TrialEvent>& e = log_.events();
    ASSERT_EQ(e.size(), 5u);
    expect_screen_event(e[0], EventKind::InstructionsShown, 0, at(0), 0);
    expect_screen_event(e[1], EventKind::InstructionsConfirmed, 0, at(3), -1);
    expect_screen_event(e[2], EventKind::ReadyShown, -1, at(3), 3);
    expect_screen_event(e[3], EventKind::ReadyConfirmed, -1, at(6), -1);
    expect_event(e[4], EventKind::Shown, 0, 1, at(7), 7);
}

// Breaks by count (every 2 data trials: before trials 2 and 4), by block (before trial 3, the
// first of block 1), both (once per gap); each shows with the frame of the decision before it.
TEST_F(ScreenSessionTest, BreaksByCountAndByBlockFallBetweenTheRightTrials) {
    struct Case {
        int every_trials;
        bool between_blocks;
        std::vector<int> before;
    };
    const Case cases[] = {
        {2, false, {2, 4}}, {0, true, {3}}, {2, true, {2, 3, 4}}, {3, true, {3}}, {6, false, {}}};
    for (const Case& c : cases) {
        SCOPED_TRACE("every " + std::to_string(c.every_trials) + " blocks " +
                     std::to_string(c.between_blocks));
        log_ = MemorySessionLog{};
        Protocol protocol = six_trial_protocol();
        protocol.day.breaks = break_settings(c.every_trials, c.between_blocks, 0);
        auto s = begin_in_memory(protocol, 0);
        ASSERT_TRUE(s);
        play(*s, 0);
        EXPECT_EQ(log_.status(), SessionStatus::Completed);
        EXPECT_EQ(log_.outcomes().size(), 6u);
        EXPECT_EQ(breaks_before(), c.before);
        EXPECT_EQ(planned_breaks(protocol.day, schedule_), c.before);
        const std::vector<TrialEvent>& e = log_.events();
        for (std::size_t i = 0; i < e.size(); ++i) {
            if (e[i].kind != EventKind::BreakStarted) continue;
            // Decided at frame n (confirmed at n's time); the break shows with frame n, is
            // confirmed at n + 1 and the next trial's label 1 shows at n + 2.
            ASSERT_GE(i, 1u);
            ASSERT_LT(i + 2, e.size());
            const std::int64_t n = e[i].frame;
            EXPECT_EQ(e[i - 1].kind, EventKind::Confirmed);
            EXPECT_EQ(e[i - 1].time_ns, at(n));
            expect_screen_event(e[i], EventKind::BreakStarted, -1, at(n), n);
            expect_screen_event(e[i + 1], EventKind::BreakEnded, -1, at(n + 1), -1);
            expect_event(e[i + 2], EventKind::Shown, e[i + 2].trial_index, 1, at(n + 2), n + 2);
        }
    }
}

// The countdown runs on the presented frames' time from the frame that shows the break;
// confirm is refused (and not logged) until it reads 0.
TEST_F(ScreenSessionTest, BreakCountdownRefusesConfirmUntilItsMinimum) {
    Protocol protocol = six_trial_protocol();
    protocol.day.breaks = break_settings(2, false, 2.0);
    auto s = begin_in_memory(protocol, 0);
    ASSERT_TRUE(s);
    std::int64_t n = decide_trial(*s, 0);
    n = decide_trial(*s, n);  // the second decision's frame shows the break
    const std::int64_t f = n - 1;
    LiveScreen screen = s->screen();
    ASSERT_EQ(screen.kind, ScreenKind::Break);
    ASSERT_NE(screen.text, nullptr);
    EXPECT_EQ(*screen.text, "Take a short break.");
    EXPECT_EQ(screen.break_remaining_ns, 2'000'000'000);
    expect_screen_event(log_.events().back(), EventKind::BreakStarted, -1, at(f), f);
    const std::size_t logged = log_.events().size();

    present(*s, f + 90);  // 90 periods: 999'999'990 ns
    EXPECT_EQ(s->screen().break_remaining_ns, 1'000'000'010);
    EXPECT_EQ(request(*s, LiveInput::Confirm, f + 90),
              "confirm ignored: the break lasts another 1.1 s");
    EXPECT_EQ(request(*s, LiveInput::Switch, f + 90), "switch ignored on the break screen");
    EXPECT_EQ(request(*s, LiveInput::Pause, f + 90), "pause ignored on the break screen");
    present(*s, f + 180);
    EXPECT_EQ(s->screen().break_remaining_ns, 20);
    EXPECT_EQ(request(*s, LiveInput::Confirm, f + 180),
              "confirm ignored: the break lasts another 0.1 s");
    EXPECT_EQ(log_.events().size(), logged);  // refusals are not events
    present(*s, f + 181);
    EXPECT_EQ(s->screen().break_remaining_ns, 0);
    EXPECT_EQ(s->screen().kind, ScreenKind::Break);
    EXPECT_EQ(request(*s, LiveInput::Confirm, f + 181), "break ended");
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    present(*s, f + 181);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 2);
    present(*s, f + 182);
    const std::vector<TrialEvent>& e = log_.events();
    ASSERT_EQ(e.size(), logged + 2);
    expect_screen_event(e[logged], EventKind::BreakEnded, -1, at(f + 181), -1);
    expect_event(e[logged + 1], EventKind::Shown, 2, 1, at(f + 182), f + 182);
}

// After the questionnaire the end screen: end_shown with its frame, then the session is
// completed, and the screen stays up.
TEST_F(ScreenSessionTest, EndScreenAfterTheQuestionnaireCompletesTheSession) {
    Protocol protocol = make_protocol(true, 5, 1, 0);
    protocol.day.end = ScreenPage{"Thank you. Please wait for the experimenter."};
    auto s = begin_in_memory(protocol, 0);
    ASSERT_TRUE(s);
    std::int64_t n = 0;
    for (int trial = 0; trial < 4; ++trial) n = decide_trial(*s, n);
    ASSERT_EQ(s->screen().kind, ScreenKind::Questionnaire);
    EXPECT_EQ(request(*s, LiveInput::Confirm, n), "answered item 1");
    ASSERT_EQ(s->screen().kind, ScreenKind::End);
    EXPECT_FALSE(s->finished());  // completed when it shows
    EXPECT_EQ(log_.status(), SessionStatus::Running);
    present(*s, n);
    EXPECT_TRUE(s->finished());
    EXPECT_EQ(log_.status(), SessionStatus::Completed);
    const LiveScreen screen = s->screen();
    EXPECT_EQ(screen.kind, ScreenKind::End);
    ASSERT_NE(screen.text, nullptr);
    EXPECT_EQ(*screen.text, "Thank you. Please wait for the experimenter.");
    expect_screen_event(log_.events().back(), EventKind::EndShown, -1, at(n), n);
    EXPECT_EQ(committed_.back(), "session completed");
    const std::size_t logged = log_.events().size();
    EXPECT_EQ(request(*s, LiveInput::Confirm, n + 1), "confirm ignored on the end screen");
    EXPECT_EQ(request(*s, LiveInput::Abort, n + 1), "abort ignored on the end screen");
    present(*s, n + 1);
    EXPECT_EQ(log_.events().size(), logged);
    EXPECT_EQ(log_.status(), SessionStatus::Completed);
    EXPECT_EQ(s->screen().kind, ScreenKind::End);
}

TEST_F(ScreenSessionTest, EndScreenWithoutQuestionnaireFollowsTheLastTrial) {
    Protocol protocol = make_protocol(true, 5, 0, 0);
    protocol.day.end = ScreenPage{"Thank you."};
    auto s = begin_in_memory(protocol, 0);
    ASSERT_TRUE(s);
    std::int64_t n = 0;
    for (int trial = 0; trial < 4; ++trial) n = decide_trial(*s, n);
    // The last decision's frame ended the neutral screen (neutral_ns 0): the end screen is
    // drawn from the next frame on.
    ASSERT_EQ(s->screen().kind, ScreenKind::End);
    EXPECT_FALSE(s->finished());
    present(*s, n);
    EXPECT_TRUE(s->finished());
    expect_screen_event(log_.events().back(), EventKind::EndShown, -1, at(n), n);
    EXPECT_EQ(log_.status(), SessionStatus::Completed);
}

TEST_F(ScreenSessionTest, AbortWorksOnEveryScreen) {
    Protocol protocol = six_trial_protocol();
    protocol.day.instructions = {{"One"}, {"Two"}};
    protocol.day.breaks = break_settings(1, false, 30);
    {
        auto s = begin_in_memory(protocol, 0);
        ASSERT_TRUE(s);
        present(*s, 0);
        EXPECT_EQ(request(*s, LiveInput::Abort, 1), "session aborted");
        EXPECT_TRUE(s->finished());
        EXPECT_EQ(s->screen().kind, ScreenKind::Aborted);
        EXPECT_EQ(log_.status(), SessionStatus::Aborted);
        ASSERT_EQ(log_.events().size(), 1u);  // the first page's appearance only
    }
    log_ = MemorySessionLog{};
    auto s = begin_in_memory(protocol, 0);
    ASSERT_TRUE(s);
    present(*s, 0);
    request(*s, LiveInput::Confirm, 1);
    present(*s, 1);
    request(*s, LiveInput::Confirm, 2);
    present(*s, 2);
    std::int64_t n = decide_trial(*s, 3);
    ASSERT_EQ(s->screen().kind, ScreenKind::Break);
    EXPECT_EQ(request(*s, LiveInput::Abort, n), "session aborted");
    EXPECT_EQ(log_.status(), SessionStatus::Aborted);
    EXPECT_EQ(log_.events().back().kind, EventKind::BreakStarted);  // no trial to abort
    present(*s, n);
    EXPECT_EQ(s->screen().kind, ScreenKind::Aborted);
}

// A resumed session interrupted on page 2 of 3 starts on page 2; the pages read before are not
// shown again.
TEST_F(ScreenSessionTest, ResumeMidInstructionsStartsAtTheFirstUnconfirmedPage) {
    Protocol protocol = make_protocol(true, 5, 0, 1);
    protocol.day.instructions = {{"One"}, {"Two"}, {"Three"}};
    const std::vector<TrialEvent> before = {
        {EventKind::InstructionsShown, -1, 0, 1'000 * kMs, 90, 0},
        {EventKind::InstructionsConfirmed, -1, 0, 4'000 * kMs, -1, 0},
        {EventKind::InstructionsShown, -1, 0, 4'000 * kMs, 360, 1},
    };
    auto s = begin_in_memory(protocol, 0, 0, {}, before);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->screen().kind, ScreenKind::Instructions);
    EXPECT_EQ(s->screen().page, 1);
    EXPECT_EQ(*s->screen().text, "Two");
    present(*s, 0);
    EXPECT_EQ(request(*s, LiveInput::Switch, 2), "instructions page 1");  // back still works
    present(*s, 2);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 4), "instructions page 2");
    present(*s, 4);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 6), "instructions page 3");
    present(*s, 6);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 8), "instructions read");
    const std::vector<TrialEvent>& e = log_.events();
    ASSERT_EQ(e.size(), 7u);
    expect_screen_event(e[0], EventKind::InstructionsShown, 1, at(0), 0);
    expect_screen_event(e[1], EventKind::InstructionsShown, 0, at(2), 2);
    expect_screen_event(e[2], EventKind::InstructionsConfirmed, 0, at(4), -1);
    expect_screen_event(e[3], EventKind::InstructionsShown, 1, at(4), 4);
    expect_screen_event(e[4], EventKind::InstructionsConfirmed, 1, at(6), -1);
    expect_screen_event(e[5], EventKind::InstructionsShown, 2, at(6), 6);
    expect_screen_event(e[6], EventKind::InstructionsConfirmed, 2, at(8), -1);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
}

// Read instructions and a confirmed ready screen are not shown again.
TEST_F(ScreenSessionTest, ResumeAfterInstructionsAndReadyShowsNeither) {
    Protocol protocol = make_protocol(true, 5, 0, 1);
    protocol.day.instructions = {{"One"}};
    protocol.day.ready = ScreenPage{"Ready?"};
    std::vector<TrialEvent> before = {
        {EventKind::InstructionsShown, -1, 0, 1'000 * kMs, 90, 0},
        {EventKind::InstructionsConfirmed, -1, 0, 4'000 * kMs, -1, 0},
    };
    {
        auto s = begin_in_memory(protocol, 0, 0, {}, before);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
        present(*s, 0);
        ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
        EXPECT_EQ(s->screen().trial->index, 0);  // the practice trial
    }
    // The practice trial decided, the ready screen shown but not confirmed: shown again.
    before.push_back({EventKind::Shown, 0, 1, 5'000 * kMs, 450, -1});
    before.push_back({EventKind::Confirmed, 0, 1, 6'000 * kMs, -1, -1});
    before.push_back({EventKind::ReadyShown, -1, 0, 6'000 * kMs, 540, -1});
    const std::vector<TrialRecord> history = {decided(make_schedule(protocol, 7, 0).trials[0])};
    log_ = MemorySessionLog{};
    {
        auto s = begin_in_memory(protocol, 0, 1, history, before);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->screen().kind, ScreenKind::Ready);
        present(*s, 0);
        expect_screen_event(log_.events().back(), EventKind::ReadyShown, -1, at(0), 0);
    }
    before.push_back({EventKind::ReadyConfirmed, -1, 0, 7'000 * kMs, -1, -1});
    log_ = MemorySessionLog{};
    auto s = begin_in_memory(protocol, 0, 1, history, before);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    present(*s, 0);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 1);
}

// Interrupted 12 s into a 30 s break (as far as the log tells: the latest time logged after
// break_started): the break is shown again for 18 s, its start logged again with the frame that
// shows it (each run's break_started has its end or its interruption), and the next trial
// follows.
TEST_F(ScreenSessionTest, ResumeMidBreakShowsTheRestOfItsMinimum) {
    Protocol protocol = six_trial_protocol();
    protocol.day.breaks = break_settings(2, false, 30);
    const Schedule schedule = make_schedule(protocol, 7, 0);
    const std::vector<TrialRecord> history = {decided(schedule.trials[0]),
                                              decided(schedule.trials[1])};
    const std::int64_t started = 50'000 * kMs + kPeriod;
    std::vector<TrialEvent> before = {
        {EventKind::Shown, 0, 1, 10'000 * kMs, 900, -1},
        {EventKind::Confirmed, 0, 1, 20'000 * kMs, -1, -1},
        {EventKind::Shown, 1, 1, 40'000 * kMs, 3600, -1},
        {EventKind::Confirmed, 1, 1, 50'000 * kMs, -1, -1},
        {EventKind::BreakStarted, -1, 0, started, 4501, -1},
        {EventKind::Paused, -1, 0, started + 12'000 * kMs, -1, -1},
    };
    auto s = begin_in_memory(protocol, 0, 2, history, before);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->screen().kind, ScreenKind::Break);
    EXPECT_EQ(s->screen().break_remaining_ns, 18'000 * kMs);
    EXPECT_EQ(s->progress().trial_number, 2);
    present(*s, 0);  // the countdown restarts with the frame that shows it again
    ASSERT_EQ(log_.events().size(), 1u);
    expect_screen_event(log_.events()[0], EventKind::BreakStarted, -1, at(0), 0);
    present(*s, 1620);  // 1620 periods: 17'999'999'820 ns
    EXPECT_EQ(s->screen().break_remaining_ns, 180);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 1620),
              "confirm ignored: the break lasts another 0.1 s");
    present(*s, 1621);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 1621), "break ended");
    present(*s, 1621);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 2);
    present(*s, 1622);
    ASSERT_EQ(log_.events().size(), 3u);
    expect_screen_event(log_.events()[1], EventKind::BreakEnded, -1, at(1621), -1);
    expect_event(log_.events()[2], EventKind::Shown, 2, 1, at(1622), 1622);

    // Nothing logged after its start (a kill during the break): all of its minimum again.
    before.pop_back();
    log_ = MemorySessionLog{};
    s = begin_in_memory(protocol, 0, 2, history, before);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->screen().kind, ScreenKind::Break);
    EXPECT_EQ(s->screen().break_remaining_ns, 30'000 * kMs);

    // Decided, then killed before the break showed: the break comes, counted once.
    before.pop_back();
    log_ = MemorySessionLog{};
    s = begin_in_memory(protocol, 0, 2, history, before);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->screen().kind, ScreenKind::Break);
    EXPECT_EQ(s->screen().break_remaining_ns, 30'000 * kMs);
    present(*s, 0);
    ASSERT_EQ(log_.events().size(), 1u);
    expect_screen_event(log_.events()[0], EventKind::BreakStarted, -1, at(0), 0);
}

// An ended break is not repeated, nor one whose next trial had started.
TEST_F(ScreenSessionTest, ResumeAfterABreakDoesNotRepeatIt) {
    Protocol protocol = six_trial_protocol();
    protocol.day.breaks = break_settings(2, false, 30);
    const Schedule schedule = make_schedule(protocol, 7, 0);
    const std::vector<TrialRecord> history = {decided(schedule.trials[0]),
                                              decided(schedule.trials[1])};
    std::vector<TrialEvent> before = {
        {EventKind::Shown, 0, 1, 10'000 * kMs, 900, -1},
        {EventKind::Confirmed, 0, 1, 20'000 * kMs, -1, -1},
        {EventKind::Shown, 1, 1, 40'000 * kMs, 3600, -1},
        {EventKind::Confirmed, 1, 1, 50'000 * kMs, -1, -1},
        {EventKind::BreakStarted, -1, 0, 50'000 * kMs, 4500, -1},
        {EventKind::BreakEnded, -1, 0, 85'000 * kMs, -1, -1},
    };
    auto s = begin_in_memory(protocol, 0, 2, history, before);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    present(*s, 0);
    ASSERT_EQ(s->screen().kind, ScreenKind::Trial);
    EXPECT_EQ(s->screen().trial->index, 2);

    before.push_back({EventKind::Shown, 2, 1, 86'000 * kMs, 7740, -1});
    log_ = MemorySessionLog{};
    s = begin_in_memory(protocol, 0, 2, history, before);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
    // And the next break still comes after trial 3, two data trials later.
    play(*s, 0);
    EXPECT_EQ(breaks_before(), (std::vector<int>{4}));
}

// The experimenter's note: the session's latest time and the trial on screen or last shown.
TEST_F(ScreenSessionTest, NotesCarryTheSessionTimeAndTheTrial) {
    Protocol protocol = make_protocol(true, 5, 0, 1);
    protocol.day.instructions = {{"One"}};
    auto s = begin_in_memory(protocol, 0);
    ASSERT_TRUE(s);
    ASSERT_TRUE(s->note("before anything").ok());
    present(*s, 3);
    ASSERT_TRUE(s->note("reading the instructions").ok());
    request(*s, LiveInput::Confirm, 5);
    present(*s, 5);  // the practice trial starts; label 1 shows at 6
    present(*s, 6);
    present(*s, 7);
    ASSERT_TRUE(s->note("participant adjusted the headset", NoteSource::Window).ok());
    request(*s, LiveInput::Switch, 8);
    present(*s, 8);
    request(*s, LiveInput::Confirm, 9);  // decided; the neutral screen
    ASSERT_TRUE(s->note("after the decision", NoteSource::Command).ok());
    const Result<void> blank = s->note(" \t\n");
    ASSERT_FALSE(blank.ok());
    EXPECT_NE(blank.error().message.find("empty"), std::string::npos);

    const std::vector<SessionNote>& notes = log_.notes();
    ASSERT_EQ(notes.size(), 4u);
    EXPECT_EQ(notes[0].text, "before anything");
    EXPECT_EQ(notes[0].source, NoteSource::Window);
    EXPECT_FALSE(notes[0].runtime_time_ns.has_value());
    EXPECT_FALSE(notes[0].trial_index.has_value());
    EXPECT_EQ(notes[1].runtime_time_ns, at(3));
    EXPECT_FALSE(notes[1].trial_index.has_value());  // none before the first trial
    EXPECT_EQ(notes[2].text, "participant adjusted the headset");
    EXPECT_EQ(notes[2].runtime_time_ns, at(7));
    EXPECT_EQ(notes[2].trial_index, 0);
    EXPECT_TRUE(notes[2].noted_utc.empty());  // the log stamps it
    EXPECT_EQ(notes[3].source, NoteSource::Command);
    EXPECT_EQ(notes[3].runtime_time_ns, at(9));
    EXPECT_EQ(notes[3].trial_index, 0);  // the last one shown
    EXPECT_EQ(committed_.back(), "note command trial 0 t " + std::to_string(at(9)));
    EXPECT_NE(std::find(committed_.begin(), committed_.end(), "note window t -1"),
              committed_.end());
}

// A resumed session's notes name its last trial before a new one shows.
TEST_F(ScreenSessionTest, ANoteAfterAResumeNamesTheLastTrialShown) {
    const Protocol protocol = make_protocol(true, 5, 0, 1);
    const Schedule schedule = make_schedule(protocol, 7, 0);
    const std::vector<TrialEvent> before = {
        {EventKind::Shown, 0, 1, 10'000 * kMs, 900, -1},
        {EventKind::Confirmed, 0, 1, 20'000 * kMs, -1, -1},
        {EventKind::Shown, 1, 1, 40'000 * kMs, 3600, -1},
    };
    auto s = begin_in_memory(protocol, 100 * kMs, 1, {decided(schedule.trials[0])}, before);
    ASSERT_TRUE(s);
    present(*s, 0);
    ASSERT_TRUE(s->note("resumed").ok());
    ASSERT_EQ(log_.notes().size(), 1u);
    EXPECT_EQ(log_.notes()[0].trial_index, 1);
    EXPECT_EQ(log_.notes()[0].runtime_time_ns, at(0));
}

// The database path: a session killed on page 2 of its instructions resumes there through
// LiveSession::open, from the events the store holds.
TEST_F(LiveSessionTest, ResumeFromTheStoreContinuesTheInstructions) {
    Protocol protocol = make_protocol(true, 5, 0, 1);
    protocol.day.instructions = {{"One"}, {"Two"}};
    const std::int64_t id = begin(protocol);
    {
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        present(*s, 0);
        EXPECT_EQ(request(*s, LiveInput::Confirm, 2), "instructions page 2");
        present(*s, 2);
        ASSERT_TRUE(s->note("the participant asked a question").ok());
    }
    {
        const std::vector<TrialEvent> e = events(id);
        ASSERT_EQ(e.size(), 3u);
        expect_screen_event(e[0], EventKind::InstructionsShown, 0, at(0), 0);
        expect_screen_event(e[1], EventKind::InstructionsConfirmed, 0, at(2), -1);
        expect_screen_event(e[2], EventKind::InstructionsShown, 1, at(2), 2);
    }
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->screen().kind, ScreenKind::Instructions);
    EXPECT_EQ(s->screen().page, 1);
    present(*s, 100);
    EXPECT_EQ(request(*s, LiveInput::Confirm, 102), "instructions read");
    const std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 5u);
    expect_screen_event(e[3], EventKind::InstructionsShown, 1, at(100), 100);
    expect_screen_event(e[4], EventKind::InstructionsConfirmed, 1, at(102), -1);
    // Read: a second resume shows no instruction page.
    s.reset();
    s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->screen().kind, ScreenKind::Neutral);
}

// --- Runs: an interrupted session resumed on a clock that starts again -------------------------

// One run of a stored session, as a front end drives it: frame k = 1, 2, ... of the run at its
// clock's base + k periods (a runtime that started again has a base of its own), numbered
// run().first_frame + k, its times placed on the session's axis.
struct RunDriver {
    LiveSession& s;
    std::int64_t clock_base_ns;

    std::int64_t frame(std::int64_t k) const { return s.run().first_frame + k; }
    std::int64_t time(std::int64_t k) const { return s.session_time(clock_base_ns + at(k)); }
    void present(std::int64_t k) const {
        const Result<void> ok = s.frame_presented(frame(k), time(k));
        ASSERT_TRUE(ok.ok()) << ok.error().message;
    }
    std::string request(LiveInput input, std::int64_t k) const {
        Result<std::string> r = s.request(input, time(k));
        EXPECT_TRUE(r.ok()) << r.error().message;
        return r.ok() ? *r : std::string();
    }
    // Presents frames from k on until `done`; returns the next k.
    template <class Done>
    std::int64_t until(std::int64_t k, Done done) const {
        for (int i = 0; i < 100'000 && !done(); ++i) present(k++);
        EXPECT_TRUE(done());
        return k;
    }
};

// Every run's times on one axis: event times never go back in the order logged, a run starts
// after every event before it (and the frame log's last time: the tests check that), and no two
// events name one frame.
void expect_one_time_axis(const std::vector<TrialEvent>& events) {
    std::int64_t latest = std::numeric_limits<std::int64_t>::min();
    std::int64_t last_frame = -1;
    for (std::size_t i = 0; i < events.size(); ++i) {
        const TrialEvent& e = events[i];
        EXPECT_GE(e.time_ns, latest) << i << " " << event_kind_name(e.kind);
        if (e.kind == EventKind::RunStarted && i > 0) {
            EXPECT_GT(e.time_ns, latest) << i;
        }
        latest = std::max(latest, e.time_ns);
        if (e.frame < 0) continue;
        EXPECT_GT(e.frame, last_frame) << i << " " << event_kind_name(e.kind);
        last_frame = e.frame;
    }
}

// What the trial's events say, counted here on their own: per run (split at run_started), each
// label's time from the event that showed it to the next change, pause or the run's last event
// of the trial; the switches.
TrialRuns count_from_events(const std::vector<TrialEvent>& events, int trial) {
    TrialRuns r;
    int visible = 0;
    std::int64_t since = 0, first = 0, paused = 0, last = 0;
    bool is_paused = false;
    const auto end_run = [&] {
        if (visible == 0) return;
        if (!is_paused) r.time_on_label_ns[visible - 1] += last - since;
        r.viewing_ns += last - first - paused;
        ++r.runs;
        visible = 0;
    };
    for (const TrialEvent& e : events) {
        if (e.kind == EventKind::RunStarted) end_run();
        if (e.trial_index != trial) continue;
        if (!is_paused) last = e.time_ns;
        if (e.kind == EventKind::Shown) {
            end_run();
            visible = e.label;
            since = first = last = e.time_ns;
            paused = 0;
            is_paused = false;
        } else if (e.kind == EventKind::Switched || e.kind == EventKind::Confirmed) {
            r.time_on_label_ns[visible - 1] += e.time_ns - since;
            since = e.time_ns;
            visible = e.kind == EventKind::Switched ? e.label : visible;
            r.switches += e.kind == EventKind::Switched;
        } else if (e.kind == EventKind::Paused) {
            r.time_on_label_ns[visible - 1] += e.time_ns - since;
            is_paused = true;
            since = e.time_ns;
        } else if (e.kind == EventKind::Resumed) {
            paused += e.time_ns - since;
            since = last = e.time_ns;
            is_paused = false;
        }
    }
    end_run();
    return r;
}

// Issue 42: a trial interrupted after six switches and a pause, resumed in a new process whose
// runtime clock starts again near 0 (21 s, after 1000 s): the resumed run continues the session's
// time axis and frame numbers, and the outcome counts the six switches and the viewing time
// before the interruption with the two after it.
TEST_F(LiveSessionTest, ATrialCutShortKeepsItsSwitchesAndTimesAcrossARestartedClock) {
    const Protocol protocol = make_protocol(true, 5, 0, 1);
    const std::int64_t id = begin(protocol);
    std::int64_t last_frame_of_run1 = 0;
    {
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        ASSERT_TRUE(
            s->begin_run({.runtime = "simulated", .clock_start_ns = 1000 * 1000 * kMs}).ok());
        const RunDriver run{*s, 1000 * 1000 * kMs};
        std::int64_t k = run.until(1, [&] { return s->progress().visible_label != 0; });
        for (int i = 0; i < 6; ++i) {
            k += 20;
            run.request(LiveInput::Switch, k);
            last_frame_of_run1 = run.frame(k);  // the last event's: later frames go unrecorded
            run.present(k++);
            if (i == 2) {
                EXPECT_EQ(run.request(LiveInput::Pause, k), "pause");
                k += 45;
                EXPECT_EQ(run.request(LiveInput::Resume, k), "resume");
            }
        }
        run.present(k + 30);
        EXPECT_EQ(s->progress().switches, 6);
    }  // killed: trial 0 undecided
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->progress().switches, 0);  // no trial on screen yet
    ASSERT_TRUE(s->begin_run({.runtime = "simulated", .clock_start_ns = 21 * 1000 * kMs}).ok());
    EXPECT_EQ(s->run().run, 2);
    EXPECT_EQ(s->run().first_frame, last_frame_of_run1 + 1);
    const RunDriver run{*s, 21 * 1000 * kMs};
    std::int64_t k = run.until(1, [&] { return s->progress().visible_label != 0; });
    EXPECT_EQ(s->progress().switches, 6);  // the trial's, from its earlier run
    for (int i = 0; i < 2; ++i) {
        k += 10;
        run.request(LiveInput::Switch, k);
        run.present(k++);
    }
    EXPECT_TRUE(contains(run.request(LiveInput::Confirm, k + 10), "decided: label 1"));

    const std::vector<TrialEvent> e = events(id);
    expect_one_time_axis(e);
    const TrialRuns counted = count_from_events(e, 0);
    const TrialRecord trial = trials(id)[0];
    ASSERT_TRUE(trial.decided);
    EXPECT_EQ(counted.runs, 2);
    EXPECT_EQ(counted.switches, 8);
    EXPECT_EQ(trial.outcome.runs, 2);
    EXPECT_EQ(trial.outcome.switches, 8);
    EXPECT_EQ(trial.outcome.time_on_label_ns[0], counted.time_on_label_ns[0]);
    EXPECT_EQ(trial.outcome.time_on_label_ns[1], counted.time_on_label_ns[1]);
    EXPECT_EQ(trial.outcome.decision_time_ns, counted.viewing_ns);
    EXPECT_EQ(trial.outcome.decision_time_ns,
              trial.outcome.time_on_label_ns[0] + trial.outcome.time_on_label_ns[1]);
    // Run 1's record of the trial: label 1 at frame 2 to the sixth switch at frame 173, less
    // the 45 frames' pause; run 2's: label 1 at frame 2 to the confirmation at 35.
    EXPECT_EQ(trial.outcome.decision_time_ns, at(173 - 2 - 45) + at(35 - 2));
    // Run 2's clock starts 1 ns after run 1's last event, the sixth switch.
    const std::vector<RunRecord> runs = store_->runs(id).value_or_throw();
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[1].clock_offset_ns, s->run().clock_offset_ns);
    EXPECT_EQ(runs[1].clock_offset_ns, 1000 * 1000 * kMs + at(173) + 1 - 21 * 1000 * kMs);
}

// A break interrupted 12 s into its 30 s (the frame log, as a headset writes it, shows 12 s) is
// shown again in the resumed run, its start logged again, for the 18 s left; every break_ended
// follows a break_started; the whole break lasts its minimum on the session's axis.
TEST_F(LiveSessionTest, ABreakCutShortStartsAgainForWhatIsLeftOnOneAxis) {
    Protocol protocol = make_protocol(true, 5, 0, 0);
    protocol.day.breaks = break_settings(1, false, 30);
    const std::int64_t id = begin(protocol);
    std::int64_t break_started_ns = 0;
    {
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        ASSERT_TRUE(s->begin_run({.clock_start_ns = 500 * 1000 * kMs}).ok());
        const RunDriver run{*s, 500 * 1000 * kMs};
        std::int64_t k = run.until(1, [&] { return s->progress().visible_label != 0; });
        run.request(LiveInput::Switch, k);
        run.present(k++);
        run.request(LiveInput::Confirm, k);
        run.present(k);  // the break shows
        ASSERT_EQ(s->screen().kind, ScreenKind::Break);
        break_started_ns = events(id).back().time_ns;
        for (int i = 1; i <= 12 * 90; ++i) {  // the frame log goes on during the break
            FrameRecord f;
            f.frame = run.frame(k + i);
            f.shown = "break";
            f.display_time_ns = run.time(k + i);
            run.present(k + i);
            store_->queue_frame(id, f);
        }
        ASSERT_TRUE(store_->flush_frames().ok());
    }
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->screen().kind, ScreenKind::Break);
    ASSERT_TRUE(s->begin_run({.clock_start_ns = 0}).ok());
    const RunDriver run{*s, 0};
    run.present(1);
    EXPECT_EQ(s->screen().break_remaining_ns, 30'000 * kMs - at(12 * 90));
    std::int64_t k = 2;
    while (s->screen().break_remaining_ns > 0 && k < 10'000) run.present(k++);
    EXPECT_EQ(run.request(LiveInput::Confirm, k - 1), "break ended");

    const std::vector<TrialEvent> e = events(id);
    expect_one_time_axis(e);
    std::vector<const TrialEvent*> breaks;
    for (const TrialEvent& event : e)
        if (event.kind == EventKind::BreakStarted || event.kind == EventKind::BreakEnded)
            breaks.push_back(&event);
    ASSERT_EQ(breaks.size(), 3u);
    EXPECT_EQ(breaks[0]->kind, EventKind::BreakStarted);
    EXPECT_EQ(breaks[1]->kind, EventKind::BreakStarted);
    EXPECT_EQ(breaks[2]->kind, EventKind::BreakEnded);
    EXPECT_EQ(breaks[0]->time_ns, break_started_ns);
    // 12 s logged, the gap to the resumed run's first frame (1 ns and one period), 18 s more.
    const std::int64_t whole = breaks[2]->time_ns - breaks[0]->time_ns;
    EXPECT_GE(whole, 30'000 * kMs);
    EXPECT_LE(whole, 30'000 * kMs + 2 * kPeriod + 1);
    EXPECT_GE(breaks[2]->time_ns - breaks[1]->time_ns, 18'000 * kMs);
}

// Killed on the second instruction page: the resumed run shows that page again from its own
// first frame, numbered after the killed run's, on the continued axis.
TEST_F(LiveSessionTest, AnInstructionPageCutShortIsShownAgainOnOneAxis) {
    Protocol protocol = make_protocol(true, 5, 0, 1);
    protocol.day.instructions = {{"One"}, {"Two"}};
    const std::int64_t id = begin(protocol);
    {
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        ASSERT_TRUE(s->begin_run({.clock_start_ns = 80 * 1000 * kMs}).ok());
        const RunDriver run{*s, 80 * 1000 * kMs};
        run.present(1);
        EXPECT_EQ(run.request(LiveInput::Confirm, 40), "instructions page 2");
        run.present(40);
        run.present(41);
    }
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    ASSERT_TRUE(s->begin_run({.clock_start_ns = 0}).ok());
    const RunDriver run{*s, 0};
    run.present(1);
    EXPECT_EQ(run.request(LiveInput::Confirm, 30), "instructions read");
    const std::vector<TrialEvent> e = events(id);
    expect_one_time_axis(e);
    ASSERT_EQ(e.size(), 7u);
    EXPECT_EQ(e[0].kind, EventKind::RunStarted);
    expect_screen_event(e[3], EventKind::InstructionsShown, 1, 80 * 1000 * kMs + at(40), 40);
    EXPECT_EQ(e[4].kind, EventKind::RunStarted);
    expect_screen_event(e[5], EventKind::InstructionsShown, 1, run.time(1), run.frame(1));
    EXPECT_EQ(run.frame(1), 41 + 1);  // numbered on after frame 40, the last one named
    EXPECT_EQ(run.time(1), e[3].time_ns + 1 + kPeriod);
    expect_screen_event(e[6], EventKind::InstructionsConfirmed, 1, run.time(30), -1);
}

// --- The simulated observer at the controls ----------------------------------------------------

// Plays `input` against `session` frame by frame from `frame` until the session ends.
struct Drive {
    std::int64_t frames = 0;
    int requests = 0;
};

Drive drive(LiveSession& session, ObserverInput& input, std::int64_t frame = 0) {
    Drive d;
    constexpr std::int64_t kLimit = 2'000'000;  // over 6 hours at 90 Hz
    for (; !session.finished() && d.frames < kLimit; ++frame, ++d.frames) {
        const std::int64_t t = at(frame);
        for (LiveInput in : input.poll(session.screen(), session.progress(), t)) {
            Result<std::string> r = session.request(in, t);
            EXPECT_TRUE(r.ok()) << r.error().message;
            ++d.requests;
        }
        Result<void> ok = session.frame_presented(frame, t);
        EXPECT_TRUE(ok.ok()) << ok.error().message;
    }
    EXPECT_TRUE(session.finished()) << "the session did not end in " << kLimit << " frames";
    return d;
}

constexpr double kErrorPx = 2.0;

class ObserverInputTest : public LiveSessionTest {
  protected:
    // A whole session of the small protocol with a named observer; checks every trial against
    // the plan a second observer of the same name and seed makes for it.
    void run_observed(const std::string& name, std::uint64_t seed) {
        SCOPED_TRACE(name + " seed " + std::to_string(seed));
        const Protocol protocol = make_protocol(true, 7, 2);
        const std::int64_t id = begin(protocol, seed, "P" + name + std::to_string(seed));
        auto s = open(id, protocol, 1'000 * kMs);
        ASSERT_TRUE(s);
        Result<std::unique_ptr<Observer>> observer = make_observer(name, seed);
        Result<std::unique_ptr<Observer>> twin = make_observer(name, seed);
        ASSERT_TRUE(observer.ok() && twin.ok());
        ObserverInput input(**observer, protocol, [](const ScheduledTrial&) { return kErrorPx; });
        drive(*s, input);

        EXPECT_EQ(status(id), SessionStatus::Completed);
        EXPECT_EQ(s->screen().kind, ScreenKind::Finished);
        const std::vector<TrialRecord> records = trials(id);
        ASSERT_EQ(records.size(), 5u);
        std::map<int, std::vector<TrialEvent>> by_trial;
        for (const TrialEvent& e : events(id)) by_trial[e.trial_index].push_back(e);

        for (const TrialRecord& r : records) {
            SCOPED_TRACE("trial " + std::to_string(r.trial.index));
            ASSERT_TRUE(r.decided);
            const int reference_label = r.trial.label1_alternative == 0 ? 1 : 2;
            const TrialPlan plan =
                (*twin)->plan_trial(schedule_.trials[r.trial.index], reference_label, kErrorPx);
            ASSERT_FALSE(plan.dwell_ns.empty());
            const std::vector<TrialEvent>& e = by_trial[r.trial.index];
            ASSERT_GE(e.size(), 2u);

            // Every Switched event is a frame's and counted in the outcome.
            int switched = 0;
            for (const TrialEvent& ev : e) {
                if (ev.kind == EventKind::Shown || ev.kind == EventKind::Switched) {
                    EXPECT_GE(ev.frame, 0);
                    EXPECT_EQ(ev.time_ns, at(ev.frame));
                }
                if (ev.kind == EventKind::Switched) ++switched;
            }
            EXPECT_EQ(switched, r.outcome.switches);
            EXPECT_EQ(r.outcome.chosen_mode,
                      r.outcome.choice == 1 ? r.trial.label1_mode : r.trial.label2_mode);
            EXPECT_TRUE(r.outcome.valid);
            expect_event(e.front(), EventKind::Shown, r.trial.index, 1, e.front().time_ns,
                         e.front().frame);
            EXPECT_EQ(e.back().kind, EventKind::Confirmed);
            EXPECT_EQ(r.outcome.decision_time_ns, e.back().time_ns - e.front().time_ns);
            EXPECT_EQ(r.outcome.time_on_label_ns[0] + r.outcome.time_on_label_ns[1],
                      r.outcome.decision_time_ns);

            // The dwell before each change is the planned one, late by at most two frames (the
            // observer notices a label one frame after it shows and acts at a frame).
            const auto dwell_ok = [](std::int64_t from, std::int64_t to, std::int64_t dwell) {
                EXPECT_GE(to - from, dwell);
                EXPECT_LE(to - from, dwell + 2 * kPeriod);
            };
            if (plan.dwell_ns.size() == 1) {
                // Refused, then the other label for as long, then confirmed.
                ASSERT_EQ(e.size(), 4u);
                EXPECT_EQ(e[1].kind, EventKind::Refused);
                EXPECT_EQ(e[1].label, 1);
                dwell_ok(e[0].time_ns, e[1].time_ns, plan.dwell_ns[0]);
                expect_event(e[2], EventKind::Switched, r.trial.index, 2, e[1].time_ns + kPeriod,
                             e[2].frame);
                dwell_ok(e[2].time_ns, e[3].time_ns, plan.dwell_ns[0]);
                EXPECT_EQ(r.outcome.choice, 2);
                EXPECT_EQ(r.outcome.switches, 1);
                ++single_dwell_trials_;
            } else {
                ASSERT_EQ(e.size(), plan.dwell_ns.size() + 1);
                for (std::size_t i = 0; i < plan.dwell_ns.size(); ++i) {
                    if (i > 0) {
                        EXPECT_EQ(e[i].kind, EventKind::Switched);
                        EXPECT_EQ(e[i].label, i % 2 == 0 ? 1 : 2);
                    }
                    dwell_ok(e[i].time_ns, e[i + 1].time_ns, plan.dwell_ns[i]);
                }
                EXPECT_EQ(r.outcome.choice, plan.confirmed_label());
                EXPECT_EQ(e.back().label, plan.confirmed_label());
                EXPECT_EQ(r.outcome.switches, static_cast<int>(plan.dwell_ns.size()) - 1);
            }
            if (name == "reference") {
                EXPECT_EQ(r.outcome.choice, reference_label);
                EXPECT_EQ(r.outcome.chosen_mode, protocol.alternatives[0]);
            }
        }

        const auto stored = answers(id);
        ASSERT_EQ(stored.size(), 2u);
        for (int item = 0; item < 2; ++item) {
            const auto& answer_row = stored[static_cast<std::size_t>(item)];
            EXPECT_EQ(answer_row.item, item);
            const int answer = answer_row.answer;
            EXPECT_EQ(answer, (*twin)->answer(item, 7)) << "item " << item;
            EXPECT_GE(answer, 1);
            EXPECT_LE(answer, 7);
        }
        ++sessions_;
    }
    int sessions_ = 0;
    int single_dwell_trials_ = 0;  // trials whose plan had one dwell (refused, then switched)
};

// 8. Whole sessions driven only by the observer.
TEST_F(ObserverInputTest, ReferenceObserverAlwaysChoosesTheFirstAlternative) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) run_observed("reference", seed);
    EXPECT_EQ(sessions_, 4);
}

TEST_F(ObserverInputTest, ChanceObserverCompletesSessions) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) run_observed("chance", seed);
    EXPECT_EQ(sessions_, 4);
}

TEST_F(ObserverInputTest, DefaultObserverCompletesSessions) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) run_observed("default", seed);
    EXPECT_EQ(sessions_, 12);
    // The model confirms label 1 unseen the other in 3.4 % of trials; among these 12 seeds' 60
    // trials it does so once (deterministic), so the refusal path is exercised.
    EXPECT_GE(single_dwell_trials_, 1);
}

// An observer that looks at label 1 only, then confirms, and answers the ends of the scale.
class SingleDwellObserver final : public Observer {
  public:
    std::string_view name() const override { return "single-dwell"; }
    TrialPlan plan_trial(const ScheduledTrial&, int, double) override {
        ++plans;
        return TrialPlan{{400 * kMs}};
    }
    int answer(int item, int scale_points) override { return item == 0 ? 1 : scale_points; }
    int plans = 0;
};

// 9. Its confirmation is refused under require_both_viewed; it then looks at the other label and
// confirms that one.
TEST_F(ObserverInputTest, RefusedConfirmationMakesTheObserverViewTheOtherLabel) {
    const Protocol protocol = make_protocol(true, 5, 2);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 500 * kMs);
    ASSERT_TRUE(s);
    SingleDwellObserver observer;
    ObserverInput input(observer, protocol, nullptr);
    drive(*s, input);
    EXPECT_EQ(status(id), SessionStatus::Completed);
    EXPECT_EQ(observer.plans, 5);  // one plan per trial

    std::map<int, std::vector<TrialEvent>> by_trial;
    for (const TrialEvent& e : events(id)) by_trial[e.trial_index].push_back(e);
    const std::vector<TrialRecord> records = trials(id);
    ASSERT_EQ(records.size(), 5u);
    for (const TrialRecord& r : records) {
        SCOPED_TRACE("trial " + std::to_string(r.trial.index));
        const std::vector<TrialEvent>& e = by_trial[r.trial.index];
        ASSERT_EQ(e.size(), 4u);
        EXPECT_EQ(e[0].kind, EventKind::Shown);
        EXPECT_EQ(e[0].label, 1);
        EXPECT_EQ(e[1].kind, EventKind::Refused);
        EXPECT_EQ(e[1].label, 1);
        EXPECT_EQ(e[1].frame, -1);
        EXPECT_GE(e[1].time_ns - e[0].time_ns, 400 * kMs);
        EXPECT_LE(e[1].time_ns - e[0].time_ns, 400 * kMs + 2 * kPeriod);
        // The switch is sent at the next frame and shows with it.
        EXPECT_EQ(e[2].kind, EventKind::Switched);
        EXPECT_EQ(e[2].label, 2);
        EXPECT_EQ(e[2].time_ns, e[1].time_ns + kPeriod);
        EXPECT_EQ(e[2].time_ns, at(e[2].frame));
        EXPECT_EQ(e[3].kind, EventKind::Confirmed);
        EXPECT_EQ(e[3].label, 2);
        EXPECT_GE(e[3].time_ns - e[2].time_ns, 400 * kMs);
        EXPECT_LE(e[3].time_ns - e[2].time_ns, 400 * kMs + 2 * kPeriod);
        ASSERT_TRUE(r.decided);
        EXPECT_EQ(r.outcome.choice, 2);
        EXPECT_EQ(r.outcome.chosen_mode, r.trial.label2_mode);
        EXPECT_EQ(r.outcome.switches, 1);
        EXPECT_TRUE(r.outcome.valid);
        EXPECT_EQ(r.outcome.decision_time_ns, e[3].time_ns - e[0].time_ns);
    }
    // From the middle (3): item 0 wants 1 (3 -> 4 -> 5 -> 1), item 1 wants 5.
    const auto stored = answers(id);
    ASSERT_EQ(stored.size(), 2u);
    EXPECT_EQ(stored[0].answer, 1);
    EXPECT_EQ(stored[1].answer, 5);
}

// Without require_both_viewed the same observer confirms label 1 after its one dwell.
TEST_F(ObserverInputTest, SingleDwellWithoutRequireBothViewedConfirmsLabel1) {
    const Protocol protocol = make_protocol(false, 5, 2);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 500 * kMs);
    ASSERT_TRUE(s);
    SingleDwellObserver observer;
    ObserverInput input(observer, protocol, nullptr);
    drive(*s, input);
    EXPECT_EQ(status(id), SessionStatus::Completed);
    std::map<int, std::vector<TrialEvent>> by_trial;
    for (const TrialEvent& e : events(id)) by_trial[e.trial_index].push_back(e);
    for (const TrialRecord& r : trials(id)) {
        SCOPED_TRACE("trial " + std::to_string(r.trial.index));
        const std::vector<TrialEvent>& e = by_trial[r.trial.index];
        ASSERT_EQ(e.size(), 2u);
        EXPECT_EQ(e[0].kind, EventKind::Shown);
        EXPECT_EQ(e[1].kind, EventKind::Confirmed);
        EXPECT_EQ(e[1].label, 1);
        EXPECT_GE(e[1].time_ns - e[0].time_ns, 400 * kMs);
        EXPECT_LE(e[1].time_ns - e[0].time_ns, 400 * kMs + 2 * kPeriod);
        ASSERT_TRUE(r.decided);
        EXPECT_EQ(r.outcome.choice, 1);
        EXPECT_EQ(r.outcome.chosen_mode, r.trial.label1_mode);
        EXPECT_EQ(r.outcome.switches, 0);
        EXPECT_FALSE(r.outcome.valid);
    }
}

// The observer does nothing while the experimenter pauses, and goes on after the resume.
TEST_F(ObserverInputTest, ObserverWaitsWhilePaused) {
    const Protocol protocol = make_protocol(true, 5, 0);
    const std::int64_t id = begin(protocol);
    auto s = open(id, protocol, 0);
    ASSERT_TRUE(s);
    SingleDwellObserver observer;
    ObserverInput input(observer, protocol, nullptr);
    std::int64_t frame = 0;
    const auto step = [&]() {
        const std::int64_t t = at(frame);
        for (LiveInput in : input.poll(s->screen(), s->progress(), t)) {
            EXPECT_TRUE(s->request(in, t).ok());
        }
        EXPECT_TRUE(s->frame_presented(frame, t).ok());
        ++frame;
    };
    step();
    step();  // label 1 visible at frame 1
    ASSERT_EQ(s->progress().visible_label, 1);
    ASSERT_EQ(request(*s, LiveInput::Pause, frame), "pause");
    // 2 s paused: far past the 400 ms dwell, but the observer sends nothing.
    for (int i = 0; i < 180; ++i) step();
    std::vector<TrialEvent> e = events(id);
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[1].kind, EventKind::Paused);
    ASSERT_EQ(request(*s, LiveInput::Resume, frame), "resume");
    while (!s->finished() && frame < 100'000) step();
    EXPECT_EQ(status(id), SessionStatus::Completed);
    for (const TrialRecord& r : trials(id)) EXPECT_EQ(r.outcome.choice, 2) << r.trial.index;
}

// Looks at label 1, label 2, label 1 for 300 ms each and confirms label 1.
class ThreeDwellObserver final : public Observer {
  public:
    std::string_view name() const override { return "three-dwell"; }
    TrialPlan plan_trial(const ScheduledTrial&, int, double) override {
        return TrialPlan{{300 * kMs, 300 * kMs, 300 * kMs}};
    }
    int answer(int, int) override { return 1; }
};

enum class Race {
    PauseBeforeSwitch,   // the experimenter's pause is applied first: the switch is refused
    PauseAfterSwitch,    // the switch is requested, then paused before a frame shows it
    PauseBeforeConfirm,  // the confirmation is refused because the trial is paused
    FramesNotPresented,  // the switch is requested, then no frame is presented for 20 frames
};

// The experimenter pauses in the same frame as the observer's first `target` request and resumes
// 20 frames later, before the observer's poll (or, FramesNotPresented, the display presents no
// frame for 20 frames, as when the runtime asks for no rendering). The observer must still carry
// out its plan: label 1 confirmed after two switches in every trial, no refusal logged.
class ObserverRaceTest : public ObserverInputTest {
  protected:
    void run_race(Race race) {
        const Protocol protocol = make_protocol(true, 5, 0, 0);
        const std::int64_t id = begin(protocol);
        auto s = open(id, protocol, 0);
        ASSERT_TRUE(s);
        ThreeDwellObserver observer;
        ObserverInput input(observer, protocol, nullptr);
        const LiveInput target =
            race == Race::PauseBeforeConfirm ? LiveInput::Confirm : LiveInput::Switch;
        bool raced = false;
        std::int64_t resume_at = -1;
        std::int64_t frame = 0;
        for (; !s->finished() && frame < 100'000; ++frame) {
            const std::int64_t t = at(frame);
            if (frame == resume_at && race != Race::FramesNotPresented) {
                EXPECT_EQ(request(*s, LiveInput::Resume, frame), "resume");
            }
            const std::vector<LiveInput> inputs = input.poll(s->screen(), s->progress(), t);
            const bool race_now =
                !raced && std::find(inputs.begin(), inputs.end(), target) != inputs.end();
            if (race_now && race != Race::PauseAfterSwitch && race != Race::FramesNotPresented) {
                EXPECT_EQ(request(*s, LiveInput::Pause, frame), "pause");
            }
            for (LiveInput in : inputs) ASSERT_TRUE(s->request(in, t).ok());
            if (race_now && race == Race::PauseAfterSwitch) {
                EXPECT_EQ(request(*s, LiveInput::Pause, frame), "pause");
            }
            if (race_now) {
                raced = true;
                resume_at = frame + 20;
            }
            // The runtime asks for no rendering (headset not visible): nothing is presented.
            const bool skipped = race == Race::FramesNotPresented && raced && frame < resume_at;
            if (!skipped) present(*s, frame);
        }
        ASSERT_TRUE(raced);
        EXPECT_EQ(status(id), SessionStatus::Completed);
        for (const TrialRecord& r : trials(id)) {
            SCOPED_TRACE("trial " + std::to_string(r.trial.index));
            ASSERT_TRUE(r.decided);
            EXPECT_EQ(r.outcome.choice, 1);
            EXPECT_EQ(r.outcome.switches, 2);
        }
        int refused = 0;
        int paused = 0;
        for (const TrialEvent& e : events(id)) {
            refused += e.kind == EventKind::Refused;
            paused += e.kind == EventKind::Paused;
        }
        EXPECT_EQ(refused, 0);
        EXPECT_EQ(paused, race == Race::FramesNotPresented ? 0 : 1);
    }
};

TEST_F(ObserverRaceTest, PauseBeforeTheObserversSwitchDoesNotChangeItsChoice) {
    run_race(Race::PauseBeforeSwitch);
}

TEST_F(ObserverRaceTest, PauseBeforeTheObserversSwitchShowsDoesNotChangeItsChoice) {
    run_race(Race::PauseAfterSwitch);
}

TEST_F(ObserverRaceTest, PauseBeforeTheObserversConfirmationDoesNotChangeItsChoice) {
    run_race(Race::PauseBeforeConfirm);
}

TEST_F(ObserverRaceTest, FramesNotPresentedAfterTheObserversSwitchDoNotChangeItsChoice) {
    run_race(Race::FramesNotPresented);
}

}  // namespace
}  // namespace monoplane::study
