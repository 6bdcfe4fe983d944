// glTF alphaMode MASK in every mode (issue 34, items 1 and 3): the fence of alpha_scenes.h shows
// what lies behind it exactly where its texture's alpha is below the cut-off, worked out from the
// texture (checker_opaque, gradient_alpha) and the projection of the quad's points, not from a
// rendered reference; the cut-outs' shadows have the holes; the depth pre-pass and MSAA's alpha
// to coverage keep them. The colours tell fence from background: the checker is orange (red well
// above green), the gradient quad blue (blue well above green), the ground grey and the backdrop
// green; a hole showing black (C's pixels skipped behind a fence taken for solid) counts as wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "tests/gpu/alpha_render.h"

namespace monoplane::testing {
namespace {

using plan::AntiAliasing;

// A configuration of the renderer, and the extra distance (pixels) from a cut-out's edge within
// which a pixel is not judged: C's mapped image may move content beyond m by a fraction of a pixel
// (papers/000 Sect. 3), the far field's copy by its rounding too.
struct Configuration {
    std::string name;
    Mode mode = Mode::kStereo;
    StereoPass pass = StereoPass::kTwoPasses;
    double m = 8.0;
    double slack_px = 0.0;
};

enum class Seen { kSurface, kBackground, kNeither };

// The checker's orange, the background's grey or green.
Seen classify_checker(const Rgb& c) {
    if (c.r > c.g + 25) return Seen::kSurface;
    if (c.g >= 30 && c.r <= c.g + 8) return Seen::kBackground;
    return Seen::kNeither;
}

// The gradient quad's blue, the background's grey or green.
Seen classify_gradient(const Rgb& c) {
    if (c.b > c.g + 25) return Seen::kSurface;
    if (c.g >= 30 && c.b <= c.g + 8) return Seen::kBackground;
    return Seen::kNeither;
}

// How many sampled points of a quad showed the wrong thing, and how many were judged.
struct Tally {
    int surface = 0;
    int background = 0;
    int wrong = 0;
    std::string first_wrong;
};

class AlphaMask : public AlphaSceneTest {
  protected:
    // Margins in metres on the fence (4 m away) around each place where the alpha crosses the
    // cut-off: one texel of bilinear filtering, a pixel (a sampled point is up to 0.71 px from
    // its pixel's centre) and the slack.
    double margin_m(double texel_m, double slack_px) const {
        return texel_m + (1.0 + slack_px) / pixels_per_metre(4.0);
    }

    // The checker fence: every point of a fine grid over it, away from the cells' edges, shows
    // the fence on an opaque cell and the background on a cut-out one.
    Tally check_checker(const modes::RgbaImage& image, Eye eye, double slack_px) const {
        const double cell_u = 4.0 / kCheckerCells, cell_v = 2.0 / kCheckerCells;  // metres
        const double margin_u = margin_m(4.0 / kAlphaTextureSize, slack_px);
        const double margin_v = margin_m(2.0 / kAlphaTextureSize, slack_px);
        Tally tally;
        for (int i = 0; i < 160; ++i) {
            for (int j = 0; j < 80; ++j) {
                const glm::vec2 uv((i + 0.5f) / 160.0f, (j + 0.5f) / 80.0f);
                const double du = std::remainder(uv.x * 4.0, cell_u);
                const double dv = std::remainder(uv.y * 2.0, cell_v);
                if (std::abs(du) < margin_u || std::abs(dv) < margin_v) continue;
                judge(image, eye, kFenceChecker.at(uv), checker_opaque(uv), classify_checker,
                      tally);
            }
        }
        return tally;
    }

    // The gradient quad: cut away left of u = cutoff.
    Tally check_gradient(const modes::RgbaImage& image, Eye eye, float cutoff,
                         double slack_px) const {
        const double margin_u = 1.0 / 255.0 + (1.0 + slack_px) / (pixels_per_metre(4.0) * 1.6);
        Tally tally;
        for (int i = 0; i < 100; ++i) {
            for (int j = 2; j < 48; ++j) {
                const glm::vec2 uv((i + 0.5f) / 100.0f, (j + 0.5f) / 50.0f);
                if (std::abs(gradient_alpha(uv) - cutoff) < margin_u) continue;
                judge(image, eye, kFenceGradient.at(uv), gradient_alpha(uv) >= cutoff,
                      classify_gradient, tally);
            }
        }
        return tally;
    }

    template <typename Classify>
    void judge(const modes::RgbaImage& image, Eye eye, const glm::vec3& point, bool opaque,
               Classify classify, Tally& tally) const {
        const std::optional<glm::ivec2> at = pixel_of(eye, point);
        if (!at) return;
        const Rgb colour = rgb_at(image, at->x, at->y);
        const Seen seen = classify(colour);
        (opaque ? tally.surface : tally.background) += 1;
        if (seen == (opaque ? Seen::kSurface : Seen::kBackground)) return;
        if (tally.wrong++ == 0) {
            tally.first_wrong = std::string(opaque ? "surface" : "background") + " expected at (" +
                                std::to_string(at->x) + ", " + std::to_string(at->y) +
                                "): " + std::to_string(colour.r) + " " + std::to_string(colour.g) +
                                " " + std::to_string(colour.b);
        }
    }

    void expect_cut_outs(const EyeImages& images, float cutoff, double slack_px,
                         const std::string& what) const {
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            const auto& image = images[static_cast<std::size_t>(eye)];
            const Tally checker = check_checker(image, eye, slack_px);
            const Tally gradient = check_gradient(image, eye, cutoff, slack_px);
            SCOPED_TRACE(what + " " + eye_text(eye));
            // Enough of both kinds judged for the test to mean something.
            EXPECT_GT(checker.surface, 300);
            EXPECT_GT(checker.background, 300);
            EXPECT_GT(gradient.surface, 300);
            EXPECT_GT(gradient.background, 300);
            EXPECT_EQ(checker.wrong, 0) << checker.first_wrong;
            EXPECT_EQ(gradient.wrong, 0) << gradient.first_wrong;
        }
    }

    std::vector<Configuration> configurations() {
        const vk_core::DeviceCapabilities& caps = ctx().capabilities();
        std::vector<Configuration> all = {
            {"stereo", Mode::kStereo},
            {"hybrid m=8 (fence nearer than m)", Mode::kHybrid, StereoPass::kTwoPasses, 8.0},
            {"hybrid m=3 (fence drawn by C)", Mode::kHybrid, StereoPass::kTwoPasses, 3.0, 0.5},
            {"hybrid-farfield m=8", Mode::kHybridFarfield, StereoPass::kTwoPasses, 8.0},
            {"hybrid-farfield m=3", Mode::kHybridFarfield, StereoPass::kTwoPasses, 3.0, 1.0}};
        if (caps.geometry_shader)
            all.push_back({"stereo-gs", Mode::kStereo, StereoPass::kGeometryShader});
        if (caps.vertex_shader_layer && caps.shader_draw_parameters) {
            all.push_back({"stereo-instanced", Mode::kStereo, StereoPass::kInstanced});
            all.push_back({"hybrid instanced m=8", Mode::kHybrid, StereoPass::kInstanced, 8.0});
        }
        return all;
    }
};

TEST_F(AlphaMask, CutOutsShowTheBackgroundExactlyWhereTheTextureAlphaIsBelowTheCutoff) {
    const scenes::Scene fence = load(write_fence_scene(dir_));
    for (const Configuration& c : configurations()) {
        expect_cut_outs(render(fence, c.mode, c.m, c.pass), 0.5f, c.slack_px, c.name);
    }
    // The control: the same quads drawn opaque fail the check at every cut-out point.
    FenceOptions opaque;
    opaque.masked = false;
    const EyeImages solid = render(load(write_fence_scene(dir_, opaque)), Mode::kStereo);
    const Tally tally = check_checker(solid[0], Eye::kLeft, 0.0);
    EXPECT_EQ(tally.wrong, tally.background);
}

// The cut-off is the file's: the same quad cut at 0.8 loses more.
TEST_F(AlphaMask, TheCutoffIsTheMaterialsAlphaCutoff) {
    FenceOptions high;
    high.gradient_cutoff = 0.8f;
    const scenes::Scene fence = load(write_fence_scene(dir_, high));
    expect_cut_outs(render(fence, Mode::kStereo), 0.8f, 0.0, "stereo, cut-off 0.8");
    expect_cut_outs(render(fence, Mode::kHybrid, 3.0), 0.8f, 0.5, "hybrid m=3, cut-off 0.8");
}

// Multiview on Debian 12's lavapipe misroutes view 1's fragments (single_pass_stereo_test): there
// the pass is run under validation and its image compared, but the difference only reported.
TEST_F(AlphaMask, MultiviewDrawsTheSameCutOuts) {
    if (!ctx().capabilities().multiview) GTEST_SKIP() << "the device has no multiview";
    const scenes::Scene fence = load(write_fence_scene(dir_));
    const EyeImages images = render(fence, Mode::kStereo, 8.0, StereoPass::kMultiview);
    const bool llvmpipe = ctx().device_info().name.find("llvmpipe") != std::string::npos;
    if (!llvmpipe) expect_cut_outs(images, 0.5f, 0.0, "stereo-multiview");
    if (!llvmpipe) return;
    const Tally left = check_checker(images[0], Eye::kLeft, 0.0);
    const Tally right = check_checker(images[1], Eye::kRight, 0.0);
    GTEST_SKIP() << "measured on " << ctx().device_info().name << ": checker points wrong, left "
                 << left.wrong << " of " << left.surface + left.background << ", right "
                 << right.wrong << " of " << right.surface + right.background
                 << " (lavapipe 22.3's multiview is defective: not asserted)";
}

// A depth pre-pass alpha-tests too: the images are those drawn without it.
TEST_F(AlphaMask, TheDepthPrepassKeepsTheCutOuts) {
    const scenes::Scene fence = load(write_fence_scene(dir_));
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        modes::RendererOptions with = options();
        with.depth_prepass = true;
        const EyeImages prepassed = render(fence, mode, 8.0, with);
        const EyeImages plain = render(fence, mode, 8.0);
        EXPECT_EQ(max_difference(prepassed[0], plain[0]), 0);
        EXPECT_EQ(max_difference(prepassed[1], plain[1]), 0);
    }
}

// MSAA turns the alpha into coverage: the cells are still cut where they should be, and their
// edges get the intermediate colours of anti-aliasing, which the alpha test alone never makes.
TEST_F(AlphaMask, MsaaUsesAlphaToCoverage) {
    const scenes::Scene fence = load(write_fence_scene(dir_));
    modes::RendererOptions msaa = options();
    msaa.anti_aliasing = AntiAliasing::kMsaa4;
    const EyeImages smooth = render(fence, Mode::kStereo, 8.0, msaa);
    const EyeImages hard = render(fence, Mode::kStereo, 8.0);
    expect_cut_outs(smooth, 0.5f, 0.0, "stereo msaa4");
    // Along one row through the checker's second cell row: pixels neither fence nor background.
    const auto between = [&](const modes::RgbaImage& image) {
        int count = 0;
        for (int i = 0; i < 400; ++i) {
            const glm::vec2 uv((i + 0.5f) / 400.0f, 1.5f / kCheckerCells);
            const std::optional<glm::ivec2> at = pixel_of(Eye::kLeft, kFenceChecker.at(uv));
            if (at && classify_checker(rgb_at(image, at->x, at->y)) == Seen::kNeither) ++count;
        }
        return count;
    };
    EXPECT_GT(between(smooth[0]), between(hard[0]));
}

// The high checker quad's shadow on the ground: dark under its opaque cells, lit under its
// cut-out ones, each judged at the cell's centre against the lit ground beside the fence.
TEST_F(AlphaMask, CutOutShadowsHaveTheHoles) {
    extent_ = vk::Extent2D{672, 756};  // ground pixels at grazing angles stay within a cell
    const scenes::Scene fence = load(write_fence_scene(dir_));
    const glm::vec3 sun = fence.lighting.sun_direction;
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        const EyeImages images = render(fence, mode, 3.0);
        const auto& image = images[0];
        int lit = 0, dark = 0;
        for (int i = 0; i < kCheckerCells; ++i) {
            for (int j = 0; j < kCheckerCells; ++j) {
                const glm::vec2 uv((i + 0.5f) / kCheckerCells, (j + 0.5f) / kCheckerCells);
                const glm::vec3 shadow = ground_shadow(kFenceHigh.at(uv), sun);
                if (shadow.z > -5.5f) continue;  // where the fence's own shadow may fall
                const std::optional<glm::ivec2> at = pixel_of(Eye::kLeft, shadow);
                const std::optional<glm::ivec2> beside =
                    pixel_of(Eye::kLeft, glm::vec3(-7.0f, 0.0f, shadow.z));
                ASSERT_TRUE(at && beside);
                const Rgb here = rgb_at(image, at->x, at->y);
                const Rgb open = rgb_at(image, beside->x, beside->y);
                SCOPED_TRACE(std::string(mode == Mode::kStereo ? "stereo" : "hybrid") + " cell " +
                             std::to_string(i) + "," + std::to_string(j));
                if (checker_opaque(uv)) {
                    EXPECT_LT(here.g, 0.75 * open.g);
                    ++dark;
                } else {
                    EXPECT_GT(here.g, 0.92 * open.g);
                    ++lit;
                }
            }
        }
        EXPECT_GE(lit, 8);
        EXPECT_GE(dark, 8);
    }
}

}  // namespace
}  // namespace monoplane::testing
