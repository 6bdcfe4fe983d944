// The analysis never mixes protocol designs nor counts a session twice without being told
// (issue 42): the protocol versions of the sessions with their designs compared by the caller's
// rule (a text change keeps the design, a version only CSV exports hold has a design not known),
// refused unless pooled; a session two inputs hold (by session_uuid) refused, counted once when
// the copies are identical and asked to, refused always when they differ; a CSV export's
// session_uuid and protocol_hash read back; summary.json and the report list what was pooled and
// dropped.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/duplicate_sessions.h"
#include "analysis/protocol_versions.h"
#include "analysis/report/report.h"

namespace monoplane::analysis {
namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A stand-in for the study library's rule: a text is "DESIGN # COMMENT"; the design is what
// comes before " #", and "unreadable" does not read.
std::optional<std::vector<std::string>> compare_texts(const std::string& a, const std::string& b) {
    if (a == "unreadable" || b == "unreadable") return std::nullopt;
    const std::string da = a.substr(0, a.find(" #"));
    const std::string db = b.substr(0, b.find(" #"));
    if (da == db) return std::vector<std::string>{};
    return std::vector<std::string>{"design: " + da + " -> " + db};
}

SessionRow session(const std::string& source, std::int64_t id, const std::string& code,
                   const std::string& hash, const std::string& text) {
    SessionRow s;
    s.source = source;
    s.session_id = id;
    s.participant = code;
    s.protocol = "fink";
    s.protocol_hash = hash;
    s.protocol_text = text;
    s.session_uuid = "uuid-" + code;
    return s;
}

TEST(ProtocolVersions, OneVersionIsListedWithItsSessionsAndFiles) {
    Dataset data;
    data.sessions = {session("a.sqlite", 1, "k1", "fnv1a64:1", "planes 3 8"),
                     session("a.sqlite", 2, "k2", "fnv1a64:1", "planes 3 8"),
                     session("b.sqlite", 1, "k3", "fnv1a64:1", "planes 3 8")};
    ASSERT_TRUE(check_protocol_versions(data, compare_texts, false, "--pool-protocols"));
    ASSERT_EQ(data.protocol_versions.size(), 1u);
    const ProtocolVersion& v = data.protocol_versions[0];
    EXPECT_EQ(v.name, "fink");
    EXPECT_EQ(v.hash, "fnv1a64:1");
    EXPECT_EQ(v.sessions, 3);
    EXPECT_EQ(v.sources, (std::vector<std::string>{"a.sqlite", "b.sqlite"}));
    EXPECT_EQ(v.design, 1);
    EXPECT_FALSE(data.pooled_protocols);
}

TEST(ProtocolVersions, AChangeOfTextOnlyIsTheSameDesignAndNotRefused) {
    Dataset data;
    data.sessions = {session("a.sqlite", 1, "k1", "fnv1a64:1", "planes 3 8 # first"),
                     session("a.sqlite", 2, "k2", "fnv1a64:2", "planes 3 8 # wording")};
    ASSERT_TRUE(check_protocol_versions(data, compare_texts, false, "--pool-protocols"));
    ASSERT_EQ(data.protocol_versions.size(), 2u);
    EXPECT_EQ(data.protocol_versions[0].design, 1);
    EXPECT_EQ(data.protocol_versions[1].design, 1);
    EXPECT_TRUE(data.protocol_versions[1].design_differences.empty());
    EXPECT_FALSE(data.pooled_protocols);
}

TEST(ProtocolVersions, DesignsThatDifferAreRefusedNamingEveryVersionUnlessPooled) {
    Dataset data;
    data.sessions = {session("a.sqlite", 1, "k1", "fnv1a64:1", "planes 3 8"),
                     session("b.sqlite", 1, "k2", "fnv1a64:2", "planes 2 6"),
                     session("b.sqlite", 2, "k3", "fnv1a64:3", "planes 3 8 # comment")};
    Result<void> refused = check_protocol_versions(data, compare_texts, false, "--pool-it");
    ASSERT_FALSE(refused);
    const std::string& m = refused.error().message;
    EXPECT_TRUE(contains(m, "different designs")) << m;
    EXPECT_TRUE(contains(m, "fink fnv1a64:1, design 1: 1 session in a.sqlite")) << m;
    EXPECT_TRUE(contains(m,
                         "fink fnv1a64:2, design 2 (design: planes 3 8 -> planes 2 6): 1 "
                         "session in b.sqlite"))
        << m;
    EXPECT_TRUE(contains(m, "fink fnv1a64:3, design 1: 1 session in b.sqlite")) << m;
    EXPECT_TRUE(contains(m, "Give --pool-it to pool them")) << m;
    EXPECT_FALSE(contains(m, "CSV")) << "every design is known: " << m;

    ASSERT_TRUE(check_protocol_versions(data, compare_texts, true, "--pool-it"));
    EXPECT_TRUE(data.pooled_protocols);
    ASSERT_EQ(data.protocol_versions.size(), 3u);
    EXPECT_EQ(data.protocol_versions[1].design, 2);
    EXPECT_EQ(data.protocol_versions[1].design_differences,
              (std::vector<std::string>{"design: planes 3 8 -> planes 2 6"}));
}

TEST(ProtocolVersions, ACsvSessionOfAVersionADatabaseHoldsHasItsDesign) {
    Dataset data;
    data.sessions = {session("a.sqlite", 1, "k1", "fnv1a64:1", "planes 3 8"),
                     session("b.csv", 1, "k2", "fnv1a64:1", "")};
    ASSERT_TRUE(check_protocol_versions(data, compare_texts, false, "--pool-protocols"));
    ASSERT_EQ(data.protocol_versions.size(), 1u);
    EXPECT_EQ(data.protocol_versions[0].design, 1);
    EXPECT_EQ(data.protocol_versions[0].sessions, 2);
}

// A CSV export records the hash, not the text: two hashes may be two designs.
TEST(ProtocolVersions, VersionsOnlyCsvExportsHoldHaveDesignsNotKnownAndAreRefused) {
    Dataset one;
    one.sessions = {session("a.csv", 1, "k1", "fnv1a64:1", ""),
                    session("a.csv", 2, "k2", "fnv1a64:1", "")};
    ASSERT_TRUE(check_protocol_versions(one, compare_texts, false, "--pool-protocols"));
    EXPECT_EQ(one.protocol_versions.at(0).design, 0);  // one version: nothing to pool

    Dataset two;
    two.sessions = {session("a.sqlite", 1, "k1", "fnv1a64:1", "planes 3 8"),
                    session("b.csv", 1, "k2", "fnv1a64:2", "")};
    Result<void> refused = check_protocol_versions(two, compare_texts, false, "--pool-protocols");
    ASSERT_FALSE(refused);
    const std::string& m = refused.error().message;
    EXPECT_TRUE(contains(m, "fink fnv1a64:2, design not known: 1 session in b.csv")) << m;
    EXPECT_TRUE(contains(m, "give the study databases instead")) << m;
    ASSERT_TRUE(check_protocol_versions(two, compare_texts, true, "--pool-protocols"));
    EXPECT_TRUE(two.pooled_protocols);
}

TEST(ProtocolVersions, AnUnreadableTextOrAMissingHashIsADesignNotKnown) {
    Dataset data;
    data.sessions = {session("a.sqlite", 1, "k1", "fnv1a64:1", "unreadable"),
                     session("old.csv", 1, "k2", "", ""), session("old.csv", 2, "k3", "", "")};
    const std::vector<ProtocolVersion> versions = list_protocol_versions(data, compare_texts);
    ASSERT_EQ(versions.size(), 2u);  // the export without hashes: one version by its name
    EXPECT_EQ(versions[0].design, 0);
    EXPECT_EQ(versions[1].hash, "");
    EXPECT_EQ(versions[1].sessions, 2);
    EXPECT_TRUE(designs_differ(versions));
}

TrialRow trial(const std::string& source, std::int64_t session, int index, bool decided,
               int switches = 2, double time = 1.5) {
    TrialRow t;
    t.source = source;
    t.session_id = session;
    t.session_uuid = "0b6e2c4a-0000-4000-8000-00000000000" + std::to_string(session);
    t.participant = "k" + std::to_string(session);
    t.trial_index = index;
    t.block = 0;
    t.scene = "beams";
    t.mono_plane = 3.0;
    t.label1_mode = "stereo";
    t.label2_mode = "hybrid";
    t.decided = decided;
    if (decided) {
        t.valid = true;
        t.chosen_mode = "hybrid";
        t.switches = switches;
        t.decision_time_s = time;
    }
    return t;
}

// site-a.sqlite holds k1 and k2; `copy` holds k1's session as `decided` says, and k3.
Dataset original_and_copy(const std::string& copy, std::vector<bool> decided) {
    Dataset d;
    d.sources = {"site-a.sqlite", copy};
    for (int i = 0; i < 3; ++i) {
        d.trials.push_back(trial("site-a.sqlite", 1, i, true));
        d.trials.push_back(trial("site-a.sqlite", 2, i, true));
    }
    for (int i = 0; i < 3; ++i) d.trials.push_back(trial(copy, 1, i, decided[i]));
    d.trials.push_back(trial(copy, 3, 0, true));
    d.answers.push_back({"site-a.sqlite", 1, "k1", 0, "comfortable", 5, 7});
    d.answers.push_back({copy, 1, "k1", 0, "comfortable", 5, 7});
    for (const auto& [source, id] : std::vector<std::pair<std::string, std::int64_t>>{
             {"site-a.sqlite", 1}, {"site-a.sqlite", 2}, {copy, 1}, {copy, 3}}) {
        SessionRow s;
        s.source = source;
        s.session_id = id;
        s.participant = "k" + std::to_string(id);
        s.protocol = "fink";
        d.sessions.push_back(s);
    }
    return d;
}

TEST(DuplicateSessions, AnIdenticalCopyIsRefusedNamingTheFilesAndTheSession) {
    Dataset data = original_and_copy("copy.sqlite", {true, true, true});
    Result<void> refused = drop_duplicate_sessions(data, false, "--drop-duplicates");
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().message,
              "copy.sqlite holds the same session as site-a.sqlite (participant k1, session 1, "
              "0b6e2c4a-0000-4000-8000-000000000001): an identical copy (the same 3 trials, "
              "decisions, switches and times); give --drop-duplicates to count it once, or leave "
              "one of the files out");
    EXPECT_EQ(data.trials.size(), 10u) << "a refusal changes nothing";
}

TEST(DuplicateSessions, DroppingKeepsTheCopyReadFirstAndEverythingElse) {
    Dataset data = original_and_copy("copy.sqlite", {true, true, true});
    ASSERT_TRUE(drop_duplicate_sessions(data, true, "--drop-duplicates"));
    EXPECT_EQ(data.trials.size(), 7u);  // k1 and k2 from site a, k3 from the copy
    for (const TrialRow& t : data.trials)
        EXPECT_FALSE(t.source == "copy.sqlite" && t.session_id == 1);
    ASSERT_EQ(data.answers.size(), 1u);
    EXPECT_EQ(data.answers[0].source, "site-a.sqlite");
    EXPECT_EQ(data.sessions.size(), 3u);
    ASSERT_EQ(data.dropped_copies.size(), 1u);
    const DroppedCopy& d = data.dropped_copies[0];
    EXPECT_EQ(d.participant, "k1");
    EXPECT_EQ(d.kept, "site-a.sqlite");
    EXPECT_EQ(d.dropped, (std::vector<std::string>{"copy.sqlite"}));
}

// Eye gaze samples (issue 45) belong to their session: merge() carries them, a dropped copy's go
// with it (else the gaze density would count that session twice), and per-database codes rename
// them as they rename the trials.
TEST(DuplicateSessions, GazeSamplesGoWithTheirSession) {
    const auto sample = [](const std::string& source, std::int64_t session) {
        GazeSampleRow g;
        g.source = source;
        g.session_id = session;
        g.participant = "k" + std::to_string(session);
        g.scene = "beams";
        return g;
    };
    Dataset data = original_and_copy("copy.sqlite", {true, true, true});
    Dataset more;
    more.gaze_samples = {sample("site-a.sqlite", 1), sample("site-a.sqlite", 1),
                         sample("copy.sqlite", 1), sample("copy.sqlite", 3)};
    merge(data, more);
    ASSERT_EQ(data.gaze_samples.size(), 4u);
    ASSERT_TRUE(drop_duplicate_sessions(data, true, "--drop-duplicates"));
    ASSERT_EQ(data.gaze_samples.size(), 3u);
    for (const GazeSampleRow& g : data.gaze_samples)
        EXPECT_FALSE(g.source == "copy.sqlite" && g.session_id == 1);
    ASSERT_TRUE(join_participant_codes(data, SharedCodes::PerDatabase));
    EXPECT_EQ(data.gaze_samples[0].participant, data.trials[0].participant);
    EXPECT_NE(data.gaze_samples[0].participant, "k1");
}

TEST(DuplicateSessions, ABackupTakenDuringTheSessionIsRefusedAlsoWhenDropping) {
    Dataset data = original_and_copy("backup.sqlite", {true, false, false});
    for (bool drop : {false, true}) {
        Result<void> refused = drop_duplicate_sessions(data, drop, "--drop-duplicates");
        ASSERT_FALSE(refused);
        const std::string& m = refused.error().message;
        EXPECT_TRUE(contains(m,
                             "backup.sqlite holds the same session as site-a.sqlite "
                             "(participant k1, session 1, "))
            << m;
        EXPECT_TRUE(contains(m,
                             "the copies differ: backup.sqlite has 1 of the session's 3 "
                             "trials decided, site-a.sqlite 3"))
            << m;
        EXPECT_TRUE(contains(m, "not even with --drop-duplicates")) << m;
    }
    EXPECT_TRUE(data.dropped_copies.empty());
}

TEST(DuplicateSessions, CopiesDifferInAnyDecisionSwitchOrTimeButAgreeToTheNanosecond) {
    Dataset switches = original_and_copy("b.csv", {true, true, true});
    switches.trials[6 + 1].switches = 5;  // the copy's trial 1
    Result<void> refused = drop_duplicate_sessions(switches, true, "--drop-duplicates");
    ASSERT_FALSE(refused);
    EXPECT_TRUE(
        contains(refused.error().message, "trial 1's switches is 5 in b.csv, 2 in site-a.sqlite"))
        << refused.error().message;

    Dataset choice = original_and_copy("b.csv", {true, true, true});
    choice.trials[6 + 2].chosen_mode = "stereo";
    ASSERT_FALSE(drop_duplicate_sessions(choice, true, "--drop-duplicates"));

    // A database holds 1600000001 ns, its CSV export "1.600000001": the same time.
    Dataset times = original_and_copy("b.csv", {true, true, true});
    for (TrialRow& t : times.trials)
        t.decision_time_s = t.source == "b.csv" ? 1.600000001 : 1600000001 * 1e-9;
    EXPECT_TRUE(drop_duplicate_sessions(times, true, "--drop-duplicates"));
    times = original_and_copy("b.csv", {true, true, true});
    times.trials[6].decision_time_s = 1.500000001;
    ASSERT_FALSE(drop_duplicate_sessions(times, true, "--drop-duplicates"));
}

TEST(DuplicateSessions, SessionsWithoutAnIdAreNotCompared) {
    Dataset data = original_and_copy("old.csv", {true, true, true});
    for (TrialRow& t : data.trials)
        if (t.source == "old.csv") t.session_uuid.clear();
    EXPECT_TRUE(find_duplicate_sessions(data).empty());
}

TEST(DuplicateSessions, SeveralCopiesAreListedOnePerLine) {
    Dataset data = original_and_copy("copy.sqlite", {true, true, true});
    for (int i = 0; i < 3; ++i) data.trials.push_back(trial("copy.sqlite", 2, i, true));
    Result<void> refused = drop_duplicate_sessions(data, false, "--drop-duplicates");
    ASSERT_FALSE(refused);
    const std::string& m = refused.error().message;
    EXPECT_TRUE(contains(m, "(participant k1, session 1, ")) << m;
    EXPECT_TRUE(contains(m,
                         "\ncopy.sqlite holds the same session as site-a.sqlite (participant "
                         "k2, session 1, "))
        << m;
    EXPECT_TRUE(contains(m, "\ngive --drop-duplicates to count each once")) << m;
}

TEST(ExportCsv, ReadsTheSessionIdAndTheProtocolHash) {
    const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "uuid.csv";
    std::ofstream(path) << "participant,session,trial_index,block,scene,mono_plane,label1_mode,"
                           "choice,chosen_mode,valid,switches,time_label1_s,time_label2_s,"
                           "decision_time_s,practice,decided,label2_mode,participant_index,"
                           "protocol,protocol_hash,session_id,repetition,participant_number,"
                           "session_uuid\n"
                           "k9,1,0,0,beams,3,stereo,2,hybrid,TRUE,1,0.5,0.5,1.5,FALSE,TRUE,"
                           "hybrid,0,fink,fnv1a64:00000000000000ab,4,1,1,"
                           "0b6e2c4a-1111-4000-8000-000000000001\n";
    Result<Dataset> data = read_export_csv(path);
    ASSERT_TRUE(data) << data.error().message;
    EXPECT_EQ(data->trials.at(0).session_uuid, "0b6e2c4a-1111-4000-8000-000000000001");
    ASSERT_EQ(data->sessions.size(), 1u);
    EXPECT_EQ(data->sessions[0].session_uuid, "0b6e2c4a-1111-4000-8000-000000000001");
    EXPECT_EQ(data->sessions[0].protocol_hash, "fnv1a64:00000000000000ab");
    EXPECT_TRUE(data->sessions[0].protocol_text.empty());
}

TEST(IntegrityReport, SummaryAndPageListTheVersionsPooledAndTheCopiesDropped) {
    Dataset data = original_and_copy("copy.sqlite", {true, true, true});
    ASSERT_TRUE(drop_duplicate_sessions(data, true, "--drop-duplicates"));
    data.sessions[0].protocol_hash = "fnv1a64:1";
    data.sessions[0].protocol_text = "planes 3 8";
    data.sessions[1].protocol = "<b>other</b>";
    data.sessions[1].protocol_hash = "fnv1a64:2";
    data.sessions[1].protocol_text = "planes 2 6";
    data.sessions[2].protocol_hash = "";
    derive_session_fields(data.trials);
    ASSERT_TRUE(check_protocol_versions(data, compare_texts, true, "--pool-protocols"));
    const report::AnalysisResults results = report::analyse(data);

    const nlohmann::json summary = nlohmann::json::parse(report::summary_json(results));
    ASSERT_EQ(summary.at("protocol_versions").size(), 3u);
    const nlohmann::json& second = summary["protocol_versions"][1];
    EXPECT_EQ(second.at("name"), "<b>other</b>");
    EXPECT_EQ(second.at("hash"), "fnv1a64:2");
    EXPECT_EQ(second.at("sessions"), 1);
    EXPECT_EQ(second.at("design"), 2);
    EXPECT_EQ(second.at("design_differences")[0], "design: planes 3 8 -> planes 2 6");
    EXPECT_TRUE(summary["protocol_versions"][2].at("hash").is_null());
    EXPECT_TRUE(summary["protocol_versions"][2].at("design").is_null());
    EXPECT_EQ(summary.at("pooled_protocols"), true);
    ASSERT_EQ(summary.at("dropped_duplicates").size(), 1u);
    EXPECT_EQ(summary["dropped_duplicates"][0].at("kept"), "site-a.sqlite");
    EXPECT_EQ(summary["dropped_duplicates"][0].at("dropped")[0], "copy.sqlite");
    EXPECT_EQ(summary["dropped_duplicates"][0].at("session"), 1);

    const std::string html = report::report_html(results, report::report_figures(results));
    EXPECT_TRUE(contains(html, "<h3 id=\"protocol-versions\">Protocol versions</h3>"));
    EXPECT_TRUE(contains(html, "<b>Pooled on request</b>"));
    EXPECT_TRUE(contains(html, "&lt;b&gt;other&lt;/b&gt;"));
    EXPECT_FALSE(contains(html, "<b>other</b>"));
    EXPECT_TRUE(contains(html, "<h3 id=\"duplicates\">Sessions held by more than one file</h3>"));
}

TEST(IntegrityReport, OneVersionAndNoCopiesSayJustThat) {
    Dataset data = original_and_copy("b.sqlite", {true, true, true});
    for (TrialRow& t : data.trials) t.session_uuid = t.source + std::to_string(t.session_id);
    for (SessionRow& s : data.sessions) s.protocol_hash = "fnv1a64:1";
    ASSERT_TRUE(drop_duplicate_sessions(data, false, "--drop-duplicates"));
    ASSERT_TRUE(check_protocol_versions(data, compare_texts, false, "--pool-protocols"));
    const report::AnalysisResults results = report::analyse(data);
    const nlohmann::json summary = nlohmann::json::parse(report::summary_json(results));
    EXPECT_EQ(summary.at("protocol_versions").size(), 1u);
    EXPECT_EQ(summary.at("pooled_protocols"), false);
    EXPECT_TRUE(summary.at("dropped_duplicates").empty());
    const std::string html = report::report_html(results, report::report_figures(results));
    EXPECT_TRUE(contains(html, "Every session ran this one version."));
    EXPECT_FALSE(contains(html, "id=\"duplicates\""));
}

}  // namespace
}  // namespace monoplane::analysis
