// The scenes library's public entry: procedural BEAMS, LANDSCAPE and SPHERES scenes
// (docs/scenes.md), deterministic from a seed, with names for the CLI and the study.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "scenes/scene.h"

namespace monoplane::scenes {

// The seed every participant and benchmark sees unless told otherwise.
inline constexpr std::uint64_t kDefaultSeed = 1;

// Builds a scene on the CPU (no GPU needed); any time, any thread. High detail takes about a
// second, Ultra several. The same arguments give the same bytes (geometry_hash) on every run with
// the same build; other compilers and C libraries give the same scene up to the last bits of a
// few sin/cos/pow results (the random numbers themselves are identical everywhere).
// id may not be SceneId::Imported (imported scenes come from scenes/gltf/load_gltf.h).
Scene generate_scene(SceneId id, Detail detail, std::uint64_t seed = kDefaultSeed);

// A 64-bit hash of the vertices, indices, chunks (their alpha modes and cut-offs too where any
// chunk is not opaque), texture coordinates and viewpoints (not the texels), for determinism
// checks and for tagging results with the exact geometry they were measured on.
std::uint64_t geometry_hash(const Scene& scene);

// "beams", "landscape", "spheres" (scene_name also gives "imported", which does not parse back).
std::optional<SceneId> parse_scene_id(std::string_view name);
std::string_view scene_name(SceneId id);
// "test", "low", "medium", "high", "ultra".
std::optional<Detail> parse_detail(std::string_view name);
std::string_view detail_name(Detail detail);

}  // namespace monoplane::scenes
