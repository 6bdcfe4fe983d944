#include "analysis/counterbalancing.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace monoplane::analysis {
namespace {

// Inputs that do not say how the protocol orders scenes are taken as the default.
bool uses_latin_square(const SessionRow& s) {
    return s.first_scene_order == "latin-square" || s.first_scene_order.empty();
}

}  // namespace

std::map<std::string, const SessionRow*> first_sessions(const std::vector<SessionRow>& sessions) {
    std::map<std::string, const SessionRow*> first;
    for (const SessionRow& s : sessions) {
        const SessionRow*& best = first[s.participant];
        if (best == nullptr || std::tie(s.session_number, s.started_utc) <
                                   std::tie(best->session_number, best->started_utc))
            best = &s;
    }
    return first;
}

std::optional<int> latin_square_row(const SessionRow& session) {
    const int rows = session.latin_square_rows;
    if (rows <= 0 || !uses_latin_square(session)) return std::nullopt;
    return ((session.participant_number % rows) + rows) % rows;
}

Counterbalancing counterbalancing(const std::vector<SessionRow>& sessions) {
    Counterbalancing c;
    if (sessions.empty()) {
        c.reason = "the inputs hold no session information";
        return c;
    }
    std::vector<const SessionRow*> counted;
    std::set<int> sizes;
    for (const auto& [participant, first] : first_sessions(sessions)) {
        if (!uses_latin_square(*first)) {
            ++c.other_order;
            continue;
        }
        if (first->latin_square_rows <= 0) continue;
        counted.push_back(first);
        sizes.insert(first->latin_square_rows);
        c.order_assumed = c.order_assumed || first->first_scene_order.empty();
    }
    if (counted.empty()) {
        c.reason = c.other_order > 0 ? "the protocol orders the scenes at random or as listed, "
                                       "not by a Latin square"
                                     : "the number of Latin-square rows is not known";
        return c;
    }
    if (sizes.size() > 1) {
        c.reason = "the participants' protocols have Latin squares of " +
                   std::to_string(*sizes.begin()) + " and " + std::to_string(*sizes.rbegin()) +
                   " rows (different scene counts): their rows do not correspond";
        return c;
    }
    c.applicable = true;
    c.latin_square_rows = *sizes.begin();
    c.participants_per_row.assign(static_cast<std::size_t>(c.latin_square_rows), 0);
    for (const SessionRow* first : counted)
        ++c.participants_per_row[static_cast<std::size_t>(*latin_square_row(*first))];
    c.participants = static_cast<int>(counted.size());
    const auto [low, high] =
        std::minmax_element(c.participants_per_row.begin(), c.participants_per_row.end());
    c.balanced = *high - *low <= 1;
    return c;
}

}  // namespace monoplane::analysis
