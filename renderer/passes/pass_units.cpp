#include "renderer/passes/pass_units.h"

#include <algorithm>

#include "common/programming_error.h"
#include "renderer/passes/pass_unit_list.h"
#include "renderer/plan/pass_unit.h"

// Each unit defines this in its own source, compiled here with MONOPLANE_UNIT_RECORDER.
#define MONOPLANE_PASS_UNIT_RECORDER(unit)                                                        \
    namespace unit {                                                                              \
    std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx,                      \
                                                const UnitScene& scene, const UnitPasses& passes, \
                                                const UnitSettings& settings);                    \
    }

namespace monoplane::passes {

MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_RECORDER)

bool UnitPasses::any(const std::function<bool(const plan::PlannedPass&)>& test) const {
    return std::any_of(passes.begin(), passes.end(),
                       [&](const auto& planned) { return test(*planned.second); });
}

bool UnitPasses::any_declares(plan::ViewId view, plan::ImageRole role) const {
    plan::ResourceKey key;
    key.view = view;
    key.image = role;
    return std::any_of(passes.begin(), passes.end(), [&](const auto& planned) {
        const std::optional<std::uint16_t> handle = planned.first->handle(key);
        const std::vector<graph::Step>& steps = planned.second->steps;
        return handle && std::any_of(steps.begin(), steps.end(), [&](const graph::Step& step) {
                   return plan::step_declares(step, *handle);
               });
    });
}

std::unique_ptr<UnitRecorder> make_unit_recorder(const std::string& unit,
                                                 const vk_core::Context& ctx,
                                                 const UnitScene& scene, const UnitPasses& passes,
                                                 const UnitSettings& settings) {
    // The declarations and the recorders expand the same list: the n-th of each are one unit's.
    using Make = std::unique_ptr<UnitRecorder> (*)(const vk_core::Context&, const UnitScene&,
                                                   const UnitPasses&, const UnitSettings&);
#define MONOPLANE_PASS_UNIT_MAKE(unit) &unit::make_recorder,
    static const Make makers[] = {MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_MAKE)};
#undef MONOPLANE_PASS_UNIT_MAKE
    const auto& declarations = pass_unit_declarations();
    for (std::size_t u = 0; u < declarations.size(); ++u) {
        if (declarations[u].name == unit) return makers[u](ctx, scene, passes, settings);
    }
    programming_error("no pass unit named '" + unit + "'");
}

}  // namespace monoplane::passes
