// The engine-style "mono far field" camera (papers/003, Palandri and Green 2016; Unreal's
// Monoscopic Far Field Rendering), for comparison with Fink et al.'s rig: C sits at the centre
// of the eyes (no offset behind them), its frustum is the union of the eyes' frusta, there is no
// overlap band (C starts exactly at m), and each eye receives C's image as a copy shifted by a
// whole number of pixels: the disparity of the mono plane, rounded.
#pragma once

#include <array>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_int2.hpp>

#include "rig/tangents.h"

namespace monoplane::modes {

struct FarfieldRig {
    rig::Tangents tangents;  // union of both eyes' tangents, from the eyes' centre
    int width = 0;           // C's size at the eyes' pixel density
    int height = 0;
    glm::dmat4 projection{1.0};           // reversed Z, m..f
    std::array<glm::ivec2, 2> offsets{};  // eye pixel + offset = C pixel, per eye
};

// Requires valid eye tangents, eye size >= 1, ipd >= 0, 0 < m < f (the rig validates these).
FarfieldRig build_farfield_rig(const std::array<rig::Tangents, 2>& eyes, int eye_width,
                               int eye_height, double ipd, double mono_plane, double far);

}  // namespace monoplane::modes
