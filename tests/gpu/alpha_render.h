// What the alpha-mode GPU tests share (alpha_mask_test.cpp, alpha_blend_test.cpp): the scenes of
// tests/gpu/alpha_scenes.h loaded from a directory of the test's own, one frame rendered in any
// mode and stereo form at the scenes' camera, and the eye pixel of a world point, worked out from
// the HMD profile's tangents (the Vive's eyes are parallel, looking down -z from the camera
// shifted by half the IPD): the expectations come from the geometry, not from a rendering.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/gltf/load_gltf.h"
#include "tests/gpu/alpha_scenes.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane::testing {

using modes::Eye;
using plan::Mode;
using plan::StereoPass;

// One frame's display images, both eyes.
using EyeImages = std::array<modes::RgbaImage, 2>;

// The RGB of one pixel, 0-255 (sRGB-encoded, as the display image holds it).
struct Rgb {
    int r = 0, g = 0, b = 0;
    int channel(int c) const { return c == 0 ? r : (c == 1 ? g : b); }
};

inline Rgb rgb_at(const modes::RgbaImage& image, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
    return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

// The largest channel difference of two pixels.
inline int difference(const Rgb& a, const Rgb& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// The largest channel difference over two images of one size.
inline int max_difference(const modes::RgbaImage& a, const modes::RgbaImage& b) {
    int worst = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
    }
    return worst;
}

class AlphaSceneTest : public GpuTest {
  protected:
    void SetUp() override {
        GpuTest::SetUp();
        dir_ = scenes::testing::test_directory("alpha_scenes");
    }

    scenes::Scene load(const std::filesystem::path& file) const {
        Result<scenes::Scene> loaded = scenes::load_gltf_scene(file, scenes::testing::quiet());
        EXPECT_TRUE(loaded) << loaded.error().message;
        return std::move(loaded).value_or_throw();
    }

    // Small shadow region, fine texels: cut-out shadows of 0.25 m cells stay sharp.
    modes::RendererOptions options(StereoPass pass = StereoPass::kTwoPasses) const {
        modes::RendererOptions o;
        o.shadow.resolution = 2048;
        o.shadow.region_radius_m = 16.0f;
        o.stereo_pass = pass;
        return o;
    }

    modes::FrameInputs inputs(const scenes::Scene& scene, double m) const {
        return profile_inputs(vive_, scene.find_viewpoint("default")->head, m);
    }

    EyeImages render(const scenes::Scene& scene, Mode mode, double m,
                     const modes::RendererOptions& with) {
        modes::ModeRenderer renderer(ctx(), scene, mode, extent_, with);
        renderer.render_frame(inputs(scene, m));
        return {renderer.eye_image(Eye::kLeft), renderer.eye_image(Eye::kRight)};
    }
    EyeImages render(const scenes::Scene& scene, Mode mode, double m = 8.0,
                     StereoPass pass = StereoPass::kTwoPasses) {
        return render(scene, mode, m, options(pass));
    }

    // Where the eye is: the camera shifted by half the IPD along x.
    glm::dvec3 eye_position(Eye eye) const {
        return glm::dvec3(kAlphaSceneEye) +
               glm::dvec3((eye == Eye::kLeft ? -0.5 : 0.5) * vive_.ipd, 0.0, 0.0);
    }

    // The eye's continuous pixel coordinate of a world point (x right, y down; the pixel
    // (i, j) covers [i, i + 1) x [j, j + 1)).
    glm::dvec2 pixel(Eye eye, const glm::dvec3& p) const {
        const rig::Tangents& t = eye == Eye::kLeft ? vive_.left : vive_.right;
        const glm::dvec3 d = p - eye_position(eye);
        const double tx = d.x / -d.z, ty = d.y / -d.z;
        return {(tx - t.left) / (t.right - t.left) * extent_.width,
                (t.up - ty) / (t.up - t.down) * extent_.height};
    }

    // The pixel a world point falls in, or nullopt off the image.
    std::optional<glm::ivec2> pixel_of(Eye eye, const glm::dvec3& p) const {
        const glm::dvec2 at = pixel(eye, p);
        const glm::ivec2 i(static_cast<int>(std::floor(at.x)), static_cast<int>(std::floor(at.y)));
        if (i.x < 0 || i.y < 0 || i.x >= static_cast<int>(extent_.width) ||
            i.y >= static_cast<int>(extent_.height)) {
            return std::nullopt;
        }
        return i;
    }

    // Pixels per metre of a surface facing the eye at distance d (its scale on the image).
    double pixels_per_metre(double d) const {
        return extent_.width / ((vive_.left.right - vive_.left.left) * d);
    }

    std::filesystem::path dir_;
    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
    vk::Extent2D extent_{336, 378};
};

inline const char* eye_text(Eye eye) {
    return eye == Eye::kLeft ? "left" : "right";
}

}  // namespace monoplane::testing
