#include "analysis/report/inputs_section.h"

#include <algorithm>

#include "analysis/report/html_format.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

std::string code_list(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items)
        out += (out.empty() ? "" : ", ") + ("<code>" + xml_escaped(item) + "</code>");
    return out;
}

std::string escaped_list(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : "; ") + xml_escaped(item);
    return out;
}

// Why the versions could be pooled, or that they were pooled because the user asked.
std::string pooling_note(const InputRecords& inputs) {
    const std::vector<ProtocolVersion>& versions = inputs.protocol_versions;
    if (versions.size() == 1) return "<p class=\"note\">Every session ran this one version.</p>\n";
    if (!inputs.pooled_protocols) {
        return "<p class=\"note\">The versions differ in their text only (comments, "
               "instructions, wording): one design, so their sessions are one experiment.</p>\n";
    }
    return "<p class=\"warn\"><b>Pooled on request</b> (<code>--pool-protocols</code>): these " +
           std::to_string(versions.size()) +
           " versions are of different designs, or of a design not known (a CSV export records "
           "its protocol's hash, not its text), and every statistic below treats their sessions "
           "as one experiment.</p>\n";
}

}  // namespace

InputRecords input_records(const Dataset& data) {
    InputRecords inputs{data.protocol_versions, data.pooled_protocols, data.dropped_copies, {}};
    for (const SessionRow& session : data.sessions) {
        const std::string version =
            session.software_version.empty() ? "unknown" : session.software_version;
        auto found = std::find_if(inputs.software_versions.begin(), inputs.software_versions.end(),
                                  [&](const SoftwareVersion& v) { return v.version == version; });
        if (found == inputs.software_versions.end()) {
            inputs.software_versions.push_back({version, 1});
        } else {
            ++found->sessions;
        }
    }
    return inputs;
}

std::string software_versions_html(const InputRecords& inputs) {
    if (inputs.software_versions.empty()) return {};
    Table t;
    t.header = {"monoplane", "sessions"};
    t.numeric = {false, true};
    for (const SoftwareVersion& v : inputs.software_versions) {
        t.rows.push_back(
            {"<code>" + xml_escaped(v.version) + "</code>", std::to_string(v.sessions)});
    }
    const std::string note =
        inputs.software_versions.size() == 1
            ? "<p class=\"note\">Every session ran this build.</p>\n"
            : "<p class=\"note\">The sessions ran on more than one build of monoplane "
              "(<code>monoplane --version</code>; \"unknown\": an export made before builds "
              "were recorded).</p>\n";
    return "<h3 id=\"software-versions\">Software versions</h3>\n" + t.html() + note;
}

std::string protocol_versions_html(const InputRecords& inputs) {
    if (inputs.protocol_versions.empty()) return {};
    Table t;
    t.header = {"protocol", "hash", "design", "differs from design 1 in", "sessions", "files"};
    t.numeric = {false, false, true, false, true, false};
    for (const ProtocolVersion& v : inputs.protocol_versions) {
        t.rows.push_back(
            {xml_escaped(v.name),
             v.hash.empty() ? "not recorded" : "<code>" + xml_escaped(v.hash) + "</code>",
             v.design == 0 ? "not known" : std::to_string(v.design),
             v.design_differences.empty() ? "&ndash;" : escaped_list(v.design_differences),
             std::to_string(v.sessions), code_list(v.sources)});
    }
    return "<h3 id=\"protocol-versions\">Protocol versions</h3>\n" + t.html() +
           pooling_note(inputs);
}

std::string dropped_copies_html(const InputRecords& inputs) {
    if (inputs.dropped_copies.empty()) return {};
    Table t;
    t.header = {"participant", "session", "session id", "counted from", "copies left out"};
    t.numeric = {false, true, false, false, false};
    for (const DroppedCopy& d : inputs.dropped_copies) {
        t.rows.push_back({xml_escaped(d.participant), std::to_string(d.session_number),
                          "<code>" + xml_escaped(d.session_uuid) + "</code>", code_list({d.kept}),
                          code_list(d.dropped)});
    }
    return "<h3 id=\"duplicates\">Sessions held by more than one file</h3>\n"
           "<p>These sessions were found in more than one input file (a copy, a backup), with "
           "the same trials, decisions, switches and times; each is counted once "
           "(<code>--drop-duplicates</code>), from the file read first.</p>\n" +
           t.html();
}

void input_records_json(JsonWriter& json, const InputRecords& inputs) {
    json.begin_array("protocol_versions");
    for (const ProtocolVersion& v : inputs.protocol_versions) {
        json.begin_object().value("name", v.name);
        if (v.hash.empty()) {
            json.null("hash");
        } else {
            json.value("hash", v.hash);
        }
        json.value("sessions", v.sessions).begin_array("sources");
        for (const std::string& source : v.sources) json.value("", source);
        json.end_array();
        if (v.design == 0) {
            json.null("design");
        } else {
            json.value("design", v.design);
        }
        json.begin_array("design_differences");
        for (const std::string& line : v.design_differences) json.value("", line);
        json.end_array().end_object();
    }
    json.end_array();
    json.value("pooled_protocols", inputs.pooled_protocols);
    json.begin_array("dropped_duplicates");
    for (const DroppedCopy& d : inputs.dropped_copies) {
        json.begin_object()
            .value("session_uuid", d.session_uuid)
            .value("participant", d.participant)
            .value("session", d.session_number)
            .value("kept", d.kept)
            .begin_array("dropped");
        for (const std::string& source : d.dropped) json.value("", source);
        json.end_array().end_object();
    }
    json.end_array();
    json.begin_array("software_versions");
    for (const SoftwareVersion& v : inputs.software_versions) {
        json.begin_object().value("version", v.version).value("sessions", v.sessions).end_object();
    }
    json.end_array();
}

}  // namespace monoplane::analysis::report
