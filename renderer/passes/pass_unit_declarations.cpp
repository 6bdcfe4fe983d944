#include "renderer/passes/pass_unit_declarations.h"

#include "renderer/passes/pass_unit_list.h"
#include "renderer/plan/frame_plan.h"

// Each unit defines this in its own source, compiled here with MONOPLANE_UNIT_DECLARATION.
#define MONOPLANE_PASS_UNIT_DECLARATION(unit) \
    namespace unit {                          \
    plan::PassUnitDeclaration declaration();  \
    }

namespace monoplane::passes {

MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_DECLARATION)

const std::vector<plan::PassUnitDeclaration>& pass_unit_declarations() {
#define MONOPLANE_PASS_UNIT_ENTRY(unit) unit::declaration(),
    static const std::vector<plan::PassUnitDeclaration> declarations = {
        MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_ENTRY)};
#undef MONOPLANE_PASS_UNIT_ENTRY
    return declarations;
}

std::vector<std::string> unit_debug_views() {
    std::vector<std::string> views;
    for (const plan::PassUnitDeclaration& unit : pass_unit_declarations()) {
        if (unit.debug_view) views.push_back(*unit.debug_view);
    }
    return views;
}

plan::FramePlan plan_frame(const plan::PlanOptions& options, const plan::PlanFrame& frame,
                           const plan::PlanDevice& device) {
    return plan::plan_frame(options, frame, device, pass_unit_declarations());
}

}  // namespace monoplane::passes
