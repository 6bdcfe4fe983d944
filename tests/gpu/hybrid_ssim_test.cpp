// Issue 3, item 6d: mean SSIM of hybrid against stereo per scene at m = 3 and m = 8, with
// local-SSIM heat maps written to the build tree (like the paper's Fig. 6). The paper finds that
// the difference "follows the formal error": smaller for the farther plane.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/quality/heat_map.h"
#include "renderer/quality/ssim.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

// A binary PPM, readable by every image viewer, so the test needs no PNG library.
void write_ppm(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba) {
    std::ofstream out(path, std::ios::binary);
    out << "P6 " << width << " " << height << " 255\n";
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        out.write(reinterpret_cast<const char*>(&rgba[i]), 3);
    }
}

class HybridSsim : public testing::GpuTest,
                   public ::testing::WithParamInterface<scenes::SceneId> {};

TEST_P(HybridSsim, FollowsTheFormalErrorAndIsReported) {
    const scenes::Scene scene = scenes::generate_scene(GetParam(), scenes::Detail::Test, 1);
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    const vk::Extent2D extent{224, 252};
    modes::RendererOptions options;
    options.shadow.resolution = 1024;
    modes::ModeRenderer stereo(ctx(), scene, plan::Mode::kStereo, extent, options);
    modes::ModeRenderer hybrid(ctx(), scene, plan::Mode::kHybrid, extent, options, 3.0);
    modes::FrameInputs inputs = testing::profile_inputs(vive, scene.viewpoints.front().head);
    stereo.render_frame(inputs);
    const std::filesystem::path out = std::filesystem::current_path() / "hybrid_ssim";
    std::filesystem::create_directories(out);
    double ssim_at[2] = {0.0, 0.0};
    int index = 0;
    for (double m : {3.0, 8.0}) {
        inputs.mono_plane = m;
        hybrid.render_frame(inputs);
        double sum = 0.0;
        for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
            const auto a = quality::rgba_view(stereo.eye_image(eye));
            const auto b = quality::rgba_view(hybrid.eye_image(eye));
            sum += quality::ssim(a, b).value_or_throw().mean;
            const auto local = quality::ssim(a, b, quality::SsimOptions::box(4)).value_or_throw();
            const auto blended =
                quality::blend_heat_map(b, quality::ssim_heat_map_rgba(local), 0.7f)
                    .value_or_throw();
            write_ppm(out / (scene.name + "_m" + std::to_string(static_cast<int>(m)) + "_" +
                             modes::eye_name(eye) + ".ppm"),
                      extent.width, extent.height, blended);
        }
        ssim_at[index++] = sum / 2.0;
        std::printf("%s m = %.0f: mean SSIM hybrid vs stereo %.4f\n", scene.name.c_str(), m,
                    sum / 2.0);
    }
    for (double s : ssim_at) {
        EXPECT_LT(s, 1.0);  // hybrid is an approximation
        EXPECT_GT(s, 0.7);  // but a close one
    }
    EXPECT_GT(ssim_at[1], ssim_at[0]);  // m = 8 is closer to stereo than m = 3
}

INSTANTIATE_TEST_SUITE_P(AllScenes, HybridSsim,
                         ::testing::Values(scenes::SceneId::Beams, scenes::SceneId::Landscape,
                                           scenes::SceneId::Spheres),
                         [](const auto& info) {
                             return std::string(scenes::scene_name(info.param));
                         });

}  // namespace
}  // namespace monoplane
