// join_participant_codes() (declared in dataset.h): what a participant code that several inputs
// hold means. Two sites that both number their participants a1, a2, a3 would otherwise be pooled
// into three clusters of two people each, and the participant count halved, without a word; two
// lab PCs that ran one person's sessions would be split into two people if codes were always
// kept apart. Only the user knows which is true, so the default refuses and says how to choose.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "analysis/dataset.h"

namespace monoplane::analysis {
namespace {

// Every code with the sources that hold it, in the order the sources were read.
std::map<std::string, std::vector<std::string>> sources_by_code(const Dataset& data) {
    std::map<std::string, std::set<std::string>> found;
    for (const TrialRow& t : data.trials) found[t.participant].insert(t.source);
    for (const AnswerRow& a : data.answers) found[a.participant].insert(a.source);
    for (const SessionRow& s : data.sessions) found[s.participant].insert(s.source);
    std::vector<std::string> order = data.sources;
    for (const auto& [code, sources] : found) {
        for (const std::string& source : sources)
            if (std::find(order.begin(), order.end(), source) == order.end())
                order.push_back(source);
    }
    std::map<std::string, std::vector<std::string>> out;
    for (const auto& [code, sources] : found) {
        for (const std::string& source : order)
            if (sources.contains(source)) out[code].push_back(source);
    }
    return out;
}

std::string and_joined(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += i + 1 == items.size() ? " and " : ", ";
        out += items[i];
    }
    return out;
}

std::string file_stem(const std::string& source) {
    return std::filesystem::path(source).stem().string();
}

// Names the codes grouped by the files that share them, then the two ways on.
std::string refusal(const std::map<std::vector<std::string>, std::vector<std::string>>& groups,
                    const SharedCodesNames& names) {
    constexpr std::size_t kCodesNamed = 10;
    std::string out = "participant codes found in more than one input:";
    for (const auto& [sources, codes] : groups) {
        std::vector<std::string> named(codes.begin(),
                                       codes.begin() + std::min(codes.size(), kCodesNamed));
        if (codes.size() > kCodesNamed)
            named.push_back(std::to_string(codes.size() - kCodesNamed) + " more");
        out += "\n  " + and_joined(named) + " in " + and_joined(sources);
    }
    const auto& [sources, codes] = *groups.begin();
    const std::string first = file_stem(sources[0]), second = file_stem(sources[1]);
    const std::string example =
        first != second ? first + "/" + codes.front() + ", " + second + "/" + codes.front()
                        : "the files need different names for that";
    // The two ways on in a column: each rule's name, then what it means.
    const std::string same = names.rule(SharedCodes::SamePerson);
    const std::string own = names.rule(SharedCodes::PerDatabase);
    const std::size_t width = std::max(same.size(), own.size()) + 2;
    out += "\n" + names.choose + "\n  " + same + std::string(width - same.size(), ' ') +
           "they are the same people (e.g. sessions run on two lab PCs): each code's sessions "
           "from every file are analysed as one participant"
           "\n  " +
           own + std::string(width - own.size(), ' ') +
           "each file's codes are its own (e.g. two sites): every code is prefixed with its "
           "file's name (" +
           example +
           ")"
           "\n(If one file is an export of another, give only one of them: their sessions would "
           "count twice.)";
    return out;
}

// Every source with its stem, refusing two sources with one stem (their codes would collide).
Result<std::map<std::string, std::string>> prefixes(const std::vector<std::string>& sources,
                                                    const SharedCodesNames& names) {
    const std::string rule = names.rule(SharedCodes::PerDatabase);
    std::map<std::string, std::string> prefix, source_of_stem;
    for (const std::string& source : sources) {
        const std::string stem = file_stem(source);
        if (stem.empty())
            return Error{rule + ": " + source +
                         " has no file name to prefix its "
                         "participant codes with"};
        const auto [seen, added] = source_of_stem.emplace(stem, source);
        if (!added && seen->second != source)
            return Error{rule + " prefixes each participant code with its file's name, but " +
                         seen->second + " and " + source + " are both called '" + stem +
                         "': rename one of them (e.g. site-a.sqlite, site-b.sqlite)"};
        prefix[source] = stem + "/";
    }
    return prefix;
}

}  // namespace

std::string_view shared_codes_name(SharedCodes rule) {
    switch (rule) {
        case SharedCodes::SamePerson:
            return "same-person";
        case SharedCodes::PerDatabase:
            return "per-database";
        case SharedCodes::Refuse:
            break;
    }
    return "refuse";
}

namespace {

// One person's sessions from several files must fit together: sessions numbered apart, one
// participant number (it picked their Latin-square row), one set of variables. Otherwise the
// files hold different people under one code, or one session twice; says which, else "".
std::string same_person_conflicts(const Dataset& data, const std::vector<std::string>& shared) {
    std::string problems;
    for (const std::string& code : shared) {
        std::map<int, std::string> session_source;
        const SessionRow* first = nullptr;
        for (const SessionRow& s : data.sessions) {
            if (s.participant != code) continue;
            const auto [at, fresh] = session_source.emplace(s.session_number, s.source);
            std::string problem;
            if (!fresh && at->second != s.source) {
                problem = "session " + std::to_string(s.session_number) + " in both " + at->second +
                          " and " + s.source;
            } else if (first && first->participant_number != s.participant_number) {
                problem = "participant number " + std::to_string(first->participant_number + 1) +
                          " in " + first->source + " but " +
                          std::to_string(s.participant_number + 1) + " in " + s.source;
            } else if (first && !s.variables.empty() && !first->variables.empty() &&
                       first->variables != s.variables) {
                problem = "different variables in " + first->source + " and " + s.source;
            }
            if (!problem.empty()) problems += "\n  " + code + ": " + problem;
            if (!first) first = &s;
        }
    }
    return problems;
}

}  // namespace

const SharedCodesNames& analysis_codes_names() {
    static const SharedCodesNames names{
        [](SharedCodes rule) { return std::string(shared_codes_name(rule)); },
        "participants from different files are not merged without being told who they are; "
        "choose one of:"};
    return names;
}

Result<void> join_participant_codes(Dataset& data, SharedCodes rule,
                                    const SharedCodesNames& names) {
    const std::map<std::string, std::vector<std::string>> by_code = sources_by_code(data);
    std::map<std::vector<std::string>, std::vector<std::string>> groups;  // sources -> codes
    std::vector<std::string> shared;
    for (const auto& [code, sources] : by_code) {
        if (sources.size() < 2) continue;
        shared.push_back(code);
        groups[sources].push_back(code);
    }
    if (rule == SharedCodes::Refuse && !groups.empty()) return Error{refusal(groups, names)};
    if (rule == SharedCodes::SamePerson) {
        const std::string conflicts = same_person_conflicts(data, shared);
        if (!conflicts.empty()) {
            return Error{names.rule(SharedCodes::SamePerson) +
                         ": these codes do not look like one person each:" + conflicts +
                         "\nIf each file's codes are its own, use " +
                         names.rule(SharedCodes::PerDatabase) +
                         "; if a session was exported twice, give that file once."};
        }
    }
    if (rule == SharedCodes::PerDatabase) {
        std::vector<std::string> sources = data.sources;
        for (const auto& [code, holders] : by_code)
            for (const std::string& source : holders)
                if (std::find(sources.begin(), sources.end(), source) == sources.end())
                    sources.push_back(source);
        Result<std::map<std::string, std::string>> prefix = prefixes(sources, names);
        MONOPLANE_TRY(prefix);
        for (TrialRow& t : data.trials) t.participant = prefix->at(t.source) + t.participant;
        for (AnswerRow& a : data.answers) a.participant = prefix->at(a.source) + a.participant;
        for (SessionRow& s : data.sessions) s.participant = prefix->at(s.source) + s.participant;
        for (GazeSampleRow& g : data.gaze_samples) {
            g.participant = prefix->at(g.source) + g.participant;
        }
    }
    data.codes = rule;
    data.shared_codes = std::move(shared);
    return Ok{};
}

}  // namespace monoplane::analysis
