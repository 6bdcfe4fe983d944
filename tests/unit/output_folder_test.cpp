// The output folder `analyze --out` writes whole (app/commands/output_folder.h): a new folder is
// staged beside it and renamed into place; an earlier run's folder is replaced so that none of
// its files survives; a folder holding anything the command did not write is refused with one
// message naming it and those files, and nothing changes; forced, the new files go in among the
// foreign ones, which stay, and the earlier run's other files go. Each case asserts the exact
// files in the output folder and in its parent (no staged folder left).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "app/commands/output_folder.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;

const FolderWriter kWriter{".monoplane-analysis", "analyze"};

void write_file(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file under `root` with its contents, relative; folders as "name/" when empty.
std::map<std::string, std::string> tree(const fs::path& root) {
    std::map<std::string, std::string> files;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
        const std::string name = e.path().lexically_relative(root).generic_string();
        if (e.is_directory()) {
            if (fs::is_empty(e.path())) files[name + "/"] = "";
        } else {
            files[name] = read_file(e.path());
        }
    }
    return files;
}

std::set<std::string> names(const std::map<std::string, std::string>& files) {
    std::set<std::string> out;
    for (const auto& [name, text] : files) out.insert(name);
    return out;
}

class OutputFolder : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "output_folder_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        out_ = dir_ / "analysis";
    }
    void TearDown() override { fs::remove_all(dir_); }

    // One run of the command: `files` (name -> text) written into the staged folder, committed.
    Result<void> run(const std::map<std::string, std::string>& files, bool force = false,
                     const fs::path& out = {}) {
        Result<StagedFolder> staged =
            StagedFolder::create(out.empty() ? out_ : out, kWriter, force);
        MONOPLANE_TRY(staged);
        for (const auto& [name, text] : files) write_file(staged->path() / name, text);
        return staged.value().commit();
    }

    std::string marker_text(const std::vector<std::string>& files) const {
        std::string text =
            "# monoplane analyze output: the files it wrote in this folder\n"
            "# A later `monoplane analyze --out` replaces this folder only while it holds "
            "nothing but these files.\n";
        for (const std::string& f : files) text += f + "\n";
        return text;
    }

    fs::path dir_;
    fs::path out_;
};

const std::map<std::string, std::string> kThreeScenes = {
    {"report.html", "three"},
    {"summary.json", "{}"},
    {"figures/psychometric_beams.svg", "b"},
    {"figures/psychometric_spheres.svg", "s"},
};
const std::map<std::string, std::string> kTwoScenes = {
    {"report.html", "two"},
    {"summary.json", "{}"},
    {"figures/psychometric_beams.svg", "b2"},
};

TEST_F(OutputFolder, ANewFolderHoldsTheFilesAndTheMarkerAndNothingIsLeftBeside) {
    ASSERT_TRUE(run(kThreeScenes).ok());
    std::map<std::string, std::string> expected = kThreeScenes;
    expected[".monoplane-analysis"] =
        marker_text({"figures/psychometric_beams.svg", "figures/psychometric_spheres.svg",
                     "report.html", "summary.json"});
    EXPECT_EQ(tree(out_), expected);
    EXPECT_EQ(names(tree(dir_)),
              (std::set<std::string>{"analysis/.monoplane-analysis",
                                     "analysis/figures/psychometric_beams.svg",
                                     "analysis/figures/psychometric_spheres.svg",
                                     "analysis/report.html", "analysis/summary.json"}));
}

TEST_F(OutputFolder, ARerunLeavesNoFileOfTheEarlierRun) {
    ASSERT_TRUE(run(kThreeScenes).ok());
    ASSERT_TRUE(run(kTwoScenes).ok());
    std::map<std::string, std::string> expected = kTwoScenes;
    expected[".monoplane-analysis"] =
        marker_text({"figures/psychometric_beams.svg", "report.html", "summary.json"});
    EXPECT_EQ(tree(out_), expected);          // psychometric_spheres.svg is gone
    EXPECT_EQ(names(tree(dir_)).size(), 4u);  // no staged or earlier folder beside it
}

TEST_F(OutputFolder, AnEmptyFolderIsReplacedAndKeepsItsMode) {
    fs::create_directory(out_);
    ::chmod(out_.c_str(), 0750);
    ASSERT_TRUE(run(kTwoScenes).ok());
    EXPECT_EQ(names(tree(out_)),
              (std::set<std::string>{".monoplane-analysis", "figures/psychometric_beams.svg",
                                     "report.html", "summary.json"}));
    struct stat st {};
    ASSERT_EQ(::stat(out_.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0750u);
}

TEST_F(OutputFolder, AFolderOfOtherFilesIsRefusedAndUnchanged) {
    write_file(out_ / "thesis.tex", "\\chapter{Results}");
    write_file(out_ / "chapters" / "one.tex", "one");
    write_file(out_ / "report.html", "my own report");
    const auto before = tree(dir_);
    const Result<void> refused = run(kTwoScenes);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message,
              "--out '" + out_.string() +
                  "' holds files analyze did not write: chapters/, report.html, thesis.tex. "
                  "Nothing was written. Choose a new or empty folder for --out, or give --force "
                  "to write among them (files of the same names are replaced, the others kept).");
    EXPECT_EQ(tree(dir_), before);
}

TEST_F(OutputFolder, AFileAddedToAnEarlierOutputMakesItForeign) {
    ASSERT_TRUE(run(kThreeScenes).ok());
    write_file(out_ / "figures" / "my_edit.png", "x");
    const auto before = tree(dir_);
    const Result<void> refused = run(kTwoScenes);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("did not write: figures/my_edit.png. Nothing"),
              std::string::npos)
        << refused.error().message;
    EXPECT_EQ(tree(dir_), before);
}

TEST_F(OutputFolder, AMarkerThatPointsOutsideVouchesForNothing) {
    ASSERT_TRUE(run(kTwoScenes).ok());
    write_file(out_ / ".monoplane-analysis", marker_text({"../precious.txt", "report.html"}));
    const Result<void> refused = run(kTwoScenes);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find(
                  "did not write: .monoplane-analysis, figures/, report.html, summary.json."),
              std::string::npos)
        << refused.error().message;
}

TEST_F(OutputFolder, ForcedTheNewFilesGoAmongTheOthersAndTheEarlierRunsStaleFilesGo) {
    ASSERT_TRUE(run(kThreeScenes).ok());
    write_file(out_ / "thesis.tex", "\\chapter{Results}");
    write_file(out_ / "figures" / "my_photo.jpg", "photo");
    ASSERT_TRUE(run(kTwoScenes, true).ok());
    std::map<std::string, std::string> expected = kTwoScenes;
    expected["thesis.tex"] = "\\chapter{Results}";
    expected["figures/my_photo.jpg"] = "photo";
    expected[".monoplane-analysis"] =
        marker_text({"figures/psychometric_beams.svg", "report.html", "summary.json"});
    EXPECT_EQ(tree(out_), expected);  // psychometric_spheres.svg gone, the others' files kept
    EXPECT_EQ(names(tree(dir_)).size(), expected.size());  // nothing staged left beside
    // The folder still holds foreign files: refused again without --force.
    EXPECT_FALSE(run(kTwoScenes).ok());
}

TEST_F(OutputFolder, AFileWhereTheFolderShouldBeIsRefusedAlsoForced) {
    write_file(out_, "not a folder");
    const Result<void> refused = run(kTwoScenes, true);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message,
              "--out '" + out_.string() +
                  "' exists and is not a folder; choose another --out (--force does not "
                  "replace a file with a folder). Nothing was written.");
    EXPECT_EQ(read_file(out_), "not a folder");
    EXPECT_EQ(names(tree(dir_)), (std::set<std::string>{"analysis"}));
}

TEST_F(OutputFolder, WhatAppearsBeforeTheCommitIsRefusedThenToo) {
    ASSERT_TRUE(run(kTwoScenes).ok());
    Result<StagedFolder> staged = StagedFolder::create(out_, kWriter, false);
    ASSERT_TRUE(staged.ok()) << staged.error().message;
    write_file(staged->path() / "report.html", "new");
    write_file(out_ / "notes.txt", "typed meanwhile");
    const auto before = tree(out_);
    const Result<void> refused = staged.value().commit();
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("did not write: notes.txt."), std::string::npos);
    EXPECT_EQ(tree(out_), before);
}

TEST_F(OutputFolder, AnUncommittedStagedFolderIsRemoved) {
    {
        Result<StagedFolder> staged = StagedFolder::create(out_, kWriter, false);
        ASSERT_TRUE(staged.ok()) << staged.error().message;
        write_file(staged->path() / "report.html", "half");
        EXPECT_TRUE(fs::exists(staged->path()));
    }
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(OutputFolder, ALinkToAFolderStaysAndItsFolderIsReplaced) {
    const fs::path real = dir_ / "real";
    ASSERT_TRUE(run(kThreeScenes, false, real).ok());
    fs::create_directory_symlink(real, out_);
    ASSERT_TRUE(run(kTwoScenes).ok());
    EXPECT_TRUE(fs::is_symlink(out_));
    EXPECT_EQ(names(tree(real)),
              (std::set<std::string>{".monoplane-analysis", "figures/psychometric_beams.svg",
                                     "report.html", "summary.json"}));
}

TEST_F(OutputFolder, FinalPathsAreUnderTheFolderAsGiven) {
    Result<StagedFolder> staged = StagedFolder::create(out_, kWriter, false);
    ASSERT_TRUE(staged.ok());
    const fs::path inside = staged->path() / "figures" / "choices.svg";
    EXPECT_EQ(staged->final_path(inside), out_ / "figures" / "choices.svg");
}

}  // namespace
}  // namespace monoplane::app
