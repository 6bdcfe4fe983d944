#include "scenes/gltf/accessor_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace monoplane::scenes::gltf {
namespace {

std::string component_name(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT:
            return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE:
            return "DOUBLE";
        default:
            return "component type " + std::to_string(type);
    }
}

// Bytes per component of the types glTF 2.0 allows (INT and DOUBLE are not among them).
std::size_t component_bytes(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

std::string type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "type " + std::to_string(type);
    }
}

std::size_t components_of(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;  // matrices are never vertex attributes or indices
    }
}

// Component c of an element, little-endian like glTF's buffers; memcpy because nothing
// guarantees alignment (the spec asks for it, files do not always give it).
float decode_float(const unsigned char* at, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? static_cast<float>(at[0]) / 255.0f : static_cast<float>(at[0]);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t value = 0;
            std::memcpy(&value, at, sizeof value);
            return normalized ? static_cast<float>(value) / 65535.0f : static_cast<float>(value);
        }
        default: {
            float value = 0.0f;
            std::memcpy(&value, at, sizeof value);
            return value;
        }
    }
}

std::uint32_t decode_unsigned(const unsigned char* at, int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return at[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t value = 0;
            std::memcpy(&value, at, sizeof value);
            return value;
        }
        default: {
            std::uint32_t value = 0;
            std::memcpy(&value, at, sizeof value);
            return value;
        }
    }
}

// count elements of element_bytes, stride apart, from a checked place in a buffer.
struct Elements {
    const unsigned char* first = nullptr;  // nullptr: no buffer view, all zeros
    std::size_t stride = 0;
};

// Checks one accessor (or one of its sparse arrays) against what the file really holds.
class Check {
  public:
    Check(const tinygltf::Model& model, int accessor, const std::string& what)
        : model_(model), accessor_(accessor), what_(what) {}

    Error fail(const std::string& problem) const {
        return Error{"accessor " + std::to_string(accessor_) + " (" + what_ + "): " + problem};
    }

    // Where count elements start, byte_offset into buffer view `view`: strided views use the
    // view's byteStride (sparse arrays are always packed).
    Result<Elements> locate(int view, std::uint64_t byte_offset, std::uint64_t count,
                            std::uint64_t element_bytes, bool strided,
                            const std::string& part) const {
        if (view < 0 || static_cast<std::size_t>(view) >= model_.bufferViews.size()) {
            return fail(part + "buffer view " + std::to_string(view) + " does not exist");
        }
        const tinygltf::BufferView& buffer_view =
            model_.bufferViews[static_cast<std::size_t>(view)];
        const std::string view_name = "buffer view " + std::to_string(view);
        if (buffer_view.buffer < 0 ||
            static_cast<std::size_t>(buffer_view.buffer) >= model_.buffers.size()) {
            return fail(view_name + " names buffer " + std::to_string(buffer_view.buffer) +
                        ", which does not exist");
        }
        const tinygltf::Buffer& buffer =
            model_.buffers[static_cast<std::size_t>(buffer_view.buffer)];
        const std::uint64_t buffer_bytes = buffer.data.size();
        const std::uint64_t view_offset = buffer_view.byteOffset;
        const std::uint64_t view_bytes = buffer_view.byteLength;
        // Buffers hold under 2^32 bytes (file limits): once view_offset is known to be inside,
        // nothing here wraps.
        if (view_offset > buffer_bytes || view_bytes > buffer_bytes - view_offset) {
            return fail(view_name + " (bytes " + std::to_string(view_offset) + " to " +
                        std::to_string(view_offset + view_bytes) + ") lies outside buffer " +
                        std::to_string(buffer_view.buffer) + " (" + std::to_string(buffer_bytes) +
                        " bytes)");
        }
        const std::uint64_t stride =
            strided && buffer_view.byteStride != 0 ? buffer_view.byteStride : element_bytes;
        if (stride < element_bytes) {
            return fail("byteStride " + std::to_string(stride) + " of " + view_name +
                        " is smaller than one element (" + std::to_string(element_bytes) +
                        " bytes)");
        }
        // The last element ends at byte_offset + stride * (count - 1) + element_bytes: with
        // byte_offset inside the view, count bounded by the caller and stride at most 252
        // (tinygltf checks), the sum cannot wrap; the first test keeps a huge offset out of it.
        const std::uint64_t end = byte_offset + stride * (count - 1) + element_bytes;
        if (byte_offset > view_bytes || end > view_bytes) {
            return fail(part + "count " + std::to_string(count) + " with stride " +
                        std::to_string(stride) + " from byte " + std::to_string(byte_offset) +
                        " reads past the end of " + view_name + " (" + std::to_string(view_bytes) +
                        " bytes)");
        }
        return Elements{buffer.data.data() + view_offset + byte_offset,
                        static_cast<std::size_t>(stride)};
    }

  private:
    const tinygltf::Model& model_;
    int accessor_;
    const std::string& what_;
};

// The accessor, with type, component type and count checked against the caller's rules.
Result<const tinygltf::Accessor*> find_accessor(const tinygltf::Model& model, int index,
                                                const Check& check, std::size_t max_count) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        return check.fail("does not exist (the file has " + std::to_string(model.accessors.size()) +
                          " accessors)");
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.count == 0) return check.fail("count is 0");
    if (accessor.count > max_count) {
        return check.fail("count " + std::to_string(accessor.count) +
                          " is more than the limit of " + std::to_string(max_count));
    }
    return &accessor;
}

// Applies an accessor's sparse substitution (glTF 2.0 section 3.6.2.3) to dense elements.
template <class Decode>
Result<void> apply_sparse(const tinygltf::Accessor& accessor, const Check& check,
                          std::size_t element_bytes, Decode store) {
    const auto& sparse = accessor.sparse;
    if (sparse.count <= 0 || static_cast<std::size_t>(sparse.count) > accessor.count) {
        return check.fail("sparse count " + std::to_string(sparse.count) +
                          " is not between 1 and the accessor's count " +
                          std::to_string(accessor.count));
    }
    const int index_type = sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        return check.fail("sparse indices have component type " + component_name(index_type) +
                          " (glTF allows UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT)");
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        return check.fail("a sparse byteOffset is negative");
    }
    const auto count = static_cast<std::uint64_t>(sparse.count);
    Result<Elements> indices = check.locate(
        sparse.indices.bufferView, static_cast<std::uint64_t>(sparse.indices.byteOffset), count,
        component_bytes(index_type), false, "sparse indices: ");
    MONOPLANE_TRY(indices);
    Result<Elements> values =
        check.locate(sparse.values.bufferView, static_cast<std::uint64_t>(sparse.values.byteOffset),
                     count, element_bytes, false, "sparse values: ");
    MONOPLANE_TRY(values);
    std::int64_t previous = -1;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t target =
            decode_unsigned(indices->first + k * indices->stride, index_type);
        if (target >= accessor.count || static_cast<std::int64_t>(target) <= previous) {
            return check.fail("sparse index " + std::to_string(target) + " (entry " +
                              std::to_string(k) +
                              ") is out of range or not above the one before it");
        }
        previous = target;
        store(target, values->first + k * values->stride);
    }
    return Ok{};
}

}  // namespace

Result<FloatElements> read_float_accessor(const tinygltf::Model& model, int index,
                                          const FloatRequest& request) {
    const Check check(model, index, request.what);
    Result<const tinygltf::Accessor*> found = find_accessor(model, index, check, request.max_count);
    MONOPLANE_TRY(found);
    const tinygltf::Accessor& accessor = **found;

    if (std::find(request.types.begin(), request.types.end(), accessor.type) ==
        request.types.end()) {
        std::string allowed;
        for (const int type : request.types)
            allowed += (allowed.empty() ? "" : " or ") + type_name(type);
        return check.fail("is " + type_name(accessor.type) + ", but must be " + allowed);
    }
    const int component = accessor.componentType;
    const bool is_float = component == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool is_unsigned_normalizable = component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                          component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    if (!(is_float || (request.normalized_unsigned && is_unsigned_normalizable))) {
        return check.fail("has component type " + component_name(component) + ", but must be " +
                          (request.normalized_unsigned
                               ? "FLOAT, or UNSIGNED_BYTE or UNSIGNED_SHORT normalized"
                               : "FLOAT"));
    }
    if (is_float && accessor.normalized)
        return check.fail("is FLOAT and normalized, which glTF forbids");
    if (!is_float && !accessor.normalized) {
        return check.fail("is " + component_name(component) + " but not normalized");
    }

    FloatElements result;
    result.components = components_of(accessor.type);
    result.count = accessor.count;
    result.values.assign(result.count * result.components, 0.0f);
    const std::size_t bytes_per_component = component_bytes(component);
    const std::size_t element_bytes = bytes_per_component * result.components;
    auto store = [&](std::size_t element, const unsigned char* at) {
        float* out = result.values.data() + element * result.components;
        for (std::size_t c = 0; c < result.components; ++c) {
            out[c] = decode_float(at + c * bytes_per_component, component, accessor.normalized);
        }
    };
    if (accessor.bufferView >= 0) {  // without one, the elements are zeros (glTF 3.6.2.1)
        Result<Elements> elements = check.locate(accessor.bufferView, accessor.byteOffset,
                                                 accessor.count, element_bytes, true, "");
        MONOPLANE_TRY(elements);
        for (std::size_t i = 0; i < result.count; ++i)
            store(i, elements->first + i * elements->stride);
    }
    if (accessor.sparse.isSparse) {
        MONOPLANE_TRY(apply_sparse(accessor, check, element_bytes, store));
    }
    for (std::size_t i = 0; i < result.values.size(); ++i) {
        if (!std::isfinite(result.values[i])) {
            std::ostringstream value;
            value << result.values[i];
            return check.fail("element " + std::to_string(i / result.components) +
                              " is not finite (" + value.str() + ")");
        }
    }
    return result;
}

Result<std::vector<std::uint32_t>> read_index_accessor(const tinygltf::Model& model, int index,
                                                       const std::string& what,
                                                       std::size_t vertex_count,
                                                       std::size_t max_count) {
    const Check check(model, index, what);
    Result<const tinygltf::Accessor*> found = find_accessor(model, index, check, max_count);
    MONOPLANE_TRY(found);
    const tinygltf::Accessor& accessor = **found;
    if (accessor.type != TINYGLTF_TYPE_SCALAR) {
        return check.fail("is " + type_name(accessor.type) + ", but indices must be SCALAR");
    }
    const int component = accessor.componentType;
    if (component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        return check.fail("has component type " + component_name(component) +
                          ", but indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    }
    if (accessor.normalized) return check.fail("indices cannot be normalized");

    std::vector<std::uint32_t> indices(accessor.count, 0u);
    const std::size_t element_bytes = component_bytes(component);
    auto store = [&](std::size_t element, const unsigned char* at) {
        indices[element] = decode_unsigned(at, component);
    };
    if (accessor.bufferView >= 0) {
        Result<Elements> elements = check.locate(accessor.bufferView, accessor.byteOffset,
                                                 accessor.count, element_bytes, true, "");
        MONOPLANE_TRY(elements);
        for (std::size_t i = 0; i < indices.size(); ++i)
            store(i, elements->first + i * elements->stride);
    }
    if (accessor.sparse.isSparse) {
        MONOPLANE_TRY(apply_sparse(accessor, check, element_bytes, store));
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertex_count) {
            return check.fail("index " + std::to_string(indices[i]) + " at position " +
                              std::to_string(i) + " is out of range (the primitive has " +
                              std::to_string(vertex_count) + " vertices)");
        }
    }
    return indices;
}

}  // namespace monoplane::scenes::gltf
