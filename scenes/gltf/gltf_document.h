// A glTF file read into tinygltf's model, after the checks tinygltf does not make itself: the
// .glb container, the glTF version and required extensions, the JSON schema's types and index
// ranges, and the buffers' sources (glb_container.h, gltf_support.h, json_schema.h,
// buffer_sources.h). What the model's accessors and images hold is still unchecked: readers
// check it where they read it (accessor_reader.h, texture_decode.h).
#pragma once

#include <filesystem>
#include <vector>

#include "common/result.h"
#include "scenes/gltf/tiny_gltf_config.h"

namespace monoplane::scenes::gltf {

struct GltfDocument {
    tinygltf::Model model;
    // Images are not decoded here: a URI image's image.image holds the file's encoded bytes
    // (as_is set), a buffer-view image's is empty; texture_decode.h decodes what a scene uses.
    std::filesystem::path base_directory;  // where the file's relative URIs resolve
    // Every file read: the .gltf/.glb first, then each external buffer and image (data: URIs
    // read none), each once, in the order read. Evidence of what a study showed.
    std::vector<std::filesystem::path> files_read;
};

// The error is one sentence without the file's name, e.g. "buffer 0: file \"Box0.bin\" not
// found in models/box" or "is not valid JSON: syntax error at line 3, column 7 ...".
Result<GltfDocument> read_gltf_document(const std::filesystem::path& file);

}  // namespace monoplane::scenes::gltf
