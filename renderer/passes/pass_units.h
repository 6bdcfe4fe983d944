// Every pass kind written as one unit (renderer/passes/shared/pass_unit.h), in the order a slot
// places them. Adding a unit: its folder (source and shader) and one line in pass_units.cpp.
//
// When may this be called: any time; declarations() is pure, make() needs the device.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "renderer/passes/shared/pass_unit.h"
#include "renderer/plan/pass_unit.h"

namespace monoplane::passes {

struct PassUnit {
    plan::PassUnitDeclaration (*declare)() = nullptr;
    std::unique_ptr<UnitRecorder> (*make)(const vk_core::Context& ctx) = nullptr;
};

const std::vector<PassUnit>& pass_units();
// Every unit's declaration, in pass_units()'s order: what plan_frame places.
std::vector<plan::PassUnitDeclaration> pass_unit_declarations();
// The `--debug-view` names the units add ("depth"), in that order.
std::vector<std::string> unit_debug_views();

}  // namespace monoplane::passes
