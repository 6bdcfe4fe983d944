#include "app/commands/stereo_comparison.h"

#include "app/png.h"
#include "renderer/quality/channel_difference.h"
#include "renderer/quality/heat_map.h"
#include "renderer/quality/ssim.h"

namespace monoplane::app {

StereoComparison compare_with_stereo(const vk_core::Context& ctx, const scenes::Scene& scene,
                                     vk::Extent2D extent, const modes::RendererOptions& options,
                                     const modes::FrameInputs& inputs,
                                     const modes::ModeRenderer& hybrid,
                                     const std::filesystem::path& out) {
    modes::RendererOptions reference_options = options;
    reference_options.read_back = true;
    reference_options.read_back_depth = true;
    reference_options.stereo_pass = plan::StereoPass::kTwoPasses;
    modes::ModeRenderer stereo(ctx, scene, plan::Mode::kStereo, extent, reference_options);
    stereo.render_frame(inputs);

    StereoComparison result;
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        const modes::RgbaImage& reference = stereo.eye_image(eye);
        const modes::RgbaImage& approximation = hybrid.eye_image(eye);
        const quality::ImageView a = quality::rgba_view(reference);
        const quality::ImageView b = quality::rgba_view(approximation);
        EyeComparison& c = result.eyes[static_cast<int>(eye)];
        c.ssim = quality::ssim(a, b).value_or_throw().mean;
        const quality::SsimResult local =
            quality::ssim(a, b, quality::SsimOptions::box(4)).value_or_throw();
        c.ssim_local_w4 = local.mean;
        c.max_channel_difference = quality::max_channel_difference(a, b).value_or_throw();

        // The far region: where the reference sees something beyond the mono plane.
        const std::vector<float>& depth = stereo.eye_linear_depth(eye);
        std::vector<std::uint8_t> beyond(depth.size());
        for (std::size_t i = 0; i < depth.size(); ++i) {
            beyond[i] = depth[i] > inputs.mono_plane ? 1 : 0;
            c.pixels_beyond_plane += beyond[i];
        }
        quality::SsimOptions masked;
        masked.mask = beyond;
        c.ssim_beyond_plane = quality::ssim(a, b, masked).value_or_throw().mean;

        const std::string name = modes::eye_name(eye);
        modes::RgbaImage heat{approximation.width, approximation.height,
                              quality::ssim_heat_map_rgba(local, 10.0f)};
        write_png(out / ("ssim_heat_" + name + ".png"), heat).value_or_throw();
        heat.pixels = quality::blend_heat_map(b, heat.pixels, 0.7f).value_or_throw();
        write_png(out / ("ssim_" + name + ".png"), heat).value_or_throw();
    }
    return result;
}

}  // namespace monoplane::app
