// glTF scenes in study protocols (issue 19, item 1; docs/scenes.md, "glTF scenes in a study"),
// through the monoplane executable: `protocol check` loads the scene files and prints their
// digests, a session records every file each imported scene was read from with the SHA-256 and
// size that the `sha256sum` program and the file system report (an independent route), exports
// carry them, `analyze` takes the file label as a scene name, a broken file refuses the session
// before it begins, `study resume` refuses changed or missing files naming both digests (and,
// with --accept-changed-scenes, goes on and records it), and a simulated-headset session renders
// the imported scene. The glTF files are written here (tests/unit/gltf_test_files.h).
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include "study/study_store.h"
#include "tests/e2e/test_files.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;
using scenes::testing::TestGltf;

// The scenes entry as the protocol writes it, relative to the protocol's folder.
constexpr const char* kLabel = "models/tri.gltf";

// Runs a shell command; returns its exit status and, in *output, stdout and stderr together.
int run(const std::string& command, std::string* output = nullptr) {
    const std::string log = (test_folder() / "command.log").string();
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    if (output) *output = text.str();
    return WEXITSTATUS(status);
}

std::string monoplane(const std::string& arguments) {
    return std::string(MONOPLANE_EXE) + " " + arguments;
}

// The digest the `sha256sum` program prints for a file (coreutils: "HASH  NAME").
std::string sha256sum(const fs::path& file) {
    std::string output;
    EXPECT_EQ(run("sha256sum '" + file.string() + "'", &output), 0) << output;
    return output.substr(0, output.find(' '));
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A 1 x 1 red PNG (8-bit RGB): the signature and the IHDR, IDAT (zlib) and IEND chunks of the PNG
// specification with their CRCs.
const std::vector<unsigned char> kRedPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
    0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0xc9, 0xfe, 0x92,
    0xef, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

class StudySceneFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "protocols" / "models");
        write_scene();
        db_ = dir_ / "study.sqlite";
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir_);
    }

    // A red, textured triangle facing +z, where the viewpoint that frames it stands: tri.gltf,
    // its buffer tri.bin and its image red.png.
    void write_scene() {
        TestGltf file;
        const int positions = file.add_positions({{-1, 0, -2}, {1, 0, -2}, {0, 1.5f, -2}});
        const int uv = file.add_vec2({{0, 0}, {1, 0}, {0.5f, 1}});
        file.add_node(
            {{"mesh", file.add_mesh({{"POSITION", positions}, {"TEXCOORD_0", uv}}, -1, 4, 0)}});
        file.json["images"] = {{{"uri", "red.png"}}};
        file.json["textures"] = {{{"source", 0}}};
        file.json["materials"] = {
            {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
        file.write_gltf_with_bin(models() / "tri.gltf", "tri.bin");
        std::ofstream png(models() / "red.png", std::ios::binary);
        png.write(reinterpret_cast<const char*>(kRedPng.data()),
                  static_cast<std::streamsize>(kRedPng.size()));
    }

    fs::path models() const { return dir_ / "protocols" / "models"; }

    fs::path write_protocol(const std::string& scenes, const std::string& planes = "[3, 8]") {
        fs::path path = dir_ / "protocols" / "files.toml";
        std::ofstream(path) << "name = \"files\"\nscenes = " << scenes
                            << "\nmono_planes = " << planes
                            << "\nalternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 0\n";
        return path;
    }

    std::string run_session(const fs::path& protocol, const std::string& participant,
                            int expect = 0) {
        std::string output;
        EXPECT_EQ(run(monoplane("study run --protocol " + protocol.string() + " --participant " +
                                participant + " --db " + db_.string() +
                                " --headset none --observer default --seed 7"),
                      &output),
                  expect)
            << output;
        return output;
    }

    // What `sha256sum` and the file system say of the scene's three files, in the order the
    // loader reads them: the .gltf, its buffer, its image.
    std::vector<study::SceneFileRecord> expected_records() const {
        std::vector<study::SceneFileRecord> records;
        for (const char* name : {"tri.gltf", "tri.bin", "red.png"}) {
            const fs::path path = models() / name;
            records.push_back({kLabel,
                               static_cast<int>(records.size()),
                               path,
                               {fs::file_size(path), sha256sum(path)}});
        }
        return records;
    }

    // An interrupted session, as a killed process leaves it (study_crash_test kills real
    // ones): its last trial undecided and its status not completed.
    void interrupt(std::int64_t session) const {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open(db_.c_str(), &db), SQLITE_OK);
        const std::string id = std::to_string(session);
        const std::string sql =
            "UPDATE trials SET decided = 0, choice = NULL, chosen_mode = NULL, valid = NULL, "
            "switches = NULL, time_label1_ns = NULL, time_label2_ns = NULL, "
            "decision_time_ns = NULL, decided_utc = NULL WHERE session_id = " +
            id +
            " AND trial_index = (SELECT max(trial_index) FROM trials WHERE session_id = " + id +
            "); UPDATE sessions SET status = 'aborted' WHERE id = " + id + ";";
        EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK)
            << sqlite3_errmsg(db);
        sqlite3_close(db);
    }

    study::SessionInfo session(std::int64_t id) const {
        auto store = study::StudyStore::open(db_);
        EXPECT_TRUE(store.ok()) << store.error().message;
        return (*store)->session(id).value_or_throw();
    }

    fs::path dir_;
    fs::path db_;
};

TEST_F(StudySceneFiles, ASessionRecordsEveryFileAsSha256sumSeesIt) {
    const fs::path protocol = write_protocol(std::string("[\"beams\", \"") + kLabel + "\"]");
    std::string output;
    ASSERT_EQ(run(monoplane("protocol check " + protocol.string()), &output), 0) << output;
    EXPECT_TRUE(
        contains(output, std::string("scene file:    ") + kLabel + ": 1 triangle in 1 chunk\n"))
        << output;
    const std::vector<study::SceneFileRecord> expected = expected_records();
    for (const study::SceneFileRecord& r : expected) {
        // The line `sha256sum` prints, verbatim.
        EXPECT_TRUE(contains(output, r.digest.sha256 + "  " + r.path.string())) << output;
    }

    run_session(protocol, "P01");
    const study::SessionInfo info = session(1);
    EXPECT_EQ(info.status, study::SessionStatus::Completed);
    EXPECT_EQ(info.scene_files, expected);
    auto store = study::StudyStore::open(db_).value_or_throw();
    std::map<std::string, int> trials_by_scene;
    for (const study::TrialRecord& t : store->trials(1).value_or_throw())
        ++trials_by_scene[t.trial.scene];
    EXPECT_EQ(trials_by_scene, (std::map<std::string, int>{{"beams", 2}, {kLabel, 2}}));

    // JSON: each trial of the imported scene lists the three files; beams' trials none.
    const fs::path json_file = dir_ / "trials.json";
    ASSERT_EQ(run(monoplane("study export --db " + db_.string() + " --format json --out " +
                            json_file.string()),
                  &output),
              0)
        << output;
    const nlohmann::json json = nlohmann::json::parse(read_text(json_file));
    ASSERT_EQ(json.size(), 4u);
    for (const nlohmann::json& trial : json) {
        const nlohmann::json& files = trial.at("scene_files");
        if (trial.at("scene") == "beams") {
            EXPECT_TRUE(files.empty());
            continue;
        }
        ASSERT_EQ(trial.at("scene"), kLabel);
        ASSERT_EQ(files.size(), 3u);
        for (std::size_t i = 0; i < 3; ++i) {
            const study::SceneFileRecord& r = expected[i];
            EXPECT_EQ(files[i].at("path"), r.path.string());
            EXPECT_EQ(files[i].at("sha256"), r.digest.sha256);
            EXPECT_EQ(files[i].at("size_bytes"), r.digest.size_bytes);
            EXPECT_EQ(files[i].at("file_index"), i);
        }
    }
    // CSV: the label as written; analyze takes it as a scene name like any other.
    const fs::path csv = dir_ / "trials.csv";
    ASSERT_EQ(
        run(monoplane("study export --db " + db_.string() + " --format csv --out " + csv.string()),
            &output),
        0);
    EXPECT_TRUE(contains(read_text(csv), std::string(",") + kLabel + ",3,")) << read_text(csv);
    ASSERT_EQ(
        run(monoplane("analyze --db " + db_.string() + " --out " + (dir_ / "analysis").string()),
            &output),
        0)
        << output;
    EXPECT_TRUE(contains(read_text(dir_ / "analysis" / "rates_by_scene.csv"), kLabel));
    // Per-scene figure files take the label with '/' replaced: no folder is named by accident.
    EXPECT_TRUE(fs::exists(dir_ / "analysis" / "figures" / "psychometric_models_tri.gltf.svg"));
}

TEST_F(StudySceneFiles, ABrokenSceneFileRefusesTheSessionBeforeItBegins) {
    fs::remove(models() / "tri.bin");
    const fs::path protocol = write_protocol(std::string("[\"") + kLabel + "\"]");
    std::string output;
    ASSERT_EQ(run(monoplane("protocol check " + protocol.string()), &output), 1) << output;
    // The protocol, the scenes entry and the loader's message, which names the missing file.
    EXPECT_TRUE(contains(output, "protocol '" + protocol.string() + "': scenes entry '" + kLabel +
                                     "' cannot be used: "))
        << output;
    EXPECT_TRUE(contains(output, "tri.bin")) << output;
    output = run_session(protocol, "P01", 1);
    EXPECT_TRUE(contains(output, "cannot be used")) << output;
    EXPECT_FALSE(fs::exists(db_)) << "nothing is written for a session that cannot begin";
}

TEST_F(StudySceneFiles, ResumeRefusesChangedOrMissingFilesNamingBothDigests) {
    const fs::path protocol = write_protocol(std::string("[\"") + kLabel + "\"]");
    run_session(protocol, "P01");
    interrupt(1);
    const std::vector<study::SceneFileRecord> recorded = expected_records();
    const std::string bin = read_text(models() / "tri.bin");
    std::ofstream(models() / "tri.bin", std::ios::binary | std::ios::app) << "changed";
    const std::string changed = sha256sum(models() / "tri.bin");
    fs::rename(models() / "red.png", dir_ / "red.png");

    std::string output;
    const std::string resume = monoplane("study resume --db " + db_.string());
    ASSERT_EQ(run(resume, &output), 1) << output;
    EXPECT_TRUE(contains(output, (models() / "tri.bin").string() + " changed: recorded sha256 " +
                                     recorded[1].digest.sha256 + " (" +
                                     std::to_string(recorded[1].digest.size_bytes) +
                                     " bytes), now sha256 " + changed))
        << output;
    EXPECT_TRUE(contains(output, (models() / "red.png").string() + " cannot be read")) << output;
    EXPECT_TRUE(contains(output, "--accept-changed-scenes")) << output;
    EXPECT_EQ(session(1).status, study::SessionStatus::Aborted) << "refused before anything ran";

    // The files as they were: the session resumes and finishes, with no note.
    std::ofstream(models() / "tri.bin", std::ios::binary | std::ios::trunc) << bin;
    fs::rename(dir_ / "red.png", models() / "red.png");
    ASSERT_EQ(run(resume, &output), 0) << output;
    EXPECT_EQ(session(1).status, study::SessionStatus::Completed);
    EXPECT_TRUE(session(1).notes.empty());
}

TEST_F(StudySceneFiles, AnAcceptedChangeIsRecordedInTheSessionsNotes) {
    const fs::path protocol = write_protocol(std::string("[\"") + kLabel + "\"]");
    run_session(protocol, "P01");
    interrupt(1);
    const std::vector<study::SceneFileRecord> recorded = expected_records();
    const std::string before = sha256sum(models() / "red.png");
    std::ofstream(models() / "red.png", std::ios::binary | std::ios::app) << "x";  // still a PNG
    const std::string after = sha256sum(models() / "red.png");
    std::string output;
    ASSERT_EQ(
        run(monoplane("study resume --db " + db_.string() + " --accept-changed-scenes"), &output),
        0)
        << output;
    const study::SessionInfo info = session(1);
    EXPECT_EQ(info.status, study::SessionStatus::Completed);
    ASSERT_EQ(info.notes.size(), 1u);
    const std::string& note = info.notes[0].text;
    EXPECT_TRUE(contains(note, "study resume --accept-changed-scenes")) << note;
    EXPECT_TRUE(contains(note, "red.png changed: recorded sha256 " + before)) << note;
    EXPECT_TRUE(contains(note, "now sha256 " + after)) << note;
    EXPECT_EQ(info.scene_files, recorded) << "the record keeps the digests the session began with";
    const fs::path json_file = dir_ / "trials.json";
    ASSERT_EQ(run(monoplane("study export --db " + db_.string() + " --format json --out " +
                            json_file.string()),
                  &output),
              0);
    const nlohmann::json json = nlohmann::json::parse(read_text(json_file));
    EXPECT_EQ(json.at(0).at("session_notes").at(0).at("note"), note);
}

// --headset simulated renders the file: the trial's frames show the red triangle, which no
// built-in scene has. Tiny: one trial, eyes at a tenth of the Vive's size, 20 Hz, and the
// simulated runtime's controller (a trigger press switches, a trackpad press confirms: the
// controller mapping of docs/headsets.md) decides within a second of virtual time.
TEST_F(StudySceneFiles, ASimulatedHeadsetSessionRendersTheImportedScene) {
    const fs::path protocol = write_protocol(std::string("[\"") + kLabel + "\"]", "[3]");
    const fs::path frames = dir_ / "frames";
    const fs::path script = dir_ / "controller.toml";
    {
        std::ofstream out(script);
        out << "hmd = \"vive\"\ndisplay_rate_hz = 20\n"
            << "interaction_profile = \"/interaction_profiles/htc/vive_controller\"\n"
            << "dump_dir = \"" << frames.string() << "\"\n";
        // Pairs every half second: whichever falls before the trial shows is refused, the
        // session ends at the first confirmation after both labels were seen.
        for (int k = 0; k < 20; ++k) {
            out << "[[input]]\nt = " << 0.5 * k + 0.1
                << "\npath = \"/user/hand/right/input/trigger/click\"\nduration = 0.1\n"
                << "[[input]]\nt = " << 0.5 * k + 0.35
                << "\npath = \"/user/hand/right/input/trackpad/click\"\nduration = 0.1\n";
        }
    }
    std::string output;
    ASSERT_EQ(run(monoplane("--validation study run --protocol " + protocol.string() +
                            " --participant H1 --db " + db_.string() +
                            " --headset simulated --observer none --sim-script " + script.string() +
                            " --window off --resolution-scale 0.1 --neutral-s 0.2 --seed 3"),
                  &output),
              0)
        << output;
    const study::SessionInfo info = session(1);
    EXPECT_EQ(info.status, study::SessionStatus::Completed);
    EXPECT_EQ(info.scene_files, expected_records());
    auto store = study::StudyStore::open(db_).value_or_throw();
    std::int64_t shown = -1;
    for (const study::TrialEvent& e : store->events(1).value_or_throw())
        if (e.kind == study::EventKind::Shown && shown < 0) shown = e.frame;
    ASSERT_GE(shown, 0);
    char name[64];
    std::snprintf(name, sizeof name, "frame_%06lld_left.png", static_cast<long long>(shown));
    int width = 0, height = 0, channels = 0;
    unsigned char* rgba = stbi_load((frames / name).c_str(), &width, &height, &channels, 4);
    ASSERT_NE(rgba, nullptr) << (frames / name);
    // Lit, tone-mapped and with the sky's reflection the red texture shows as about (223, 146,
    // 139) on llvmpipe; the ground (about 173, 165, 150) and the sky (blue above red) are far from
    // it, and so are the label digits (white and grey).
    std::size_t red = 0;
    for (int i = 0; i < width * height; ++i) {
        const unsigned char* p = rgba + 4 * i;
        red += p[0] > 96 && p[0] > p[1] + 40 && p[0] > p[2] + 40;
    }
    stbi_image_free(rgba);
    // The triangle covers about 3.5 % of the eye (703 of 20,234 pixels when this was written).
    EXPECT_GT(red, static_cast<std::size_t>(width * height) / 100) << red << " red pixels";
}

}  // namespace
}  // namespace monoplane
