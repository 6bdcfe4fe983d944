// `monoplane --version` names the build (version, git revision, database schema, build type), and
// every session records the same identity as its software_version, so that a lab can tell which
// build collected which data. The expected values come from CMake and git, not from the program.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "study/study_store.h"
#include "tests/e2e/child_process.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// What `git cat-file -t REV` says in the source tree ("" without git or a checkout).
std::string git_object_type(const std::string& revision) {
    const std::string command =
        "git -C '" + source_dir() + "' cat-file -t " + revision + " 2>/dev/null";
    std::string type;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[64];
        while (fgets(buffer, sizeof buffer, pipe)) type += buffer;
        pclose(pipe);
    }
    while (!type.empty() && type.back() == '\n') type.pop_back();
    return type;
}

struct Version {
    std::string version, revision, schema, build_type;
};

Version read_version() {
    std::string output;
    EXPECT_EQ(run_to_end({MONOPLANE_EXE, "--version"}, &output), 0) << output;
    const std::vector<std::string> lines = lines_of(output);
    EXPECT_EQ(lines.size(), 4u) << output;
    Version v;
    auto after = [&](std::size_t i, const std::string& prefix) {
        if (i >= lines.size() || lines[i].rfind(prefix, 0) != 0) {
            ADD_FAILURE() << "line " << i + 1 << " is not \"" << prefix << "...\":\n" << output;
            return std::string();
        }
        return lines[i].substr(prefix.size());
    };
    v.version = after(0, "monoplane ");
    v.revision = after(1, "git revision: ");
    v.schema = after(2, "study database schema: ");
    v.build_type = after(3, "build type: ");
    return v;
}

TEST(VersionCli, NamesVersionRevisionSchemaAndBuildType) {
    const Version v = read_version();
    EXPECT_EQ(v.version, MONOPLANE_PROJECT_VERSION);
    EXPECT_EQ(v.schema, std::to_string(study::StudyStore::kSchemaVersion));
    EXPECT_EQ(v.build_type, MONOPLANE_BUILD_TYPE);
    // 12 hex digits of a commit (with "-modified" for a build of uncommitted changes), or
    // "unknown" when built outside a git checkout.
    std::smatch match;
    ASSERT_TRUE(std::regex_match(v.revision, match, std::regex("([0-9a-f]{12})(-modified)?")) ||
                v.revision == "unknown")
        << v.revision;
    if (v.revision != "unknown" && !git_object_type("HEAD").empty()) {
        EXPECT_EQ(git_object_type(match[1].str()), "commit") << v.revision;
    }
}

TEST(VersionCli, EverySessionRecordsTheBuild) {
    const fs::path dir = test_folder();
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path db = dir / "study.sqlite";
    std::string output;
    ASSERT_EQ(run_to_end({MONOPLANE_EXE, "study", "run", "--protocol",
                          source_dir() + "/protocols/demo.toml", "--participant", "P01", "--db",
                          db.string(), "--headset", "none"},
                         &output),
              0)
        << output;
    const Version v = read_version();
    sqlite3* handle = nullptr;
    ASSERT_EQ(sqlite3_open_v2(db.c_str(), &handle, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    sqlite3_stmt* select = nullptr;
    ASSERT_EQ(
        sqlite3_prepare_v2(handle, "SELECT software_version FROM sessions", -1, &select, nullptr),
        SQLITE_OK);
    ASSERT_EQ(sqlite3_step(select), SQLITE_ROW);
    EXPECT_EQ(reinterpret_cast<const char*>(sqlite3_column_text(select, 0)),
              "monoplane " + v.version + " (" + v.revision + ")");
    sqlite3_finalize(select);
    sqlite3_close(handle);
}

}  // namespace
}  // namespace monoplane
