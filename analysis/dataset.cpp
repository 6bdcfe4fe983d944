#include "analysis/dataset.h"

#include <map>
#include <set>
#include <string_view>
#include <utility>

namespace monoplane::analysis {

void merge(Dataset& into, Dataset from) {
    into.trials.insert(into.trials.end(), std::make_move_iterator(from.trials.begin()),
                       std::make_move_iterator(from.trials.end()));
    into.answers.insert(into.answers.end(), std::make_move_iterator(from.answers.begin()),
                        std::make_move_iterator(from.answers.end()));
    into.sessions.insert(into.sessions.end(), std::make_move_iterator(from.sessions.begin()),
                         std::make_move_iterator(from.sessions.end()));
    into.gaze_samples.insert(into.gaze_samples.end(),
                             std::make_move_iterator(from.gaze_samples.begin()),
                             std::make_move_iterator(from.gaze_samples.end()));
    into.sources.insert(into.sources.end(), std::make_move_iterator(from.sources.begin()),
                        std::make_move_iterator(from.sources.end()));
}

std::string unguarded_cell(std::string text) {
    // The export guards every apostrophe run before a formula character ("'=x" typed is written
    // "''=x"), so removing one apostrophe restores the typed text.
    const std::size_t first = text.find_first_not_of('\'');
    if (first != 0 && first != std::string::npos &&
        std::string_view("=+-@\t\r").find(text[first]) != std::string_view::npos)
        text.erase(0, 1);
    return text;
}

void derive_session_fields(std::vector<TrialRow>& trials) {
    using SessionKey = std::pair<std::string, std::int64_t>;
    struct Session {
        std::set<std::string> modes;  // sorted: "alphabetically first" is *begin()
        std::string reference;
        std::string first_scene;
    };
    std::map<SessionKey, Session> sessions;
    for (const TrialRow& t : trials) {
        Session& s = sessions[{t.source, t.session_id}];
        for (const std::string* mode : {&t.label1_mode, &t.label2_mode})
            if (!mode->empty()) s.modes.insert(*mode);
        if (s.reference.empty()) s.reference = t.reference_mode;
        if (!t.practice && t.block == 0 && s.first_scene.empty()) s.first_scene = t.scene;
    }
    for (auto& [key, s] : sessions) {
        if (s.reference.empty() && !s.modes.empty())
            s.reference = s.modes.contains("stereo") ? "stereo" : *s.modes.begin();
    }
    for (TrialRow& t : trials) {
        const Session& s = sessions.at({t.source, t.session_id});
        t.reference_mode = s.reference;
        t.test_mode.clear();
        for (const std::string& mode : s.modes) {
            if (mode != s.reference) {
                t.test_mode = mode;
                break;
            }
        }
        t.first_scene = s.first_scene;
        t.chose_test = t.decided && !t.test_mode.empty() && t.chosen_mode == t.test_mode;
    }
}

}  // namespace monoplane::analysis
