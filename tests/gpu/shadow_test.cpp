// The sun's shadow falls where geometry says it must: a roof 1 m above a ground plane, the sun at
// 45 degrees, so the shadow lies 1 m beside the roof's footprint. Points are located in the image
// with the rig's projection (tested on its own in rig_projection_test).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/modes/mode_renderer.h"
#include "rig/projection.h"
#include "tests/gpu/gpu_test.h"

namespace monoplane {
namespace {

void add_quad(scenes::Scene& scene, glm::vec3 corner, glm::vec3 edge_u, glm::vec3 edge_v,
              std::uint32_t albedo) {
    const glm::vec3 normal = glm::normalize(glm::cross(edge_u, edge_v));
    const std::uint32_t material = scenes::pack_material({0.9f, 0.02f, 0});
    const auto base = static_cast<std::uint32_t>(scene.vertices.size());
    for (const glm::vec3 p : {corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v}) {
        scene.vertices.push_back({p, normal, albedo, material});
    }
    scenes::Chunk chunk;
    chunk.first_index = static_cast<std::uint32_t>(scene.indices.size());
    chunk.index_count = 6;
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(base + i);
    chunk.bounds = {glm::min(corner, corner + edge_u + edge_v),
                    glm::max(corner, corner + edge_u + edge_v)};
    scene.chunks.push_back(chunk);
}

// The display image is sRGB-encoded; light adds up in linear values.
double linear(std::uint8_t encoded) {
    const double c = encoded / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double luminance_at(const modes::RgbaImage& image, const glm::dmat4& view_proj, glm::dvec3 world) {
    const glm::dvec4 clip = view_proj * glm::dvec4(world, 1.0);
    const int x = static_cast<int>((clip.x / clip.w * 0.5 + 0.5) * image.width);
    const int y = static_cast<int>((clip.y / clip.w * 0.5 + 0.5) * image.height);
    double sum = 0.0;  // 3x3 linear average, away from the shadow's edge
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const std::uint8_t* p = &image.pixels[((y + dy) * image.width + (x + dx)) * 4];
            sum += 0.2126 * linear(p[0]) + 0.7152 * linear(p[1]) + 0.0722 * linear(p[2]);
        }
    }
    return sum / 9.0;
}

class Shadow : public testing::GpuTest {};

TEST_F(Shadow, RoofCastsItsShadowBesideItsFootprint) {
    scenes::Scene scene;
    const std::uint32_t grey = scenes::pack_rgba8(0.6f, 0.6f, 0.6f);
    add_quad(scene, {-6.0f, 0.0f, 6.0f}, {12.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -12.0f},
             grey);                                                                       // ground
    add_quad(scene, {-0.5f, 1.0f, 0.5f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, grey);  // roof
    scene.bounds = {{-6.0f, 0.0f, -6.0f}, {6.0f, 1.0f, 6.0f}};
    // Towards the sun: up and to +x at 45 degrees, so a point at height 1 shades (x - 1, 0, z).
    scene.lighting.sun_direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));

    modes::StereoViewInputs inputs;
    inputs.head.position = {0.0, 4.0, 4.0};
    inputs.head.orientation = rig::orientation_from_yaw_pitch(0.0, -std::numbers::pi / 4.0);
    inputs.left = inputs.right = rig::Tangents{-1.0, 1.0, -1.0, 1.0};
    modes::RendererOptions options;
    options.shadow.resolution = 1024;
    modes::ModeRenderer stereo(ctx(), scene, plan::Mode::kStereo, {256, 256}, options);
    stereo.render_frame({inputs});

    const glm::dmat4 view_proj = modes::eye_view_proj(inputs, modes::Eye::kLeft);
    const auto& image = stereo.eye_image(modes::Eye::kLeft);
    const double shadowed = luminance_at(image, view_proj, {-1.0, 0.0, 0.0});
    const double lit_left = luminance_at(image, view_proj, {-2.5, 0.0, 0.0});
    const double lit_right = luminance_at(image, view_proj, {1.5, 0.0, 0.0});
    // In shadow only the sky's ambient light remains: well under half the sunlit luminance.
    EXPECT_LT(shadowed, 0.5 * lit_left);
    EXPECT_LT(shadowed, 0.5 * lit_right);
    EXPECT_GT(shadowed, 0.0);  // but not black: the sky still lights it
    // Ground on both sides of the shadow gets the same sunlight.
    EXPECT_NEAR(lit_left, lit_right, 0.1 * lit_right);
}

}  // namespace
}  // namespace monoplane
