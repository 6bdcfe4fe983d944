#include "renderer/passes/pass_units.h"

// Each unit defines these two in its own source (renderer/passes/<unit>/<unit>_unit.cpp).
#define MONOPLANE_PASS_UNIT(unit)                                             \
    namespace unit {                                                          \
    plan::PassUnitDeclaration declaration();                                  \
    std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx); \
    }

namespace monoplane::passes {

// The registration: one line per unit.
#define MONOPLANE_PASS_UNITS(X) X(depth_view)

MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT)

const std::vector<PassUnit>& pass_units() {
#define MONOPLANE_PASS_UNIT_ENTRY(unit) PassUnit{&unit::declaration, &unit::make_recorder},
    static const std::vector<PassUnit> units = {MONOPLANE_PASS_UNITS(MONOPLANE_PASS_UNIT_ENTRY)};
#undef MONOPLANE_PASS_UNIT_ENTRY
    return units;
}

std::vector<plan::PassUnitDeclaration> pass_unit_declarations() {
    std::vector<plan::PassUnitDeclaration> declarations;
    for (const PassUnit& unit : pass_units()) declarations.push_back(unit.declare());
    return declarations;
}

std::vector<std::string> unit_debug_views() {
    std::vector<std::string> views;
    for (const plan::PassUnitDeclaration& unit : pass_unit_declarations()) {
        if (unit.debug_view) views.push_back(*unit.debug_view);
    }
    return views;
}

}  // namespace monoplane::passes
