// One primitive of one mesh instance into world-space triangles (glTF 2.0 section 3.7.2): its
// mode turned into a list, positions through the node's world transform, normals through its
// inverse transpose (or generated), the winding flipped under a mirroring transform, colours
// from the material, COLOR_0 and the base-colour texture.
#pragma once

#include <cstddef>
#include <string>

#include <glm/ext/matrix_double4x4.hpp>

#include "common/result.h"
#include "scenes/gltf/imported_geometry.h"
#include "scenes/gltf/load_gltf.h"
#include "scenes/gltf/texture_set.h"
#include "scenes/gltf/tiny_gltf_config.h"

namespace monoplane::scenes::gltf {

// Positions farther from the origin than this (metres) are refused: 10 000 km is no scene a
// participant stands in, and squared distances must stay far from float's range.
inline constexpr double kMaxCoordinate = 1e7;

struct PrimitiveSource {
    const tinygltf::Model& model;
    int mesh = -1;
    int primitive = -1;
    glm::dmat4 world{1.0};
};

// "mesh 'Cube' primitive 0" (or "mesh 2 primitive 0" for an unnamed mesh), for messages.
std::string describe_primitive(const tinygltf::Model& model, int mesh, int primitive);

// Appends the primitive's triangles to geometry as one batch. Points and lines, primitives
// without positions and primitives whose triangles all vanish add nothing (counted in report).
// The error names the accessor, mesh and primitive.
Result<void> import_primitive(const PrimitiveSource& source, const GltfLoadOptions& options,
                              TextureSet& textures, GltfLoadReport& report,
                              ImportedGeometry& geometry);

}  // namespace monoplane::scenes::gltf
