#include "renderer/passes/pass_units.h"

#include "common/programming_error.h"
#include "renderer/passes/pass_unit_list.h"

// Each unit defines this in its own source, compiled here with MONOPLANE_UNIT_RECORDER.
#define MONOPLANE_PASS_UNIT_RECORDER(unit)                                    \
    namespace unit {                                                          \
    std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx); \
    }

namespace monoplane::passes {

MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_RECORDER)

std::unique_ptr<UnitRecorder> make_unit_recorder(const std::string& unit,
                                                 const vk_core::Context& ctx) {
    // The declarations and the recorders expand the same list: the n-th of each are one unit's.
    using Make = std::unique_ptr<UnitRecorder> (*)(const vk_core::Context&);
#define MONOPLANE_PASS_UNIT_MAKE(unit) &unit::make_recorder,
    static const Make makers[] = {MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_MAKE)};
#undef MONOPLANE_PASS_UNIT_MAKE
    const auto& declarations = pass_unit_declarations();
    for (std::size_t u = 0; u < declarations.size(); ++u) {
        if (declarations[u].name == unit) return makers[u](ctx);
    }
    programming_error("no pass unit named '" + unit + "'");
}

}  // namespace monoplane::passes
