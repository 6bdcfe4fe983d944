#include "study/live_session.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/name_table.h"

namespace monoplane::study {

namespace {

// Logged, printed and stored with each key press (response_press.h: the screen seen).
constexpr NameTable<LiveInput> kLiveInputNames = {
    {LiveInput::Switch, "switch"}, {LiveInput::Confirm, "confirm"}, {LiveInput::Pause, "pause"},
    {LiveInput::Resume, "resume"}, {LiveInput::Abort, "abort"},
};
static_assert(kLiveInputNames.size() == static_cast<std::size_t>(LiveInput::Abort) + 1,
              "every LiveInput needs its name");

constexpr NameTable<ScreenKind> kScreenKindNames = {
    {ScreenKind::Neutral, "neutral"},
    {ScreenKind::Trial, "trial"},
    {ScreenKind::Questionnaire, "questionnaire"},
    {ScreenKind::Finished, "finished"},
    {ScreenKind::Aborted, "aborted"},
    {ScreenKind::Instructions, "instructions"},
    {ScreenKind::Ready, "ready"},
    {ScreenKind::Break, "break"},
    {ScreenKind::End, "end"},
};
static_assert(kScreenKindNames.size() == static_cast<std::size_t>(ScreenKind::End) + 1,
              "every ScreenKind needs its name");

}  // namespace

std::string_view live_input_name(LiveInput input) {
    return find_name(kLiveInputNames, input, "invalid");
}

std::string_view screen_kind_name(ScreenKind kind) {
    return find_name(kScreenKindNames, kind, "invalid");
}

Result<std::unique_ptr<LiveSession>> LiveSession::open(StudyStore& store, std::int64_t session_id,
                                                       const Protocol& protocol,
                                                       const LiveOptions& options) {
    Result<Schedule> schedule = store.load_schedule(session_id);
    MONOPLANE_TRY(schedule);
    Result<int> first = store.first_undecided_trial(session_id);
    MONOPLANE_TRY(first);
    // Every decision so far: a staircase's slots skipped (stopped) may lie before decided ones.
    Result<std::vector<TrialRecord>> history = store.trials(session_id);
    MONOPLANE_TRY(history);
    // Where it stood among the protocol's screens is in the events alone.
    Result<std::vector<TrialEvent>> events = store.events(session_id);
    MONOPLANE_TRY(events);
    // A break's time also shows in the frame log of a headset session.
    Result<std::vector<FrameRecord>> frames = store.frames(session_id);
    MONOPLANE_TRY(frames);
    return begin(store, session_id, protocol, options, std::move(schedule).value(), *first,
                 *history, *events, *frames);
}

Result<std::unique_ptr<LiveSession>> LiveSession::begin(
    SessionLog& log, std::int64_t session_id, const Protocol& protocol, const LiveOptions& options,
    Schedule schedule, int first_trial, const std::vector<TrialRecord>& history,
    const std::vector<TrialEvent>& events, const std::vector<FrameRecord>& frames) {
    MONOPLANE_TRY(log.set_status(session_id, SessionStatus::Running));
    auto session = std::unique_ptr<LiveSession>(
        new LiveSession(log, session_id, protocol, options, std::move(schedule), first_trial));
    std::vector<const TrialRecord*> decided;
    for (const TrialRecord& r : history) {
        if (r.decided) decided.push_back(&r);
    }
    std::ranges::sort(decided, {}, [](const TrialRecord* r) { return r->trial.index; });
    for (const TrialRecord* r : decided) {
        session->decided_.insert(r->trial.index);
        if (session->staircases_) session->staircases_->record(r->trial, r->outcome);
        session->last_trial_shown_ = r->trial.index;
    }
    // A trial an interruption cut short keeps what its earlier runs showed.
    for (const auto& [index, runs] : trial_runs(events, frames))
        if (!session->decided_.contains(index)) session->earlier_runs_.emplace(index, runs);
    session->resume_screens(events, frames);
    return session;
}

Result<void> LiveSession::begin_run(const RunInfo& info) {
    Result<RunStart> run = log_.begin_run(session_id_, info);
    MONOPLANE_TRY(run);
    run_ = *run;
    committed("run " + std::to_string(run_.run) + " started t " + std::to_string(run_.start_ns) +
              " frame " + std::to_string(run_.first_frame));
    return Ok{};
}

LiveSession::LiveSession(SessionLog& log, std::int64_t session_id, const Protocol& protocol,
                         const LiveOptions& options, Schedule schedule, int first_trial)
    : log_(log),
      session_id_(session_id),
      protocol_(protocol),
      options_(options),
      schedule_(std::move(schedule)),
      next_trial_(0),
      answers_(protocol.questionnaire.items.size(), 0) {
    if (protocol_.procedure == Procedure::Staircase) staircases_.emplace(protocol_);
    while (next_trial_ < schedule_.trials.size() &&
           schedule_.trials[next_trial_].index < first_trial) {
        ++next_trial_;
    }
    trial_number_ = static_cast<int>(next_trial_);
}

void LiveSession::committed(const std::string& what) const {
    if (options_.on_committed) options_.on_committed(what);
}

Result<void> LiveSession::log(const std::vector<TrialEvent>& events) {
    for (const TrialEvent& e : events) {
        MONOPLANE_TRY(log_.append_event(session_id_, e));
        committed(describe(e));
    }
    return Ok{};
}

LiveScreen LiveSession::screen() const {
    LiveScreen screen;
    screen.kind = kind_;
    if (kind_ == ScreenKind::Trial) {
        const ScheduledTrial& trial = machine_->trial();
        screen.trial = &trial;
        screen.paused = machine_->state() == TrialState::Paused;
        screen.label = machine_->label_to_draw();
        screen.mode = screen.label == 1 ? trial.label1_mode : trial.label2_mode;
    }
    if (kind_ == ScreenKind::Questionnaire) {
        for (std::size_t i = 0; i < answers_.size(); ++i) {
            if (answers_[i] == 0) {
                screen.question = static_cast<int>(i);
                break;
            }
        }
        screen.selection = selection_;
    }
    if (on_page_screen()) {
        const StudyDaySettings& day = protocol_.day;
        if (kind_ == ScreenKind::Instructions) {
            screen.text = &day.instructions[static_cast<std::size_t>(page_)].text;
            screen.page = page_;
            screen.page_count = static_cast<int>(day.instructions.size());
        }
        if (kind_ == ScreenKind::Ready) screen.text = &day.ready->text;
        if (kind_ == ScreenKind::End) screen.text = &day.end->text;
        if (kind_ == ScreenKind::Break) {
            screen.text = &day.breaks->text;
            screen.break_remaining_ns = screen_visible_ ? break_remaining_ns_ : break_min_ns_;
        }
    }
    return screen;
}

LiveProgress LiveSession::progress() const {
    LiveProgress p;
    p.trial_number = trial_number_;
    p.trial_count = static_cast<int>(schedule_.trials.size());
    if (machine_) {
        p.visible_label = machine_->visible_label();
        p.switches = machine_->outcome().switches;
        p.both_seen = machine_->seen(1) && machine_->seen(2);
        p.trial_started_ns = trial_started_ns_;
    }
    return p;
}

bool LiveSession::finished() const {
    return kind_ == ScreenKind::Finished || kind_ == ScreenKind::Aborted ||
           (kind_ == ScreenKind::End && screen_visible_);
}

Result<void> LiveSession::finish(SessionStatus status) {
    MONOPLANE_TRY(log_.set_status(session_id_, status));
    // A completed session's end screen stays up for the participant.
    if (status == SessionStatus::Aborted) {
        kind_ = ScreenKind::Aborted;
    } else if (kind_ != ScreenKind::End) {
        kind_ = ScreenKind::Finished;
    }
    committed("session " + std::string(session_status_name(status)));
    return Ok{};
}

Result<bool> LiveSession::prepare_next_trial() {
    for (; next_trial_ < schedule_.trials.size(); ++next_trial_) {
        ScheduledTrial& trial = schedule_.trials[next_trial_];
        if (decided_.contains(trial.index)) continue;  // after a skipped slot, in a resume
        // Constant and practice trials, and an adaptive trial whose m was chosen before an
        // interruption (it is shown at that m again).
        if (!trial.adaptive || !std::isnan(trial.mono_plane)) return true;
        if (staircases_->finished(trial.scene)) continue;  // its staircase has stopped
        trial.mono_plane = staircases_->next_mono_plane(trial.scene);
        MONOPLANE_TRY(log_.record_stimulus(session_id_, trial));
        committed("trial " + std::to_string(trial.index) + " stimulus m " +
                  std::to_string(trial.mono_plane));
        return true;
    }
    return false;
}

Result<void> LiveSession::start_next_trial(std::int64_t time_ns) {
    Result<bool> prepared = prepare_next_trial();
    MONOPLANE_TRY(prepared);
    if (!*prepared) {
        machine_.reset();
        if (protocol_.questionnaire.items.empty()) return complete();
        kind_ = ScreenKind::Questionnaire;
        // The middle of the scale: no answer is suggested by the starting position.
        selection_ = (protocol_.questionnaire.scale_points + 1) / 2;
        committed("questionnaire");
        return Ok{};
    }
    const ScheduledTrial& trial = schedule_.trials[next_trial_];
    const auto earlier = earlier_runs_.find(trial.index);
    machine_.emplace(trial, protocol_.require_both_viewed,
                     earlier == earlier_runs_.end() ? TrialRuns{} : earlier->second);
    ++next_trial_;
    trial_number_ = static_cast<int>(next_trial_);
    last_trial_shown_ = machine_->trial().index;
    trial_started_ns_ = -1;
    kind_ = ScreenKind::Trial;
    Result<std::vector<TrialEvent>> events = machine_->start(time_ns);
    MONOPLANE_TRY(events);
    return log(*events);
}

Result<void> LiveSession::frame_presented(std::int64_t frame, std::int64_t time_ns) {
    latest_ns_ = std::max(latest_ns_, time_ns);
    if (on_page_screen()) return screen_presented(frame, time_ns);
    if (kind_ == ScreenKind::Neutral) {
        if (neutral_since_ns_ < 0) neutral_since_ns_ = time_ns;
        // The trial starts now and its label 1 is visible from the next frame on.
        if (time_ns - neutral_since_ns_ >= options_.neutral_ns) return start_next_trial(time_ns);
        return Ok{};
    }
    if (kind_ != ScreenKind::Trial) return Ok{};
    const std::vector<TrialEvent> events = machine_->frame_presented(frame, time_ns);
    if (trial_started_ns_ < 0 && machine_->visible_label() != 0) trial_started_ns_ = time_ns;
    return log(events);
}

Result<void> LiveSession::record_answer(int item, int value) {
    const Questionnaire& q = protocol_.questionnaire;
    MONOPLANE_TRY(log_.record_answer(session_id_, item, q.items[item], value));
    answers_[item] = value;
    committed("answer " + std::to_string(item + 1) + ": " + std::to_string(value));
    for (int a : answers_) {
        if (a == 0) {
            selection_ = (q.scale_points + 1) / 2;
            return Ok{};
        }
    }
    return complete();
}

Result<void> LiveSession::answer(int item, int value) {
    if (kind_ != ScreenKind::Questionnaire) {
        return Error{"the questionnaire is not being asked (screen: " +
                     std::string(screen_kind_name(kind_)) + ")"};
    }
    if (item < 0 || item >= static_cast<int>(answers_.size()) || value < 1 ||
        value > protocol_.questionnaire.scale_points) {
        return Error{"questionnaire answer out of range: item " + std::to_string(item + 1) +
                     ", value " + std::to_string(value)};
    }
    return record_answer(item, value);
}

Result<void> LiveSession::complete() {
    if (!protocol_.day.end) return finish(SessionStatus::Completed);
    show_screen(ScreenKind::End);  // completed when it shows (screen_presented)
    return Ok{};
}

Result<void> LiveSession::note(const std::string& text, NoteSource source) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
        return Error{"a note must not be empty"};
    }
    SessionNote note;
    note.text = text;
    note.source = source;
    if (latest_ns_ >= 0) note.runtime_time_ns = latest_ns_;
    note.trial_index = last_trial_shown_;
    MONOPLANE_TRY(log_.add_note(session_id_, note));
    // The text stays out of the line: it may hold line breaks, and the line is parsed by tests.
    committed("note " + std::string(note_source_name(source)) +
              (last_trial_shown_ ? " trial " + std::to_string(*last_trial_shown_) : "") + " t " +
              std::to_string(latest_ns_));
    return Ok{};
}

Result<void> LiveSession::record_press(PressSource source, PressAction action,
                                       const std::string& key, std::int64_t time_ns) {
    const LiveScreen shown = screen();
    ResponsePress press;
    press.source = source;
    press.action = action;
    press.key = key;
    press.screen = std::string(screen_kind_name(shown.kind));
    if (shown.trial) press.trial_index = shown.trial->index;
    press.time_ns = time_ns;
    MONOPLANE_TRY(log_.record_press(session_id_, press));
    committed("press " + std::string(press_source_name(source)) + " " +
              std::string(press_action_name(action)) + (key.empty() ? "" : " key " + key) + " t " +
              std::to_string(time_ns));
    return Ok{};
}

Result<std::string> LiveSession::abort_session(std::int64_t time_ns) {
    if (machine_ && kind_ == ScreenKind::Trial) {
        Result<std::vector<TrialEvent>> events = machine_->abort(time_ns);
        if (events) {
            MONOPLANE_TRY(log(*events));
        }
    }
    MONOPLANE_TRY(finish(SessionStatus::Aborted));
    return std::string("session aborted");
}

Result<std::string> LiveSession::questionnaire_request(LiveInput input) {
    const int scale = protocol_.questionnaire.scale_points;
    if (input == LiveInput::Switch) {
        selection_ = selection_ % scale + 1;
        return "questionnaire selection " + std::to_string(selection_);
    }
    if (input == LiveInput::Confirm) {
        const int item = screen().question;
        MONOPLANE_TRY(record_answer(item, selection_));
        return "answered item " + std::to_string(item + 1);
    }
    return std::string(live_input_name(input)) + " ignored during the questionnaire";
}

Result<std::string> LiveSession::request(LiveInput input, std::int64_t time_ns) {
    latest_ns_ = std::max(latest_ns_, time_ns);
    if (input == LiveInput::Abort && !finished()) return abort_session(time_ns);
    if (kind_ == ScreenKind::Questionnaire) return questionnaire_request(input);
    if (on_page_screen() && !finished()) return screen_request(input, time_ns);
    if (kind_ != ScreenKind::Trial) {
        return std::string(live_input_name(input)) + " ignored on the " +
               std::string(screen_kind_name(kind_)) + " screen";
    }
    return trial_request(input, time_ns);
}

Result<std::string> LiveSession::trial_request(LiveInput input, std::int64_t time_ns) {
    Result<std::vector<TrialEvent>> events = std::vector<TrialEvent>{};
    switch (input) {
        case LiveInput::Switch:
            events = machine_->request_switch(time_ns);
            break;
        case LiveInput::Confirm:
            events = machine_->request_confirm(time_ns);
            break;
        case LiveInput::Pause:
            events = machine_->pause(time_ns);
            break;
        case LiveInput::Resume:
            events = machine_->resume(time_ns);
            break;
        case LiveInput::Abort:
            break;
    }
    if (!events) {
        // Refused or not applicable now: the refusal is part of the record, the rest is not.
        if (input == LiveInput::Confirm && machine_->last_refusal()) {
            MONOPLANE_TRY(log({*machine_->last_refusal()}));
        }
        return events.error().message;
    }
    MONOPLANE_TRY(log(*events));
    if (machine_->state() != TrialState::Decided) return std::string(live_input_name(input));
    const int index = machine_->trial().index;
    MONOPLANE_TRY(log_.record_outcome(session_id_, index, machine_->outcome()));
    if (staircases_) staircases_->record(machine_->trial(), machine_->outcome());
    committed("trial " + std::to_string(index) + " outcome choice " +
              std::to_string(machine_->outcome().choice));
    decided_.insert(index);
    screens_.break_taken = false;  // a new gap between trials
    enter_next(time_ns);
    return "trial " + std::to_string(index) + " decided: label " +
           std::to_string(machine_->outcome().choice);
}

}  // namespace monoplane::study
