// Each eye's depth through XR_KHR_composition_layer_depth (issue 18, item 3): `monoplane
// --validation study run --headset simulated` on a one-trial BEAMS protocol (stereo against
// hybrid at m = 3), simxr dumping every frame's depth as PFM (the distance in front of each eye,
// decoded with the layer's own minDepth, maxDepth, nearZ and farZ; docs/simxr.md). The dumped
// distances are checked against BEAMS' flat ground (y = 0, the eyes 1.7 m above it at the
// scene's viewpoint, looking level): the pixel row with vertical tangent ty < 0 meets it at
// 1.7 / -ty metres along the eye's axis, and nothing lies below it; in hybrid, beyond m, the
// distance C sees through the mono plane instead (below). The sky, the neutral screen, the
// questionnaire and the label are at infinity. Then the same with TAA and SSAO, and with MSAA
// over two-pass and geometry-shader stereo (each leaves the renderer's depth in another layout
// or image; validation would object to a wrong one); and with --layer-depth off, no depth at all.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "study/study_store.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

int run(const std::string& command, std::string* output) {
    fs::create_directories(test_folder());
    const std::string log = (test_folder() / "command.log").string();
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    *output = text.str();
    return WEXITSTATUS(status);
}

// A PFM file: "Pf\n<width> <height>\n<scale>\n", a negative scale for little-endian floats,
// then the rows from the bottom up. Held here top row first, like the eye's image.
struct Pfm {
    int width = 0, height = 0;
    std::vector<float> top_down;
    float at(int x, int y) const { return top_down[std::size_t(y) * width + x]; }
};

Pfm load_pfm(const fs::path& path) {
    Pfm pfm;
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    double scale = 0.0;
    in >> magic >> pfm.width >> pfm.height >> scale;
    in.get();  // the single whitespace character after the scale
    if (!in || magic != "Pf" || scale >= 0.0 || pfm.width <= 0 || pfm.height <= 0) return {};
    std::vector<float> bottom_up(std::size_t(pfm.width) * pfm.height);
    // This test runs on little-endian hosts (x86, arm64), where the bytes are the floats.
    in.read(reinterpret_cast<char*>(bottom_up.data()),
            static_cast<std::streamsize>(bottom_up.size() * sizeof(float)));
    if (!in) return {};
    pfm.top_down.resize(bottom_up.size());
    for (int y = 0; y < pfm.height; ++y) {
        std::memcpy(&pfm.top_down[std::size_t(y) * pfm.width],
                    &bottom_up[std::size_t(pfm.height - 1 - y) * pfm.width],
                    std::size_t(pfm.width) * sizeof(float));
    }
    return pfm;
}

fs::path depth_file(const fs::path& dir, std::int64_t frame, const char* eye) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%06lld_%s_depth.pfm", static_cast<long long>(frame),
                  eye);
    return dir / name;
}

// The Vive's calibrated frusta and IPD (hmd/profiles/vive.toml), which simxr reports.
struct EyeFrustum {
    const char* name;
    double left, right, up, down;
};
constexpr EyeFrustum kEyes[2] = {{"left", -1.391937, 1.247409, 1.464287, -1.468819},
                                 {"right", -1.246557, 1.398447, 1.472458, -1.465505}};
constexpr double kIpd = 0.064;
constexpr double kEyeHeight = 1.7;  // BEAMS' viewpoint "default": (0, 1.7, 0), looking level
constexpr double kMonoPlane = 3.0;
// C sits s behind the eyes where their outer frustum planes meet (papers/000 Sect. 3, eq. 1).
const double kMonoBehind = std::max(kIpd / (2.0 * -kEyes[0].left), kIpd / (2.0 * kEyes[1].right));

double tan_y(const EyeFrustum& eye, double row, int height) {
    return eye.up - (row + 0.5) / height * (eye.up - eye.down);
}

// The ground along the pixel row's ray (ty < 0): a point s metres along the eye's axis lies
// s * ty below the eye.
double ground_distance(double ty) {
    return kEyeHeight / -ty;
}

// Hybrid beyond m: the eye shows what C sees through the pixel's point on the mono plane,
// P = (x, 1.7 + m ty, -m) relative to the eyes' centre, with C at (0, 1.7, s). C's ray reaches the
// ground y = 0 at parameter 1.7 / (-m ty) from C towards P, i.e. at depth
// (1.7 / -ty) (m + s) / m - s in front of the eyes' plane: the distance the composite writes.
double mono_ground_depth(double ty) {
    return ground_distance(ty) * (kMonoPlane + kMonoBehind) / kMonoPlane - kMonoBehind;
}

// What the session showed in each frame, and in which mode each label was.
struct Session {
    std::vector<study::FrameRecord> frames;
    std::string label1_mode, label2_mode;
    // The n-th frame (from 0) that showed `shown`, or -1.
    std::int64_t nth(const std::string& shown, int n) const {
        for (const auto& f : frames) {
            if (f.shown == shown && n-- == 0) return f.frame;
        }
        return -1;
    }
};

class HeadsetDepthTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "frames");
    }

    // Runs the one-trial protocol with these alternatives and [render] lines; the simple
    // controller switches at 1.0 s and confirms at 1.5 s, then answers the questionnaire.
    Session run_session(const std::string& alternatives, const std::string& render,
                        const std::string& extra_options = "", const std::string& hmd = "vive") {
        const fs::path protocol = dir_ / "depth.toml";
        std::ofstream(protocol) << "name = \"depth\"\nscenes = [\"beams\"]\nmono_planes = [3]\n"
                                << "alternatives = " << alternatives << "\n"
                                << "practice_trials = 0\n"
                                << "[questionnaire]\nscale_points = 5\nitems = [\"Depth?\"]\n"
                                << "[render]\n"
                                << render << "\n";
        const fs::path script = dir_ / "controller.toml";
        std::ofstream(script)
            << "hmd = \"" << hmd << "\"\ndisplay_rate_hz = 20\n"
            << "dump_dir = \"" << (dir_ / "frames").string() << "\"\n"
            << "[[input]]\nt = 1.0\npath = \"/user/hand/right/input/select/click\"\n"
            << "[[input]]\nt = 1.5\npath = \"/user/hand/left/input/select/click\"\n"
            << "[[input]]\nt = 2.3\npath = \"/user/hand/right/input/select/click\"\n"
            << "[[input]]\nt = 2.6\npath = \"/user/hand/left/input/select/click\"\n";
        const fs::path db = dir_ / "depth.sqlite";
        std::string output;
        const int rc =
            run(std::string(MONOPLANE_EXE) + " --validation study run --protocol " +
                    protocol.string() + " --participant D --db " + db.string() +
                    " --headset simulated --observer none --sim-script " + script.string() +
                    " --window off --detail test --resolution-scale 0.1 "
                    "--neutral-s 0.3 --seed 3 " +
                    extra_options,
                &output);
        EXPECT_EQ(rc, 0) << output;
        Session session;
        auto store = study::StudyStore::open(db);
        if (!store) {
            ADD_FAILURE() << store.error().message;
            return session;
        }
        EXPECT_EQ((*store)->session(1)->status, study::SessionStatus::Completed);
        session.frames = (*store)->frames(1).value_or_throw();
        const auto trials = (*store)->trials(1).value_or_throw();
        if (trials.size() == 1) {
            session.label1_mode = std::string(study::render_mode_name(trials[0].trial.label1_mode));
            session.label2_mode = std::string(study::render_mode_name(trials[0].trial.label2_mode));
        }
        return session;
    }

    Pfm depth(std::int64_t frame, const EyeFrustum& eye) const {
        return load_pfm(depth_file(dir_ / "frames", frame, eye.name));
    }

    fs::path dir_;
};

// Both eyes at infinity everywhere (no scene; nothing to reproject but the head's rotation).
void expect_all_infinite(const Pfm& pfm, const std::string& what) {
    ASSERT_GT(pfm.width, 0) << what;
    std::size_t finite = 0;
    for (float d : pfm.top_down) finite += !(std::isinf(d) && d > 0.0f);
    EXPECT_EQ(finite, 0u) << what;
}

// A scene frame of BEAMS against the ground's geometry. `slack_px`: how many pixel rows the
// sampled position may be off (TAA's jitter, MSAA's sample positions); 0 for exact pixel centres.
// Hybrid's far region always has a row's slack: the composite reads C's depth at the nearest of
// C's texels, which are no smaller than the eye's pixels (papers/000 Sect. 4.2, eq. 8).
// `ground_within`: only rows whose ground is nearer are checked against it (a canted eye's near
// region does not end at a row).
void expect_beams_depth(const Pfm& pfm, const EyeFrustum& eye, bool hybrid, double slack_px,
                        const std::string& what,
                        double ground_within = std::numeric_limits<double>::infinity()) {
    SCOPED_TRACE(what);
    ASSERT_GT(pfm.width, 0);
    const int w = pfm.width, h = pfm.height;
    // The label ("1" or "2"), centred at the direction (0, -0.55): at infinity.
    const int label_x = static_cast<int>((0.0 - eye.left) / (eye.right - eye.left) * w);
    const int label_y = static_cast<int>((eye.up + 0.55) / (eye.up - eye.down) * h);
    EXPECT_TRUE(std::isinf(pfm.at(label_x, label_y))) << pfm.at(label_x, label_y);
    const auto in_label = [&](int x, int y) {
        return std::abs(x - label_x) <= 4 && std::abs(y - label_y) <= 3;
    };
    // The depth expected at a row's ray, tangent ty: the ground, or beyond m in hybrid C's view
    // of it; nothing is expected within 0.3 m of m (the overlap, where either may show).
    const auto expected = [&](double ty) -> double {
        const double ground = ground_distance(ty);
        if (!hybrid || ground < kMonoPlane - 0.3) return ground;
        if (ground > kMonoPlane + 0.3) return mono_ground_depth(ty);
        return std::numeric_limits<double>::quiet_NaN();
    };
    const double tolerance = slack_px == 0.0 ? 1e-5 : 0.0;  // relative, float precision
    std::size_t sky = 0, above = 0, bottom = 0, bottom_on_ground = 0, far = 0, far_on_ground = 0;
    for (int y = 0; y < h; ++y) {
        const double ty = tan_y(eye, y, h);
        for (int x = 0; x < w; ++x) {
            const float d = pfm.at(x, y);
            ASSERT_TRUE(d > 0.0f) << "pixel " << x << ", " << y << ": " << d;
            if (ty > 0.05) {
                ++above;
                sky += std::isinf(d);
                continue;
            }
            if (ty > -0.05 || in_label(x, y) || ground_distance(ty) > ground_within) continue;
            // The depth range the row allows: its centre's, widened by the slack in rows (the
            // ground nears as the ray steepens).
            const bool mono = hybrid && ground_distance(ty) > kMonoPlane + 0.3;
            const double rows = mono ? std::max(slack_px, 1.0) : slack_px;
            const double nearest = expected(ty - rows * (eye.up - eye.down) / h);
            const double farthest = expected(ty + rows * (eye.up - eye.down) / h);
            if (std::isnan(nearest) || std::isnan(farthest)) continue;
            // Nothing is deeper than the ground: things stand on it.
            EXPECT_LE(d, farthest * (1.0 + tolerance)) << "pixel " << x << ", " << y;
            const bool on_ground =
                d >= nearest * (1.0 - tolerance) && d <= farthest * (1.0 + tolerance);
            // The lowest rows look at the ground right in front of the viewer, which is clear.
            if (ty < -1.2) {
                ++bottom;
                bottom_on_ground += on_ground;
            }
            if (mono) {
                ++far;
                far_on_ground += on_ground;
            }
        }
    }
    // BEAMS from its viewpoint: most of the upper half is sky.
    EXPECT_GT(sky, above / 2);
    ASSERT_GT(bottom, 0u);
    EXPECT_GE(bottom_on_ground, bottom * 99 / 100) << bottom_on_ground << " of " << bottom;
    if (hybrid && std::isinf(ground_within)) {
        // Beyond m the ground is C's (the beams standing on it cover much of it).
        ASSERT_GT(far, 0u);
        EXPECT_GT(far_on_ground, far / 4) << far_on_ground << " of " << far;
    }
}

TEST_F(HeadsetDepthTest, GroundSkyAndLabelAtTheirDistances) {
    const Session s = run_session("[\"stereo\", \"hybrid\"]", "anti_aliasing = \"none\"");
    ASSERT_FALSE(s.frames.empty());
    const bool hybrid_first = s.label1_mode == "hybrid";
    ASSERT_TRUE(hybrid_first || s.label2_mode == "hybrid");
    // A few frames into each label, and into the neutral screen and the questionnaire.
    const std::int64_t hybrid_frame = s.nth(hybrid_first ? "label1" : "label2", 3);
    const std::int64_t stereo_frame = s.nth(hybrid_first ? "label2" : "label1", 3);
    ASSERT_GE(hybrid_frame, 0);
    ASSERT_GE(stereo_frame, 0);
    for (const EyeFrustum& eye : kEyes) {
        expect_beams_depth(depth(stereo_frame, eye), eye, false, 0.0,
                           std::string("stereo, ") + eye.name);
        expect_beams_depth(depth(hybrid_frame, eye), eye, true, 0.0,
                           std::string("hybrid, ") + eye.name);
        expect_all_infinite(depth(s.nth("neutral", 2), eye), "neutral screen");
        expect_all_infinite(depth(s.nth("questionnaire", 2), eye), "questionnaire");

        // Hybrid's near region is the eye's own depth, the same as stereo's for the same pose;
        // beyond m it is C's, which differs (the same ground, seen from C's texels).
        const Pfm stereo = depth(stereo_frame, eye);
        const Pfm hybrid = depth(hybrid_frame, eye);
        std::size_t near_same = 0, near_count = 0, far_different = 0, far_count = 0;
        for (int y = 0; y < stereo.height; ++y) {
            const double ty = tan_y(eye, y, stereo.height);
            if (ty > -0.05) continue;
            for (int x = 0; x < stereo.width; ++x) {
                const float a = stereo.at(x, y), b = hybrid.at(x, y);
                if (std::isinf(a) || std::isinf(b)) continue;
                if (a < kMonoPlane - 0.3 && b < kMonoPlane - 0.3) {
                    ++near_count;
                    near_same += std::abs(a - b) <= 1e-5 * a;
                } else if (a > kMonoPlane + 0.3 && b > kMonoPlane + 0.3) {
                    ++far_count;
                    far_different += std::abs(a - b) > 1e-3 * a;
                }
            }
        }
        ASSERT_GT(near_count, 0u);
        // (Where two surfaces nearly touch, the modes' different depth ranges may order them
        // apart: a pixel or two.)
        EXPECT_GE(near_same, near_count * 995 / 1000) << near_same << " of " << near_count;
        ASSERT_GT(far_count, 0u);
        EXPECT_GT(far_different, far_count / 2) << eye.name;
    }
}

TEST_F(HeadsetDepthTest, TaaAndSsaoKeepTheDepthWithinTheJitter) {
    const Session s =
        run_session("[\"stereo\", \"hybrid\"]", "anti_aliasing = \"taa\"\nssao = \"per-eye\"");
    ASSERT_FALSE(s.frames.empty());
    for (const char* label : {"label1", "label2"}) {
        const bool hybrid =
            (std::string(label) == "label1" ? s.label1_mode : s.label2_mode) == "hybrid";
        const std::int64_t frame = s.nth(label, 3);
        ASSERT_GE(frame, 0);
        // TAA moves each frame's samples by up to half a pixel.
        for (const EyeFrustum& eye : kEyes) {
            expect_beams_depth(depth(frame, eye), eye, hybrid, 1.0,
                               std::string(label) + ", " + eye.name);
        }
    }
}

TEST_F(HeadsetDepthTest, MsaaOverTwoPassAndSinglePassStereo) {
    const Session s = run_session("[\"stereo\", \"stereo-gs\"]", "anti_aliasing = \"msaa4\"");
    ASSERT_FALSE(s.frames.empty());
    for (const char* label : {"label1", "label2"}) {
        const std::int64_t frame = s.nth(label, 3);
        ASSERT_GE(frame, 0);
        // The resolve averages four samples spread over the pixel.
        for (const EyeFrustum& eye : kEyes) {
            expect_beams_depth(depth(frame, eye), eye, false, 0.5,
                               std::string(label) + ", " + eye.name);
        }
    }
}

// Eyes turned 15 degrees outwards (the canted-15 profile, which simxr presents as turned views):
// the ground's distance along a turned eye's axis is still 1.7 / -ty (the turn is about the
// vertical), while the renderer's linear depth, measured along the head's forward axis, is that
// times cos 15 deg + tx sin 15 deg: only the writer's conversion to the eye's axis matches.
TEST_F(HeadsetDepthTest, CantedEyesMeasureAlongTheirOwnAxes) {
    const Session s =
        run_session("[\"stereo\", \"hybrid\"]", "anti_aliasing = \"none\"", "", "canted-15");
    ASSERT_FALSE(s.frames.empty());
    const bool hybrid_first = s.label1_mode == "hybrid";
    const std::int64_t hybrid_frame = s.nth(hybrid_first ? "label1" : "label2", 3);
    const std::int64_t stereo_frame = s.nth(hybrid_first ? "label2" : "label1", 3);
    ASSERT_GE(hybrid_frame, 0);
    ASSERT_GE(stereo_frame, 0);
    for (const EyeFrustum& eye : kEyes) {
        expect_beams_depth(depth(stereo_frame, eye), eye, false, 0.0,
                           std::string("stereo, ") + eye.name);
        // In hybrid the eye's own content ends at the head's plane z = -m: at most
        // (m - 0.3) / (cos 15 deg + 1.4 sin 15 deg) = 2.1 m along a turned eye's axis.
        expect_beams_depth(depth(hybrid_frame, eye), eye, true, 0.0,
                           std::string("hybrid, ") + eye.name, 2.0);
    }
}

// Without the extension (as with a runtime that does not offer it): the same session, colour
// only.
TEST_F(HeadsetDepthTest, LayerDepthOffSubmitsColourOnly) {
    const Session s = run_session("[\"stereo\", \"hybrid\"]", "", "--layer-depth off");
    ASSERT_FALSE(s.frames.empty());
    std::size_t colour = 0, depths = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "frames")) {
        const std::string name = entry.path().filename().string();
        colour += name.ends_with(".png");
        depths += name.ends_with(".pfm");
    }
    EXPECT_GT(colour, 40u);
    EXPECT_EQ(depths, 0u);
}

}  // namespace
}  // namespace monoplane
