// The simulated observer at the controls of a live session: it plays its TrialPlan against what is
// on screen, as a participant reacting to what they see: it looks at a label for the planned
// dwell from the frame that showed it, switches, and confirms after the last dwell; a refused
// confirmation makes it look at the other label too. It answers the questionnaire by moving the
// selection to its answer and confirming. The protocol's screens: it reads an instruction page or
// the ready screen for reading_ns() from its first poll, then confirms; on a break it waits for the
// countdown to end, then confirms; on the end screen it does nothing. Used with the simulated
// headset (`study run --headset simulated`) and headless (`--headset none`, on the virtual
// clock), where it drives the same requests a controller would.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/live_session.h"
#include "study/observer.h"

namespace monoplane::study {

class ObserverInput {
  public:
    // trial_error_px: the largest projection error of a trial's hybrid condition (rig).
    ObserverInput(Observer& observer, const Protocol& protocol,
                  std::function<double(const ScheduledTrial&)> trial_error_px);

    // The requests due at time_ns, given what the last presented frame showed. Call once per
    // frame, before the frame is rendered.
    std::vector<LiveInput> poll(const LiveScreen& screen, const LiveProgress& progress,
                                std::int64_t time_ns);

    // How long the observer reads a screen's text: 2 s, plus 40 ms a character (about 250 words
    // a minute, a typical adult's silent reading rate). Deterministic, so tests can count on it.
    static std::int64_t reading_ns(const std::string& text);

  private:
    std::vector<LiveInput> poll_page(const LiveScreen& screen, std::int64_t time_ns);

    Observer& observer_;
    const Protocol& protocol_;
    std::function<double(const ScheduledTrial&)> trial_error_px_;
    int trial_index_ = -1;
    TrialPlan plan_;
    std::size_t dwell_ = 0;      // the dwell being played
    int seen_label_ = 0;         // the visible label the current dwell belongs to
    std::int64_t since_ns_ = 0;  // when that label became visible to the observer
    bool waiting_ = false;       // a switch or confirmation was sent and has not shown yet
    // Which of the two was sent.
    LiveInput sent_ = LiveInput::Switch;
    int question_ = -1;
    int wanted_answer_ = 0;
    // The instructions, ready or break screen being read (its kind and page) and since when.
    std::optional<std::pair<ScreenKind, int>> page_;
    std::int64_t page_since_ns_ = 0;
};

}  // namespace monoplane::study
