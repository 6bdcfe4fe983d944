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

}  // namespace monoplane::window
