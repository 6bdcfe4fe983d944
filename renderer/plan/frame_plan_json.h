// The executed frame plan as render --json and bench.json report it (docs/architecture.md):
// "plan": [{"pass": name, "kind": k, "view": v, "skipped": reason-or-null, "draws": [...]}, ...],
// every planned pass in order, skipped ones with their reason; "when" for a predicated pass, and
// "writes_display": true for a composite that tone maps into the display image itself.
#pragma once

#include <string_view>

#include "common/json_writer.h"
#include "renderer/plan/frame_plan.h"

namespace monoplane::plan {

// Writes the array under `key` into the open object of `j`.
void write_plan_json(JsonWriter& j, const FramePlan& plan, std::string_view key = "plan");

}  // namespace monoplane::plan
