#include "scenes/gltf/node_instances.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace monoplane::scenes::gltf {
namespace {

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

std::string node_name(const tinygltf::Model& model, int node) {
    const std::string& name = model.nodes[static_cast<std::size_t>(node)].name;
    return "node " + std::to_string(node) + (name.empty() ? "" : " '" + name + "'");
}

// parent[n] is n's parent or -1; refuses children that do not exist, nodes that are their own
// child, and nodes with two parents.
Result<std::vector<int>> parents_of(const tinygltf::Model& model) {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        for (const int child : model.nodes[n].children) {
            const auto node = static_cast<int>(n);
            if (child < 0 || static_cast<std::size_t>(child) >= model.nodes.size()) {
                return Error{node_name(model, node) + " has child " + std::to_string(child) +
                             ", which does not exist"};
            }
            if (child == node) return Error{node_name(model, node) + " is its own child"};
            int& slot = parent[static_cast<std::size_t>(child)];
            if (slot >= 0) {
                return Error{node_name(model, child) + " has two parents (nodes " +
                             std::to_string(slot) + " and " + std::to_string(node) +
                             "): glTF nodes form trees"};
            }
            slot = node;
        }
    }
    return parent;
}

// With at most one parent each, following parents from any node ends at a root or runs around a
// cycle. Marks whole walks, so every node is walked over once.
Result<void> refuse_cycles(const tinygltf::Model& model, const std::vector<int>& parent) {
    enum : std::uint8_t { kUnknown, kOnThisWalk, kReachesRoot };
    std::vector<std::uint8_t> state(parent.size(), kUnknown);
    std::vector<int> walk;
    for (std::size_t start = 0; start < parent.size(); ++start) {
        walk.clear();
        int node = static_cast<int>(start);
        while (node >= 0 && state[static_cast<std::size_t>(node)] == kUnknown) {
            state[static_cast<std::size_t>(node)] = kOnThisWalk;
            walk.push_back(node);
            node = parent[static_cast<std::size_t>(node)];
        }
        if (node >= 0 && state[static_cast<std::size_t>(node)] == kOnThisWalk) {
            // `node` is on the cycle: list the cycle downwards from it.
            std::vector<int> upward{node};
            for (int up = parent[static_cast<std::size_t>(node)]; up != node;
                 up = parent[static_cast<std::size_t>(up)]) {
                upward.push_back(up);
            }
            std::string path = std::to_string(node);
            for (auto it = upward.rbegin(); it != upward.rend(); ++it)
                path += " -> " + std::to_string(*it);
            return Error{"the node hierarchy has a cycle (" + path +
                         "): " + node_name(model, node) +
                         " is its own ancestor, but glTF nodes form trees"};
        }
        for (const int w : walk) state[static_cast<std::size_t>(w)] = kReachesRoot;
    }
    return Ok{};
}

}  // namespace

Result<glm::dmat4> local_transform(const tinygltf::Model& model, int node_index) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(node_index)];
    glm::dmat4 local(1.0);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) {
            return Error{node_name(model, node_index) + ": matrix has " +
                         std::to_string(node.matrix.size()) + " elements, not 16"};
        }
        for (int c = 0; c < 4; ++c) {  // glTF matrices are column-major
            for (int r = 0; r < 4; ++r)
                local[c][r] =
                    node.matrix[4 * static_cast<std::size_t>(c) + static_cast<std::size_t>(r)];
        }
    } else {
        if ((!node.translation.empty() && node.translation.size() != 3) ||
            (!node.rotation.empty() && node.rotation.size() != 4) ||
            (!node.scale.empty() && node.scale.size() != 3)) {
            return Error{node_name(model, node_index) +
                         ": translation, rotation or scale has the wrong number of elements"};
        }
        if (!node.translation.empty()) {
            local = glm::translate(local,
                                   {node.translation[0], node.translation[1], node.translation[2]});
        }
        if (!node.rotation.empty()) {
            // glTF stores x, y, z, w; glm's constructor takes w first.
            glm::dquat rotation(node.rotation[3], node.rotation[0], node.rotation[1],
                                node.rotation[2]);
            const double length = glm::length(rotation);
            if (!(length > 1e-12) || !std::isfinite(length)) {
                return Error{node_name(model, node_index) + ": rotation is not a unit quaternion"};
            }
            // Exporters round; the specification asks for unit length, so normalise.
            local *= glm::mat4_cast(rotation / length);
        }
        if (!node.scale.empty())
            local = glm::scale(local, {node.scale[0], node.scale[1], node.scale[2]});
    }
    if (!finite(local))
        return Error{node_name(model, node_index) + ": its transform is not finite"};
    return local;
}

Result<SceneInstances> instantiate_scene(const tinygltf::Model& model) {
    Result<std::vector<int>> parents = parents_of(model);
    MONOPLANE_TRY(parents);
    const std::vector<int>& parent = *parents;
    MONOPLANE_TRY(refuse_cycles(model, parent));

    SceneInstances instances;
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        instances.scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (static_cast<std::size_t>(instances.scene) >= model.scenes.size()) {
            return Error{"scene " + std::to_string(instances.scene) + " does not exist"};
        }
        roots = model.scenes[static_cast<std::size_t>(instances.scene)].nodes;
    } else {
        for (std::size_t n = 0; n < parent.size(); ++n) {
            if (parent[n] < 0) roots.push_back(static_cast<int>(n));
        }
    }

    // Depth-first from the roots, each node at most once.
    std::vector<bool> visited(model.nodes.size(), false);
    std::vector<std::pair<int, glm::dmat4>> pending;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
        if (*root < 0 || static_cast<std::size_t>(*root) >= model.nodes.size()) {
            return Error{"scene " + std::to_string(instances.scene) + " lists node " +
                         std::to_string(*root) + ", which does not exist"};
        }
        if (parent[static_cast<std::size_t>(*root)] >= 0) {
            return Error{"scene " + std::to_string(instances.scene) + " lists " +
                         node_name(model, *root) + " as a root, but it is a child of node " +
                         std::to_string(parent[static_cast<std::size_t>(*root)])};
        }
        pending.emplace_back(*root, glm::dmat4(1.0));
    }
    while (!pending.empty()) {
        const auto [node, parent_world] = pending.back();
        pending.pop_back();
        if (visited[static_cast<std::size_t>(node)]) {
            return Error{"scene " + std::to_string(instances.scene) + " lists " +
                         node_name(model, node) + " twice"};
        }
        visited[static_cast<std::size_t>(node)] = true;
        Result<glm::dmat4> local = local_transform(model, node);
        MONOPLANE_TRY(local);
        const glm::dmat4 world = parent_world * *local;
        if (!finite(world)) {
            return Error{node_name(model, node) + ": its world transform overflows"};
        }
        const tinygltf::Node& n = model.nodes[static_cast<std::size_t>(node)];
        if (n.mesh >= 0) instances.meshes.push_back({node, n.mesh, world});
        if (n.camera >= 0 && !instances.camera)
            instances.camera = NodeInstance{node, n.camera, world};
        for (auto child = n.children.rbegin(); child != n.children.rend(); ++child) {
            pending.emplace_back(*child, world);
        }
    }

    return instances;
}

}  // namespace monoplane::scenes::gltf
