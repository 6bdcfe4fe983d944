// Imported glTF scenes through every mode and the accuracy checks (issue 19 item 4): a file the
// test writes (a red marker, its node placed by a translation, a grey backdrop far behind it, a
// camera) is loaded by scenes/gltf and rendered. Expected positions come from the geometry here
// (a pinhole of the Vive's eye, C's position from eq. 1), not from the rig or the loader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/gltf/load_gltf.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/marker_centroid.h"
#include "tests/gpu/profile_inputs.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane {
namespace {

using modes::Eye;
using plan::Mode;

constexpr glm::dvec3 kCamera{0.0, 1.7, 0.0};
constexpr glm::dvec3 kMarker{-0.6, 1.9, -5.0};  // the marker node's translation, world
constexpr double kHalf = 0.25;

// A (n x n)-cell square facing +z, centred at the origin, with a red COLOR_0 that rises smoothly
// from 0 at the border to 1 at the centre (its centroid is sub-pixel exact), and a backdrop quad.
std::filesystem::path write_marker_file(const std::filesystem::path& dir) {
    scenes::testing::TestGltf gltf;
    constexpr int n = 24;
    std::vector<glm::vec3> positions;
    std::vector<float> colours;
    std::vector<std::uint32_t> indices;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const float u = -1.0f + 2.0f * i / n, v = -1.0f + 2.0f * j / n;
            positions.push_back(
                {static_cast<float>(kHalf) * u, static_cast<float>(kHalf) * v, 0.0f});
            const float bump = (1.0f - u * u) * (1.0f - v * v);
            colours.insert(colours.end(), {bump * bump, 0.0f, 0.0f, 1.0f});
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            indices.insert(indices.end(), {a, b, d, a, d, c});  // counter-clockwise seen from +z
        }
    }
    const int marker_positions = gltf.add_positions(positions);
    const int marker_colours =
        gltf.add_accessor(colours, scenes::testing::kFloat, "VEC4", positions.size());
    const int marker_indices = gltf.add_indices(indices);
    const int marker = gltf.add_mesh({{"POSITION", marker_positions}, {"COLOR_0", marker_colours}},
                                     marker_indices, 4, -1, "marker");
    gltf.add_node({{"mesh", marker}, {"translation", {kMarker.x, kMarker.y, kMarker.z}}});
    // The backdrop: 40 m wide at z = -60, facing +z, dark grey (no redness).
    const int backdrop_positions = gltf.add_positions({{-20.0f, -5.0f, -60.0f},
                                                       {20.0f, -5.0f, -60.0f},
                                                       {20.0f, 15.0f, -60.0f},
                                                       {-20.0f, 15.0f, -60.0f}});
    const int backdrop_indices = gltf.add_indices({0, 1, 2, 0, 2, 3});
    gltf.json["materials"] = {
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.2, 0.2, 1.0}}}}}};
    const int backdrop =
        gltf.add_mesh({{"POSITION", backdrop_positions}}, backdrop_indices, 4, 0, "backdrop");
    gltf.add_node({{"mesh", backdrop}});
    gltf.json["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.5}, {"znear", 0.1}}}}};
    gltf.add_node({{"camera", 0}, {"translation", {kCamera.x, kCamera.y, kCamera.z}}});
    const std::filesystem::path file = dir / "marker.gltf";
    gltf.write_gltf(file);
    return file;
}

// Eye pixel of a world point for the Vive's parallel eye at the camera (head looking down -z).
glm::dvec2 eye_pixel(const hmd::HmdProfile& vive, Eye eye, const glm::dvec3& p,
                     vk::Extent2D extent) {
    const rig::Tangents& t = eye == Eye::kLeft ? vive.left : vive.right;
    const glm::dvec3 d =
        p - kCamera - glm::dvec3((eye == Eye::kLeft ? -0.5 : 0.5) * vive.ipd, 0, 0);
    const double tx = d.x / -d.z, ty = d.y / -d.z;
    return {(tx - t.left) / (t.right - t.left) * extent.width,
            (t.up - ty) / (t.up - t.down) * extent.height};
}

class ImportedScene : public testing::GpuTest {
  protected:
    void SetUp() override {
        testing::GpuTest::SetUp();
        dir_ =
            std::filesystem::temp_directory_path() / ("imported_scene_" + std::to_string(getpid()));
        std::filesystem::create_directories(dir_);
        Result<scenes::Scene> loaded = scenes::load_gltf_scene(write_marker_file(dir_));
        ASSERT_TRUE(loaded) << loaded.error().message;
        scene_ = std::move(loaded).value();
    }
    void TearDown() override {
        std::filesystem::remove_all(dir_);
        testing::GpuTest::TearDown();
    }
    modes::RendererOptions options() const {
        modes::RendererOptions o;
        o.shadow.resolution = 512;
        return o;
    }
    modes::FrameInputs inputs(double m) const {
        return testing::profile_inputs(vive_, scene_.find_viewpoint("default")->head, m);
    }

    std::filesystem::path dir_;
    scenes::Scene scene_;
    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
    const vk::Extent2D extent_{336, 378};
};

TEST_F(ImportedScene, TheFilesCameraIsTheDefaultViewpoint) {
    const scenes::Viewpoint* view = scene_.find_viewpoint("default");
    ASSERT_NE(view, nullptr);
    EXPECT_NEAR(glm::length(view->head.position - kCamera), 0.0, 1e-6);
    // glTF cameras look down their -z, as the head does: no turn.
    EXPECT_NEAR(std::abs(view->head.orientation.w), 1.0, 1e-6);
}

TEST_F(ImportedScene, StereoPutsTheMarkerWhereItsNodeDoes) {
    modes::ModeRenderer stereo(ctx(), scene_, Mode::kStereo, extent_, options());
    stereo.render_frame(inputs(8.0));
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        SCOPED_TRACE(modes::eye_name(eye));
        const testing::Centroid c = testing::red_centroid(stereo.eye_image(eye));
        const glm::dvec2 expected = eye_pixel(vive_, eye, kMarker, extent_);
        EXPECT_GT(c.weight, 100.0);
        EXPECT_NEAR(c.x, expected.x, 0.5);
        EXPECT_NEAR(c.y, expected.y, 0.5);
    }
}

TEST_F(ImportedScene, HybridDriftsByTheCentralProjectionAndEqualsStereoAtFar) {
    modes::ModeRenderer stereo(ctx(), scene_, Mode::kStereo, extent_, options());
    modes::ModeRenderer hybrid(ctx(), scene_, Mode::kHybrid, extent_, options());
    const double m = 2.0;  // the marker (5 m) lies beyond: C draws it
    stereo.render_frame(inputs(m));
    hybrid.render_frame(inputs(m));
    const double s =
        std::max(vive_.ipd / (2.0 * -vive_.left.left), vive_.ipd / (2.0 * vive_.right.right));
    const glm::dvec3 in_head = kMarker - kCamera;
    const glm::dvec3 c(0.0, 0.0, s);
    const glm::dvec3 on_plane = c + (in_head - c) * ((m + s) / (-in_head.z + s)) + kCamera;
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        SCOPED_TRACE(modes::eye_name(eye));
        const glm::dvec2 expected =
            eye_pixel(vive_, eye, on_plane, extent_) - eye_pixel(vive_, eye, kMarker, extent_);
        const testing::Centroid st = testing::red_centroid(stereo.eye_image(eye));
        const testing::Centroid hy = testing::red_centroid(hybrid.eye_image(eye));
        EXPECT_GT(std::abs(expected.x), 0.5);
        EXPECT_NEAR(hy.x - st.x, expected.x, 0.35);
        EXPECT_NEAR(hy.y - st.y, expected.y, 0.35);
    }
    // m at the far plane: nothing lies beyond it, hybrid is stereo.
    stereo.render_frame(inputs(1000.0));
    hybrid.render_frame(inputs(1000.0));
    EXPECT_EQ(hybrid.mono_image(), nullptr);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto& a = stereo.eye_image(eye).pixels;
        const auto& b = hybrid.eye_image(eye).pixels;
        int worst = 0;
        for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
        EXPECT_LE(worst, 1) << modes::eye_name(eye);
    }
}

TEST_F(ImportedScene, SinglePassStereoDrawsWhatTwoPassesDraw) {
    modes::ModeRenderer two(ctx(), scene_, Mode::kStereo, extent_, options());
    modes::RendererOptions gs_options = options();
    gs_options.stereo_pass = plan::StereoPass::kGeometryShader;
    modes::ModeRenderer gs(ctx(), scene_, Mode::kStereo, extent_, gs_options);
    two.render_frame(inputs(8.0));
    gs.render_frame(inputs(8.0));
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto& a = two.eye_image(eye).pixels;
        const auto& b = gs.eye_image(eye).pixels;
        int worst = 0;
        for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
        EXPECT_LE(worst, 1) << modes::eye_name(eye);
        const testing::Centroid c = testing::red_centroid(gs.eye_image(eye));
        EXPECT_NEAR(c.x, eye_pixel(vive_, eye, kMarker, extent_).x, 0.5);
    }
}

}  // namespace
}  // namespace monoplane
