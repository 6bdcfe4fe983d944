#include "analysis/duplicate_sessions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <utility>

namespace monoplane::analysis {
namespace {

using SessionKey = std::pair<std::string, std::int64_t>;

// One input's session with its trials in trial order.
struct Copy {
    SessionKey key;
    std::string uuid;
    std::string participant;
    int session_number = 1;
    std::vector<const TrialRow*> trials;
};

// Sessions in the order their first trial was read; the uuid from the trials, else the session.
std::vector<Copy> copies_of(const Dataset& data) {
    std::vector<Copy> copies;
    std::map<SessionKey, std::size_t> index;
    for (const TrialRow& t : data.trials) {
        const SessionKey key{t.source, t.session_id};
        auto found = index.find(key);
        if (found == index.end()) {
            found = index.emplace(key, copies.size()).first;
            copies.push_back(Copy{key, t.session_uuid, t.participant, t.session_number, {}});
        }
        copies[found->second].trials.push_back(&t);
    }
    for (const SessionRow& s : data.sessions) {
        const auto found = index.find({s.source, s.session_id});
        if (found != index.end() && copies[found->second].uuid.empty())
            copies[found->second].uuid = s.session_uuid;
    }
    for (Copy& c : copies) {
        std::stable_sort(
            c.trials.begin(), c.trials.end(),
            [](const TrialRow* a, const TrialRow* b) { return a->trial_index < b->trial_index; });
    }
    return copies;
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9f s", s);
    return text;
}

std::string yes_no(bool value) {
    return value ? "yes" : "no";
}

// What a copy of a trial must agree on, each as text for the message. Times to the nanosecond:
// a database holds nanoseconds, its CSV export the same as decimal seconds.
const std::vector<std::pair<const char*, std::function<std::string(const TrialRow&)>>>&
trial_fields() {
    static const std::vector<std::pair<const char*, std::function<std::string(const TrialRow&)>>>
        fields = {
            {"practice", [](const TrialRow& t) { return yes_no(t.practice); }},
            {"block", [](const TrialRow& t) { return std::to_string(t.block); }},
            {"scene", [](const TrialRow& t) { return t.scene; }},
            {"m", [](const TrialRow& t) { return std::to_string(t.mono_plane); }},
            {"label 1", [](const TrialRow& t) { return t.label1_mode; }},
            {"label 2", [](const TrialRow& t) { return t.label2_mode; }},
            {"repetition", [](const TrialRow& t) { return std::to_string(t.repetition); }},
            {"decided", [](const TrialRow& t) { return yes_no(t.decided); }},
            {"choice", [](const TrialRow& t) { return t.chosen_mode; }},
            {"valid", [](const TrialRow& t) { return yes_no(t.valid); }},
            {"switches", [](const TrialRow& t) { return std::to_string(t.switches); }},
            {"decision time",
             [](const TrialRow& t) { return seconds(std::round(t.decision_time_s * 1e9) * 1e-9); }},
        };
    return fields;
}

int decided(const Copy& c) {
    return static_cast<int>(std::count_if(c.trials.begin(), c.trials.end(),
                                          [](const TrialRow* t) { return t->decided; }));
}

// How b's trials differ from a's, naming both files; "" when they are the same.
std::string difference(const Copy& a, const Copy& b) {
    const std::string& fa = a.key.first;
    const std::string& fb = b.key.first;
    if (a.trials.size() != b.trials.size())
        return fb + " holds " + std::to_string(b.trials.size()) + " of its trials, " + fa + " " +
               std::to_string(a.trials.size());
    if (decided(a) != decided(b))
        return fb + " has " + std::to_string(decided(b)) + " of the session's " +
               std::to_string(b.trials.size()) + " trials decided, " + fa + " " +
               std::to_string(decided(a)) + " (a copy made while the session ran?)";
    for (std::size_t i = 0; i < a.trials.size(); ++i) {
        const TrialRow& ta = *a.trials[i];
        const TrialRow& tb = *b.trials[i];
        if (ta.trial_index != tb.trial_index)
            return "trial " + std::to_string(ta.trial_index) + " is in " + fa + " only";
        for (const auto& [name, text] : trial_fields()) {
            if (text(ta) != text(tb))
                return "trial " + std::to_string(ta.trial_index) + "'s " + name + " is " +
                       text(tb) + " in " + fb + ", " + text(ta) + " in " + fa;
        }
    }
    return {};
}

std::string session_text(const DuplicateSession& d) {
    return "participant " + d.participant + ", session " + std::to_string(d.session_number) + ", " +
           d.session_uuid;
}

std::string holds_line(const DuplicateSession& d) {
    return d.other.source + " holds the same session as " + d.first.source + " (" +
           session_text(d) + ")";
}

// One line per duplicate (at most ten, then how many more), then `advice`: on the line itself
// when there is only one.
template <class Line>
std::string listed(const std::vector<const DuplicateSession*>& found, Line line,
                   const std::string& advice) {
    constexpr std::size_t kNamed = 10;
    std::string out;
    for (std::size_t i = 0; i < found.size() && i < kNamed; ++i)
        out += (i > 0 ? "\n" : "") + line(*found[i]);
    if (found.size() > kNamed)
        out += "\nand " + std::to_string(found.size() - kNamed) + " more sessions held twice";
    return out + (found.size() == 1 ? "; " : "\n") + advice;
}

void remove_copies(Dataset& data, const std::vector<DuplicateSession>& found) {
    std::set<SessionKey> dropped;
    std::map<std::string, DroppedCopy> by_uuid;
    std::vector<std::string> order;
    for (const DuplicateSession& d : found) {
        dropped.insert({d.other.source, d.other.session_id});
        auto [it, added] = by_uuid.try_emplace(
            d.session_uuid,
            DroppedCopy{d.session_uuid, d.participant, d.session_number, d.first.source, {}});
        if (added) order.push_back(d.session_uuid);
        it->second.dropped.push_back(d.other.source);
    }
    const auto gone = [&](const auto& row) {
        return dropped.contains({row.source, row.session_id});
    };
    std::erase_if(data.trials, gone);
    std::erase_if(data.answers, gone);
    std::erase_if(data.sessions, gone);
    std::erase_if(data.gaze_samples, gone);
    for (const std::string& uuid : order) data.dropped_copies.push_back(by_uuid.at(uuid));
}

}  // namespace

std::vector<DuplicateSession> find_duplicate_sessions(const Dataset& data) {
    const std::vector<Copy> copies = copies_of(data);
    std::map<std::string, std::size_t> first;  // uuid -> the copy read first
    std::vector<DuplicateSession> found;
    for (std::size_t i = 0; i < copies.size(); ++i) {
        const Copy& c = copies[i];
        if (c.uuid.empty()) continue;
        const auto [earlier, is_first] = first.emplace(c.uuid, i);
        if (is_first) continue;
        const Copy& a = copies[earlier->second];
        found.push_back(DuplicateSession{
            .session_uuid = c.uuid,
            .participant = a.participant,
            .session_number = a.session_number,
            .first = {a.key.first, a.key.second},
            .other = {c.key.first, c.key.second},
            .trials = static_cast<int>(a.trials.size()),
            .difference = difference(a, c),
        });
    }
    return found;
}

Result<void> drop_duplicate_sessions(Dataset& data, bool drop, std::string_view drop_option) {
    const std::vector<DuplicateSession> found = find_duplicate_sessions(data);
    if (found.empty()) return Ok{};
    std::vector<const DuplicateSession*> differing, identical;
    for (const DuplicateSession& d : found)
        (d.difference.empty() ? identical : differing).push_back(&d);
    const std::string option(drop_option);
    if (!differing.empty()) {
        return Error{listed(
            differing,
            [](const DuplicateSession& d) {
                return holds_line(d) + ", but the copies differ: " + d.difference;
            },
            "a copy that differs is not counted, not even with " + option +
                ": give only the file that holds the whole session (the original, not a backup "
                "or copy made while the session ran)")};
    }
    if (!drop) {
        return Error{listed(
            identical,
            [](const DuplicateSession& d) {
                return holds_line(d) + ": an identical copy (the same " + std::to_string(d.trials) +
                       " trials, decisions, switches and times)";
            },
            identical.size() == 1
                ? "give " + option + " to count it once, or leave one of the files out"
                : "give " + option +
                      " to count each once, or leave out the files that are copies")};
    }
    remove_copies(data, found);
    return Ok{};
}

}  // namespace monoplane::analysis
