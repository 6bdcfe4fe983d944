// Where a ray meets a scene's surfaces, on the CPU (docs/gaze.md): the point a participant's gaze
// rests on. Embree (Debian's libembree-dev) builds a bounding volume hierarchy over the scene's
// triangles once and answers each ray in microseconds, so a session may ask every frame without
// a GPU pass.
//
// What is cast against is what writes depth when the scene is drawn: opaque and alpha-masked
// chunks at their finest level of detail (Scene::indices). Blended chunks (glass, water) write no
// depth and are passed through, as the eye's depth image passes through them. A masked chunk's
// cut-outs are not: its triangles count whole (procedural scenes have none).
#pragma once

#include <memory>
#include <optional>

#include <glm/ext/vector_double3.hpp>

#include "common/result.h"
#include "scenes/scene.h"

namespace monoplane::scenes {

struct RayHit {
    double distance = 0.0;  // along the ray, in units of its direction's length
    glm::dvec3 point{0.0};  // world frame
    int chunk = -1;         // index into Scene::chunks
};

class SceneRayCaster {
  public:
    // Builds the hierarchy over `scene`'s opaque and masked triangles (copied: the scene need not
    // outlive the caster). An error where Embree cannot make its device or the scene holds an
    // index beyond its vertices. May take a second for millions of triangles; call before frames
    // run.
    static Result<std::unique_ptr<SceneRayCaster>> build(const Scene& scene);
    ~SceneRayCaster();
    SceneRayCaster(const SceneRayCaster&) = delete;
    SceneRayCaster& operator=(const SceneRayCaster&) = delete;

    // The nearest surface the ray origin + t direction meets for t > 0, either side of a triangle;
    // none where it meets nothing (the sky). `direction` need not be unit length but must not be
    // zero. Any thread, any time after build; the caster is not changed.
    std::optional<RayHit> cast(const glm::dvec3& origin, const glm::dvec3& direction) const;

  private:
    struct Impl;
    explicit SceneRayCaster(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace monoplane::scenes
