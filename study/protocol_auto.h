// The protocol's [auto] table (issue 20): how a `hybrid-auto` alternative chooses its mono plane
// every frame (renderer/plan/mono_plane_chooser.h), as plain data the app translates. A trial's
// distance m is the nearest plane the chooser may take in that trial, so `mono_planes` stays the
// trial factor: "hybrid-auto at 8 m" never cuts nearer than 8 m, and goes farther where the
// budget, a gap or the time says so. Validated with located errors like the rest of the protocol.
#pragma once

#include <optional>
#include <string>

#include "common/toml/toml_keys.h"

namespace monoplane::study {

struct AutoPlaneSettings {
    double error_budget_arcmin = 6.0;      // > 0
    std::string measure = "eye";           // eye | disparity
    double step_arcmin = 0.25;             // > 0: the far content's largest shift per frame
    std::optional<double> time_budget_ms;  // > 0: stereo while the stereo frame fits

    bool operator==(const AutoPlaneSettings&) const = default;
};

// Reads [auto] from the protocol's root into `settings` (left at its defaults when absent).
// Reports, located: a non-table, unknown keys, non-numbers, values that are not positive, a
// measure other than eye or disparity, and [auto] in a protocol without a hybrid-auto
// alternative (it would silently do nothing). uses_auto: whether an alternative is hybrid-auto.
void read_auto_plane(const TomlScope& root, bool uses_auto, AutoPlaneSettings& settings,
                     TomlProblems& problems);

}  // namespace monoplane::study
