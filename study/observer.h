// The simulated observer: a seeded model participant whose preference for
// the reference alternative grows with the trial's projection error, with switch counts and dwell
// times drawn from simple distributions. Used by tests, demos and power analysis; with a headset
// the same plan drives the input path a controller would.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/schedule.h"

namespace monoplane::study {

// What the observer will do in one trial: look at label 1 for dwell_ns[0], switch, look at the
// other label for dwell_ns[1], ..., then confirm the label visible after the last dwell.
// switches = dwell_ns.size() - 1; the confirmed label follows from it (odd: 2, even: 1), so a plan
// is consistent by construction.
struct TrialPlan {
    std::vector<std::int64_t> dwell_ns;
    int confirmed_label() const { return dwell_ns.size() % 2 == 1 ? 1 : 2; }
};

class Observer {
  public:
    virtual ~Observer() = default;
    virtual std::string_view name() const = 0;
    // reference_label: the label showing the protocol's first alternative (the reference);
    // error_px: the largest projection error of the trial's hybrid condition (rig), 0 for none.
    virtual TrialPlan plan_trial(const ScheduledTrial& trial, int reference_label,
                                 double error_px) = 0;
    // True for an observer whose stimulus is hybrid's error where its gaze rests ("gaze:..."):
    // its runner passes the trial's error at gaze (arcmin) as error_px.
    virtual bool decides_on_gaze_error() const { return false; }
    // Likert answer (1..scale_points) to questionnaire item `item`.
    virtual int answer(int item, int scale_points) = 0;
};

// "default", "chance", "reference" (observer_names()), or
// "psychometric:threshold=T,slope=B,lapse=L" or "gaze:threshold=T,slope=B,lapse=L"
// (study/observer_spec.h; a bad specification is an error saying where). An unknown name is an
// error listing these.
Result<std::unique_ptr<Observer>> make_observer(std::string_view name, std::uint64_t seed);
std::vector<std::string> observer_names();

}  // namespace monoplane::study
