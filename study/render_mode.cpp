#include "study/render_mode.h"

#include <array>
#include <string>

#include "common/programming_error.h"

namespace monoplane::study {
namespace {

// Every named mode is a study mode, in the table's order.
constexpr std::array<RenderMode, 7> kAllModes = [] {
    static_assert(kRenderModeNames.size() == 7, "a new named mode needs its RenderMode");
    std::array<RenderMode, 7> modes{};
    std::size_t i = 0;
    for (const auto& [named, text] : kRenderModeNames) modes[i++] = static_cast<RenderMode>(named);
    return modes;
}();

}  // namespace

std::span<const RenderMode> all_render_modes() {
    return kAllModes;
}

std::string_view render_mode_name(RenderMode mode) {
    const std::string_view name =
        find_name(kRenderModeNames, static_cast<NamedRenderMode>(mode), "invalid");
    MONOPLANE_EXPECTS(name != "invalid" && "RenderMode value outside the enum");
    return name;
}

Result<RenderMode> parse_render_mode(std::string_view name) {
    if (const auto named = parse_name(kRenderModeNames, name))
        return static_cast<RenderMode>(*named);
    return Error{"unknown render mode '" + std::string(name) +
                 "' (valid: " + joined_names(kRenderModeNames) + ")"};
}

}  // namespace monoplane::study
