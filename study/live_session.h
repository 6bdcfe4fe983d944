// A session driven frame by frame by a display and live input: the headset
// path of `study run`. Between trials, and before the first, a neutral screen; then each trial of
// the stored schedule through the 2AFC state machine; then the questionnaire, answered one item
// at a time on a Likert scale (switch moves the selection, confirm accepts it) or all at once by
// the experimenter; then the session's status. A protocol's screens come in between: its
// instruction pages before the first trial (confirm: next page, switch: back one), the ready
// screen before the first data trial, breaks between data trials (confirm continues once the
// countdown is over) and the end screen last. Every event is written to the store inside the
// call that caused it, so it is durable before the next frame starts.
//
// Time: the caller passes the monotonic time of each request and of each presented frame (in a
// headset session, the runtime's predicted display time) on the session's time axis: the run's
// clock through session_time() once begin_run() placed the run. A requested change of label or
// screen becomes visible with the next presented frame, whose index the events carry; the run's
// frames are numbered from run().first_frame on, after every frame an earlier run used.
//
// Resumed: a trial an interruption cut short is shown again from label 1, and its outcome counts
// what every run showed of it (trial_runs.h); a break cut short is shown again, its start logged
// again, for what is left of its minimum.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/protocol.h"
#include "study/session_runs.h"
#include "study/session_screens.h"
#include "study/staircases.h"
#include "study/study_store.h"
#include "study/trial_runs.h"
#include "study/trial_state_machine.h"

namespace monoplane::study {

enum class LiveInput { Switch, Confirm, Pause, Resume, Abort };
std::string_view live_input_name(LiveInput input);

// Instructions, Ready, Break and End are the protocol's pages (study/protocol_study_day.h):
// instructions before the first trial, ready after practice, breaks between data trials, end
// after the questionnaire (End counts as finished: the session is completed when it shows).
enum class ScreenKind {
    Neutral,
    Trial,
    Questionnaire,
    Finished,
    Aborted,
    Instructions,
    Ready,
    Break,
    End
};
std::string_view screen_kind_name(ScreenKind kind);

// What the next frame shows.
struct LiveScreen {
    ScreenKind kind = ScreenKind::Neutral;
    bool paused = false;  // Trial: the experimenter paused it (the trial stays on screen)
    const ScheduledTrial* trial = nullptr;  // Trial: the trial; else null
    int label = 0;                          // Trial: the label to draw, 1 or 2
    RenderMode mode = RenderMode::Stereo;   // Trial: that label's mode
    int question = 0;                       // Questionnaire: the item asked, 0-based
    int selection = 0;                      // Questionnaire: the answer selected, 1..scale
    // Instructions, Ready, Break, End: the page's text (the protocol's), else null.
    const std::string* text = nullptr;
    int page = 0;        // Instructions: the page shown, 0-based
    int page_count = 0;  // Instructions: how many pages
    // Break: how long until confirm continues (the countdown; 0: "press confirm to continue").
    std::int64_t break_remaining_ns = 0;
};

// Progress for the experimenter's window (not logged: derived from what is).
struct LiveProgress {
    int trial_number = 0;  // 1-based position of the current or last trial; 0 before the first
    int trial_count = 0;
    int visible_label = 0;
    int switches = 0;
    bool both_seen = false;
    std::int64_t trial_started_ns = -1;  // first visibility of the current trial
};

struct LiveOptions {
    // The neutral screen's duration between trials and before the first.
    std::int64_t neutral_ns = 1'000'000'000;
    // Called after each durable write with a one-line description (log tail, tests).
    std::function<void(const std::string&)> on_committed;
};

class LiveSession {
  public:
    // Continues a stored session at its first undecided trial, or at the screen where it stood,
    // and marks it running; a staircase protocol's staircases are rebuilt from the session's
    // stored decisions.
    static Result<std::unique_ptr<LiveSession>> open(StudyStore& store, std::int64_t session_id,
                                                     const Protocol& protocol,
                                                     const LiveOptions& options);
    // Runs `schedule` from trial position first_trial on, writing to `log` (a simulation's
    // memory, or the store as open() does); marks the session running. `history`: the trials of
    // a resumed session: its decided ones are not shown again (a staircase's skipped slot may
    // precede them), and a staircase protocol's staircases record them again, in trial order,
    // before the first trial starts. `events`: a resumed session's events, in the order logged:
    // they tell where it stood among the protocol's screens (study/session_screens.h):
    // instructions already read and a ready screen already confirmed are not shown again, a
    // break that had started and not ended is shown for the rest of its minimum time.
    static Result<std::unique_ptr<LiveSession>> begin(SessionLog& log, std::int64_t session_id,
                                                      const Protocol& protocol,
                                                      const LiveOptions& options, Schedule schedule,
                                                      int first_trial,
                                                      const std::vector<TrialRecord>& history = {},
                                                      const std::vector<TrialEvent>& events = {},
                                                      const std::vector<FrameRecord>& frames = {});

    // This process's run of the session begins (SessionLog::begin_run): numbered, its frames
    // placed after every stored one and its clock on the session's axis, with a run_started
    // event. Once, after open() or begin() and before the first request or frame; a session
    // whose front end never calls it (a test, a simulation) runs on its caller's times as
    // they are.
    Result<void> begin_run(const RunInfo& info);
    // The run begin_run() placed (before it: run 0, frames from 0, its clock as it is).
    const RunStart& run() const { return run_; }
    // A time of the run's clock on the session's axis, for every time the front end passes in
    // and logs beside the session (its frame log). Any time.
    std::int64_t session_time(std::int64_t clock_ns) const { return run_.session_time(clock_ns); }

    // The staircases of a staircase protocol (their estimates for the experimenter), else null.
    const Staircases* staircases() const { return staircases_ ? &*staircases_ : nullptr; }

    LiveScreen screen() const;
    LiveProgress progress() const;
    bool finished() const;  // completed or aborted

    // A participant's or experimenter's request. A request that does not apply now (a switch on
    // the neutral screen, a refused confirmation, a confirm before a break's countdown is over or
    // on a screen not yet presented) is not an error: the returned line says what happened.
    // Errors are failures to write the log. Abort ends the session on any screen but the end.
    Result<std::string> request(LiveInput input, std::int64_t time_ns);
    // The experimenter's answer to questionnaire item `item` (1..scale), entered in the window:
    // recorded at once; the questionnaire moves past answered items.
    Result<void> answer(int item, int value);
    // The experimenter's note, typed in the window: stored at once with the session's latest time
    // (of its latest presented frame or request; none before either) and the trial on screen or
    // the last one shown (none before the first). Refuses a blank note.
    Result<void> note(const std::string& text, NoteSource source = NoteSource::Window);
    // A press of the participant's controller or keys, logged (SessionLog::record_press) with the
    // screen shown and the trial on it, before the caller requests what it asks for: every press
    // is in the log, whatever it changes. `key`: the key's name (keyboard, device), else empty.
    Result<void> record_press(PressSource source, PressAction action, const std::string& key,
                              std::int64_t time_ns);
    // Frame `frame` became visible at time_ns: pending changes take effect and are logged; the
    // neutral screen ends and the next trial starts when its time is up.
    Result<void> frame_presented(std::int64_t frame, std::int64_t time_ns);

  private:
    LiveSession(SessionLog& log, std::int64_t session_id, const Protocol& protocol,
                const LiveOptions& options, Schedule schedule, int first_trial);

    Result<void> log(const std::vector<TrialEvent>& events);
    void committed(const std::string& what) const;
    Result<void> start_next_trial(std::int64_t time_ns);
    // Skips the slots of stopped staircases and has the next adaptive trial's m chosen and
    // recorded; false when no trial is left.
    Result<bool> prepare_next_trial();
    Result<void> record_answer(int item, int value);
    Result<std::string> abort_session(std::int64_t time_ns);
    Result<std::string> questionnaire_request(LiveInput input);
    Result<std::string> trial_request(LiveInput input, std::int64_t time_ns);
    // The end screen when the protocol has one (completed when it shows), else completed now.
    Result<void> complete();
    Result<void> finish(SessionStatus status);

    // The protocol's screens (live_session_screens.cpp; the rules in study/session_screens.h).
    // Where a resumed (or new) session starts: a screen, or the neutral screen before a trial.
    void resume_screens(const std::vector<TrialEvent>& events,
                        const std::vector<FrameRecord>& frames);
    // After a decision or a screen: the screen due before the next trial, else the neutral
    // screen from time_ns (-1: from the next frame).
    void enter_next(std::int64_t time_ns);
    void show_screen(ScreenKind kind);
    // The position of the next trial to show, as prepare_next_trial() will find it, without
    // choosing an adaptive trial's m; none when no trial is left.
    std::optional<std::size_t> peek_next_trial() const;
    bool on_page_screen() const;
    Result<void> screen_presented(std::int64_t frame, std::int64_t time_ns);
    Result<std::string> screen_request(LiveInput input, std::int64_t time_ns);
    Result<std::string> confirm_screen(std::int64_t time_ns);
    Result<void> log_screen(EventKind kind, std::int64_t time_ns, std::int64_t frame);

    SessionLog& log_;
    std::int64_t session_id_;
    Protocol protocol_;
    LiveOptions options_;
    Schedule schedule_;
    std::size_t next_trial_;  // position in schedule_.trials of the next trial to start
    ScreenKind kind_ = ScreenKind::Neutral;
    std::optional<TrialStateMachine> machine_;
    std::optional<Staircases> staircases_;  // procedure = "staircase" only
    std::set<int> decided_;                 // trial indices decided (this run and before)
    // What earlier runs showed of trials they left undecided, by trial index.
    std::map<int, TrialRuns> earlier_runs_;
    RunStart run_{.start_ns = std::numeric_limits<std::int64_t>::min()};
    std::int64_t neutral_since_ns_ = -1;  // -1: from the next frame
    int trial_number_ = 0;
    std::int64_t trial_started_ns_ = -1;
    std::vector<int> answers_;  // per questionnaire item, 0: not yet answered
    int selection_ = 0;
    ScreenProgress screens_;
    int page_ = 0;                 // Instructions: the page on screen
    bool screen_visible_ = false;  // a screen's appearance was presented (and logged)
    // Break: the countdown's start (the minimum, or what a resumed break has left of it) and
    // the time of the frame that first showed it in this run.
    std::int64_t break_min_ns_ = 0;
    std::int64_t break_visible_ns_ = -1;
    std::int64_t break_remaining_ns_ = 0;
    std::optional<int> last_trial_shown_;  // for notes: the trial on screen or last shown
    std::int64_t latest_ns_ = -1;          // the latest request or frame time (the session clock)
};

}  // namespace monoplane::study
