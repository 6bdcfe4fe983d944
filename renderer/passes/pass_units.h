// Every pass kind written as one unit (renderer/passes/shared/pass_unit.h), by name: the
// renderer's half, the recorders. Adding a unit: its folder (source and shaders) and one line in
// pass_unit_list.h. Their declarations: pass_unit_declarations.h.
//
// When may this be called: any time; make_unit_recorder() needs the device.
#pragma once

#include <memory>
#include <string>

#include "renderer/passes/pass_unit_declarations.h"
#include "renderer/passes/shared/pass_unit.h"

namespace monoplane::passes {

// The recorder of the unit named `unit` (PassUnitDeclaration::name), which must be registered,
// for a renderer of `scene` and `passes` (the unit's passes that renderer may record; it makes
// their pipelines).
std::unique_ptr<UnitRecorder> make_unit_recorder(const std::string& unit,
                                                 const vk_core::Context& ctx,
                                                 const UnitScene& scene, const UnitPasses& passes,
                                                 const UnitSettings& settings);

}  // namespace monoplane::passes
