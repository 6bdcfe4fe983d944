#include "scenes/gltf/json_schema.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace monoplane::scenes::gltf {
namespace {

using nlohmann::json;

// The top-level arrays that indices point into.
enum class Target {
    None,
    Accessors,
    Animations,
    Buffers,
    BufferViews,
    Cameras,
    Images,
    Materials,
    Meshes,
    Nodes,
    Samplers,
    Scenes,
    Skins,
    Textures,
};

enum class Kind {
    Integer,      // a non-negative integer; an index when target is set
    Number,       // any number
    String,       //
    Boolean,      //
    Object,       // checked against shape
    NumberArray,  // numbers, `length` of them unless length is 0
    IndexArray,   // indices into target
    ObjectArray,  // objects, each checked against shape
    StringArray,  //
    IndexMap,     // an object whose members are indices into target (attributes)
    IndexMapArray,
};

struct Shape;

struct Property {
    std::string_view name;
    Kind kind;
    Target target = Target::None;
    const Shape* shape = nullptr;
    std::size_t length = 0;
    bool required = false;
    std::uint64_t minimum = 0;  // Integer only
};

struct Shape {
    std::span<const Property> properties;
};

constexpr Property kRequired(Property p) {
    p.required = true;
    return p;
}
constexpr Property kAtLeast(Property p, std::uint64_t minimum) {
    p.minimum = minimum;
    return p;
}

constexpr std::array kTextureInfoProperties = {
    kRequired({"index", Kind::Integer, Target::Textures}),
    Property{"texCoord", Kind::Integer},
    Property{"scale", Kind::Number},
    Property{"strength", Kind::Number},
};
constexpr Shape kTextureInfo{kTextureInfoProperties};

constexpr std::array kPbrProperties = {
    Property{"baseColorFactor", Kind::NumberArray, Target::None, nullptr, 4},
    Property{"baseColorTexture", Kind::Object, Target::None, &kTextureInfo},
    Property{"metallicFactor", Kind::Number},
    Property{"roughnessFactor", Kind::Number},
    Property{"metallicRoughnessTexture", Kind::Object, Target::None, &kTextureInfo},
};
constexpr Shape kPbr{kPbrProperties};

constexpr std::array kMaterialProperties = {
    Property{"name", Kind::String},
    Property{"pbrMetallicRoughness", Kind::Object, Target::None, &kPbr},
    Property{"normalTexture", Kind::Object, Target::None, &kTextureInfo},
    Property{"occlusionTexture", Kind::Object, Target::None, &kTextureInfo},
    Property{"emissiveTexture", Kind::Object, Target::None, &kTextureInfo},
    Property{"emissiveFactor", Kind::NumberArray, Target::None, nullptr, 3},
    Property{"alphaMode", Kind::String},
    Property{"alphaCutoff", Kind::Number},
    Property{"doubleSided", Kind::Boolean},
};
constexpr Shape kMaterial{kMaterialProperties};

constexpr std::array kSparseIndicesProperties = {
    kRequired({"bufferView", Kind::Integer, Target::BufferViews}),
    Property{"byteOffset", Kind::Integer},
    kRequired({"componentType", Kind::Integer}),
};
constexpr Shape kSparseIndices{kSparseIndicesProperties};

constexpr std::array kSparseValuesProperties = {
    kRequired({"bufferView", Kind::Integer, Target::BufferViews}),
    Property{"byteOffset", Kind::Integer},
};
constexpr Shape kSparseValues{kSparseValuesProperties};

constexpr std::array kSparseProperties = {
    kRequired(kAtLeast({"count", Kind::Integer}, 1)),
    kRequired({"indices", Kind::Object, Target::None, &kSparseIndices}),
    kRequired({"values", Kind::Object, Target::None, &kSparseValues}),
};
constexpr Shape kSparse{kSparseProperties};

constexpr std::array kAccessorProperties = {
    Property{"bufferView", Kind::Integer, Target::BufferViews},
    Property{"byteOffset", Kind::Integer},
    kRequired({"componentType", Kind::Integer}),
    Property{"normalized", Kind::Boolean},
    kRequired(kAtLeast({"count", Kind::Integer}, 1)),
    kRequired({"type", Kind::String}),
    Property{"max", Kind::NumberArray},
    Property{"min", Kind::NumberArray},
    Property{"sparse", Kind::Object, Target::None, &kSparse},
    Property{"name", Kind::String},
};
constexpr Shape kAccessor{kAccessorProperties};

constexpr std::array kBufferViewProperties = {
    kRequired({"buffer", Kind::Integer, Target::Buffers}),
    Property{"byteOffset", Kind::Integer},
    kRequired(kAtLeast({"byteLength", Kind::Integer}, 1)),
    Property{"byteStride", Kind::Integer},
    Property{"target", Kind::Integer},
    Property{"name", Kind::String},
};
constexpr Shape kBufferView{kBufferViewProperties};

constexpr std::array kBufferProperties = {
    Property{"uri", Kind::String},
    kRequired(kAtLeast({"byteLength", Kind::Integer}, 1)),
    Property{"name", Kind::String},
};
constexpr Shape kBuffer{kBufferProperties};

constexpr std::array kPerspectiveProperties = {
    Property{"aspectRatio", Kind::Number},
    kRequired({"yfov", Kind::Number}),
    Property{"zfar", Kind::Number},
    kRequired({"znear", Kind::Number}),
};
constexpr Shape kPerspective{kPerspectiveProperties};

constexpr std::array kOrthographicProperties = {
    kRequired({"xmag", Kind::Number}),
    kRequired({"ymag", Kind::Number}),
    kRequired({"zfar", Kind::Number}),
    kRequired({"znear", Kind::Number}),
};
constexpr Shape kOrthographic{kOrthographicProperties};

constexpr std::array kCameraProperties = {
    kRequired({"type", Kind::String}),
    Property{"perspective", Kind::Object, Target::None, &kPerspective},
    Property{"orthographic", Kind::Object, Target::None, &kOrthographic},
    Property{"name", Kind::String},
};
constexpr Shape kCamera{kCameraProperties};

constexpr std::array kImageProperties = {
    Property{"uri", Kind::String},
    Property{"mimeType", Kind::String},
    Property{"bufferView", Kind::Integer, Target::BufferViews},
    Property{"name", Kind::String},
};
constexpr Shape kImage{kImageProperties};

constexpr std::array kPrimitiveProperties = {
    kRequired({"attributes", Kind::IndexMap, Target::Accessors}),
    Property{"indices", Kind::Integer, Target::Accessors},
    Property{"material", Kind::Integer, Target::Materials},
    Property{"mode", Kind::Integer},
    Property{"targets", Kind::IndexMapArray, Target::Accessors},
};
constexpr Shape kPrimitive{kPrimitiveProperties};

constexpr std::array kMeshProperties = {
    kRequired({"primitives", Kind::ObjectArray, Target::None, &kPrimitive}),
    Property{"weights", Kind::NumberArray},
    Property{"name", Kind::String},
};
constexpr Shape kMesh{kMeshProperties};

constexpr std::array kNodeProperties = {
    Property{"camera", Kind::Integer, Target::Cameras},
    Property{"children", Kind::IndexArray, Target::Nodes},
    Property{"skin", Kind::Integer, Target::Skins},
    Property{"matrix", Kind::NumberArray, Target::None, nullptr, 16},
    Property{"mesh", Kind::Integer, Target::Meshes},
    Property{"rotation", Kind::NumberArray, Target::None, nullptr, 4},
    Property{"scale", Kind::NumberArray, Target::None, nullptr, 3},
    Property{"translation", Kind::NumberArray, Target::None, nullptr, 3},
    Property{"weights", Kind::NumberArray},
    Property{"name", Kind::String},
};
constexpr Shape kNode{kNodeProperties};

constexpr std::array kSamplerProperties = {
    Property{"magFilter", Kind::Integer}, Property{"minFilter", Kind::Integer},
    Property{"wrapS", Kind::Integer},     Property{"wrapT", Kind::Integer},
    Property{"name", Kind::String},
};
constexpr Shape kSampler{kSamplerProperties};

constexpr std::array kSceneProperties = {
    Property{"nodes", Kind::IndexArray, Target::Nodes},
    Property{"name", Kind::String},
};
constexpr Shape kScene{kSceneProperties};

constexpr std::array kSkinProperties = {
    Property{"inverseBindMatrices", Kind::Integer, Target::Accessors},
    Property{"skeleton", Kind::Integer, Target::Nodes},
    kRequired({"joints", Kind::IndexArray, Target::Nodes}),
    Property{"name", Kind::String},
};
constexpr Shape kSkin{kSkinProperties};

constexpr std::array kTextureProperties = {
    Property{"sampler", Kind::Integer, Target::Samplers},
    Property{"source", Kind::Integer, Target::Images},
    Property{"name", Kind::String},
};
constexpr Shape kTexture{kTextureProperties};

constexpr std::array kChannelTargetProperties = {
    Property{"node", Kind::Integer, Target::Nodes},
    kRequired({"path", Kind::String}),
};
constexpr Shape kChannelTarget{kChannelTargetProperties};

constexpr std::array kChannelProperties = {
    kRequired({"sampler", Kind::Integer}),
    kRequired({"target", Kind::Object, Target::None, &kChannelTarget}),
};
constexpr Shape kChannel{kChannelProperties};

constexpr std::array kAnimationSamplerProperties = {
    kRequired({"input", Kind::Integer, Target::Accessors}),
    Property{"interpolation", Kind::String},
    kRequired({"output", Kind::Integer, Target::Accessors}),
};
constexpr Shape kAnimationSampler{kAnimationSamplerProperties};

constexpr std::array kAnimationProperties = {
    kRequired({"channels", Kind::ObjectArray, Target::None, &kChannel}),
    kRequired({"samplers", Kind::ObjectArray, Target::None, &kAnimationSampler}),
    Property{"name", Kind::String},
};
constexpr Shape kAnimation{kAnimationProperties};

constexpr std::array kAssetProperties = {
    kRequired({"version", Kind::String}),
    Property{"minVersion", Kind::String},
    Property{"generator", Kind::String},
    Property{"copyright", Kind::String},
};
constexpr Shape kAsset{kAssetProperties};

struct Collection {
    std::string_view name;
    Target target;
    const Shape* shape;
    std::string_view singular;  // for "the file has 1 image"
};

constexpr std::array kCollections = {
    Collection{"accessors", Target::Accessors, &kAccessor, "accessor"},
    Collection{"animations", Target::Animations, &kAnimation, "animation"},
    Collection{"buffers", Target::Buffers, &kBuffer, "buffer"},
    Collection{"bufferViews", Target::BufferViews, &kBufferView, "buffer view"},
    Collection{"cameras", Target::Cameras, &kCamera, "camera"},
    Collection{"images", Target::Images, &kImage, "image"},
    Collection{"materials", Target::Materials, &kMaterial, "material"},
    Collection{"meshes", Target::Meshes, &kMesh, "mesh"},
    Collection{"nodes", Target::Nodes, &kNode, "node"},
    Collection{"samplers", Target::Samplers, &kSampler, "sampler"},
    Collection{"scenes", Target::Scenes, &kScene, "scene"},
    Collection{"skins", Target::Skins, &kSkin, "skin"},
    Collection{"textures", Target::Textures, &kTexture, "texture"},
};

std::string type_of(const json& value) {
    if (value.is_number_integer()) return "an integer";
    if (value.is_number()) return "a number";
    const std::string name = value.type_name();
    return (name == "array" || name == "object" ? "an " : "a ") + name;
}

std::size_t depth_of(const json& root) {
    // Iterative: the point is to refuse what would overflow a recursive reader.
    std::size_t deepest = 0;
    std::vector<std::pair<const json*, std::size_t>> pending{{&root, 1}};
    while (!pending.empty()) {
        const auto [value, depth] = pending.back();
        pending.pop_back();
        deepest = std::max(deepest, depth);
        if (depth > kMaxJsonDepth) break;
        if (value->is_structured()) {
            for (const json& child : *value) pending.emplace_back(&child, depth + 1);
        }
    }
    return deepest;
}

class SchemaCheck {
  public:
    explicit SchemaCheck(const json& root) : root_(root) {
        for (const Collection& collection : kCollections) {
            const auto found = root.find(collection.name);
            sizes_[static_cast<std::size_t>(collection.target)] =
                found != root.end() && found->is_array() ? found->size() : 0;
        }
    }

    Result<void> run() {
        if (!root_.is_object())
            return Error{"the JSON document is " + type_of(root_) + ", not an object"};
        MONOPLANE_TRY(extensions(root_, ""));
        const auto asset = root_.find("asset");
        if (asset == root_.end()) return Error{"asset is missing (every glTF file has one)"};
        MONOPLANE_TRY(object(*asset, kAsset, "asset"));
        MONOPLANE_TRY(index(root_, "scene", Target::Scenes, "scene"));
        for (const std::string_view list : {"extensionsUsed", "extensionsRequired"}) {
            const auto found = root_.find(list);
            if (found == root_.end()) continue;
            MONOPLANE_TRY(string_array(*found, std::string(list)));
        }
        for (const Collection& collection : kCollections) {
            const auto found = root_.find(collection.name);
            if (found == root_.end()) continue;
            const std::string path(collection.name);
            if (!found->is_array()) {
                return Error{path + " must be an array, not " + type_of(*found)};
            }
            for (std::size_t i = 0; i < found->size(); ++i) {
                MONOPLANE_TRY(object((*found)[i], *collection.shape, element(path, i)));
            }
        }
        return Ok{};
    }

  private:
    static std::string element(const std::string& path, std::size_t i) {
        return path + "[" + std::to_string(i) + "]";
    }
    static std::string member(const std::string& path, std::string_view name) {
        return path.empty() ? std::string(name) : path + "." + std::string(name);
    }

    std::size_t size_of(Target target) const { return sizes_[static_cast<std::size_t>(target)]; }

    static std::string count_of(Target target, std::size_t count) {
        for (const Collection& collection : kCollections) {
            if (collection.target != target) continue;
            std::string noun(collection.singular);
            if (count != 1) noun += noun == "mesh" ? "es" : "s";
            return std::to_string(count) + " " + noun;
        }
        return std::to_string(count);
    }

    // Extension objects may hold anything, but each extension's value is an object.
    static Result<void> extensions(const json& object, const std::string& path) {
        const auto found = object.find("extensions");
        if (found == object.end()) return Ok{};
        const std::string where = member(path, "extensions");
        if (!found->is_object()) return Error{where + " must be an object, not " + type_of(*found)};
        for (auto it = found->begin(); it != found->end(); ++it) {
            if (!it->is_object()) {
                return Error{member(where, it.key()) + " must be an object, not " + type_of(*it)};
            }
        }
        return Ok{};
    }

    Result<void> integer(const json& value, const std::string& path, Target target,
                         std::uint64_t minimum) const {
        if (!value.is_number_integer()) {
            return Error{path + " must be a non-negative integer, not " + type_of(value)};
        }
        if (value.is_number_unsigned() == false && value.get<std::int64_t>() < 0) {
            return Error{path + " must be a non-negative integer, not " + value.dump()};
        }
        const std::uint64_t number = value.get<std::uint64_t>();
        if (number < minimum) {
            return Error{path + " must be at least " + std::to_string(minimum) + ", not " +
                         std::to_string(number)};
        }
        if (target != Target::None && number >= size_of(target)) {
            return Error{path + " is " + std::to_string(number) + ", but the file has " +
                         count_of(target, size_of(target))};
        }
        return Ok{};
    }

    Result<void> index(const json& object, std::string_view name, Target target,
                       const std::string& path) const {
        const auto found = object.find(name);
        if (found == object.end()) return Ok{};
        return integer(*found, path, target, 0);
    }

    static Result<void> string_array(const json& value, const std::string& path) {
        if (!value.is_array()) return Error{path + " must be an array, not " + type_of(value)};
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!value[i].is_string()) {
                return Error{element(path, i) + " must be a string, not " + type_of(value[i])};
            }
        }
        return Ok{};
    }

    Result<void> index_map(const json& value, const std::string& path, Target target) const {
        if (!value.is_object()) return Error{path + " must be an object, not " + type_of(value)};
        for (auto it = value.begin(); it != value.end(); ++it) {
            MONOPLANE_TRY(integer(*it, member(path, it.key()), target, 0));
        }
        return Ok{};
    }

    Result<void> property(const json& value, const Property& p, const std::string& path) const {
        switch (p.kind) {
            case Kind::Integer:
                return integer(value, path, p.target, p.minimum);
            case Kind::Number:
                if (!value.is_number())
                    return Error{path + " must be a number, not " + type_of(value)};
                return Ok{};
            case Kind::String:
                if (!value.is_string())
                    return Error{path + " must be a string, not " + type_of(value)};
                return Ok{};
            case Kind::Boolean:
                if (!value.is_boolean()) {
                    return Error{path + " must be true or false, not " + type_of(value)};
                }
                return Ok{};
            case Kind::Object:
                return object(value, *p.shape, path);
            case Kind::StringArray:
                return string_array(value, path);
            case Kind::IndexMap:
                return index_map(value, path, p.target);
            case Kind::NumberArray:
            case Kind::IndexArray:
            case Kind::ObjectArray:
            case Kind::IndexMapArray:
                break;
        }
        if (!value.is_array()) return Error{path + " must be an array, not " + type_of(value)};
        if (p.length != 0 && value.size() != p.length) {
            return Error{path + " must have " + std::to_string(p.length) + " elements, not " +
                         std::to_string(value.size())};
        }
        for (std::size_t i = 0; i < value.size(); ++i) {
            const json& item = value[i];
            const std::string where = element(path, i);
            Result<void> ok = Ok{};
            if (p.kind == Kind::NumberArray && !item.is_number()) {
                ok = Error{where + " must be a number, not " + type_of(item)};
            } else if (p.kind == Kind::IndexArray) {
                ok = integer(item, where, p.target, 0);
            } else if (p.kind == Kind::ObjectArray) {
                ok = object(item, *p.shape, where);
            } else if (p.kind == Kind::IndexMapArray) {
                ok = index_map(item, where, p.target);
            }
            MONOPLANE_TRY(ok);
        }
        return Ok{};
    }

    Result<void> object(const json& value, const Shape& shape, const std::string& path) const {
        if (!value.is_object()) return Error{path + " must be an object, not " + type_of(value)};
        MONOPLANE_TRY(extensions(value, path));
        for (const Property& p : shape.properties) {
            const auto found = value.find(p.name);
            if (found == value.end()) {
                if (p.required) return Error{member(path, p.name) + " is missing"};
                continue;
            }
            MONOPLANE_TRY(property(*found, p, member(path, p.name)));
        }
        return Ok{};
    }

    const json& root_;
    std::array<std::size_t, static_cast<std::size_t>(Target::Textures) + 1> sizes_{};
};

}  // namespace

Result<void> check_json_schema(const json& root) {
    if (depth_of(root) > kMaxJsonDepth) {
        return Error{"the JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels"};
    }
    return SchemaCheck(root).run();
}

}  // namespace monoplane::scenes::gltf
