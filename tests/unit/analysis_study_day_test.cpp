// A study day in the analysis (issue 30): participant codes that several inputs hold
// (join_participant_codes), the Latin square's rows over participants (counterbalancing), a CSV
// export's session, repetition, participant-number and variable columns with its guard against
// spreadsheet formulas, and repetitions and several sessions per participant in the fits.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/counterbalancing.h"
#include "analysis/dataset.h"
#include "analysis/logistic_regression.h"
#include "analysis/psychometric_fits.h"

namespace monoplane::analysis {
namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TrialRow trial(const std::string& source, std::int64_t session, const std::string& participant,
               int index, double m, bool chose_test) {
    TrialRow t;
    t.source = source;
    t.session_id = session;
    t.participant = participant;
    t.trial_index = index;
    t.block = 0;
    t.scene = "beams";
    t.mono_plane = m;
    t.label1_mode = "stereo";
    t.label2_mode = "hybrid";
    t.reference_mode = "stereo";
    t.decided = true;
    t.valid = true;
    t.chosen_mode = chose_test ? "hybrid" : "stereo";
    return t;
}

SessionRow session(const std::string& source, std::int64_t id, const std::string& participant,
                   int number, int participant_number, int rows = 4) {
    SessionRow s;
    s.source = source;
    s.session_id = id;
    s.participant = participant;
    s.session_number = number;
    s.participant_number = participant_number;
    s.first_scene_order = "latin-square";
    s.scenes = rows;
    s.latin_square_rows = rows;
    return s;
}

// Two sites that both code their participants a1, a2 (and b3 at one site only).
Dataset two_sites() {
    Dataset d;
    d.sources = {"data/site-a.sqlite", "other/site-b.sqlite"};
    int id = 0;
    for (const std::string& source : d.sources) {
        for (const char* code : {"a1", "a2"}) {
            ++id;
            d.trials.push_back(trial(source, id, code, 0, 3.0, true));
            d.sessions.push_back(session(source, id, code, 1, id - 1));
        }
    }
    d.trials.push_back(trial(d.sources[0], 9, "b3", 0, 3.0, false));
    d.sessions.push_back(session(d.sources[0], 9, "b3", 1, 2));
    d.answers.push_back({d.sources[1], 3, "a1", 0, "comfortable", 5, 7});
    return d;
}

TEST(ParticipantCodes, ACodeInTwoFilesIsRefusedNamingCodesFilesAndTheWaysOn) {
    Dataset d = two_sites();
    const Result<void> joined = join_participant_codes(d, SharedCodes::Refuse);
    ASSERT_FALSE(joined.ok());
    const std::string& message = joined.error().message;
    EXPECT_TRUE(contains(message, "a1 and a2 in data/site-a.sqlite and other/site-b.sqlite"))
        << message;
    EXPECT_FALSE(contains(message, "b3")) << message;
    // The analysis' own names for the two ways on (`analyze` names its --codes option).
    EXPECT_TRUE(contains(message, "\n  same-person   they are the same people")) << message;
    EXPECT_TRUE(contains(message, "\n  per-database  each file's codes are its own")) << message;
    EXPECT_FALSE(contains(message, "--codes")) << message;
    EXPECT_TRUE(contains(message, "site-a/a1, site-b/a1")) << message;
    EXPECT_EQ(d.trials[0].participant, "a1");  // nothing changed
}

TEST(ParticipantCodes, DistinctCodesNeedNoRule) {
    Dataset d = two_sites();
    d.trials.resize(2);
    d.sessions.resize(2);
    d.answers.clear();
    ASSERT_TRUE(join_participant_codes(d, SharedCodes::Refuse).ok());
    EXPECT_TRUE(d.shared_codes.empty());
}

// One participant's two sessions, run on two lab PCs: session 2 on the second PC with the number
// the participant has had since their first session.
Dataset two_pcs() {
    Dataset d = two_sites();
    for (SessionRow& s : d.sessions) {
        if (s.source != d.sources[1]) continue;
        s.session_number = 2;
        s.participant_number = s.participant == "a1" ? 0 : 1;
    }
    return d;
}

TEST(ParticipantCodes, SamePersonRefusesFilesThatCannotBeOnePerson) {
    Dataset d = two_sites();  // a1 and a2 have a session 1 at each site, other numbers
    const Result<void> joined = join_participant_codes(d, SharedCodes::SamePerson);
    ASSERT_FALSE(joined.ok());
    const std::string& message = joined.error().message;
    EXPECT_TRUE(
        contains(message, "a1: session 1 in both data/site-a.sqlite and other/site-b.sqlite"))
        << message;
    EXPECT_TRUE(contains(message, "use per-database;")) << message;
    Dataset numbers = two_pcs();
    numbers.sessions[2].participant_number = 5;  // a1 at the second PC
    const Result<void> renumbered = join_participant_codes(numbers, SharedCodes::SamePerson);
    ASSERT_FALSE(renumbered.ok());
    EXPECT_TRUE(contains(renumbered.error().message,
                         "a1: participant number 1 in data/site-a.sqlite but 6 in "
                         "other/site-b.sqlite"))
        << renumbered.error().message;
}

TEST(ParticipantCodes, SamePersonKeepsTheCodesAsOneParticipant) {
    Dataset d = two_pcs();
    const Result<void> joined = join_participant_codes(d, SharedCodes::SamePerson);
    ASSERT_TRUE(joined.ok()) << joined.error().message;
    EXPECT_EQ(d.codes, SharedCodes::SamePerson);
    EXPECT_EQ(d.shared_codes, (std::vector<std::string>{"a1", "a2"}));
    EXPECT_EQ(d.trials[0].participant, "a1");
    EXPECT_EQ(d.trials[2].participant, "a1");
    EXPECT_EQ(d.answers[0].participant, "a1");
}

TEST(ParticipantCodes, PerDatabasePrefixesEveryCodeWithItsFileStem) {
    Dataset d = two_sites();
    const Result<void> joined = join_participant_codes(d, SharedCodes::PerDatabase);
    ASSERT_TRUE(joined.ok()) << joined.error().message;
    EXPECT_EQ(d.codes, SharedCodes::PerDatabase);
    EXPECT_EQ(d.trials[0].participant, "site-a/a1");
    EXPECT_EQ(d.trials[2].participant, "site-b/a1");
    EXPECT_EQ(d.trials[4].participant, "site-a/b3");
    EXPECT_EQ(d.sessions[3].participant, "site-b/a2");
    EXPECT_EQ(d.answers[0].participant, "site-b/a1");
    EXPECT_EQ(shared_codes_name(d.codes), "per-database");
}

TEST(ParticipantCodes, PerDatabaseRefusesTwoFilesOfOneName) {
    Dataset d = two_sites();
    for (TrialRow& t : d.trials)
        if (t.source == "other/site-b.sqlite") t.source = "other/site-a.sqlite";
    for (SessionRow& s : d.sessions)
        if (s.source == "other/site-b.sqlite") s.source = "other/site-a.sqlite";
    d.answers.clear();
    d.sources[1] = "other/site-a.sqlite";
    const Result<void> joined = join_participant_codes(d, SharedCodes::PerDatabase);
    ASSERT_FALSE(joined.ok());
    EXPECT_TRUE(contains(joined.error().message, "are both called 'site-a'"))
        << joined.error().message;
}

TEST(Counterbalancing, CountsEachParticipantInTheRowOfTheirFirstSession) {
    // 4 rows; participants numbered 0, 1, 2, 3, 4 (row 0 twice): balanced. a1's second session
    // (another participant number, e.g. given wrongly) does not count.
    std::vector<SessionRow> sessions;
    for (int p = 0; p < 5; ++p)
        sessions.push_back(session("s.sqlite", p + 1, "a" + std::to_string(p), 1, p));
    sessions.push_back(session("s.sqlite", 9, "a1", 2, 3));
    const Counterbalancing c = counterbalancing(sessions);
    ASSERT_TRUE(c.applicable) << c.reason;
    EXPECT_EQ(c.latin_square_rows, 4);
    EXPECT_EQ(c.participants_per_row, (std::vector<int>{2, 1, 1, 1}));
    EXPECT_TRUE(c.balanced);
    EXPECT_EQ(c.participants, 5);
    EXPECT_FALSE(c.order_assumed);
}

TEST(Counterbalancing, TwoFilesThatEachStartAtRowZeroAreNotBalanced) {
    // Two sites with 3 participants each, numbered 0, 1, 2 in each file (the default, each
    // database's own index): of 4 rows, three hold two participants and one none.
    std::vector<SessionRow> sessions;
    for (const char* site : {"a.sqlite", "b.sqlite"})
        for (int p = 0; p < 3; ++p)
            sessions.push_back(
                session(site, p + 1, std::string(site).substr(0, 1) + std::to_string(p), 1, p));
    const Counterbalancing c = counterbalancing(sessions);
    ASSERT_TRUE(c.applicable);
    EXPECT_EQ(c.participants_per_row, (std::vector<int>{2, 2, 2, 0}));
    EXPECT_FALSE(c.balanced);
}

TEST(Counterbalancing, NotApplicableWithoutALatinSquare) {
    EXPECT_FALSE(counterbalancing({}).applicable);
    std::vector<SessionRow> sessions = {session("s", 1, "a", 1, 0), session("s", 2, "b", 1, 1)};
    for (SessionRow& s : sessions) s.first_scene_order = "random";
    Counterbalancing c = counterbalancing(sessions);
    EXPECT_FALSE(c.applicable);
    EXPECT_EQ(c.other_order, 2);
    EXPECT_TRUE(contains(c.reason, "not by a Latin square")) << c.reason;

    sessions = {session("s", 1, "a", 1, 0, 4), session("s", 2, "b", 1, 1, 6)};
    c = counterbalancing(sessions);
    EXPECT_FALSE(c.applicable);
    EXPECT_TRUE(contains(c.reason, "4 and 6 rows")) << c.reason;
}

TEST(Counterbalancing, AnUnrecordedOrderCountsAsTheDefaultAndIsSaidSo) {
    std::vector<SessionRow> sessions = {session("e.csv", 1, "a", 1, 0, 6),
                                        session("e.csv", 2, "b", 1, 7, 6)};
    for (SessionRow& s : sessions) s.first_scene_order = "";
    const Counterbalancing c = counterbalancing(sessions);
    ASSERT_TRUE(c.applicable);
    EXPECT_TRUE(c.order_assumed);
    EXPECT_EQ(c.participants_per_row, (std::vector<int>{1, 1, 0, 0, 0, 0}));
    EXPECT_TRUE(c.balanced);
    EXPECT_EQ(latin_square_row(sessions[1]), 1);
}

TEST(CsvGuard, TheExportsApostropheComesOff) {
    EXPECT_EQ(unguarded_cell("'=1+2"), "=1+2");
    EXPECT_EQ(unguarded_cell("'+49 30"), "+49 30");
    EXPECT_EQ(unguarded_cell("'-x"), "-x");
    EXPECT_EQ(unguarded_cell("'@a"), "@a");
    EXPECT_EQ(unguarded_cell("'\tx"), "\tx");
    EXPECT_EQ(unguarded_cell("''=x"), "'=x");  // "'=x" as typed
    EXPECT_EQ(unguarded_cell("'quoted'"), "'quoted'");
    EXPECT_EQ(unguarded_cell("=x"), "=x");
    EXPECT_EQ(unguarded_cell("'"), "'");
    EXPECT_EQ(unguarded_cell(""), "");
}

const std::string kStudyDayHeader =
    "participant,session,trial_index,block,scene,mono_plane,label1_mode,choice,chosen_mode,valid,"
    "switches,time_label1_s,time_label2_s,decision_time_s,practice,decided,label2_mode,"
    "participant_index,protocol,protocol_hash,session_id,repetition,participant_number,var_age,"
    "var_remark";

TEST(StudyDayCsv, ReadsSessionsRepetitionsParticipantNumbersAndVariables) {
    // a1: sessions 1 (id 4) and 2 (id 7), participant number 5 (1-based); a2: index 1, no
    // variables given. Text cells guarded as the export guards them.
    const std::filesystem::path path = write_file(
        "study_day.csv",
        kStudyDayHeader + "\n" +
            "a1,1,0,0,beams,3,stereo,1,stereo,TRUE,1,1,1,2,FALSE,TRUE,hybrid,0,p,h,4,1,5,34,"
            "\"'=HYPERLINK(\"\"x\"\")\"\n"
            "a1,1,1,0,beams,3,hybrid,1,hybrid,TRUE,1,1,1,2,FALSE,TRUE,stereo,0,p,h,4,2,5,34,"
            "\"'=HYPERLINK(\"\"x\"\")\"\n"
            "a1,2,0,0,spheres,8,stereo,2,hybrid,TRUE,1,1,1,2,FALSE,TRUE,hybrid,0,p,h,7,1,5,34,"
            "\"'=HYPERLINK(\"\"x\"\")\"\n"
            "a2,1,0,0,beams,8,stereo,2,hybrid,TRUE,1,1,1,2,FALSE,TRUE,hybrid,1,p,h,5,1,NA,NA,NA\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_TRUE(read.ok()) << read.error().message;
    const Dataset& d = *read;
    ASSERT_EQ(d.trials.size(), 4u);
    EXPECT_EQ(d.trials[0].session_id, 4);
    EXPECT_EQ(d.trials[0].session_number, 1);
    EXPECT_EQ(d.trials[1].repetition, 2);
    EXPECT_EQ(d.trials[2].session_id, 7);
    EXPECT_EQ(d.trials[2].session_number, 2);
    ASSERT_EQ(d.sessions.size(), 3u);
    const SessionRow& first = d.sessions[0];
    EXPECT_EQ(first.participant, "a1");
    EXPECT_EQ(first.session_id, 4);
    EXPECT_EQ(first.participant_number, 4);  // 0-based
    EXPECT_EQ(first.scenes, 1);
    EXPECT_EQ(first.first_scene_order, "");  // a CSV does not say
    ASSERT_EQ(first.variables.size(), 2u);
    EXPECT_EQ(first.variables[0], (std::pair<std::string, std::string>{"age", "34"}));
    EXPECT_EQ(first.variables[1],
              (std::pair<std::string, std::string>{"remark", "=HYPERLINK(\"x\")"}));
    EXPECT_EQ(d.sessions[1].session_number, 2);
    EXPECT_EQ(d.sessions[2].participant, "a2");
    EXPECT_EQ(d.sessions[2].participant_number, 1);  // NA: the index
    EXPECT_TRUE(d.sessions[2].variables.empty());
}

TEST(StudyDayCsv, SessionNumbersWithoutIdsKeepSessionsApart) {
    // An export without session_id numbers sessions per participant: a1's and a2's session 1
    // are two sessions.
    std::string header = kStudyDayHeader;
    header.replace(header.find("session_id,"), 11, "");
    const std::filesystem::path path = write_file(
        "no_ids.csv",
        header + "\n" +
            "a1,1,0,0,beams,3,stereo,1,stereo,TRUE,1,1,1,2,FALSE,TRUE,hybrid,0,p,h,1,1,NA,NA\n"
            "a2,1,0,0,spheres,3,stereo,1,stereo,TRUE,1,1,1,2,FALSE,TRUE,hybrid,1,p,h,1,2,NA,NA\n"
            "a1,2,0,0,beams,3,stereo,1,stereo,TRUE,1,1,1,2,FALSE,TRUE,hybrid,0,p,h,1,1,NA,NA\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->sessions.size(), 3u);
    EXPECT_NE(read->trials[0].session_id, read->trials[1].session_id);
    EXPECT_NE(read->trials[0].session_id, read->trials[2].session_id);
    EXPECT_EQ(read->trials[1].first_scene, "spheres");  // a2's own first scene
}

TEST(StudyDayCsv, AnOlderExportHasOneSessionPerParticipant) {
    const Result<Dataset> read = read_export_csv(MONOPLANE_ANALYSIS_FIXTURES "/tiny.csv");
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_EQ(read->sessions.size(), 2u);
    for (const SessionRow& s : read->sessions) EXPECT_EQ(s.session_number, 1);
    for (const TrialRow& t : read->trials) EXPECT_EQ(t.repetition, 1);
}

// 3 participants x 2 sessions x 5 distances x 2 repetitions per session: 4 rows per
// participant and distance. The reference is chosen in 4, 3, 2, 1, 0 of them.
std::vector<TrialRow> repeated_trials() {
    const double distances[] = {2, 4, 8, 16, 32};
    std::vector<TrialRow> trials;
    for (int p = 0; p < 3; ++p) {
        for (int session = 1; session <= 2; ++session) {
            int index = 0;
            for (int d = 0; d < 5; ++d) {
                for (int repetition = 1; repetition <= 2; ++repetition) {
                    const int row = (session - 1) * 2 + repetition - 1;  // 0..3
                    // Reference in the first 4 - d rows, the others chose the test.
                    TrialRow t = trial("s.sqlite", p * 2 + session, "P" + std::to_string(p),
                                       index++, distances[d], row >= 4 - d);
                    t.session_number = session;
                    t.repetition = repetition;
                    trials.push_back(t);
                }
            }
        }
    }
    derive_session_fields(trials);
    return trials;
}

TEST(Repetitions, EveryRepeatedRowCountsInTheFitsAndSessionsClusterByParticipant) {
    const std::vector<TrialRow> trials = repeated_trials();
    ASSERT_EQ(trials.size(), 60u);
    const std::vector<PsychometricFit> fits =
        fit_psychometric_functions(trials, {.bootstrap_replicates = 20});
    ASSERT_EQ(fits.size(), 4u);  // the group, then P0, P1, P2
    EXPECT_EQ(fits[0].participant, "all");
    EXPECT_EQ(fits[0].n, 60);
    EXPECT_EQ(fits[0].participants, 3);
    for (std::size_t i = 1; i < fits.size(); ++i) {
        const PsychometricFit& f = fits[i];
        EXPECT_EQ(f.n, 20) << f.participant;
        ASSERT_EQ(f.levels.size(), 5u);
        for (std::size_t level = 0; level < 5; ++level) {
            EXPECT_EQ(f.levels[level].trials, 4) << f.participant;
            EXPECT_EQ(f.levels[level].reference, 4 - static_cast<int>(level)) << f.participant;
        }
    }
    const Result<LogisticFit> model = fit_choice_model(trials);
    ASSERT_TRUE(model.ok()) << model.error().message;
    EXPECT_EQ(model->n, 60);
    EXPECT_EQ(model->clusters, 3);  // two sessions each, one cluster per participant
}

}  // namespace
}  // namespace monoplane::analysis
