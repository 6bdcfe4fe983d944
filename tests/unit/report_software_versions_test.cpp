// The builds of monoplane that ran a report's sessions (issue 46): each session's recorded
// software_version counted once per session, in the order first read, "unknown" for a session
// whose input records none; report.html's "Software versions" table and summary.json's
// "software_versions" say the same.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "analysis/report/inputs_section.h"

namespace monoplane::analysis::report {
namespace {

Dataset sessions_of(const std::vector<std::string>& versions) {
    Dataset data;
    for (std::size_t i = 0; i < versions.size(); ++i) {
        SessionRow& s = data.sessions.emplace_back();
        s.session_id = static_cast<std::int64_t>(i + 1);
        s.participant = "P" + std::to_string(i + 1);
        s.software_version = versions[i];
    }
    return data;
}

TEST(ReportSoftwareVersions, EachBuildIsCountedOncePerSessionInReadingOrder) {
    const InputRecords inputs =
        input_records(sessions_of({"monoplane 0.1.0 (aaaa)", "monoplane 0.1.0 (aaaa)", "",
                                   "monoplane 0.2.0 (bbbb)", "unknown"}));
    ASSERT_EQ(inputs.software_versions.size(), 3u);
    EXPECT_EQ(inputs.software_versions[0].version, "monoplane 0.1.0 (aaaa)");
    EXPECT_EQ(inputs.software_versions[0].sessions, 2);
    EXPECT_EQ(inputs.software_versions[1].version, "unknown");
    EXPECT_EQ(inputs.software_versions[1].sessions, 2);
    EXPECT_EQ(inputs.software_versions[2].version, "monoplane 0.2.0 (bbbb)");
    EXPECT_EQ(inputs.software_versions[2].sessions, 1);

    const std::string html = software_versions_html(inputs);
    EXPECT_NE(html.find("Software versions"), std::string::npos);
    EXPECT_NE(html.find("<code>monoplane 0.2.0 (bbbb)</code>"), std::string::npos) << html;
    EXPECT_NE(html.find("more than one build"), std::string::npos) << html;

    JsonWriter json;
    json.begin_object();
    input_records_json(json, inputs);
    json.end_object();
    const nlohmann::json j = nlohmann::json::parse(json.str());
    ASSERT_EQ(j["software_versions"].size(), 3u);
    EXPECT_EQ(j["software_versions"][1]["version"], "unknown");
    EXPECT_EQ(j["software_versions"][1]["sessions"], 2);
}

TEST(ReportSoftwareVersions, OneBuildSaysSoAndNoSessionsShowNoTable) {
    const InputRecords one = input_records(sessions_of({"monoplane 0.1.0 (aaaa)"}));
    EXPECT_NE(software_versions_html(one).find("Every session ran this build"), std::string::npos);
    EXPECT_EQ(software_versions_html(input_records(Dataset{})), "");
}

TEST(ReportSoftwareVersions, TheVersionIsEscaped) {
    const InputRecords inputs = input_records(sessions_of({"<b>built</b> & co"}));
    const std::string html = software_versions_html(inputs);
    EXPECT_EQ(html.find("<b>built"), std::string::npos) << html;
    EXPECT_NE(html.find("&lt;b&gt;built&lt;/b&gt; &amp; co"), std::string::npos) << html;
}

}  // namespace
}  // namespace monoplane::analysis::report
