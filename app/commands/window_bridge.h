// Between the session and the experimenter window: the window's phase for a screen, the page the
// participant reads mirrored into the window's view, and what the window's note field reports.
// Pure, so that what the window is told can be tested without a window.
#pragma once

#include <string>

#include "app/window/experimenter_view.h"
#include "common/result.h"
#include "study/live_session.h"

namespace monoplane::app {

window::Phase window_phase(const study::LiveScreen& screen);

// On a page (instructions, ready, break, end): its text as the headset draws it, the page
// number and count, and the break's countdown as the headset shows it. Off the pages: cleared.
void mirror_page(const study::LiveScreen& screen, window::ExperimenterView& view);

// The note field's report of LiveSession::note's result for `text`, typed while trial
// `trial_number` (1-based, 0: before the first) was on screen or the last shown.
std::string note_outcome(const Result<void>& stored, const std::string& text, int trial_number);

}  // namespace monoplane::app
