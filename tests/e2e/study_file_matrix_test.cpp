// Every command against every state a study file can be in (issue 42): each cell runs the real
// executable (or, for the launcher, its model) on a fresh copy of the state and asserts its
// documented outcome: refused with its message and every input byte unchanged, or done with its
// documented effect (and, for a command that only reads, every byte unchanged too). The table in
// docs/data.md ("Every command against every file") is this test's: it fails when the two
// differ, and MONOPLANE_WRITE_DOCS=1 writes the table into the doc.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/lab/launcher_model.h"
#include "study/file_digest.h"
#include "study/session_hold.h"
#include "study/store_schema.h"
#include "tests/e2e/child_process.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

constexpr const char* kProtocol = R"(name = "matrix"
scenes = ["beams"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
practice_trials = 0
sessions = 2
)";
// Another design of it: other distances.
constexpr const char* kOtherDesign = R"(name = "matrix"
scenes = ["beams"]
mono_planes = [2, 6, 12]
alternatives = ["stereo", "hybrid"]
practice_trials = 0
sessions = 2
)";

// The commands, as columns.
const std::vector<std::string> kCommands = {"run",
                                            "resume",
                                            "note",
                                            "list",
                                            "export csv",
                                            "export json",
                                            "export frames-csv",
                                            "export notes-csv",
                                            "analyze",
                                            "protocol check",
                                            "launcher Open"};

// The states, as rows, each with the outcome of every command: "done" or "refused: <what the
// message says>" (a part of it). Writing commands that are done write; reading ones never do.
struct Row {
    std::string state;
    std::string how;  // what the file is, for the doc
    std::map<std::string, std::string> expected;
};

std::map<std::string, std::string> all(const std::string& outcome) {
    std::map<std::string, std::string> m;
    for (const std::string& c : kCommands) m[c] = outcome;
    return m;
}

std::map<std::string, std::string> with(std::map<std::string, std::string> m,
                                        const std::map<std::string, std::string>& changes) {
    for (const auto& [k, v] : changes) m[k] = v;
    return m;
}

// A study the lab uses: k9's session 1 completed, k10's interrupted. Commands: run starts k9's
// session 2, resume continues k10's, note writes to k9's.
std::map<std::string, std::string> usable() {
    return with(all("done"), {{"protocol check",
                               "refused: is a SQLite database (a study "
                               "database?), not a protocol"}});
}

std::vector<Row> rows() {
    return {
        {"missing", "no such file",
         with(all("refused: no study database"),
              {{"run", "done"}, {"protocol check", "refused: cannot open protocol file"}})},
        {"0 bytes", "an empty file (a failed copy)",
         with(all("refused: is 0 bytes: not a study database"),
              {{"protocol check", "refused: not a protocol"}})},
        {"truncated", "the first 4096 bytes of a study",
         with(all("refused: is truncated"), {{"protocol check", "refused: not a protocol"}})},
        {"corrupt page", "a study whose last page is overwritten",
         with(all("refused: is damaged"), {{"protocol check", "refused: not a protocol"}})},
        {"foreign SQLite", "another program's SQLite database",
         with(all("refused: is a SQLite database of another program"),
              {{"protocol check", "refused: not a protocol"}})},
        {"read-only", "mode 0444 in a folder of mode 0555, read by another user",
         with(usable(), {{"run", "refused: is read-only for you"},
                         {"resume", "refused: is read-only for you"},
                         {"note", "refused: is read-only for you"}})},
        {"older schema", "written by schema version 7",
         with(usable(), {{"run", "done (migrated; FILE.schema7.bak kept)"},
                         {"resume", "done (migrated; FILE.schema7.bak kept)"},
                         {"note", "done (migrated; FILE.schema7.bak kept)"}})},
        {"newer schema", "schema version 11",
         with(all("refused: newer than this build of monoplane knows"),
              {{"protocol check", "refused: not a protocol"}})},
        {"live session", "k9's session 1 held by a running process",
         with(usable(), {{"run", "refused: is running: process"}})},
        {"interrupted", "k9's session 1 interrupted",
         with(usable(), {{"run", "refused: was interrupted"}})},
        {"a copy of another", "a copy of a study, analysed with the original",
         with(usable(), {{"analyze", "refused: holds the same session"}})},
        {"another protocol version",
         "run gives k9 another design; the file also holds a session of that design",
         with(usable(),
              {{"run", "refused: differs in design"}, {"analyze", "refused: --pool-protocols"}})},
        {"another study", "outputs of another study already in place",
         with(usable(), {{"export csv", "refused: another study"},
                         {"export json", "refused: another study"},
                         {"analyze", "refused: holds files analyze did not write"}})},
    };
}

int sql(const fs::path& db, const std::string& text) {
    sqlite3* raw = nullptr;
    sqlite3_open(db.c_str(), &raw);
    const int rc = sqlite3_exec(raw, text.c_str(), nullptr, nullptr, nullptr);
    sqlite3_close_v2(raw);
    return rc;
}

// Every file under `dir` (outputs excluded) with its digest.
std::map<std::string, std::string> fingerprint(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        const std::string name = fs::relative(entry.path(), dir).string();
        Result<study::FileDigest> digest = study::digest_file(entry.path());
        files[name] = digest ? digest->sha256 : "unreadable";
    }
    return files;
}

// The same study as schema version 7 wrote it (the base's rows, less what version 8 added).
void make_version7(const fs::path& from, const fs::path& db) {
    std::string text;
    for (int v = 0; v < 7; ++v) text += std::string(study::store_migrations()[v]);
    text += "PRAGMA application_id = " + std::to_string(study::kStoreApplicationId) + ";";
    text += "PRAGMA user_version = 7;";
    ASSERT_EQ(sql(db, text), SQLITE_OK);
    const std::string copy =
        "ATTACH DATABASE '" + from.string() +
        "' AS v8;"
        "INSERT INTO participants SELECT * FROM v8.participants;"
        "INSERT INTO participant_variables SELECT * FROM v8.participant_variables;"
        "INSERT INTO sessions SELECT id, participant_id, protocol_name, protocol_hash, "
        "protocol_text, seed, block_order, software_version, hmd, runtime, device, observer, "
        "started_utc, ended_utc, status, render_anti_aliasing, render_ssao, render_detail, "
        "procedure, session_number FROM v8.sessions;"
        "INSERT INTO trials SELECT session_id, trial_index, practice, block, scene, mono_plane, "
        "label1_alternative, label1_mode, label2_mode, decided, choice, chosen_mode, valid, "
        "switches, time_label1_ns, time_label2_ns, decision_time_ns, decided_utc, repetition "
        "FROM v8.trials;"
        "INSERT INTO events SELECT id, session_id, trial_index, kind, label, time_ns, frame, page "
        "FROM v8.events WHERE kind NOT IN ('session_abandoned', 'protocol_changed', "
        "'protocol_text_changed', 'run_started');"
        "INSERT INTO answers SELECT * FROM v8.answers;"
        "PRAGMA journal_mode = WAL;";
    ASSERT_EQ(sql(db, copy), SQLITE_OK) << sqlite3_errstr(sql(db, copy));
}

// Makes the state's file at `db` (and what the cell needs beside it); returns the files
// analyze reads there.
std::vector<std::string> make_state(const std::string& state, const fs::path& base,
                                    const fs::path& db, const fs::path& other_design) {
    const auto copy_base = [&] { fs::copy_file(base, db); };
    if (state == "missing") return {db};
    if (state == "0 bytes") {
        std::ofstream(db).close();
    } else if (state == "truncated") {
        copy_base();
        fs::resize_file(db, 4096);
    } else if (state == "corrupt page") {
        copy_base();
        std::fstream f(db, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(fs::file_size(db) - 4096));
        const std::string garbage(4096, '\xA5');
        f.write(garbage.data(), 4096);
    } else if (state == "foreign SQLite") {
        sql(db,
            "CREATE TABLE photos (id INTEGER PRIMARY KEY, path TEXT);"
            "INSERT INTO photos (path) VALUES ('a.jpg');");
    } else if (state == "older schema") {
        make_version7(base, db);
    } else if (state == "newer schema") {
        copy_base();
        sql(db, "PRAGMA user_version = 11");
    } else if (state == "live session" || state == "interrupted") {
        copy_base();
        sql(db, "UPDATE sessions SET status = 'running', ended_utc = NULL WHERE id = 1");
    } else if (state == "a copy of another") {
        copy_base();
        const fs::path original = db.parent_path() / "original.sqlite";
        fs::copy_file(base, original);
        return {original.string(), db.string()};
    } else {
        copy_base();  // read-only, another protocol version, another study
    }
    (void)other_design;
    return {db.string()};
}

bool reads_only(const std::string& command) {
    return command != "run" && command != "resume" && command != "note";
}

// One cell's files: the state's folder, and the outputs' folder beside it.
struct CellFiles {
    fs::path dir;
    fs::path db;
    fs::path out;
    std::vector<std::string> analysed;  // what analyze reads
};

// What a state needs beyond its file: another design's sessions, another study's outputs.
void add_surroundings(const std::string& state, const CellFiles& cell, const fs::path& root,
                      const std::function<int(std::vector<std::string>)>& monoplane) {
    if (state == "another protocol version") {
        ASSERT_EQ(monoplane({"study", "run", "--protocol", (root / "other-design.toml").string(),
                             "--participant", "k11", "--db", cell.db.string(), "--headset", "none",
                             "--seed", "6"}),
                  0);
    } else if (state == "another study") {
        const fs::path other = cell.out / "other.sqlite";
        ASSERT_EQ(monoplane({"study", "run", "--protocol", (root / "matrix.toml").string(),
                             "--participant", "x1", "--db", other.string(), "--headset", "none"}),
                  0);
        for (const char* format : {"csv", "json"})
            ASSERT_EQ(monoplane({"study", "export", "--db", other.string(), "--format", format,
                                 "--out", (cell.out / ("export." + std::string(format))).string()}),
                      0);
        fs::create_directories(cell.out / "analysis");
        std::ofstream(cell.out / "analysis" / "thesis.tex") << "\\chapter{Results}\n";
    }
}

std::vector<std::string> command_line(const std::string& command, const CellFiles& cell,
                                      const fs::path& protocol) {
    const std::string db = cell.db.string();
    if (command == "run")
        return {"study",         "run",  "--protocol", protocol.string(),
                "--participant", "k9",   "--db",       db,
                "--headset",     "none", "--seed",     "5"};
    if (command == "resume")
        return {"study", "resume", "--db", db, "--participant", "k10", "--headset", "none"};
    if (command == "note")
        return {"study", "note", "--db", db, "--participant", "k9", "checked the headset"};
    if (command == "list") return {"study", "list", "--db", db};
    if (command.starts_with("export ")) {
        const std::string format = command.substr(7);
        const std::string name =
            format == "csv" || format == "json" ? "export." + format : "export-" + format + ".csv";
        return {"study",    "export", "--db",  db,
                "--format", format,   "--out", (cell.out / name).string()};
    }
    if (command == "analyze") {
        std::vector<std::string> args = {"analyze"};
        for (const std::string& file : cell.analysed) args.insert(args.end(), {"--db", file});
        args.insert(args.end(), {"--out", (cell.out / "analysis").string()});
        return args;
    }
    return {"protocol", "check", db};
}

// The launcher's Open, in its model: what its window shows under the Database step.
std::pair<int, std::string> open_in_launcher(const fs::path& db) {
    lab::LauncherModel model(lab::LauncherSettings{});
    Result<void> opened = model.open_database(db, false);
    return {opened ? 0 : 1, opened ? std::string() : opened.error().message};
}

class StudyFileMatrix : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        root_ = fs::temp_directory_path() / ("monoplane_matrix_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_);
        fs::permissions(root_, fs::perms::all);  // another user runs the read-only cells
        std::ofstream(root_ / "matrix.toml") << kProtocol;
        std::ofstream(root_ / "other-design.toml") << kOtherDesign;
        make_base();
    }
    static void TearDownTestSuite() { fs::remove_all(root_); }

    static std::string protocol() { return (root_ / "matrix.toml").string(); }

    static int monoplane(std::vector<std::string> args, std::string* out, bool as_other_user) {
        args.insert(args.begin(), MONOPLANE_EXE);
        if (as_other_user)
            args.insert(args.begin(),
                        {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"});
        const fs::path tmp = root_ / ("tmp" + std::to_string(counter_++));
        fs::create_directories(tmp);
        fs::permissions(tmp, fs::perms::all);
        return run_to_end(args, out, tmp.string());
    }

    // The study every usable state starts from.
    static void make_base() {
        const std::string db = (root_ / "base.sqlite").string();
        std::string out;
        for (const char* code : {"k9", "k10"}) {
            ASSERT_EQ(monoplane({"study", "run", "--protocol", protocol(), "--participant", code,
                                 "--db", db, "--headset", "none", "--seed", "4"},
                                &out, false),
                      0)
                << out;
        }
        ASSERT_EQ(sql(db,
                      "UPDATE sessions SET status = 'running', ended_utc = NULL WHERE "
                      "participant_id = (SELECT id FROM participants WHERE code = 'k10');"
                      "UPDATE trials SET decided = 0, choice = NULL, chosen_mode = NULL, "
                      "valid = NULL, switches = NULL, time_label1_ns = NULL, "
                      "time_label2_ns = NULL, decision_time_ns = NULL, decided_utc = NULL "
                      "WHERE session_id = 2 AND trial_index = 1;"),
                  SQLITE_OK);
    }

    // Makes the state afresh, runs the command, and checks the outcome against `expected`.
    void run_cell(const std::string& state, const std::string& command, const std::string& expected,
                  bool as_other_user) {
        const int n = counter_++;
        CellFiles cell{.dir = root_ / ("cell" + std::to_string(n)),
                       .db = root_ / ("cell" + std::to_string(n)) / "study.sqlite",
                       .out = root_ / ("out" + std::to_string(n)),
                       .analysed = {}};
        for (const fs::path& d : {cell.dir, cell.out}) {
            fs::create_directories(d);
            fs::permissions(d, fs::perms::all);
        }
        cell.analysed = make_state(state, root_ / "base.sqlite", cell.db, {});
        std::string log;
        add_surroundings(state, cell, root_, [&](std::vector<std::string> args) {
            return monoplane(std::move(args), &log, false);
        });
        ASSERT_FALSE(HasFatalFailure()) << log;
        std::optional<study::SessionHold> hold;
        if (state == "live session")
            hold.emplace(study::SessionHold::acquire(cell.db, 1).value_or_throw());
        if (state == "read-only") {
            fs::permissions(cell.db,
                            fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
            fs::permissions(cell.dir, fs::perms::owner_read | fs::perms::owner_exec |
                                          fs::perms::group_read | fs::perms::group_exec |
                                          fs::perms::others_read | fs::perms::others_exec);
        }
        const auto inputs = fingerprint(cell.dir);
        const auto outputs = fingerprint(cell.out);
        const fs::path protocol =
            root_ / (state == "another protocol version" ? "other-design.toml" : "matrix.toml");
        const auto [code, output] = command == "launcher Open" ? open_in_launcher(cell.db) : [&] {
            std::string out;
            const int rc = monoplane(command_line(command, cell, protocol), &out, as_other_user);
            return std::pair<int, std::string>(rc, out);
        }();
        check_outcome(expected, command, code, output, cell, inputs, outputs);
        fs::permissions(cell.dir, fs::perms::all);
    }

    static void check_outcome(const std::string& expected, const std::string& command, int code,
                              const std::string& output, const CellFiles& cell,
                              const std::map<std::string, std::string>& inputs,
                              const std::map<std::string, std::string>& outputs) {
        if (expected.starts_with("refused: ")) {
            EXPECT_NE(code, 0) << output;
            EXPECT_NE(output.find(expected.substr(9)), std::string::npos) << output;
            EXPECT_EQ(fingerprint(cell.dir), inputs) << "a refused command changed its input";
            EXPECT_EQ(fingerprint(cell.out), outputs) << "a refused command changed an output";
            return;
        }
        EXPECT_EQ(code, 0) << output;
        if (reads_only(command)) {
            EXPECT_EQ(fingerprint(cell.dir), inputs) << "a reading command changed its input";
        } else {
            EXPECT_NE(fingerprint(cell.dir), inputs)
                << "a writing command that was done wrote nothing";
        }
        if (expected.find("schema7.bak kept") != std::string::npos) {
            EXPECT_TRUE(fs::exists(cell.db.string() + ".schema7.bak"));
        }
    }

    // The table in docs/data.md between its markers is this test's table.
    static void check_doc_table(const std::string& table) {
        const fs::path doc = fs::path(source_dir()) / "docs" / "data.md";
        std::string text = read_file(doc);
        const std::string begin = "<!-- file-matrix:begin -->\n";
        const std::string end = "<!-- file-matrix:end -->";
        const std::size_t from = text.find(begin);
        const std::size_t to = text.find(end);
        ASSERT_NE(from, std::string::npos) << doc << " has no " << begin;
        ASSERT_NE(to, std::string::npos) << doc << " has no " << end;
        const std::string written = text.substr(from + begin.size(), to - from - begin.size());
        if (std::getenv("MONOPLANE_WRITE_DOCS") != nullptr) {
            text.replace(from + begin.size(), to - from - begin.size(), table);
            std::ofstream(doc) << text;
            return;
        }
        EXPECT_EQ(written, table) << "docs/data.md's table is not this test's: run the test with "
                                     "MONOPLANE_WRITE_DOCS=1 to write it";
    }

    static fs::path root_;
    static int counter_;
};

fs::path StudyFileMatrix::root_;
int StudyFileMatrix::counter_ = 0;

TEST_F(StudyFileMatrix, EveryCommandAgainstEveryStateDoesWhatTheDocSays) {
    ASSERT_FALSE(HasFatalFailure());
    // Another user for the read-only cells: root reads and writes whatever the modes say.
    std::string probe;
    const bool other_user =
        ::geteuid() == 0 && run_to_end({"/usr/bin/setpriv", "--reuid=65534", "--regid=65534",
                                        "--clear-groups", "/usr/bin/test", "-x", MONOPLANE_EXE},
                                       &probe) == 0;
    std::ostringstream table;
    table << "| state | the file |";
    for (const std::string& c : kCommands) table << " " << c << " |";
    table << " the refusals say |\n|---|---|";
    for (std::size_t i = 0; i <= kCommands.size(); ++i) table << "---|";
    table << "\n";
    for (const Row& row : rows()) {
        table << "| " << row.state << " | " << row.how << " |";
        std::vector<std::string> says;
        for (const std::string& command : kCommands) {
            const std::string& expected = row.expected.at(command);
            const bool refused = expected.starts_with("refused: ");
            table << " " << (refused ? "**refused**" : expected) << " |";
            const std::string quote = refused ? "\"" + expected.substr(9) + "\"" : "";
            if (refused && std::find(says.begin(), says.end(), quote) == says.end())
                says.push_back(quote);
            SCOPED_TRACE(row.state + " x " + command);
            if (row.state == "read-only" && !other_user && !reads_only(command)) {
                // Root may write whatever the modes say: the refusal needs another user.
                std::cerr << "skipped read-only x " << command
                          << ": not root, or user nobody cannot run " << MONOPLANE_EXE << "\n";
                continue;
            }
            run_cell(row.state, command, expected, other_user && row.state == "read-only");
        }
        std::string joined;
        for (const std::string& q : says) joined += (joined.empty() ? "" : "; ") + q;
        table << " " << joined << " |\n";
    }
    check_doc_table(table.str());
}

// `study migrate`: an older file migrated on request with its original kept beside it; a file of
// this version left alone; a refused file refused as by every command.
TEST_F(StudyFileMatrix, MigrateKeepsTheOriginalAndLeavesACurrentFileAlone) {
    const fs::path dir = root_ / "migrate";
    fs::create_directories(dir);
    const fs::path db = dir / "old.sqlite";
    make_version7(root_ / "base.sqlite", db);
    std::string out;
    ASSERT_EQ(monoplane({"study", "migrate", "--db", db.string()}, &out, false), 0) << out;
    EXPECT_NE(out.find(db.string() +
                       ": migrated from schema version 7 to 10; the original is "
                       "kept as " +
                       db.string() + ".schema7.bak"),
              std::string::npos)
        << out;
    const auto version = [](const fs::path& file) {
        sqlite3* raw = nullptr;
        sqlite3_open(file.c_str(), &raw);
        sqlite3_stmt* stmt = nullptr;
        sqlite3_prepare_v2(raw, "PRAGMA user_version", -1, &stmt, nullptr);
        const int v = sqlite3_step(stmt) == SQLITE_ROW ? sqlite3_column_int(stmt, 0) : -1;
        sqlite3_finalize(stmt);
        sqlite3_close_v2(raw);
        return v;
    };
    EXPECT_EQ(version(db), 10);
    EXPECT_EQ(version(db.string() + ".schema7.bak"), 7);
    const auto migrated = fingerprint(dir);
    ASSERT_EQ(monoplane({"study", "migrate", "--db", db.string()}, &out, false), 0) << out;
    EXPECT_NE(out.find("schema version 10, already this build's; unchanged"), std::string::npos)
        << out;
    EXPECT_EQ(fingerprint(dir), migrated);
    const fs::path empty = dir / "empty.sqlite";
    std::ofstream(empty).close();
    EXPECT_EQ(monoplane({"study", "migrate", "--db", empty.string()}, &out, false), 1);
    EXPECT_NE(out.find("is 0 bytes: not a study database"), std::string::npos) << out;
    EXPECT_EQ(fs::file_size(empty), 0u);
}

// An abandoned session, as the lab will find it later: study list says so with the reason, and
// the analysis report and summary.json carry the reason among the session's notes.
TEST_F(StudyFileMatrix, AnAbandonedSessionIsShownWithItsReasonByTheRosterAndTheReport) {
    const fs::path dir = root_ / "abandon";
    fs::create_directories(dir);
    const fs::path db = dir / "study.sqlite";
    fs::copy_file(root_ / "base.sqlite", db);  // k10's session 1 is interrupted
    std::string out;
    ASSERT_EQ(
        monoplane({"study", "run", "--protocol", protocol(), "--participant", "k10", "--db",
                   db.string(), "--headset", "none", "--abandon", "1", "participant felt unwell"},
                  &out, false),
        0)
        << out;
    ASSERT_EQ(monoplane({"study", "list", "--db", db.string()}, &out, false), 0) << out;
    EXPECT_NE(out.find("abandoned (participant felt unwell)"), std::string::npos) << out;
    ASSERT_EQ(monoplane({"analyze", "--db", db.string(), "--out", (dir / "analysis").string()},
                        &out, false),
              0)
        << out;
    const std::string json = read_file(dir / "analysis" / "summary.json");
    EXPECT_NE(json.find("\"text\": \"session abandoned: participant felt unwell\""),
              std::string::npos);
    const std::string html = read_file(dir / "analysis" / "report.html");
    EXPECT_NE(html.find("session abandoned: participant felt unwell"), std::string::npos);
}

}  // namespace
}  // namespace monoplane
