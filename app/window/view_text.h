// The words the panels show, built without ImGui so that what is (and is not) shown can be
// unit-tested: above all that the modes behind the blind labels appear only when unblinded.
#pragma once

#include <string>
#include <vector>

#include "app/window/experimenter_view.h"

namespace monoplane::window {

const char* phase_name(Phase phase);

// "Trial 3 of 30", "Trial 1 of 30 (practice)", or "Before the first trial".
std::string progress_text(const ExperimenterView& view);

// Fraction of the session done, for the progress bar: trials finished over trial_count.
float progress_fraction(const ExperimenterView& view);

// Seconds as m:ss.s (h:mm:ss past an hour): long sessions stay readable at a glance.
std::string format_duration(double seconds);

// The trial-state panel: phase, the visible label, switches, both seen, and the modes behind the
// labels only when `view.unblinded`.
std::vector<std::string> trial_state_lines(const ExperimenterView& view);

// Whether every questionnaire item has an answer in 1..scale_points (Submit is offered only then).
bool questionnaire_complete(const ExperimenterView& view);

// Whether the participant reads one of the protocol's pages (instructions, ready, break, end).
bool shows_page(Phase phase);

// The line above the mirrored page: which page, and what the participant is asked to do
// ("Instructions, page 2 of 3 ...", "Break: 0:23 until CONFIRM continues"); empty off the pages.
std::string page_heading(const ExperimenterView& view);

// What the note field reports after Enter: "note stored at trial 12" (the trial on screen or the
// last one shown; "before the first trial" before it), or why it was not stored, with the text.
std::string note_stored_text(int trial_number);
std::string note_refused_text(const std::string& error, const std::string& note);

}  // namespace monoplane::window
