// glTF alphaMode BLEND in every mode (issue 34, items 2 and 3), on the panes of alpha_scenes.h.
// A blended pane of alpha a over a background shows a * pane + (1 - a) * background, in linear
// light before the display transform: the pane's own colour is read from the same scene with the
// panes opaque, the background from the scene without them, both taken back through the inverse
// of the tone curve (ACES fit, then sRGB) and the expectation sent forward through it again.
// Hybrid: panes nearer than m are drawn per eye after the composite, exactly where stereo has them;
// a pane beyond m is C's, displaced by the mapping's analytic error (papers/000 Sect. 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "tests/gpu/alpha_render.h"

namespace monoplane::testing {
namespace {

using plan::AntiAliasing;

// The display transform (renderer/passes/tonemap/tone_mapping.glsl, exposure 1, then sRGB) and
// its inverse, per channel, in [0, 1].
double aces(double x) {
    return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
double srgb_encode(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double srgb_decode(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}
double display(double hdr) {
    return 255.0 * srgb_encode(aces(hdr));
}
// aces(x) = y solved for x >= 0: (2.43 y - 2.51) x^2 + (0.59 y - 0.03) x + 0.14 y = 0.
double hdr_of(int encoded) {
    const double y = srgb_decode(encoded / 255.0);
    const double a = 2.43 * y - 2.51, b = 0.59 * y - 0.03, c = 0.14 * y;
    return (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

// The alpha the GPU blends with: the vertex colour's RGBA8 (the base-colour factor's alpha).
double stored_alpha(float alpha) {
    return std::round(alpha * 255.0) / 255.0;
}

// The three renderings every expectation is made of.
struct PaneFrames {
    EyeImages blended, opaque, empty;
};

class AlphaBlend : public AlphaSceneTest {
  protected:
    void SetUp() override {
        AlphaSceneTest::SetUp();
        blended_ = load(write_pane_scene(dir_));
        opaque_ = load(write_pane_scene(dir_, PaneOptions{false, true}));
        empty_ = load(write_pane_scene(dir_, PaneOptions{true, false}));
    }

    PaneFrames frames(Mode mode = Mode::kStereo, double m = 8.0) {
        return {render(blended_, mode, m), render(opaque_, mode, m), render(empty_, mode, m)};
    }

    // The colour the image shows at a world point.
    Rgb at(const EyeImages& images, Eye eye, const glm::vec3& point) const {
        const glm::ivec2 p = *pixel_of(eye, point);
        return rgb_at(images[static_cast<std::size_t>(eye)], p.x, p.y);
    }

    // The largest channel deviation (8-bit levels) of `shown` from the layers blended over the
    // background, farthest first, each an alpha and the pane's colour drawn opaque.
    struct Layer {
        double alpha;
        Rgb colour;
    };
    static double deviation(const Rgb& shown, const Rgb& background,
                            const std::vector<Layer>& farthest_first) {
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            double hdr = hdr_of(background.channel(c));
            for (const Layer& layer : farthest_first) {
                hdr = layer.alpha * hdr_of(layer.colour.channel(c)) + (1.0 - layer.alpha) * hdr;
            }
            worst = std::max(worst, std::abs(shown.channel(c) - display(hdr)));
        }
        return worst;
    }

    // The point of behind_near (z = -6) on the eye's ray through a point of near_red (z = -3),
    // if it lies inside behind_near by `margin` of its size (a negative one: near it).
    std::optional<glm::vec3> behind_near_on_ray(Eye eye, const glm::vec3& on_near,
                                                float margin = 0.05f) const {
        const glm::vec3 from = glm::vec3(eye_position(eye));
        const glm::vec3 on_behind = from + (on_near - from) * 2.0f;
        const glm::vec3 b0 = kBehindNearPane.quad.at({margin, margin});
        const glm::vec3 b1 = kBehindNearPane.quad.at({1.0f - margin, 1.0f - margin});
        if (on_behind.x < b0.x || on_behind.x > b1.x || on_behind.y > b0.y || on_behind.y < b1.y) {
            return std::nullopt;
        }
        return on_behind;
    }

    // One pane over the background at a point of it.
    double single_pane_deviation(const PaneFrames& f, Eye eye, const glm::vec3& point,
                                 double alpha) const {
        return deviation(at(f.blended, eye, point), at(f.empty, eye, point),
                         {{alpha, at(f.opaque, eye, point)}});
    }

    scenes::Scene blended_, opaque_, empty_;
};

// Interior points of a pane (uv in [0.2, 0.8]^2 on a 7 x 7 grid).
std::vector<glm::vec2> interior() {
    std::vector<glm::vec2> uvs;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) uvs.emplace_back(0.2f + 0.1f * i, 0.2f + 0.1f * j);
    return uvs;
}

TEST_F(AlphaBlend, APaneShowsAlphaTimesItsColourPlusTheRestTimesTheBackground) {
    const PaneFrames f = frames();
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        SCOPED_TRACE(eye_text(eye));
        for (const AlphaPane& pane : {kNearRedPane, kFarBluePane}) {
            for (const glm::vec2& uv : interior()) {
                // Where near_red lies over behind_near: OverlappingPanesBlendFarthestFirst.
                if (behind_near_on_ray(eye, pane.quad.at(uv), -0.05f)) continue;
                EXPECT_LE(
                    single_pane_deviation(f, eye, pane.quad.at(uv), stored_alpha(pane.colour.a)),
                    2.0)
                    << pane.quad.name << " at " << uv.x << "," << uv.y;
            }
        }
        // The gradient pane: alpha u (the texture) times the factor's 1, within 1/255.
        for (const glm::vec2& uv : interior()) {
            EXPECT_LE(single_pane_deviation(f, eye, kGradientPane.quad.at(uv), gradient_alpha(uv)),
                      3.0)
                << "gradient at " << uv.x;
        }
    }
}

// behind_near's right part is uncovered; its left part lies behind near_red, which is blended
// over it: the far pane first ("over" does not commute, and the two orders differ by far more
// than the tolerance here).
TEST_F(AlphaBlend, OverlappingPanesBlendFarthestFirst) {
    const PaneFrames f = frames();
    const double near_a = stored_alpha(kNearRedPane.colour.a);
    const double behind_a = stored_alpha(kBehindNearPane.colour.a);
    int overlapping = 0;
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        SCOPED_TRACE(eye_text(eye));
        // behind_near's own colour, where near_red does not cover it.
        const Rgb behind_colour = at(f.opaque, eye, kBehindNearPane.quad.at({0.9f, 0.5f}));
        for (int i = 0; i < 18; ++i) {
            const glm::vec2 uv(0.6f + 0.02f * i, 0.15f + 0.04f * i);
            const glm::vec3 on_near = kNearRedPane.quad.at(uv);
            if (!behind_near_on_ray(eye, on_near)) continue;
            ++overlapping;
            const Rgb shown = at(f.blended, eye, on_near);
            const Rgb background = at(f.empty, eye, on_near);
            const Rgb near_colour = at(f.opaque, eye, on_near);
            EXPECT_LE(
                deviation(shown, background, {{behind_a, behind_colour}, {near_a, near_colour}}),
                2.0);
            // The other order would be far off.
            EXPECT_GT(
                deviation(shown, background, {{near_a, near_colour}, {behind_a, behind_colour}}),
                8.0);
        }
        for (float u : {0.85f, 0.9f}) {
            EXPECT_LE(single_pane_deviation(f, eye, kBehindNearPane.quad.at({u, 0.5f}), behind_a),
                      2.0);
        }
    }
    EXPECT_GT(overlapping, 10);
}

// Hybrid with nothing beyond the mono plane is stereo, blended panes included.
TEST_F(AlphaBlend, HybridWithTheMonoPlaneAtTheFarPlaneEqualsStereo) {
    for (Mode mode : {Mode::kHybrid, Mode::kHybridFarfield}) {
        const EyeImages hybrid = render(blended_, mode, 1000.0);
        const EyeImages stereo = render(blended_, Mode::kStereo);
        EXPECT_EQ(max_difference(hybrid[0], stereo[0]), 0);
        EXPECT_EQ(max_difference(hybrid[1], stereo[1]), 0);
    }
}

// The pixel box a pane covers in an eye, grown by `grow` pixels and clipped to the image.
struct PixelBox {
    glm::ivec2 lo, hi;  // inclusive
};

class AlphaBlendHybrid : public AlphaBlend {
  protected:
    PixelBox box_of(const AlphaQuad& quad, Eye eye, int grow) const {
        const glm::dvec2 a = pixel(eye, quad.at({0.0f, 0.0f}));
        const glm::dvec2 b = pixel(eye, quad.at({1.0f, 1.0f}));
        const glm::ivec2 size(static_cast<int>(extent_.width) - 1,
                              static_cast<int>(extent_.height) - 1);
        return {glm::clamp(glm::ivec2(glm::floor(glm::min(a, b))) - grow, glm::ivec2(0), size),
                glm::clamp(glm::ivec2(glm::floor(glm::max(a, b))) + grow, glm::ivec2(0), size)};
    }

    // The largest difference of two images over a box, leaving out the rows within two pixels of
    // the horizon (the backdrop's foot at z = -40, which C's mapping moves by a fraction of a
    // pixel: papers/000 Sect. 3).
    int box_difference(const modes::RgbaImage& a, const modes::RgbaImage& b, const PixelBox& box,
                       Eye eye) const {
        const double horizon = pixel(eye, glm::dvec3(0.0, 0.0, -40.0)).y;
        int worst = 0;
        for (int y = box.lo.y; y <= box.hi.y; ++y) {
            if (std::abs(y + 0.5 - horizon) < 2.5) continue;
            for (int x = box.lo.x; x <= box.hi.x; ++x) {
                worst = std::max(worst, difference(rgb_at(a, x, y), rgb_at(b, x, y)));
            }
        }
        return worst;
    }

    // How much of a pixel a pane covers: its change to the image over the change well inside it.
    static double coverage(const modes::RgbaImage& with, const modes::RgbaImage& without, int x,
                           int y, double inside) {
        return std::clamp(difference(rgb_at(with, x, y), rgb_at(without, x, y)) / inside, 0.0, 1.0);
    }

    // Where a pane's left and right edges and its top edge lie, to a fraction of a pixel, from the
    // coverage of the rows above the horizon (below it the ground behind the pane, moved by C's
    // mapping by its own amount, would weigh in): x the middle of the two edges, y the top edge.
    glm::dvec2 pane_edges(const modes::RgbaImage& with, const modes::RgbaImage& without,
                          const AlphaQuad& quad, Eye eye) const {
        const PixelBox box = box_of(quad, eye, 4);
        const glm::ivec2 centre(pixel(eye, quad.centre()));
        const int top_row = box.lo.y;
        const int last_row = static_cast<int>(pixel(eye, glm::dvec3(0.0, 0.0, -40.0)).y) - 4;
        const double inside = difference(rgb_at(with, centre.x, (top_row + last_row) / 2),
                                         rgb_at(without, centre.x, (top_row + last_row) / 2));
        double width_sum = 0.0, left_sum = 0.0;
        const int rows = last_row - (top_row + 8);
        for (int y = top_row + 8; y < last_row; ++y) {
            double covered = 0.0, before = 0.0;
            for (int x = box.lo.x; x <= box.hi.x; ++x) {
                const double c = coverage(with, without, x, y, inside);
                covered += c;
                if (x < centre.x) before += 1.0 - c;
            }
            width_sum += covered;
            left_sum += box.lo.x + before;  // the left edge: uncovered pixels before it
        }
        const double left = left_sum / rows;
        const double middle = left + 0.5 * width_sum / rows;
        double top = top_row;
        for (int y = top_row; y < centre.y; ++y) {
            double c = 0.0;
            for (int x = centre.x - 5; x <= centre.x + 5; ++x) {
                c += coverage(with, without, x, y, inside);
            }
            top += 1.0 - c / 11.0;
        }
        return {middle, top};
    }

    // Where hybrid shows a point beyond m, less where stereo does: the ray from C, a distance s
    // behind the eyes where the outer frustum planes cross (papers/000 eq. 1), through the point
    // meets the plane z = -m, and the eye sees that (Sect. 3, Fig. 2). Head frame = world less
    // the camera here.
    glm::dvec2 analytic_drift(Eye eye, const glm::dvec3& point, double m) const {
        const double d = vive_.ipd;
        const double s = std::max(d / (2.0 * -vive_.left.left), d / (2.0 * vive_.right.right));
        const glm::dvec3 in_head = point - glm::dvec3(kAlphaSceneEye);
        const glm::dvec3 c(0.0, 0.0, s);
        const glm::dvec3 on_plane = c + (in_head - c) * ((m + s) / (-in_head.z + s));
        return pixel(eye, on_plane + glm::dvec3(kAlphaSceneEye)) - pixel(eye, point);
    }
};

// m = 8: near_red (3 m), gradient (5 m) and behind_near (6 m) are drawn per eye after the
// composite, pixel for pixel where stereo draws them (within C's bilinear background's 2 levels).
TEST_F(AlphaBlendHybrid, NearPanesLandExactlyWhereStereoDrawsThem) {
    const PaneFrames stereo = frames(Mode::kStereo);
    const PaneFrames hybrid = frames(Mode::kHybrid, 8.0);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        SCOPED_TRACE(eye_text(eye));
        const auto e = static_cast<std::size_t>(eye);
        for (const AlphaPane& pane : {kNearRedPane, kBehindNearPane, kGradientPane}) {
            const PixelBox box = box_of(pane.quad, eye, 3);
            EXPECT_LE(box_difference(stereo.blended[e], hybrid.blended[e], box, eye), 2)
                << pane.quad.name;
        }
    }
}

// m = 4 at 672 x 756: far_blue (14 m) is C's, and shows displaced by the mapping's analytic
// error, over a pixel here.
TEST_F(AlphaBlendHybrid, APaneBeyondMIsDisplacedByTheMappingsAnalyticError) {
    extent_ = vk::Extent2D{672, 756};
    const double m = 4.0;
    const PaneFrames stereo = frames(Mode::kStereo);
    const PaneFrames hybrid = frames(Mode::kHybrid, m);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto e = static_cast<std::size_t>(eye);
        const glm::dvec2 in_stereo =
            pane_edges(stereo.blended[e], stereo.empty[e], kFarBluePane.quad, eye);
        const glm::dvec2 in_hybrid =
            pane_edges(hybrid.blended[e], hybrid.empty[e], kFarBluePane.quad, eye);
        // The middle of the pane's row at its centre height, and its top edge's middle.
        const glm::dvec2 expected(analytic_drift(eye, kFarBluePane.quad.centre(), m).x,
                                  analytic_drift(eye, kFarBluePane.quad.at({0.5f, 0.0f}), m).y);
        std::cout << eye_text(eye) << ": far_blue moved by (" << in_hybrid.x - in_stereo.x << ", "
                  << in_hybrid.y - in_stereo.y << ") px, analytic (" << expected.x << ", "
                  << expected.y << ")\n";
        SCOPED_TRACE(eye_text(eye));
        EXPECT_GT(std::abs(expected.x), 1.0);  // a drift worth measuring
        // A hard edge lands on the pixel grids of C and of the eye, each rounding it by up to half
        // a pixel; the two edges' middle (x) averages some of that out, the top edge (y) not.
        EXPECT_NEAR(in_hybrid.x - in_stereo.x, expected.x, 0.5);
        EXPECT_NEAR(in_hybrid.y - in_stereo.y, expected.y, 0.75);
    }
}

// Each blended pane is in exactly one of the lists that reach an eye.
TEST_F(AlphaBlendHybrid, EachBlendedPaneIsInOneListThatReachesAnEye) {
    modes::RendererOptions with = options();
    with.read_back_draw_lists = true;
    modes::ModeRenderer hybrid(ctx(), blended_, Mode::kHybrid, extent_, with);
    hybrid.render_frame(inputs(blended_, 8.0));
    const auto listed = [&](passes::CullView view, std::uint32_t chunk) {
        const std::vector<std::uint32_t> list = hybrid.drawn_chunks(view);
        return std::count(list.begin(), list.end(), chunk);
    };
    int blended = 0;
    for (std::uint32_t c = 0; c < blended_.chunks.size(); ++c) {
        const scenes::Chunk& chunk = blended_.chunks[c];
        if (chunk.alpha_mode != scenes::AlphaMode::kBlend) continue;
        ++blended;
        const bool beyond = chunk.bounds.max.z < -8.0f;  // only far_blue, at z = -14
        SCOPED_TRACE("chunk " + std::to_string(c) + " at z " + std::to_string(chunk.bounds.min.z));
        EXPECT_EQ(listed(passes::CullView::kMono, c), beyond ? 1 : 0);
        EXPECT_EQ(listed(passes::CullView::kLeft, c), beyond ? 0 : 1);
        EXPECT_EQ(listed(passes::CullView::kRight, c), beyond ? 0 : 1);
    }
    EXPECT_EQ(blended, 4);
}

// The single-pass forms draw what two passes draw, blended panes included (within 1/255, the
// single-pass equality tests' bound), in stereo and in hybrid's near region.
TEST_F(AlphaBlendHybrid, SinglePassFormsDrawWhatTwoPassesDraw) {
    const vk_core::DeviceCapabilities& caps = ctx().capabilities();
    std::vector<std::pair<std::string, StereoPass>> forms;
    if (caps.geometry_shader) forms.emplace_back("gs", StereoPass::kGeometryShader);
    if (caps.vertex_shader_layer && caps.shader_draw_parameters) {
        forms.emplace_back("instanced", StereoPass::kInstanced);
    }
    ASSERT_FALSE(forms.empty());
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        const EyeImages two = render(blended_, mode, 8.0);
        for (const auto& [name, pass] : forms) {
            const EyeImages one = render(blended_, mode, 8.0, pass);
            SCOPED_TRACE(name + (mode == Mode::kStereo ? " stereo" : " hybrid"));
            EXPECT_LE(max_difference(one[0], two[0]), 1);
            EXPECT_LE(max_difference(one[1], two[1]), 1);
        }
    }
}

// hybrid-farfield: the near panes as in stereo (drawn after the copy), far_blue copied with C.
TEST_F(AlphaBlendHybrid, FarfieldDrawsNearPanesWhereStereoDoes) {
    const PaneFrames stereo = frames(Mode::kStereo);
    const PaneFrames farfield = frames(Mode::kHybridFarfield, 8.0);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto e = static_cast<std::size_t>(eye);
        for (const AlphaPane& pane : {kNearRedPane, kBehindNearPane, kGradientPane}) {
            EXPECT_LE(box_difference(stereo.blended[e], farfield.blended[e],
                                     box_of(pane.quad, eye, 3), eye),
                      2)
                << pane.quad.name << " " << eye_text(eye);
        }
        const glm::dvec2 a = pane_edges(stereo.blended[e], stereo.empty[e], kFarBluePane.quad, eye);
        const glm::dvec2 b =
            pane_edges(farfield.blended[e], farfield.empty[e], kFarBluePane.quad, eye);
        EXPECT_NEAR(b.x, a.x, 1.5);  // the copy's rounding and the eyes' asymmetry
        EXPECT_NEAR(b.y, a.y, 1.5);
    }
}

// A pane straddling m: a ramp rising from 5 m to 9 m in front of the camera, with m = 7, over an
// opaque backdrop. It is the eyes', drawn whole after the composite (depth clamping, not the
// eyes' far plane at m, bounds it), so hybrid shows it where and as stereo does; C draws none of
// it.
TEST_F(AlphaBlendHybrid, APaneStraddlingMIsDrawnWholeByTheEyes) {
    scenes::testing::TestGltf gltf;
    gltf.json["materials"] = {
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.2, 0.5, 0.3, 1.0}}, {"metallicFactor", 0.0}}}},
        {{"alphaMode", "BLEND"},
         {"doubleSided", true},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.9, 0.5, 0.1, 0.5}}, {"metallicFactor", 0.0}}}}};
    const auto add_quad = [&](const std::vector<glm::vec3>& corners, int material) {
        const int positions = gltf.add_positions(corners);
        const int indices = gltf.add_indices({0, 2, 1, 1, 2, 3});
        gltf.add_node({{"mesh", gltf.add_mesh({{"POSITION", positions}}, indices, 4, material)}});
    };
    // Corners: top-left, top-right, bottom-left, bottom-right seen from the camera.
    add_quad({{-60, 50, -40}, {60, 50, -40}, {-60, -30, -40}, {60, -30, -40}}, 0);
    add_quad({{-1.0f, 2.4f, -9.0f}, {1.0f, 2.4f, -9.0f}, {-1.0f, 0.8f, -5.0f}, {1.0f, 0.8f, -5.0f}},
             1);
    const glm::vec3 eye = kAlphaSceneEye;
    gltf.json["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.5}, {"znear", 0.1}}}}};
    gltf.add_node({{"camera", 0}, {"translation", {eye.x, eye.y, eye.z}}});
    gltf.write_gltf(dir_ / "ramp.gltf");
    const scenes::Scene ramp = load(dir_ / "ramp.gltf");

    const EyeImages stereo = render(ramp, Mode::kStereo);
    modes::RendererOptions with = options();
    with.read_back_draw_lists = true;
    modes::ModeRenderer hybrid(ctx(), ramp, Mode::kHybrid, extent_, with);
    hybrid.render_frame(inputs(ramp, 7.0));
    const AlphaQuad ramp_quad{
        "ramp", {-1.0f, 2.4f, -9.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, -1.6f, 4.0f}};
    for (Eye e : {Eye::kLeft, Eye::kRight}) {
        const auto i = static_cast<std::size_t>(e);
        const modes::RgbaImage& image = hybrid.eye_image(e);
        const PixelBox box = box_of(ramp_quad, e, 3);
        EXPECT_GT((box.hi.y - box.lo.y) * (box.hi.x - box.lo.x), 400);
        EXPECT_LE(box_difference(stereo[i], image, box, e), 2) << eye_text(e);
        // Both ends of the ramp are there, orange over the green backdrop.
        for (const glm::vec2 uv : {glm::vec2(0.5f, 0.1f), glm::vec2(0.5f, 0.9f)}) {
            const glm::ivec2 p = *pixel_of(e, ramp_quad.at(uv));
            const Rgb c = rgb_at(image, p.x, p.y);
            EXPECT_GT(c.r, c.g) << eye_text(e) << " at v " << uv.y;
        }
    }
    for (std::uint32_t c = 0; c < ramp.chunks.size(); ++c) {
        if (ramp.chunks[c].alpha_mode != scenes::AlphaMode::kBlend) continue;
        const auto listed = [&](passes::CullView view) {
            const std::vector<std::uint32_t> list = hybrid.drawn_chunks(view);
            return std::count(list.begin(), list.end(), c);
        };
        EXPECT_EQ(listed(passes::CullView::kMono), 0);
        EXPECT_EQ(listed(passes::CullView::kLeft), 1);
        EXPECT_EQ(listed(passes::CullView::kRight), 1);
    }
}

// TAA on a pose path: the head moves sideways 1 cm a frame, so near_red (3 m) slides over the
// backdrop (40 m) by about 0.4 px a frame. A blended surface writes no velocity (its pixels keep
// the background's), so its history is reprojected with the background's motion; TAA's clamp to
// the current neighbourhood must keep it from leaving a trail. Measured where the pane was along
// the path but is no longer, against a converged frame at the final pose, and compared with the
// same panes drawn opaque (whose velocity is their own).
class AlphaBlendTaa : public AlphaBlend {
  protected:
    static constexpr int kFrames = 30;

    modes::FrameInputs pose(const scenes::Scene& scene, int frame) const {
        modes::FrameInputs in = inputs(scene, 8.0);
        in.views.head.position.x += 0.01 * frame;
        in.frame_index = static_cast<std::uint64_t>(frame);
        return in;
    }

    modes::RgbaImage moving(const scenes::Scene& scene, Mode mode) {
        modes::RendererOptions with = options();
        with.anti_aliasing = AntiAliasing::kTaa;
        modes::ModeRenderer renderer(ctx(), scene, mode, extent_, with);
        for (int i = 0; i < kFrames; ++i) renderer.render_frame(pose(scene, i));
        return renderer.eye_image(Eye::kLeft);
    }

    modes::RgbaImage converged(const scenes::Scene& scene, Mode mode) {
        modes::RendererOptions with = options();
        with.anti_aliasing = AntiAliasing::kTaa;
        modes::ModeRenderer renderer(ctx(), scene, mode, extent_, with);
        for (int i = 0; i < kFrames; ++i) {
            modes::FrameInputs in = pose(scene, kFrames - 1);
            in.frame_index = static_cast<std::uint64_t>(i);
            renderer.render_frame(in);
        }
        return renderer.eye_image(Eye::kLeft);
    }

    // Mean and largest difference over the trail: pixels near_red covered along the path but
    // not in the final pose, `from_edge` pixels or more from its final box.
    std::pair<double, int> trail(const modes::RgbaImage& a, const modes::RgbaImage& b,
                                 int from_edge) const {
        const glm::dvec3 shift(0.01 * (kFrames - 1), 0.0, 0.0);
        const auto box_at = [&](double back) {
            const glm::dvec3 offset(0.01 * back, 0.0, 0.0);
            const glm::dvec2 p =
                pixel(Eye::kLeft, glm::dvec3(kNearRedPane.quad.at({0, 0})) - shift + offset);
            const glm::dvec2 q =
                pixel(Eye::kLeft, glm::dvec3(kNearRedPane.quad.at({1, 1})) - shift + offset);
            return std::pair(glm::min(p, q), glm::max(p, q));
        };
        const auto [now_lo, now_hi] = box_at(0.0);
        const auto [then_lo, then_hi] = box_at(kFrames - 1.0);
        double sum = 0.0;
        int worst = 0, count = 0;
        for (int y = static_cast<int>(now_lo.y) + 2; y < static_cast<int>(now_hi.y) - 2; ++y) {
            for (int x = static_cast<int>(std::min(now_lo.x, then_lo.x));
                 x <= static_cast<int>(std::max(now_hi.x, then_hi.x)); ++x) {
                if (x >= now_lo.x - from_edge && x <= now_hi.x + from_edge) continue;
                const int d = difference(rgb_at(a, x, y), rgb_at(b, x, y));
                sum += d;
                worst = std::max(worst, d);
                ++count;
            }
        }
        EXPECT_GT(count, 50);
        return {count > 0 ? sum / count : 0.0, worst};
    }
};

TEST_F(AlphaBlendTaa, ABlendedPaneMovingOverTheBackgroundLeavesNoTrail) {
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        const modes::RgbaImage blended = moving(blended_, mode);
        const modes::RgbaImage blended_still = converged(blended_, mode);
        const modes::RgbaImage opaque = moving(opaque_, mode);
        const modes::RgbaImage opaque_still = converged(opaque_, mode);
        const std::string name = mode == Mode::kStereo ? "stereo" : "hybrid m=8";
        SCOPED_TRACE(name);
        for (int from_edge : {1, 3, 6}) {
            const auto [blended_mean, blended_worst] = trail(blended, blended_still, from_edge);
            const auto [opaque_mean, opaque_worst] = trail(opaque, opaque_still, from_edge);
            std::cout << name << ": " << from_edge << "+ px behind the moving pane, mean "
                      << blended_mean << " max " << blended_worst << " levels (opaque panes: mean "
                      << opaque_mean << " max " << opaque_worst << ")\n";
            // Over the path the pane left, no more than the opaque panes leave on average; the
            // largest lag fades within a few pixels of the edge (measured on llvmpipe: 17, 13 and
            // 5 levels at 1, 3 and 6 px, against 9, 5 and 1 for opaque panes): the clamp, not a
            // velocity of its own, removes a blended pane's history (docs/hybrid.md).
            EXPECT_LE(blended_mean, opaque_mean + 0.2);
            EXPECT_LE(blended_worst, from_edge == 1 ? 20 : (from_edge == 3 ? 16 : 6));
        }
    }
}

}  // namespace
}  // namespace monoplane::testing
