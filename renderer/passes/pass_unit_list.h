// The registration of every pass kind written as one unit (renderer/plan/pass_unit.h): one line
// each, X(<folder name>), in the order a slot places them. A unit's folder under renderer/passes/
// holds its <folder>_unit.cpp and its shaders; pass_unit_declarations.cpp and pass_units.cpp
// expand this list into the plan's declarations and the renderer's recorders.
#pragma once

#define MONOPLANE_PASS_UNITS(X) \
    X(culling)                  \
    X(shadow)                   \
    X(forward)                  \
    X(depth_pyramid)            \
    X(occlusion_culling)        \
    X(ssao)                     \
    X(composite)                \
    X(transparency)             \
    X(taa)                      \
    X(tonemap)                  \
    X(depth_view)               \
    X(depth_histogram)          \
    X(readback)
