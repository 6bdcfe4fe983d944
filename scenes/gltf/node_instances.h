// The node hierarchy flattened into world transforms (glTF 2.0 section 3.5): which meshes are
// drawn where, and the first camera. Iterative, so a deep hierarchy cannot overflow the stack;
// cycles and nodes with two parents are refused, so nothing is visited twice (a file could
// otherwise instance a subtree exponentially often).
#pragma once

#include <optional>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>

#include "common/result.h"
#include "scenes/gltf/tiny_gltf_config.h"

namespace monoplane::scenes::gltf {

struct NodeInstance {
    int node = -1;
    int index = -1;  // the mesh's or camera's index
    glm::dmat4 world{1.0};
};

struct SceneInstances {
    std::vector<NodeInstance> meshes;    // in depth-first order from the roots
    std::optional<NodeInstance> camera;  // the first camera node in that order
    int scene = -1;                      // the glTF scene drawn, or -1 for "all root nodes"
};

// The node's local transform: its matrix, or translation * rotation * scale. The error names
// the node ("node 3: its transform is not finite").
Result<glm::dmat4> local_transform(const tinygltf::Model& model, int node);

// The default scene (`scene`), else the first scene, else every node that has no parent.
Result<SceneInstances> instantiate_scene(const tinygltf::Model& model);

}  // namespace monoplane::scenes::gltf
