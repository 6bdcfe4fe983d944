#include "study/session_runner.h"

#include <chrono>
#include <cmath>
#include <thread>

namespace monoplane::study {
namespace {

// A display that presents a frame every 1/rate seconds of virtual time: a change requested at t
// becomes visible with the first frame after t.
class VirtualDisplay {
  public:
    explicit VirtualDisplay(double rate_hz)
        : period_ns_(static_cast<std::int64_t>(std::llround(1e9 / rate_hz))) {}

    std::int64_t now() const { return now_ns_; }
    void advance(std::int64_t ns) { now_ns_ += ns; }
    // Presents the next frame after now; returns its index and moves the clock to it.
    std::int64_t present_next_frame() {
        const std::int64_t frame = now_ns_ / period_ns_ + 1;
        now_ns_ = frame * period_ns_;
        return frame;
    }

  private:
    std::int64_t period_ns_;
    std::int64_t now_ns_ = 0;
};

class Run {
  public:
    Run(StudyStore& store, std::int64_t session_id, const RunOptions& options)
        : store_(store),
          session_id_(session_id),
          options_(options),
          display_(options.frame_rate_hz) {}

    // Logs events durably, in order, before anything else happens.
    Result<bool> log(const std::vector<TrialEvent>& events) {
        for (const TrialEvent& e : events) {
            Result<bool> ok = store_.append_event(session_id_, e);
            if (!ok) return ok;
            committed(describe(e));
        }
        return true;
    }

    void committed(const std::string& what) {
        if (options_.on_committed) options_.on_committed(what);
        if (options_.pace_ns > 0)
            std::this_thread::sleep_for(std::chrono::nanoseconds(options_.pace_ns));
    }

    Result<bool> present_frame(TrialStateMachine& machine) {
        const std::int64_t frame = display_.present_next_frame();
        return log(machine.frame_presented(frame, display_.now()));
    }

    template <class Events>
    Result<bool> request(Events&& events) {
        if (!events) return Error{events.error()};
        return log(events.value());
    }

    Result<bool> run_trial(const ScheduledTrial& trial, const Protocol& protocol,
                           Observer& observer) {
        TrialStateMachine machine(trial, protocol.require_both_viewed);
        const int reference_label = trial.label1_alternative == 0 ? 1 : 2;
        const double error_px = options_.trial_error_px ? options_.trial_error_px(trial) : 0.0;
        const TrialPlan plan = observer.plan_trial(trial, reference_label, error_px);

        Result<bool> ok = request(machine.start(display_.now()));
        if (!ok) return ok;
        ok = present_frame(machine);
        if (!ok) return ok;
        for (std::size_t i = 0; i < plan.dwell_ns.size(); ++i) {
            display_.advance(plan.dwell_ns[i]);
            if (i + 1 < plan.dwell_ns.size()) {
                ok = request(machine.request_switch(display_.now()));
                if (!ok) return ok;
                ok = present_frame(machine);
                if (!ok) return ok;
            }
        }
        auto confirmed = machine.request_confirm(display_.now());
        if (!confirmed) {
            // Refused (not both seen): log the refusal, then look at the other label and confirm
            // again, as a participant asked to view both would.
            if (machine.last_refusal()) ok = log({*machine.last_refusal()});
            if (!ok) return ok;
            ok = request(machine.request_switch(display_.now()));
            if (!ok) return ok;
            ok = present_frame(machine);
            if (!ok) return ok;
            display_.advance(plan.dwell_ns.back());
            confirmed = machine.request_confirm(display_.now());
            if (!confirmed) return Error{confirmed.error()};
        }
        ok = log(confirmed.value());
        if (!ok) return ok;
        ok = store_.record_outcome(session_id_, trial.index, machine.outcome());
        if (!ok) return ok;
        committed("trial " + std::to_string(trial.index) + " outcome choice " +
                  std::to_string(machine.outcome().choice));
        return true;
    }

  private:
    StudyStore& store_;
    std::int64_t session_id_;
    const RunOptions& options_;
    VirtualDisplay display_;
};

}  // namespace

Result<SessionStatus> run_session(StudyStore& store, std::int64_t session_id,
                                  const Protocol& protocol, Observer& observer,
                                  const RunOptions& options) {
    Result<Schedule> schedule = store.load_schedule(session_id);
    if (!schedule) return schedule.error();
    Result<int> first = store.first_undecided_trial(session_id);
    if (!first) return first.error();
    Result<bool> ok = store.set_status(session_id, SessionStatus::Running);
    if (!ok) return ok.error();

    Run run(store, session_id, options);
    for (const ScheduledTrial& trial : schedule->trials) {
        if (trial.index < *first) continue;
        ok = run.run_trial(trial, protocol, observer);
        if (!ok) return ok.error();
    }
    const Questionnaire& q = protocol.questionnaire;
    for (int item = 0; item < static_cast<int>(q.items.size()); ++item) {
        ok = store.record_answer(session_id, item, q.items[item],
                                 observer.answer(item, q.scale_points));
        if (!ok) return ok.error();
        run.committed("answer " + std::to_string(item));
    }
    ok = store.set_status(session_id, SessionStatus::Completed);
    if (!ok) return ok.error();
    run.committed("session completed");
    return SessionStatus::Completed;
}

}  // namespace monoplane::study
