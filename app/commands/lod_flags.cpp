#include "app/commands/lod_flags.h"

#include <cmath>
#include <sstream>

#include "common/result.h"

namespace monoplane::app {

void add_lod_flags(CLI::App& cmd, LodFlags& flags, bool list) {
    cmd.add_option("--lod", flags.lod,
                   list ? "Level of detail, or a comma-separated sweep of them: auto (each view "
                          "draws each chunk at the coarsest level within --lod-error-px) or off "
                          "(full detail)"
                        : "Level of detail: auto (each view draws each chunk at the coarsest "
                          "level within --lod-error-px) or off (full detail)")
        ->capture_default_str();
    cmd.add_option("--lod-error-px", flags.error_px,
                   "The largest geometric error, in the drawing view's pixels, a chunk's "
                   "simplified level may show (C uses its own pixel size)")
        ->capture_default_str();
}

plan::LodOptions parse_lod_flags(const std::string& lod, double error_px) {
    const auto enabled = plan::parse_lod_mode(lod);
    if (!enabled) throw UserError("--lod " + lod + ": use auto or off");
    if (!(error_px > 0.0 && std::isfinite(error_px))) {
        throw UserError("--lod-error-px must be a positive number of pixels");
    }
    return {*enabled, error_px};
}

std::vector<plan::LodOptions> parse_lod_list(const LodFlags& flags) {
    std::vector<plan::LodOptions> sweep;
    std::stringstream stream(flags.lod);
    std::string item;
    while (std::getline(stream, item, ',')) {
        const plan::LodOptions options = parse_lod_flags(item, flags.error_px);
        bool seen = false;
        for (const plan::LodOptions& earlier : sweep)
            seen = seen || earlier.enabled == options.enabled;
        if (!seen) sweep.push_back(options);
    }
    if (sweep.empty()) throw UserError("--lod: no setting given; use auto, off or off,auto");
    return sweep;
}

}  // namespace monoplane::app
