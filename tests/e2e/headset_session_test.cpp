// A whole demo-protocol session through the simulated OpenXR runtime (issue 6, item 5): the
// monoplane executable runs `study run --headset simulated` with controller input from a simxr
// script (HTC Vive controllers: trigger switches, trackpad confirms), the Khronos validation
// layer on; then the database is checked (every trial decided, every switch logged with the index
// of the frame that showed it, the questionnaire answered through the controller) and the frames
// the runtime dumped are compared: label 1 and label 2 of a trial differ where stereo and hybrid
// differ, and two frames of the same label do not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <stb/stb_image.h>

#include "study/study_store.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

std::string source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir ? dir : ".";
}

int run(const std::string& command, std::string* output = nullptr) {
    fs::create_directories(test_folder());
    const std::string log = (test_folder() / "command.log").string();
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    if (output) *output = text.str();
    return WEXITSTATUS(status);
}

struct Png {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
};

Png load(const fs::path& path) {
    Png png;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 4);
    if (data) {
        png.rgba.assign(data, data + std::size_t(png.width) * png.height * 4);
        stbi_image_free(data);
    }
    return png;
}

// Mean absolute channel difference over rows [row0, row1).
double mean_difference(const Png& a, const Png& b, int row0, int row1) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = row0; y < row1; ++y) {
        for (int x = 0; x < a.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = (std::size_t(y) * a.width + x) * 4 + c;
                sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
                ++n;
            }
        }
    }
    return n ? sum / n : 0.0;
}

// The share of pixels in rows [row0, row1) whose channels differ at all.
double differing_pixels(const Png& a, const Png& b, int row0, int row1) {
    std::size_t differ = 0, n = 0;
    for (int y = row0; y < row1; ++y) {
        for (int x = 0; x < a.width; ++x, ++n) {
            const std::size_t i = (std::size_t(y) * a.width + x) * 4;
            differ += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] ||
                      a.rgba[i + 2] != b.rgba[i + 2];
        }
    }
    return n ? double(differ) / double(n) : 0.0;
}

fs::path frame_png(const fs::path& dir, std::int64_t frame, const char* eye) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%06lld_%s.png", static_cast<long long>(frame), eye);
    return dir / name;
}

class HeadsetSessionTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "frames");
    }
    fs::path dir_;
};

// The controller's script: a Vive trigger press (switch) every 0.5 s and a trackpad press
// (confirm) 0.25 s after each, for 40 s. With a 0.3 s neutral screen the presses fall on every
// phase of a trial: switches before label 1 shows are refused, confirmations before both labels
// were seen are refused and logged, the rest decide; in the questionnaire the trigger moves the
// selection and the trackpad answers.
std::string controller_script(const fs::path& frames) {
    std::ostringstream s;
    s << "hmd = \"vive\"\n"
      << "display_rate_hz = 20\n"
      << "interaction_profile = \"/interaction_profiles/htc/vive_controller\"\n"
      << "dump_dir = \"" << frames.string() << "\"\n";
    for (int k = 0; k < 80; ++k) {
        s << "[[input]]\nt = " << 0.5 * k + 0.1
          << "\npath = \"/user/hand/right/input/trigger/click\"\nduration = 0.1\n";
        s << "[[input]]\nt = " << 0.5 * k + 0.35
          << "\npath = \"/user/hand/right/input/trackpad/click\"\nduration = 0.1\n";
    }
    return s.str();
}

TEST_F(HeadsetSessionTest, DemoSessionThroughTheSimulatedRuntime) {
    const fs::path script = dir_ / "controller.toml";
    std::ofstream(script) << controller_script(dir_ / "frames");
    const fs::path db = dir_ / "demo.sqlite";
    std::string output;
    const int rc =
        run(std::string(MONOPLANE_EXE) + " --validation study run --protocol " + source_dir() +
                "/protocols/demo.toml --participant E2E --db " + db.string() +
                " --headset simulated --observer none --sim-script " + script.string() +
                " --window off --detail test --resolution-scale 0.1 --neutral-s 0.3 "
                "--seed 11",
            &output);
    ASSERT_EQ(rc, 0) << output;

    auto store = study::StudyStore::open(db);
    ASSERT_TRUE(store) << store.error().message;
    const auto info = (*store)->session(1);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->status, study::SessionStatus::Completed);
    EXPECT_NE(info->runtime.find("simxr"), std::string::npos) << info->runtime;
    const auto trials = (*store)->trials(1);
    ASSERT_TRUE(trials);
    ASSERT_EQ(trials->size(), 7u);  // demo.toml: 3 scenes x 2 distances + 1 practice
    for (const auto& t : *trials) {
        EXPECT_TRUE(t.decided) << "trial " << t.trial.index;
        EXPECT_TRUE(t.outcome.valid) << "trial " << t.trial.index;
        EXPECT_GE(t.outcome.switches, 1);
    }
    const auto events = (*store)->events(1);
    ASSERT_TRUE(events);
    int switched = 0, refused = 0;
    for (const auto& e : *events) {
        if (e.kind == study::EventKind::Switched || e.kind == study::EventKind::Shown) {
            EXPECT_GE(e.frame, 0) << "trial " << e.trial_index;
        }
        switched += e.kind == study::EventKind::Switched;
        refused += e.kind == study::EventKind::Refused;
    }
    int counted = 0;
    for (const auto& t : *trials) counted += t.outcome.switches;
    EXPECT_EQ(switched, counted);
    EXPECT_GT(refused, 0);  // the script confirms too early in some trials
    // Every button press is logged with its source, whatever it changed: a switch that showed
    // the other label was a press, and so were the refused ones.
    const auto presses = (*store)->presses(1);
    ASSERT_TRUE(presses) << presses.error().message;
    int switch_presses = 0;
    for (const auto& p : *presses) {
        EXPECT_EQ(p.source, study::PressSource::Controller);
        EXPECT_EQ(p.key, "");
        switch_presses += p.action == study::PressAction::Switch;
    }
    EXPECT_GE(switch_presses, switched);
    EXPECT_GT(presses->size(), static_cast<std::size_t>(switched + refused));

    // A data trial comparing stereo with hybrid at m = 3: its label 1 and label 2 frames.
    const study::TrialRecord* chosen = nullptr;
    for (const auto& t : *trials) {
        if (!t.trial.practice && t.trial.mono_plane == 3.0) chosen = &t;
    }
    ASSERT_NE(chosen, nullptr);
    std::int64_t shown = -1, switched_to_2 = -1;
    for (const auto& e : *events) {
        if (e.trial_index != chosen->trial.index) continue;
        if (e.kind == study::EventKind::Shown) shown = e.frame;
        if (e.kind == study::EventKind::Switched && e.label == 2 && switched_to_2 < 0)
            switched_to_2 = e.frame;
    }
    ASSERT_GE(shown, 0);
    ASSERT_GT(switched_to_2, shown + 1);
    const Png label1 = load(frame_png(dir_ / "frames", shown, "left"));
    const Png label1_later = load(frame_png(dir_ / "frames", shown + 1, "left"));
    const Png label2 = load(frame_png(dir_ / "frames", switched_to_2, "left"));
    ASSERT_GT(label1.width, 0);
    ASSERT_EQ(label1.width, label2.width);
    ASSERT_EQ(label1.width, label1_later.width);
    // The upper half holds the scene beyond the label: the modes differ there (hybrid maps C's
    // image beyond m = 3), the same label on a still head does not.
    const int half = label1.height / 2;
    EXPECT_GT(mean_difference(label1, label2, 0, half), 0.05);
    EXPECT_EQ(mean_difference(label1, label1_later, 0, half), 0.0);
    // The label itself (lower part) differs between "1" and "2".
    EXPECT_GT(mean_difference(label1, label2, half, label1.height), 0.0);

    // What the runtime located reached the rig: the headset's frame of label 1 equals the
    // `render` command's image of the same scene, mode and m from the scene's viewpoint with the
    // Vive profile's frusta and IPD (simxr reports those; the seat is the first tracked pose).
    const std::string mode(study::render_mode_name(chosen->trial.label1_mode));
    const fs::path reference = dir_ / "reference";
    ASSERT_EQ(run(std::string(MONOPLANE_EXE) + " render --scene " + chosen->trial.scene +
                  " --mode " + mode + " --mono-plane 3 --hmd vive --detail test --width " +
                  std::to_string(label1.width) + " --height " + std::to_string(label1.height) +
                  " --out " + reference.string()),
              0);
    const Png rendered = load(reference / "left.png");
    ASSERT_EQ(rendered.width, label1.width);
    ASSERT_EQ(rendered.height, label1.height);
    // Poses cross OpenXR as floats (XrPosef): a few edge pixels may round the other way.
    EXPECT_LT(differing_pixels(label1, rendered, 0, half), 0.002);
    EXPECT_LT(mean_difference(label1, rendered, 0, half), 0.01);
    // The other mode differs in far more pixels: the comparison above is a real constraint.
    EXPECT_GT(differing_pixels(label1, label2, 0, half), 0.01);
}

// The runtime loses the session mid-study (LOSS_PENDING, as when a headset is unplugged): the
// command ends with the lost runtime's exit status and message (tests/e2e/runtime_lost_test.cpp
// checks them word for word), every decision made so far is stored, and `study resume` on a
// fresh simulated headset finishes the session.
TEST_F(HeadsetSessionTest, LostSessionIsResumable) {
    std::string script = controller_script(dir_ / "frames");
    const fs::path lossy = dir_ / "lossy.toml";
    std::ofstream(lossy) << "lose_session_at_s = 4.0\n" << script;
    const fs::path db = dir_ / "lost.sqlite";
    const std::string common = std::string(MONOPLANE_EXE) + " --validation study ";
    std::string output;
    const int rc = run(
        common + "run --protocol " + source_dir() + "/protocols/demo.toml --participant L --db " +
            db.string() + " --headset simulated --observer none --sim-script " + lossy.string() +
            " --window off --detail test --resolution-scale 0.1 --neutral-s 0.3 --seed 5",
        &output);
    EXPECT_EQ(rc, 3) << output;
    EXPECT_NE(output.find("the OpenXR runtime was lost"), std::string::npos) << output;
    EXPECT_NE(output.find("study resume"), std::string::npos) << output;
    int decided_before = 0;
    {
        auto store = study::StudyStore::open(db);
        ASSERT_TRUE(store) << store.error().message;
        EXPECT_EQ((*store)->session(1)->status, study::SessionStatus::Running);
        const auto trials = (*store)->trials(1);
        ASSERT_TRUE(trials);
        for (const auto& t : *trials) decided_before += t.decided;
    }
    EXPECT_GT(decided_before, 0);
    EXPECT_LT(decided_before, 7);

    const fs::path fresh = dir_ / "fresh.toml";
    std::ofstream(fresh) << script;
    ASSERT_EQ(run(common + "resume --db " + db.string() +
                      " --headset simulated --observer none --sim-script " + fresh.string() +
                      " --window off --detail test --resolution-scale 0.1 --neutral-s 0.3",
                  &output),
              0)
        << output;
    auto store = study::StudyStore::open(db);
    ASSERT_TRUE(store);
    EXPECT_EQ((*store)->session(1)->status, study::SessionStatus::Completed);
    const auto trials = (*store)->trials(1);
    ASSERT_TRUE(trials);
    int decided = 0;
    for (const auto& t : *trials) decided += t.decided;
    EXPECT_EQ(decided, 7);
}

// The frame and head log on the path participants use (issue 17 item 4): simxr makes every 8th
// frame one display slot late (missed_slot_every); the log marks exactly those frames missed
// (derived here from the frame indices alone), every frame has the head and every scene frame its
// GPU time, and analyze flags every data trial (1 in 8 frames missed is above the protocol's 5 %).
// Heads turn (issue 29): every frame sees a new view, and once a screen has shown for a few
// frames the renderer builds nothing: no pipeline after the first frame, and no shader the
// driver compiles (where it can be counted: lavapipe) in a frame of a trial's scene showing what
// the three frames before it showed.
// distinct_views: the least share of frames whose head orientation no earlier frame had.
void expect_nothing_built_while_the_head_turns(const std::vector<study::FrameRecord>& frames,
                                               double distinct_views) {
    std::set<std::array<double, 4>> orientations;
    int counted = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const study::FrameRecord& f = frames[i];
        ASSERT_TRUE(f.pipelines_created.has_value()) << "frame " << f.frame;
        if (i > 0) {
            EXPECT_EQ(*f.pipelines_created, 0) << "frame " << f.frame << " " << f.shown;
        }
        if (f.head) orientations.insert({(*f.head)[3], (*f.head)[4], (*f.head)[5], (*f.head)[6]});
        // A screen's first frames may still compile what they are the first to draw, and the
        // driver compiles a frame's work while it runs, up to three frames later (two in flight).
        const auto same = [&](std::size_t back) {
            return i >= back && frames[i - back].trial_index == f.trial_index &&
                   frames[i - back].shown == f.shown;
        };
        const bool scene = f.shown == "label1" || f.shown == "label2";
        const bool steady = scene && same(1) && same(2) && same(3);
        if (!steady || !f.driver_compiles) continue;
        ++counted;
        EXPECT_EQ(*f.driver_compiles, 0) << "frame " << f.frame << " " << f.shown;
    }
    EXPECT_GT(static_cast<double>(orientations.size()),
              distinct_views * static_cast<double>(frames.size()))
        << "the head turns";
    // Counted at all (an LLVM-based driver such as lavapipe; turning_head_test checks that the
    // count is live there): then in every steady frame.
    if (frames.back().driver_compiles) {
        EXPECT_GT(counted, 50);
    }
}

TEST_F(HeadsetSessionTest, MissedSlotsAreLoggedPerFrameAndFlaggedPerTrial) {
    const fs::path script = dir_ / "late.toml";
    // 5 Hz: the default observer looks for seconds per trial on the virtual clock; fewer frames
    // per virtual second keep the test short, and 1 in 8 late is still above the 5 % flag. The
    // head moves as a seated participant's does (the default of `--headset simulated`).
    std::ofstream(script)
        << "hmd = \"vive\"\ndisplay_rate_hz = 5\nmissed_slot_every = 8\nhead_motion = \"seated\"\n";
    const fs::path db = dir_ / "late.sqlite";
    std::string output;
    ASSERT_EQ(run(std::string(MONOPLANE_EXE) + " --validation study run --protocol " +
                      source_dir() + "/protocols/demo.toml --participant M --db " + db.string() +
                      " --headset simulated --observer default --sim-script " + script.string() +
                      " --window off --detail test --resolution-scale 0.1 --neutral-s 0.3 "
                      "--seed 5",
                  &output),
              0)
        << output;
    {
        auto store = study::StudyStore::open(db);
        ASSERT_TRUE(store) << store.error().message;
        const auto frames = (*store)->frames(1);
        ASSERT_TRUE(frames) << frames.error().message;
        ASSERT_GT(frames->size(), 100u);
        int missed = 0;
        int scene_frames = 0;
        for (std::size_t i = 1; i < frames->size(); ++i) {
            const study::FrameRecord& f = (*frames)[i];
            ASSERT_EQ(f.frame, (*frames)[i - 1].frame + 1) << "every displayed frame is logged";
            EXPECT_EQ(f.missed, f.frame % 8 == 0) << "frame " << f.frame;
            // simxr always tracks: every frame has the head, neutral screens too.
            EXPECT_TRUE(f.head.has_value()) << "frame " << f.frame << " (" << f.shown << ")";
            missed += f.missed;
            if (f.shown == "label1" || f.shown == "label2") {
                ++scene_frames;
                EXPECT_TRUE(f.gpu_ms.has_value()) << "frame " << f.frame;
                EXPECT_TRUE(f.trial_index.has_value()) << "frame " << f.frame;
            }
        }
        EXPECT_GT(missed, 10);
        EXPECT_GT(scene_frames, 50);
        expect_nothing_built_while_the_head_turns(*frames, 0.9);  // simxr: a new view each frame
    }
    // The session's summary says so too.
    EXPECT_NE(output.find("builds while frames ran: 0 pipelines created after the first frame"),
              std::string::npos)
        << output;
    const fs::path report = dir_ / "analysis";
    ASSERT_EQ(run(std::string(MONOPLANE_EXE) + " analyze --db " + db.string() + " --out " +
                      report.string(),
                  &output),
              0)
        << output;
    std::ifstream in(report / "summary.json");
    std::stringstream summary;
    summary << in.rdbuf();
    // demo.toml: 6 data trials after 1 practice trial, each about 1 frame in 8 late.
    EXPECT_NE(summary.str().find("\"trials_with_log\": 6,\n    \"flagged\": 6,"), std::string::npos)
        << summary.str().substr(0, 2000);
}

// On Monado, the open-source runtime most Linux headsets use (docs/headsets.md says how to build
// it; Debian 12 does not package it): set MONOPLANE_MONADO_RUNTIME_JSON to its manifest
// (openxr_monado-dev.json of a build with the null compositor runs headless on its simulated
// HMD, whose head wobbles). The demo runs to the end with both validation layers on and no
// message, and nothing is built while the head moves.
TEST_F(HeadsetSessionTest, DemoSessionOnMonado) {
    const char* manifest = std::getenv("MONOPLANE_MONADO_RUNTIME_JSON");
    if (manifest == nullptr || *manifest == '\0') {
        GTEST_SKIP() << "set MONOPLANE_MONADO_RUNTIME_JSON to a Monado runtime manifest to run";
    }
    const fs::path db = dir_ / "monado.sqlite";
    std::string output;
    ASSERT_EQ(run("XR_RUNTIME_JSON=" + std::string(manifest) + " " + MONOPLANE_EXE +
                      " --validation study run --protocol " + source_dir() +
                      "/protocols/demo.toml --participant MONADO --db " + db.string() +
                      " --headset openxr --observer default --window off --detail test "
                      "--resolution-scale 0.2 --neutral-s 0.3 --seed 11864227553095332889",
                  &output),
              0)
        << output;
    auto store = study::StudyStore::open(db);
    ASSERT_TRUE(store) << store.error().message;
    const auto info = (*store)->session(1);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->status, study::SessionStatus::Completed);
    EXPECT_NE(info->runtime.find("Monado"), std::string::npos) << info->runtime;
    const auto frames = (*store)->frames(1);
    ASSERT_TRUE(frames) << frames.error().message;
    ASSERT_GT(frames->size(), 60u);
    // Monado's simulated HMD wobbles, holding some poses for more than a frame.
    expect_nothing_built_while_the_head_turns(*frames, 0.25);
}

// Memory stays bounded however long a session runs (issue 29): 3,000 frames of one trial with
// the head turning, until the runtime ends the session (exit_after_s). The session's summary
// gives resident memory after 300 frames and at the end. With the culling constants in a uniform
// buffer lavapipe grew about 0.55 MB a frame (1.5 GB here); the bound, 16 MiB (5 KiB a frame),
// leaves room for the frame log's queued rows and the allocator's arenas.
TEST_F(HeadsetSessionTest, ALongSessionKeepsResidentMemoryBounded) {
    const fs::path script = dir_ / "long.toml";
    std::ofstream(script) << "hmd = \"vive\"\ndisplay_rate_hz = 30\nhead_motion = \"seated\"\n"
                             "exit_after_s = 100\n";
    // The demo design without its instruction page: no one confirms a page here.
    const fs::path protocol = dir_ / "long-protocol.toml";
    std::ofstream(protocol) << "name = \"long\"\nscenes = [\"beams\", \"landscape\", "
                               "\"spheres\"]\nmono_planes = [3, 8]\n"
                               "alternatives = [\"stereo\", \"hybrid\"]\n";
    std::string output;
    // No one answers (--observer none and no scripted presses): the first trial shows until the
    // runtime asks monoplane to exit, which leaves the session resumable.
    run(std::string(MONOPLANE_EXE) + " study run --protocol " + protocol.string() +
            " --participant LONG --db " + (dir_ / "long.sqlite").string() +
            " --headset simulated --observer none --sim-script " + script.string() +
            " --window off --detail test --resolution-scale 0.05 --seed 5",
        &output);
    const std::size_t at = output.find("resident memory: ");
    ASSERT_NE(at, std::string::npos) << output;
    double after_warmup = 0.0, at_end = 0.0, growth = 0.0;
    int warmup_frames = 0, frames = 0;
    ASSERT_EQ(std::sscanf(output.c_str() + at,
                          "resident memory: %lf MiB after %d frames, %lf MiB after %d (%lf MiB)",
                          &after_warmup, &warmup_frames, &at_end, &frames, &growth),
              5)
        << output.substr(at);
    EXPECT_EQ(warmup_frames, 300);
    EXPECT_GE(frames, 2900);
    EXPECT_NEAR(growth, at_end - after_warmup, 0.11);
    EXPECT_LT(growth, 16.0) << output.substr(at);
}

TEST(HeadsetWithoutRuntime, ClearMessageAndNonZeroExit) {
    const fs::path dir = test_folder() / "run";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string output;
    const int rc = run("XR_RUNTIME_JSON=" + (dir / "missing.json").string() + " " +
                           std::string(MONOPLANE_EXE) + " study run --protocol " + source_dir() +
                           "/protocols/demo.toml --participant P --db " +
                           (dir / "db.sqlite").string() + " --headset openxr --window off",
                       &output);
    EXPECT_NE(rc, 0);
    EXPECT_LT(rc, 128) << "crashed: " << output;
    EXPECT_NE(output.find("OpenXR runtime"), std::string::npos) << output;
    EXPECT_NE(output.find("--headset simulated"), std::string::npos) << output;
}

}  // namespace
}  // namespace monoplane
