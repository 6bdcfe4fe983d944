#include "analysis/protocol_versions.h"

#include <algorithm>
#include <set>

namespace monoplane::analysis {
namespace {

// The session's version: by hash, or by name where the input did not record the hash.
bool runs_version(const SessionRow& s, const ProtocolVersion& v) {
    if (s.protocol_hash.empty()) return v.hash.empty() && v.name == s.protocol;
    return v.hash == s.protocol_hash;
}

// Numbers the designs: a version joins the first earlier design whose representative (the
// version that first had it) has the same design, or starts the next one. A version without a
// readable text keeps design 0.
void number_designs(std::vector<ProtocolVersion>& versions, const std::vector<std::string>& texts,
                    const DesignComparison& compare) {
    std::vector<std::size_t> representatives;  // [d - 1]: the first version of design d
    for (std::size_t i = 0; i < versions.size(); ++i) {
        if (texts[i].empty() || !compare(texts[i], texts[i])) continue;
        for (std::size_t d = 0; d < representatives.size() && versions[i].design == 0; ++d) {
            const auto differences = compare(texts[representatives[d]], texts[i]);
            if (differences && differences->empty()) versions[i].design = static_cast<int>(d) + 1;
        }
        if (versions[i].design != 0) continue;
        representatives.push_back(i);
        versions[i].design = static_cast<int>(representatives.size());
        if (representatives.size() > 1) {
            versions[i].design_differences = compare(texts[representatives.front()], texts[i])
                                                 .value_or(std::vector<std::string>{});
        }
    }
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

// "  outputs fnv1a64:0123456789abcdef, design 2 (mono_planes: 3, 8 -> 2, 6): 1 session in a.sqlite"
std::string version_line(const ProtocolVersion& v) {
    std::string line = "  " + v.name + " " + (v.hash.empty() ? "(hash not recorded)" : v.hash);
    if (v.design == 0) {
        line += ", design not known";
    } else {
        line += ", design " + std::to_string(v.design);
        if (!v.design_differences.empty()) line += " (" + joined(v.design_differences, "; ") + ")";
    }
    return line + ": " + std::to_string(v.sessions) + (v.sessions == 1 ? " session" : " sessions") +
           " in " + joined(v.sources, ", ");
}

}  // namespace

std::vector<ProtocolVersion> list_protocol_versions(const Dataset& data,
                                                    const DesignComparison& compare) {
    std::vector<ProtocolVersion> versions;
    std::vector<std::string> texts;  // per version: the text of the first session holding it
    for (const SessionRow& s : data.sessions) {
        auto found = std::find_if(versions.begin(), versions.end(),
                                  [&](const ProtocolVersion& v) { return runs_version(s, v); });
        if (found == versions.end()) {
            versions.push_back(ProtocolVersion{.name = s.protocol, .hash = s.protocol_hash});
            texts.emplace_back();
            found = std::prev(versions.end());
        }
        const auto i = static_cast<std::size_t>(found - versions.begin());
        ++found->sessions;
        if (std::find(found->sources.begin(), found->sources.end(), s.source) ==
            found->sources.end())
            found->sources.push_back(s.source);
        if (texts[i].empty()) texts[i] = s.protocol_text;
    }
    number_designs(versions, texts, compare);
    return versions;
}

bool designs_differ(const std::vector<ProtocolVersion>& versions) {
    std::set<int> designs;
    bool unknown = false;
    for (const ProtocolVersion& v : versions) {
        if (v.design == 0)
            unknown = true;
        else
            designs.insert(v.design);
    }
    return designs.size() > 1 || (unknown && versions.size() > 1);
}

Result<void> check_protocol_versions(Dataset& data, const DesignComparison& compare, bool pool,
                                     std::string_view pool_option) {
    data.protocol_versions = list_protocol_versions(data, compare);
    data.pooled_protocols = false;
    if (!designs_differ(data.protocol_versions)) return Ok{};
    if (pool) {
        data.pooled_protocols = true;
        return Ok{};
    }
    std::string message =
        "the sessions ran protocol versions of different designs, which are pooled only when "
        "asked for:";
    bool unknown = false;
    for (const ProtocolVersion& v : data.protocol_versions) {
        message += "\n" + version_line(v);
        unknown = unknown || v.design == 0;
    }
    if (unknown) {
        message +=
            "\nA design is not known where no input holds the protocol's text (a CSV export "
            "records its hash only) or the text no longer reads, so it may differ from the "
            "others; give the study databases instead of their exports and the designs are "
            "compared.";
    }
    message += "\nGive " + std::string(pool_option) +
               " to pool them (the report then lists the versions it pooled), or analyse each "
               "design on its own from files that hold only its sessions.";
    return Error{message};
}

}  // namespace monoplane::analysis
