#include "scenes/scene_ray_cast.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace monoplane::scenes {

struct SceneRayCaster::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    // first_triangle[i]: the caster's first triangle of the i-th chunk cast against, whose index
    // into Scene::chunks is chunks[i] (blended chunks are left out).
    std::vector<unsigned> first_triangle;
    std::vector<int> chunks;

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
    int chunk_of(unsigned triangle) const {
        const auto it = std::upper_bound(first_triangle.begin(), first_triangle.end(), triangle);
        return chunks[static_cast<std::size_t>(it - first_triangle.begin() - 1)];
    }
};

namespace {

// The triangles of the chunks that write depth, with indices made absolute (Scene::indices are
// chunk-relative), and each such chunk's first triangle among them; an error for an index beyond
// the vertices.
Result<std::vector<unsigned>> depth_writing_triangles(const Scene& scene,
                                                      std::vector<unsigned>& first_triangle,
                                                      std::vector<int>& chunks) {
    std::vector<unsigned> indices;
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        const Chunk& chunk = scene.chunks[c];
        if (chunk.alpha_mode == AlphaMode::kBlend) continue;
        first_triangle.push_back(static_cast<unsigned>(indices.size() / 3));
        chunks.push_back(static_cast<int>(c));
        for (std::uint32_t i = 0; i < chunk.index_count; ++i) {
            const std::int64_t v = static_cast<std::int64_t>(chunk.vertex_offset) +
                                   scene.indices[chunk.first_index + i];
            if (v < 0 || v >= static_cast<std::int64_t>(scene.vertices.size())) {
                return Error{"scene '" + scene.name + "': chunk " + std::to_string(c) +
                             " indexes vertex " + std::to_string(v) + " of " +
                             std::to_string(scene.vertices.size())};
            }
            indices.push_back(static_cast<unsigned>(v));
        }
    }
    return indices;
}

}  // namespace

Result<std::unique_ptr<SceneRayCaster>> SceneRayCaster::build(const Scene& scene) {
    auto impl = std::make_unique<Impl>();
    Result<std::vector<unsigned>> indices =
        depth_writing_triangles(scene, impl->first_triangle, impl->chunks);
    MONOPLANE_TRY(indices);
    impl->device = rtcNewDevice(nullptr);
    if (!impl->device) return Error{"Embree could not make a device for casting gaze rays"};
    impl->scene = rtcNewScene(impl->device);
    const std::size_t triangles = indices->size() / 3;
    if (triangles > 0) {
        RTCGeometry geometry = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), scene.vertices.size()));
        for (std::size_t v = 0; v < scene.vertices.size(); ++v) {
            const glm::vec3& p = scene.vertices[v].position;
            std::copy_n(&p.x, 3, vertices + 3 * v);
        }
        auto* triangle_indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
        std::copy(indices->begin(), indices->end(), triangle_indices);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(impl->scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(impl->scene);
    if (rtcGetDeviceError(impl->device) != RTC_ERROR_NONE) {
        return Error{"Embree could not build the ray-casting hierarchy of scene '" + scene.name +
                     "'"};
    }
    return std::unique_ptr<SceneRayCaster>(new SceneRayCaster(std::move(impl)));
}

SceneRayCaster::SceneRayCaster(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SceneRayCaster::~SceneRayCaster() = default;

std::optional<RayHit> SceneRayCaster::cast(const glm::dvec3& origin,
                                           const glm::dvec3& direction) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit ray{};
    ray.ray.org_x = static_cast<float>(origin.x);
    ray.ray.org_y = static_cast<float>(origin.y);
    ray.ray.org_z = static_cast<float>(origin.z);
    ray.ray.dir_x = static_cast<float>(direction.x);
    ray.ray.dir_y = static_cast<float>(direction.y);
    ray.ray.dir_z = static_cast<float>(direction.z);
    ray.ray.tnear = 0.0f;
    ray.ray.tfar = std::numeric_limits<float>::infinity();
    ray.ray.mask = std::numeric_limits<unsigned>::max();
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &ray);
    if (ray.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    RayHit hit;
    hit.distance = ray.ray.tfar;
    hit.point = origin + hit.distance * direction;
    hit.chunk = impl_->chunk_of(ray.hit.primID);
    return hit;
}

}  // namespace monoplane::scenes
