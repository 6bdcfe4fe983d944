// Base-colour textures of imported scenes as the forward pass samples them (issue 19 item 1):
// sRGB decoding, the texture's placement by its coordinates, glTF's wrap modes, mip-mapping, and
// the same through hybrid's C and single-pass stereo. Each expectation is an untextured scene of
// the same geometry whose base-colour factor is the texel's colour decoded by the sRGB formula
// written here: on these flat, rough (roughness 1: no reflections, a constant highlight) quads
// under a directional light, a pixel's colour depends on its albedo only, so texture and factor
// must give the same pixels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/gltf/load_gltf.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"
#include "tests/unit/gltf_test_files.h"
#include "tests/unit/png_bytes.h"

namespace monoplane {
namespace {

using modes::Eye;
using nlohmann::json;
using plan::Mode;
using Rgb = std::array<int, 3>;

constexpr glm::dvec3 kCamera{0.0, 1.7, 0.0};

// The quadrants of the test texture, sRGB as in the file: top-left (v = 0), top-right,
// bottom-left, bottom-right.
constexpr std::array<Rgb, 4> kQuadrants = {Rgb{200, 60, 40}, Rgb{40, 180, 60}, Rgb{50, 70, 210},
                                           Rgb{230, 210, 40}};

double srgb_to_linear(int encoded) {
    const double c = encoded / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// 64 x 64 texels, a solid colour per quadrant.
std::vector<unsigned char> quadrant_png() {
    std::vector<unsigned char> rgba;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const Rgb& c = kQuadrants[(y < 32 ? 0 : 2) + (x < 32 ? 0 : 1)];
            rgba.insert(rgba.end(),
                        {static_cast<unsigned char>(c[0]), static_cast<unsigned char>(c[1]),
                         static_cast<unsigned char>(c[2]), 255});
        }
    }
    return testing::png_bytes(64, 64, rgba);
}

// 128 x 128 texels alternating black and white: its mean is linear 0.5.
std::vector<unsigned char> checker_png() {
    std::vector<unsigned char> rgba;
    for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
            const unsigned char v = (x + y) % 2 == 0 ? 255 : 0;
            rgba.insert(rgba.end(), {v, v, v, 255});
        }
    }
    return testing::png_bytes(128, 128, rgba);
}

// A quad facing +z: centre, half size, texture coordinates at its top-left and bottom-right
// corners (glTF: v grows downwards in the image), material index.
struct Quad {
    glm::vec3 centre;
    float half = 1.0f;
    glm::vec2 uv_top_left{0.0f, 0.0f};
    glm::vec2 uv_bottom_right{1.0f, 1.0f};
    int material = 0;
};

void add_quad(scenes::testing::TestGltf& gltf, const Quad& q) {
    const glm::vec3 c = q.centre;
    const float h = q.half;
    const int positions = gltf.add_positions({{c.x - h, c.y + h, c.z},
                                              {c.x + h, c.y + h, c.z},
                                              {c.x - h, c.y - h, c.z},
                                              {c.x + h, c.y - h, c.z}});
    const glm::vec2 a = q.uv_top_left, b = q.uv_bottom_right;
    const int uv = gltf.add_vec2({{a.x, a.y}, {b.x, a.y}, {a.x, b.y}, {b.x, b.y}});
    const int indices = gltf.add_indices({0, 2, 1, 1, 2, 3});  // counter-clockwise from +z
    gltf.add_node({{"mesh", gltf.add_mesh({{"POSITION", positions}, {"TEXCOORD_0", uv}}, indices, 4,
                                          q.material)}});
}

json textured(int texture) {
    return {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}};
}
json plain(const Rgb& srgb) {
    return {{"pbrMetallicRoughness",
             {{"baseColorFactor",
               {srgb_to_linear(srgb[0]), srgb_to_linear(srgb[1]), srgb_to_linear(srgb[2]), 1.0}}}}};
}

void add_camera(scenes::testing::TestGltf& gltf) {
    gltf.json["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.5}, {"znear", 0.1}}}}};
    gltf.add_node({{"camera", 0}, {"translation", {kCamera.x, kCamera.y, kCamera.z}}});
}

class TexturedScene : public testing::GpuTest {
  protected:
    void SetUp() override {
        testing::GpuTest::SetUp();
        dir_ = scenes::testing::test_directory("textured_scene");
        write(dir_ / "quadrants.png", quadrant_png());
        write(dir_ / "checker.png", checker_png());
    }
    static void write(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
        std::ofstream out(path, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
    }
    scenes::Scene load(scenes::testing::TestGltf& gltf, const std::string& name) const {
        add_camera(gltf);
        gltf.write_gltf(dir_ / name);
        Result<scenes::Scene> loaded =
            scenes::load_gltf_scene(dir_ / name, scenes::testing::quiet());
        EXPECT_TRUE(loaded) << loaded.error().message;
        return std::move(loaded).value_or_throw();
    }
    modes::RendererOptions options(plan::StereoPass pass = plan::StereoPass::kTwoPasses) const {
        modes::RendererOptions o;
        o.shadow.resolution = 256;
        o.stereo_pass = pass;
        return o;
    }
    // Both eyes of one frame at the file's camera.
    std::array<modes::RgbaImage, 2> render(const scenes::Scene& scene, Mode mode, double m = 8.0,
                                           plan::StereoPass pass = plan::StereoPass::kTwoPasses) {
        modes::ModeRenderer renderer(ctx(), scene, mode, extent_, options(pass));
        renderer.render_frame(
            testing::profile_inputs(vive_, scene.find_viewpoint("default")->head, m));
        return {renderer.eye_image(Eye::kLeft), renderer.eye_image(Eye::kRight)};
    }
    // The eye's pixel of a world point (the Vive's parallel eye at the camera, looking down -z).
    glm::dvec2 pixel(Eye eye, const glm::dvec3& p) const {
        const rig::Tangents& t = eye == Eye::kLeft ? vive_.left : vive_.right;
        const glm::dvec3 d =
            p - kCamera - glm::dvec3((eye == Eye::kLeft ? -0.5 : 0.5) * vive_.ipd, 0, 0);
        const double tx = d.x / -d.z, ty = d.y / -d.z;
        return {(tx - t.left) / (t.right - t.left) * extent_.width,
                (t.up - ty) / (t.up - t.down) * extent_.height};
    }
    // Mean RGB of the (2r+1)^2 pixels around the world point's pixel, and their largest spread
    // from that mean (any channel).
    struct Patch {
        std::array<double, 3> mean{};
        double spread = 0.0;
    };
    Patch patch(const modes::RgbaImage& image, Eye eye, const glm::dvec3& p, int r = 3) const {
        const glm::dvec2 at = pixel(eye, p);
        const int cx = static_cast<int>(at.x), cy = static_cast<int>(at.y);
        Patch result;
        std::vector<std::array<int, 3>> values;
        for (int y = cy - r; y <= cy + r; ++y) {
            for (int x = cx - r; x <= cx + r; ++x) {
                const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
                values.push_back({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]});
                for (int c = 0; c < 3; ++c) result.mean[c] += values.back()[c];
            }
        }
        for (double& m : result.mean) m /= static_cast<double>(values.size());
        for (const auto& v : values) {
            for (int c = 0; c < 3; ++c)
                result.spread = std::max(result.spread, std::abs(v[c] - result.mean[c]));
        }
        return result;
    }
    void expect_same_colour(const Patch& a, const Patch& b, double tolerance,
                            const std::string& what) const {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a.mean[c], b.mean[c], tolerance) << what << " c" << c;
    }

    std::filesystem::path dir_;
    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
    const vk::Extent2D extent_{336, 378};
};

// The quadrants' centres on a 2 m quad at z = -3 in front of the camera.
std::array<glm::dvec3, 4> quadrant_centres(const glm::dvec3& centre) {
    return {centre + glm::dvec3(-0.5, 0.5, 0), centre + glm::dvec3(0.5, 0.5, 0),
            centre + glm::dvec3(-0.5, -0.5, 0), centre + glm::dvec3(0.5, -0.5, 0)};
}

TEST_F(TexturedScene, TexelsLandWhereTheirCoordinatesSayAndDecodeFromSrgb) {
    const glm::vec3 centre(0.0f, 1.7f, -3.0f);
    scenes::testing::TestGltf with_texture;
    with_texture.json["images"] = {{{"uri", "quadrants.png"}}};
    with_texture.json["textures"] = {{{"source", 0}}};
    with_texture.json["materials"] = {textured(0)};
    add_quad(with_texture, {centre});
    const scenes::Scene textured_scene = load(with_texture, "quadrants.gltf");
    scenes::testing::TestGltf without;
    for (int q = 0; q < 4; ++q) {
        without.json["materials"].push_back(plain(kQuadrants[q]));
        const glm::dvec3 at = quadrant_centres(centre)[q];
        add_quad(without, {glm::vec3(at), 0.5f, {0, 0}, {1, 1}, q});
    }
    const scenes::Scene reference_scene = load(without, "reference.gltf");

    const auto textured = render(textured_scene, Mode::kStereo);
    const auto reference = render(reference_scene, Mode::kStereo);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto e = static_cast<std::size_t>(eye);
        for (int q = 0; q < 4; ++q) {
            const glm::dvec3 at = quadrant_centres(centre)[q];
            const Patch t = patch(textured[e], eye, at);
            const Patch r = patch(reference[e], eye, at);
            expect_same_colour(
                t, r, 1.5, std::string(modes::eye_name(eye)) + " quadrant " + std::to_string(q));
            EXPECT_LE(t.spread, 1.0);
        }
    }
    // The quadrants differ (the texture is sampled, not averaged): top-left's green (sRGB 60)
    // against bottom-right's (210).
    const Patch a = patch(textured[0], Eye::kLeft, quadrant_centres(centre)[0]);
    const Patch d = patch(textured[0], Eye::kLeft, quadrant_centres(centre)[3]);
    EXPECT_GT(d.mean[1] - a.mean[1], 30.0);

    // Hybrid with the quad beyond m: C samples the texture, the composite maps it into the eyes.
    const auto hybrid = render(textured_scene, Mode::kHybrid, 1.5);
    const auto hybrid_reference = render(reference_scene, Mode::kHybrid, 1.5);
    // Single-pass stereo draws what two passes draw.
    const auto gs = render(textured_scene, Mode::kStereo, 8.0, plan::StereoPass::kGeometryShader);
    // Instanced stereo's right eye is instance 1: its texture is still the base instance's chunk's.
    const auto instanced = render(textured_scene, Mode::kStereo, 8.0, plan::StereoPass::kInstanced);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto e = static_cast<std::size_t>(eye);
        for (int q = 0; q < 4; ++q) {
            // C's view drifts the quad by under a pixel here; the patches stay inside their
            // quadrant.
            const glm::dvec3 at = quadrant_centres(centre)[q];
            expect_same_colour(patch(hybrid[e], eye, at), patch(hybrid_reference[e], eye, at), 1.5,
                               "hybrid quadrant " + std::to_string(q));
            expect_same_colour(patch(gs[e], eye, at), patch(textured[e], eye, at), 0.5,
                               "stereo-gs quadrant " + std::to_string(q));
            expect_same_colour(patch(instanced[e], eye, at), patch(textured[e], eye, at), 0.5,
                               "stereo-instanced quadrant " + std::to_string(q));
        }
    }
}

// Texture coordinates from -0.5 to 1.5 across the quad: at coordinate (-0.25, -0.25) repeat
// finds texel (0.75, 0.75) (bottom-right), clamp the edge texel (0, 0) (top-left), mirror
// (0.25, 0.25) (top-left); at (1.25, 0.25) repeat finds (0.25, 0.25) (top-left), clamp (1, 0.25)
// (top-right), mirror (0.75, 0.25) (top-right).
TEST_F(TexturedScene, GltfWrapModesFoldCoordinatesOutsideTheImage) {
    struct Case {
        int gl_wrap;
        int at_minus_quarter;    // quadrant shown at (-0.25, -0.25)
        int at_one_and_quarter;  // quadrant shown at (1.25, 0.25)
    };
    const std::vector<Case> cases = {{10497, 3, 0}, {33071, 0, 1}, {33648, 0, 1}};
    const glm::vec3 centre(0.0f, 1.7f, -3.0f);
    // Quad corners span coordinates -0.5..1.5: coordinate u lies at x = centre - 1 + (u + 0.5).
    auto world_at = [&](double u, double v) {
        return glm::dvec3(centre) + glm::dvec3(-1.0 + (u + 0.5), 1.0 - (v + 0.5), 0.0);
    };
    // A plain quad of each quadrant's colour where the textured one lies, rendered once.
    std::map<int, modes::RgbaImage> plain_quads;
    auto plain_quad = [&](int quadrant) -> const modes::RgbaImage& {
        if (!plain_quads.contains(quadrant)) {
            scenes::testing::TestGltf single;
            single.json["materials"] = {plain(kQuadrants[quadrant])};
            add_quad(single, {centre});
            plain_quads[quadrant] = render(load(single, "plain.gltf"), Mode::kStereo)[0];
        }
        return plain_quads.at(quadrant);
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.gl_wrap);
        scenes::testing::TestGltf gltf;
        gltf.json["images"] = {{{"uri", "quadrants.png"}}};
        gltf.json["samplers"] = {{{"wrapS", c.gl_wrap}, {"wrapT", c.gl_wrap}}};
        gltf.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
        gltf.json["materials"] = {textured(0)};
        add_quad(gltf, {centre, 1.0f, {-0.5f, -0.5f}, {1.5f, 1.5f}});
        const auto image = render(load(gltf, "wrap.gltf"), Mode::kStereo)[0];
        for (const auto& [uv, quadrant] :
             {std::pair{glm::dvec2(-0.25, -0.25), c.at_minus_quarter},
              std::pair{glm::dvec2(1.25, 0.25), c.at_one_and_quarter}}) {
            const glm::dvec3 at = world_at(uv.x, uv.y);
            expect_same_colour(patch(image, Eye::kLeft, at, 2),
                               patch(plain_quad(quadrant), Eye::kLeft, at, 2), 1.5,
                               "uv " + std::to_string(uv.x) + "," + std::to_string(uv.y));
        }
    }
}

// A far quad covered by a one-texel checker: several texels fall in each pixel, so without mip
// maps the pixels alias between black and white; with them each pixel shows the mean, linear
// 0.5 (averaging sRGB bytes would give the darker sRGB 128, linear 0.216).
TEST_F(TexturedScene, MipMapsAverageDistantDetailInLinearLight) {
    const glm::vec3 centre(0.0f, 1.7f, -40.0f);
    scenes::testing::TestGltf gltf;
    gltf.json["images"] = {{{"uri", "checker.png"}}};
    gltf.json["textures"] = {{{"source", 0}}};
    gltf.json["materials"] = {textured(0)};
    add_quad(gltf, {centre, 4.0f});
    const auto image = render(load(gltf, "checker.gltf"), Mode::kStereo)[0];
    scenes::testing::TestGltf grey;
    grey.json["materials"] = {
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}}}}};
    add_quad(grey, {centre, 4.0f});
    const auto expected = render(load(grey, "grey.gltf"), Mode::kStereo)[0];
    const Patch t = patch(image, Eye::kLeft, glm::dvec3(centre), 4);
    const Patch r = patch(expected, Eye::kLeft, glm::dvec3(centre), 4);
    expect_same_colour(t, r, 2.0, "checker");
    EXPECT_LE(t.spread, 3.0);
}

// A double-sided quad seen from behind is drawn; a single-sided one is culled (the sky shows).
TEST_F(TexturedScene, DoubleSidedQuadsShowTheirBack) {
    const glm::vec3 centre(0.0f, 1.7f, -3.0f);
    std::array<Patch, 2> seen;
    for (const bool double_sided : {false, true}) {
        scenes::testing::TestGltf gltf;
        gltf.json["materials"] = {plain(kQuadrants[0])};
        gltf.json["materials"][0]["doubleSided"] = double_sided;
        // Facing -z: its front looks away from the camera.
        const int positions = gltf.add_positions(
            {{-1.0f, 2.7f, -3.0f}, {1.0f, 2.7f, -3.0f}, {-1.0f, 0.7f, -3.0f}, {1.0f, 0.7f, -3.0f}});
        const int indices = gltf.add_indices({0, 1, 2, 1, 3, 2});
        gltf.add_node({{"mesh", gltf.add_mesh({{"POSITION", positions}}, indices, 4, 0)}});
        const auto image = render(load(gltf, "sides.gltf"), Mode::kStereo)[0];
        seen[double_sided ? 1 : 0] = patch(image, Eye::kLeft, glm::dvec3(centre));
    }
    scenes::testing::TestGltf front;
    front.json["materials"] = {plain(kQuadrants[0])};
    add_quad(front, {centre});
    const Patch facing =
        patch(render(load(front, "front.gltf"), Mode::kStereo)[0], Eye::kLeft, glm::dvec3(centre));
    // Single-sided: culled, the sky (blue) shows. Double-sided: the back is drawn, and lit as a
    // quad facing the camera is (its back faces carry the turned normal).
    EXPECT_LT(seen[0].mean[0], seen[0].mean[2]);
    EXPECT_GT(seen[1].mean[0], seen[1].mean[2] + 40.0);
    expect_same_colour(seen[1], facing, 1.5, "back of a double-sided quad");
}

}  // namespace
}  // namespace monoplane
