// tinygltf's implementation, compiled once for monoplane_gltf (Debian ships it header-only, with
// nlohmann-json for the JSON).
#define TINYGLTF_IMPLEMENTATION
#include "scenes/gltf/tiny_gltf_config.h"
