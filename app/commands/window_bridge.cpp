#include "app/commands/window_bridge.h"

#include "app/commands/screen_pages.h"
#include "app/headset/text_panel.h"
#include "app/window/view_text.h"

namespace monoplane::app {

using study::ScreenKind;
using window::Phase;

Phase window_phase(const study::LiveScreen& screen) {
    switch (screen.kind) {
        case ScreenKind::Neutral:
            return Phase::Neutral;
        case ScreenKind::Trial:
            return screen.paused ? Phase::Paused : Phase::Trial;
        case ScreenKind::Questionnaire:
            return Phase::Questionnaire;
        case ScreenKind::Finished:
            return Phase::Finished;
        case ScreenKind::Aborted:
            return Phase::Aborted;
        case ScreenKind::Instructions:
            return Phase::Instructions;
        case ScreenKind::Ready:
            return Phase::Ready;
        case ScreenKind::Break:
            return Phase::Break;
        case ScreenKind::End:
            return Phase::End;
    }
    return Phase::Starting;
}

void mirror_page(const study::LiveScreen& screen, window::ExperimenterView& view) {
    const bool page = is_page_screen(screen.kind);
    view.page_text = page && screen.text ? headset::shown_text(*screen.text) : std::string();
    view.page = page ? screen.page : 0;
    view.page_count = page ? screen.page_count : 0;
    view.break_countdown = screen.kind == ScreenKind::Break && screen.break_remaining_ns > 0
                               ? countdown_text(screen.break_remaining_ns)
                               : std::string();
}

std::string note_outcome(const Result<void>& stored, const std::string& text, int trial_number) {
    if (stored.ok()) return window::note_stored_text(trial_number);
    return window::note_refused_text(stored.error().message, text);
}

}  // namespace monoplane::app
