// Anti-aliasing (issue 8; papers/000 Sect. 4.5): TAA after Karis 2014 converges on a static view,
// and TAA and MSAA bring the image closer to a supersampled reference than no anti-aliasing.
// The reference is the same view rendered at 4 x 4 the resolution and box-filtered in linear
// light here: an independent estimate of the pixel's true average.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "rig/pose_path.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using modes::Eye;
using plan::AntiAliasing;
using plan::Mode;

constexpr vk::Extent2D kExtent{96, 108};

double srgb_to_linear(std::uint8_t value) {
    const double c = value / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

class AntiAliasingTest : public testing::GpuTest {
  protected:
    void SetUp() override {
        GpuTest::SetUp();
        scene_ = scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test);
        inputs_ = testing::profile_inputs(vive_, scene_.find_viewpoint("default")->head,
                                          inputs_.mono_plane);
    }

    modes::RendererOptions options(AntiAliasing aa) const {
        modes::RendererOptions o;
        o.shadow.resolution = 1024;
        o.anti_aliasing = aa;
        return o;
    }

    // The left eye's image after `frames` consecutive frames of a static head.
    modes::RgbaImage render(modes::ModeRenderer& renderer, int frames) {
        for (int i = 0; i < frames; ++i) {
            inputs_.frame_index = static_cast<std::uint64_t>(i);
            renderer.render_frame(inputs_);
        }
        return renderer.eye_image(Eye::kLeft);
    }

    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
    scenes::Scene scene_;
    modes::FrameInputs inputs_;
};

// Per pixel, the variance over the frames of its mean 8-bit channel value; the 99th percentile.
double temporal_variance_percentile(const std::vector<modes::RgbaImage>& frames, double q) {
    const std::size_t pixels = std::size_t{frames[0].width} * frames[0].height;
    std::vector<double> variances(pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        double sum = 0.0;
        double sum_sq = 0.0;
        for (const modes::RgbaImage& f : frames) {
            const double v = (f.pixels[4 * p] + f.pixels[4 * p + 1] + f.pixels[4 * p + 2]) / 3.0;
            sum += v;
            sum_sq += v * v;
        }
        const double n = static_cast<double>(frames.size());
        variances[p] = std::max(0.0, sum_sq / n - (sum / n) * (sum / n));
    }
    std::sort(variances.begin(), variances.end());
    return variances[static_cast<std::size_t>(q * static_cast<double>(pixels - 1))];
}

TEST_F(AntiAliasingTest, TaaConvergesOnAStaticView) {
    // The jittered frames without a history (weight 0) flicker at every edge: the control.
    modes::RendererOptions jitter_only = options(AntiAliasing::kTaa);
    jitter_only.taa.history_weight = 0.0f;
    modes::ModeRenderer taa(ctx(), scene_, Mode::kStereo, kExtent, options(AntiAliasing::kTaa));
    modes::ModeRenderer control(ctx(), scene_, Mode::kStereo, kExtent, jitter_only);
    constexpr int kConverged = 32;  // N: two jitter periods, about 20 history time constants
    std::vector<modes::RgbaImage> taa_frames;
    std::vector<modes::RgbaImage> control_frames;
    for (int i = 0; i < kConverged + 16; ++i) {
        inputs_.frame_index = static_cast<std::uint64_t>(i);
        taa.render_frame(inputs_);
        control.render_frame(inputs_);
        EXPECT_EQ(taa.history_restarted(), i == 0);
        if (i >= kConverged) {
            taa_frames.push_back(taa.eye_image(Eye::kLeft));
            control_frames.push_back(control.eye_image(Eye::kLeft));
        }
    }
    // Sub-pixel beams still flicker a little under TAA (the colour box of a frame that misses
    // them clips their history: Karis' known limit), so the bounds are on percentiles.
    for (double q : {0.5, 0.9, 0.99}) {
        const double with_taa = temporal_variance_percentile(taa_frames, q);
        const double jittered = temporal_variance_percentile(control_frames, q);
        std::cout << "temporal variance over a jitter period, percentile " << q * 100
                  << " of pixels (8-bit levels^2): TAA " << with_taa << ", jitter without history "
                  << jittered << "\n";
        // Where the jitter moves an edge, TAA removes over 90 % of the flicker.
        if (q >= 0.9) {
            EXPECT_LT(with_taa, 0.1 * jittered) << "percentile " << q;
        }
    }
    EXPECT_GT(temporal_variance_percentile(control_frames, 0.99), 1000.0);  // edges really move
    EXPECT_LT(temporal_variance_percentile(taa_frames, 0.5), 1.0);          // most pixels are still
    EXPECT_LT(temporal_variance_percentile(taa_frames, 0.9), 36.0);         // 90 %: sd < 6 levels
}

// The RMS difference, in linear light, between an image and the box-filtered supersampled
// reference over the pixels whose reference block holds an edge (its samples span > 0.05).
struct EdgeError {
    double rms = 0.0;
    std::size_t pixels = 0;
};

EdgeError edge_error(const modes::RgbaImage& image, const modes::RgbaImage& supersampled,
                     int factor) {
    double sum_sq = 0.0;
    std::size_t count = 0;
    for (std::uint32_t y = 0; y < image.height; ++y) {
        for (std::uint32_t x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                double mean = 0.0;
                double lo = 1.0;
                double hi = 0.0;
                for (int sy = 0; sy < factor; ++sy) {
                    for (int sx = 0; sx < factor; ++sx) {
                        const std::size_t i =
                            (std::size_t{y} * factor + sy) * supersampled.width + x * factor + sx;
                        const double v = srgb_to_linear(supersampled.pixels[4 * i + c]);
                        mean += v;
                        lo = std::min(lo, v);
                        hi = std::max(hi, v);
                    }
                }
                mean /= factor * factor;
                if (hi - lo <= 0.05) continue;
                const double d =
                    srgb_to_linear(image.pixels[4 * (std::size_t{y} * image.width + x) + c]) - mean;
                sum_sq += d * d;
                ++count;
            }
        }
    }
    return {count ? std::sqrt(sum_sq / static_cast<double>(count)) : 0.0, count};
}

TEST_F(AntiAliasingTest, TaaAndMsaaAliasLessThanNoAntiAliasing) {
    constexpr int kFactor = 4;
    const vk::Extent2D big{kExtent.width * kFactor, kExtent.height * kFactor};
    modes::ModeRenderer reference_renderer(ctx(), scene_, Mode::kStereo, big,
                                           options(AntiAliasing::kNone));
    const modes::RgbaImage reference = render(reference_renderer, 1);
    modes::ModeRenderer none(ctx(), scene_, Mode::kStereo, kExtent, options(AntiAliasing::kNone));
    modes::ModeRenderer taa(ctx(), scene_, Mode::kStereo, kExtent, options(AntiAliasing::kTaa));
    modes::ModeRenderer msaa(ctx(), scene_, Mode::kStereo, kExtent, options(AntiAliasing::kMsaa4));
    const EdgeError e_none = edge_error(render(none, 1), reference, kFactor);
    const EdgeError e_taa = edge_error(render(taa, 32), reference, kFactor);
    const EdgeError e_msaa = edge_error(render(msaa, 1), reference, kFactor);
    std::cout << "RMS error at edges against the 4x4 supersampled reference (linear light, "
              << e_none.pixels << " channel samples): none " << e_none.rms << ", TAA " << e_taa.rms
              << ", MSAA 4x " << e_msaa.rms << "\n";
    EXPECT_GT(e_none.pixels, 1000u);
    EXPECT_LT(e_taa.rms, 0.75 * e_none.rms);
    EXPECT_LT(e_msaa.rms, 0.75 * e_none.rms);
}

TEST_F(AntiAliasingTest, MsaaIsRefusedInHybridModes) {
    EXPECT_THROW(
        modes::ModeRenderer(ctx(), scene_, Mode::kHybrid, kExtent, options(AntiAliasing::kMsaa4)),
        UserError);
}

double mean_abs_difference(const modes::RgbaImage& a, const modes::RgbaImage& b) {
    double total = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        total += std::abs(static_cast<int>(a.pixels[i]) - static_cast<int>(b.pixels[i]));
    }
    return total / static_cast<double>(a.pixels.size() / 4 * 3);
}

// Issue 17 item 3: in a study each alternative has its own renderer, and a switch shows the
// other one's next frame. Its TAA history must not restart (a visible transient that would cue
// the switch): the first frame after a switch, under head motion, matches the frame of a renderer
// that showed that alternative all along far better than a restarted history does.
TEST_F(AntiAliasingTest, ASwitchBetweenAlternativesShowsAConvergedImageAtOnce) {
    const rig::Pose start = inputs_.views.head;
    const rig::PosePath sway = *rig::builtin_pose_path("sway");
    modes::ModeRenderer shown(ctx(), scene_, Mode::kStereo, kExtent, options(AntiAliasing::kTaa));
    modes::ModeRenderer other(ctx(), scene_, Mode::kHybrid, kExtent, options(AntiAliasing::kTaa));
    modes::ModeRenderer continuous(ctx(), scene_, Mode::kStereo, kExtent,
                                   options(AntiAliasing::kTaa));
    constexpr int kShownFrames = 24;  // label 1, converging
    constexpr int kOtherFrames = 16;  // label 2 while the head keeps moving
    constexpr int kBack = kShownFrames + kOtherFrames;
    modes::FrameInputs inputs = inputs_;
    inputs.mono_plane = 8.0;
    for (int frame = 0; frame <= kBack; ++frame) {
        inputs.views.head = rig::pose_along(sway, start, frame / 90.0);
        inputs.frame_index.reset();  // each renderer counts its own frames, as a headset session
        continuous.render_frame(inputs);
        if (frame < kShownFrames || frame == kBack) {
            shown.render_frame(inputs);
            EXPECT_FALSE(frame > 0 && shown.history_restarted()) << frame;
        } else {
            other.render_frame(inputs);
        }
    }
    modes::ModeRenderer restarted(ctx(), scene_, Mode::kStereo, kExtent,
                                  options(AntiAliasing::kTaa));
    restarted.render_frame(inputs);
    ASSERT_TRUE(restarted.history_restarted());
    const modes::RgbaImage& reference = continuous.eye_image(Eye::kLeft);
    const double after_switch = mean_abs_difference(shown.eye_image(Eye::kLeft), reference);
    const double after_restart = mean_abs_difference(restarted.eye_image(Eye::kLeft), reference);
    std::printf(
        "mean |difference| to the continuous frame: after a switch %.3f, restarted %.3f "
        "(8-bit levels)\n",
        after_switch, after_restart);
    // Measured on llvmpipe: 1.8 after the switch against 8.6 for a restarted history; what is
    // left is the 16 frames of accumulation the kept history missed (docs/headsets.md).
    EXPECT_LT(after_switch, 0.3 * after_restart);
    EXPECT_LT(after_switch, 2.5);
}

}  // namespace
}  // namespace monoplane
