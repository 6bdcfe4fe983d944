#include "app/window/view_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace monoplane::window {

const char* phase_name(Phase phase) {
    switch (phase) {
        case Phase::Starting:
            return "starting";
        case Phase::Trial:
            return "trial";
        case Phase::Neutral:
            return "between trials";
        case Phase::Paused:
            return "paused";
        case Phase::Questionnaire:
            return "questionnaire";
        case Phase::Finished:
            return "finished";
        case Phase::Aborted:
            return "aborted";
        case Phase::Instructions:
            return "instructions";
        case Phase::Ready:
            return "ready screen";
        case Phase::Break:
            return "break";
        case Phase::End:
            return "end screen";
    }
    return "unknown";
}

std::string progress_text(const ExperimenterView& view) {
    if (view.trial_number <= 0) return "Before the first trial";
    std::string text =
        "Trial " + std::to_string(view.trial_number) + " of " + std::to_string(view.trial_count);
    if (view.practice) text += " (practice)";
    return text;
}

float progress_fraction(const ExperimenterView& view) {
    if (view.trial_count <= 0) return 0.0f;
    // The current trial is not finished yet, except once the session is over.
    const bool over = view.phase == Phase::Questionnaire || view.phase == Phase::Finished ||
                      view.phase == Phase::End;
    const int done = over ? view.trial_count : std::max(0, view.trial_number - 1);
    return std::clamp(static_cast<float>(done) / static_cast<float>(view.trial_count), 0.0f, 1.0f);
}

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) seconds = 0.0;
    const auto tenths = static_cast<long long>(std::floor(seconds * 10.0));
    const long long total_s = tenths / 10;
    char text[32];
    if (total_s >= 3600) {
        std::snprintf(text, sizeof(text), "%lld:%02lld:%02lld", total_s / 3600, total_s / 60 % 60,
                      total_s % 60);
    } else {
        std::snprintf(text, sizeof(text), "%lld:%02lld.%lld", total_s / 60, total_s % 60,
                      tenths % 10);
    }
    return text;
}

std::vector<std::string> trial_state_lines(const ExperimenterView& view) {
    std::vector<std::string> lines;
    lines.push_back(std::string("Phase: ") + phase_name(view.phase));
    if (view.visible_label == 1 || view.visible_label == 2) {
        lines.push_back("Label " + std::to_string(view.visible_label) + " visible");
    } else {
        lines.push_back("No label visible");
    }
    lines.push_back("Switches: " + std::to_string(view.switches));
    lines.push_back(std::string("Both seen: ") + (view.both_seen ? "yes" : "no"));
    if (view.unblinded) {
        for (int label = 1; label <= 2; ++label) {
            const std::string& mode = view.label_modes[static_cast<std::size_t>(label - 1)];
            lines.push_back("Label " + std::to_string(label) + " = " + (mode.empty() ? "?" : mode));
        }
    } else {
        lines.push_back("Modes hidden (blinded)");
    }
    return lines;
}

bool questionnaire_complete(const ExperimenterView& view) {
    if (view.questionnaire_items.empty()) return false;
    if (view.answers.size() != view.questionnaire_items.size()) return false;
    return std::all_of(view.answers.begin(), view.answers.end(),
                       [&](int answer) { return answer >= 1 && answer <= view.scale_points; });
}

bool shows_page(Phase phase) {
    return phase == Phase::Instructions || phase == Phase::Ready || phase == Phase::Break ||
           phase == Phase::End;
}

std::string page_heading(const ExperimenterView& view) {
    switch (view.phase) {
        case Phase::Instructions:
            return "Instructions, page " + std::to_string(view.page + 1) + " of " +
                   std::to_string(view.page_count) + " (CONFIRM: next, SWITCH: back)";
        case Phase::Ready:
            return "Ready screen: waiting for CONFIRM to begin the data trials";
        case Phase::Break:
            if (!view.break_countdown.empty()) {
                return "Break: " + view.break_countdown + " until CONFIRM continues";
            }
            return "Break over: waiting for CONFIRM to continue";
        case Phase::End:
            return "End screen: the session is complete";
        default:
            return "";
    }
}

std::string note_stored_text(int trial_number) {
    if (trial_number <= 0) return "note stored before the first trial";
    return "note stored at trial " + std::to_string(trial_number);
}

std::string note_refused_text(const std::string& error, const std::string& note) {
    std::string text = "note not stored: " + error;
    // What was typed stays visible, to copy or type again: the field was cleared.
    if (!note.empty()) text += " (the note: \"" + note + "\")";
    return text;
}

}  // namespace monoplane::window
