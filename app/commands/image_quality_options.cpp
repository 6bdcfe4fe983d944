#include "app/commands/image_quality_options.h"

namespace monoplane::app {

void apply_image_quality_flags(const std::string& anti_aliasing, const std::string& ssao,
                               modes::RendererOptions& options) {
    const auto aa = plan::parse_anti_aliasing(anti_aliasing);
    if (!aa) {
        throw UserError("--anti-aliasing " + anti_aliasing +
                        ": use none, taa, msaa2, msaa4 or msaa8");
    }
    options.anti_aliasing = *aa;
    options.ssao.reset();
    if (ssao == "off") return;
    options.ssao = passes::parse_ssao_variant(ssao);
    if (!options.ssao) throw UserError("--ssao " + ssao + ": use off, per-eye or stereo");
}

plan::StereoPass parse_stereo_pass_flag(const std::string& stereo_pass) {
    const auto pass = plan::parse_stereo_pass(stereo_pass);
    if (!pass) {
        throw UserError("--stereo-pass " + stereo_pass + ": use two, multiview, gs or instanced");
    }
    return *pass;
}

}  // namespace monoplane::app
