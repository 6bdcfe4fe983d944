// Single-pass stereo (modes::StereoPass, papers/001): drawing both eyes in one forward pass, by
// geometry-shader duplication or by VK_KHR_multiview, draws the images two passes draw, and the
// vertex work it saves is measured on pipeline-statistics counters, never on times. The reference
// is the same renderer configuration with StereoPass::kTwoPasses and the same inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/generate.h"
#include "tests/gpu/frame_checks.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using testing::has_pass;
using testing::max_channel_difference;
using testing::view_of;

using modes::AntiAliasing;
using modes::Eye;
using modes::Mode;
using modes::StereoPass;
using passes::CullView;
using Chunks = std::vector<std::uint32_t>;

constexpr vk::Extent2D kExtent{96, 108};
constexpr std::array<scenes::SceneId, 3> kScenes = {
    scenes::SceneId::Beams, scenes::SceneId::Landscape, scenes::SceneId::Spheres};

modes::RendererOptions options_with(StereoPass pass) {
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    options.stereo_pass = pass;
    return options;
}

std::string list_text(const Chunks& chunks) {
    std::ostringstream text;
    text << "{";
    for (std::size_t i = 0; i < chunks.size(); ++i) text << (i ? ", " : "") << chunks[i];
    text << "}";
    return text.str();
}

std::uint64_t triangles(const scenes::Scene& scene, const Chunks& chunks) {
    std::uint64_t count = 0;
    for (std::uint32_t c : chunks) count += scene.chunks[c].index_count / 3;
    return count;
}

// The mean of an image's colour channels, 0 to 255: an eye left black reads near 0.
double mean_level(const modes::RgbaImage& image) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (i % 4 != 3) sum += image.pixels[i];
    }
    return image.pixels.empty() ? 0.0 : sum / (0.75 * static_cast<double>(image.pixels.size()));
}

// One renderer's last frame: both eyes' images and the frame's statistics.
struct Frame {
    std::array<modes::RgbaImage, 2> eyes;
    profile::FrameStats stats;
};

// Renders `frames` consecutive frames (frame_index 0, 1, ...) of a static head; keeps the last.
Frame render(const vk_core::Context& ctx, const scenes::Scene& scene, Mode mode,
             const modes::RendererOptions& options, modes::FrameInputs inputs, int frames = 1) {
    modes::ModeRenderer renderer(ctx, scene, mode, kExtent, options);
    Frame frame;
    for (int i = 0; i < frames; ++i) {
        inputs.frame_index = static_cast<std::uint64_t>(i);
        frame.stats = renderer.render_frame(inputs);
    }
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        frame.eyes[static_cast<int>(eye)] = renderer.eye_image(eye);
    }
    return frame;
}

// A single-pass frame, the two-pass frame drawn from the same inputs, and the largest channel
// difference of each eye between them.
struct Comparison {
    Frame one;
    Frame two;
    std::array<int, 2> difference{};
    int worst() const { return std::max(difference[0], difference[1]); }
};

class SinglePassStereo : public testing::GpuTest {
  protected:
    bool statistics() { return ctx().capabilities().pipeline_statistics; }
    bool has_geometry_shader() { return ctx().capabilities().geometry_shader; }
    bool llvmpipe() { return ctx().device_info().name.find("llvmpipe") != std::string::npos; }

    modes::FrameInputs inputs_at(const scenes::Scene& scene, double m = 8.0,
                                 const std::string& viewpoint = "default") const {
        const scenes::Viewpoint* where = scene.find_viewpoint(viewpoint);
        EXPECT_NE(where, nullptr) << viewpoint;
        return testing::profile_inputs(vive_, where ? where->head : rig::Pose{}, m);
    }

    // The same frames drawn with `pass` and with two passes. The single pass's eyes must be lit
    // and differ by far more than the bound, so that an eye drawn into the other's layer, or
    // into none, shows in the comparison.
    Comparison compare(const scenes::Scene& scene, Mode mode, StereoPass pass,
                       modes::RendererOptions options, const modes::FrameInputs& inputs,
                       int frames = 1) {
        Comparison c;
        options.stereo_pass = StereoPass::kTwoPasses;
        c.two = render(ctx(), scene, mode, options, inputs, frames);
        options.stereo_pass = pass;
        c.one = render(ctx(), scene, mode, options, inputs, frames);
        // The single pass really ran as one pass, the reference as two.
        EXPECT_TRUE(has_pass(c.one.stats, "eyes.forward"));
        EXPECT_FALSE(has_pass(c.one.stats, "left.forward"));
        EXPECT_FALSE(has_pass(c.two.stats, "eyes.forward"));
        EXPECT_TRUE(has_pass(c.two.stats, "left.forward"));
        EXPECT_GT(max_channel_difference(c.one.eyes[0], c.one.eyes[1]), 16)
            << "the eyes look alike";
        for (int e = 0; e < 2; ++e) {
            EXPECT_GT(mean_level(c.one.eyes[e]), 40.0)
                << modes::eye_name(static_cast<Eye>(e)) << " eye dark";
            c.difference[e] = max_channel_difference(c.one.eyes[e], c.two.eyes[e]);
        }
        std::cout << scene.name << " " << modes::mode_name(mode) << " m = " << inputs.mono_plane
                  << ", " << modes::anti_aliasing_name(options.anti_aliasing)
                  << (inputs.debug == modes::DebugView::kRouting ? ", routing view" : "") << ": "
                  << modes::stereo_pass_name(pass) << " vs two passes, max channel difference left "
                  << c.difference[0] << ", right " << c.difference[1] << "\n";
        return c;
    }

    void expect_within_one(const Comparison& c, const std::string& what) {
        for (int e = 0; e < 2; ++e) {
            EXPECT_LE(c.difference[e], 1)
                << what << " " << modes::eye_name(static_cast<Eye>(e))
                << ": max channel difference " << c.difference[e] << " of 255";
        }
    }

    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
};

// A draw list as a set: its chunk indices ascending.
Chunks ascending(Chunks chunks) {
    std::sort(chunks.begin(), chunks.end());
    return chunks;
}

// Whether `part` appears in `whole` in the same order (not necessarily adjacent).
bool is_subsequence(const Chunks& part, const Chunks& whole) {
    auto at = whole.begin();
    for (std::uint32_t chunk : part) {
        at = std::find(at, whole.end(), chunk);
        if (at == whole.end()) return false;
        ++at;
    }
    return true;
}

// 1. Stereo: geometry-shader duplication draws each scene's eyes as two passes do.
TEST_F(SinglePassStereo, GeometryShaderStereoEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    for (scenes::SceneId id : kScenes) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        const Comparison c = compare(scene, Mode::kStereo, StereoPass::kGeometryShader,
                                     options_with(StereoPass::kTwoPasses), inputs_at(scene));
        expect_within_one(c, scene.name + " stereo");
    }
}

// 2. Hybrid: the near passes drawn in one pass, at m = 8 in every scene and at m = 3, where more
// of the scene lies in the eyes' region, in one.
TEST_F(SinglePassStereo, GeometryShaderHybridEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    for (scenes::SceneId id : kScenes) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        std::vector<double> planes = {8.0};
        if (id == scenes::SceneId::Spheres) planes.push_back(3.0);
        for (double m : planes) {
            const Comparison c = compare(scene, Mode::kHybrid, StereoPass::kGeometryShader,
                                         options_with(StereoPass::kTwoPasses), inputs_at(scene, m));
            EXPECT_TRUE(has_pass(c.one.stats, "mono.forward"));  // C really drew the far part
            expect_within_one(c, scene.name + " hybrid m = " + std::to_string(m));
        }
    }
}

// 3. Stereo with VK_KHR_multiview. Debian 12's lavapipe (Mesa 22.3) routes some of view 1's
// fragments into layer 0 and drops view 1's sky, so there the difference is measured and
// reported but not asserted; the renderer is still built and run under validation.
TEST_F(SinglePassStereo, MultiviewStereoEqualsTwoPasses) {
    if (!ctx().capabilities().multiview) GTEST_SKIP() << "the device has no multiview";
    int worst = 0;
    for (scenes::SceneId id : kScenes) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        const Comparison c = compare(scene, Mode::kStereo, StereoPass::kMultiview,
                                     options_with(StereoPass::kTwoPasses), inputs_at(scene));
        worst = std::max(worst, c.worst());
        if (!llvmpipe()) expect_within_one(c, scene.name + " stereo multiview");
    }
    if (llvmpipe()) {
        GTEST_SKIP() << "measured max channel difference " << worst
                     << " of 255 against two passes on " << ctx().device_info().name
                     << ": lavapipe 22.3's multiview is defective (view 1's fragments partly land "
                        "in layer 0, its sky is dropped); the renderer is validation-clean";
    }
}

// 4. The work single-pass stereo saves, on pipeline-statistics counters: the single pass draws
// the union of the eyes' lists once, so its vertex shader runs once per vertex for both eyes,
// its geometry shader once per triangle, and it shades the fragments the two passes shade.
// Spheres' default view: both eyes draw the same chunks (the vertex work is halved exactly).
// Landscape's default view: the right eye also draws chunk 13, so the union is the right list.
TEST_F(SinglePassStereo, GeometryShaderDrawsTheUnionOnceAndHalvesTheVertexWork) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    for (scenes::SceneId id : {scenes::SceneId::Spheres, scenes::SceneId::Landscape}) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        SCOPED_TRACE(scene.name);
        const bool same_lists = id == scenes::SceneId::Spheres;
        const modes::FrameInputs inputs = inputs_at(scene);
        modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
        options.read_back_draw_lists = true;
        modes::ModeRenderer two(ctx(), scene, Mode::kStereo, kExtent, options);
        options.stereo_pass = StereoPass::kGeometryShader;
        modes::ModeRenderer gs(ctx(), scene, Mode::kStereo, kExtent, options);
        const profile::FrameStats two_stats = two.render_frame(inputs);
        const profile::FrameStats gs_stats = gs.render_frame(inputs);

        // In draw order (nearest first), and as sets.
        const Chunks left_drawn = two.drawn_chunks(CullView::kLeft);
        const Chunks right_drawn = two.drawn_chunks(CullView::kRight);
        const Chunks both_drawn = gs.drawn_chunks(CullView::kBothEyes);
        const Chunks left = ascending(left_drawn);
        const Chunks right = ascending(right_drawn);
        Chunks either;
        std::set_union(left.begin(), left.end(), right.begin(), right.end(),
                       std::back_inserter(either));
        const Chunks both = ascending(both_drawn);
        std::cout << scene.name << " default: left " << list_text(left_drawn) << "\n  right "
                  << list_text(right_drawn) << "\n  both eyes (single pass) "
                  << list_text(both_drawn) << " of " << scene.chunks.size() << " chunks\n";
        ASSERT_FALSE(left.empty());
        // The single pass draws the chunks either eye draws, once each, in the eyes' order.
        EXPECT_EQ(both, either);
        EXPECT_EQ(both.size(), both_drawn.size());
        EXPECT_TRUE(is_subsequence(left_drawn, both_drawn));
        EXPECT_TRUE(is_subsequence(right_drawn, both_drawn));
        if (same_lists) {
            EXPECT_EQ(left, right);
        } else {
            EXPECT_NE(left, right);
            EXPECT_TRUE(std::includes(right.begin(), right.end(), left.begin(), left.end()));
            EXPECT_EQ(both, right);
        }

        if (!statistics()) {
            GTEST_SKIP() << "no pipelineStatisticsQuery: the counters are not checked";
        }
        const profile::ViewStatistics& l = view_of(two_stats, "left");
        const profile::ViewStatistics& r = view_of(two_stats, "right");
        const profile::ViewStatistics& eyes = view_of(gs_stats, "eyes");
        std::cout << "  two passes: left vertices " << l.vertex_invocations << ", primitives "
                  << l.input_primitives << ", fragments " << l.fragment_invocations
                  << "; right vertices " << r.vertex_invocations << ", primitives "
                  << r.input_primitives << ", fragments " << r.fragment_invocations << "\n"
                  << "  geometry shader: vertices " << eyes.vertex_invocations << ", primitives "
                  << eyes.input_primitives << ", geometry invocations " << eyes.geometry_invocations
                  << ", geometry primitives " << eyes.geometry_primitives << ", fragments "
                  << eyes.fragment_invocations << "\n";
        EXPECT_EQ(eyes.draws, both.size());
        // Each pass draws its chunks' triangles and the sky's full-screen triangle.
        EXPECT_EQ(l.input_primitives, triangles(scene, left) + 1);
        EXPECT_EQ(r.input_primitives, triangles(scene, right) + 1);
        EXPECT_EQ(eyes.input_primitives, triangles(scene, both) + 1);
        // Two passes run no geometry shader; the single pass runs it once per triangle, each
        // invocation emitting at most one copy per eye (none into an eye whose frustum the
        // triangle lies wholly outside).
        EXPECT_EQ(l.geometry_invocations, 0u);
        EXPECT_EQ(r.geometry_invocations, 0u);
        EXPECT_EQ(eyes.geometry_invocations, eyes.input_primitives);
        EXPECT_LE(eyes.geometry_primitives, 2 * eyes.geometry_invocations);
        EXPECT_GT(eyes.geometry_primitives, 0u);
        // The same pixels are shaded.
        EXPECT_EQ(eyes.fragment_invocations, l.fragment_invocations + r.fragment_invocations);
        // The vertex work: once for both eyes.
        EXPECT_GT(eyes.vertex_invocations, 0u);
        if (same_lists) {
            EXPECT_EQ(2 * eyes.vertex_invocations, l.vertex_invocations + r.vertex_invocations);
        } else {
            EXPECT_EQ(eyes.vertex_invocations, r.vertex_invocations);  // the union is right's
        }
    }
}

// 5. MSAA 4x: the single pass resolves both layers as two passes resolve their eyes. The right
// eye is also compared with the same camera drawn as the left eye of two passes (a head moved
// right by the IPD, with the right eye's tangents). This check found that lavapipe 22.3 resolves
// MSAA into layer 0 of a layered image only; two-pass stereo now keeps an image per eye.
TEST_F(SinglePassStereo, GeometryShaderStereoWithMsaaEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    for (scenes::SceneId id : kScenes) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
        options.anti_aliasing = AntiAliasing::kMsaa4;
        const modes::FrameInputs inputs = inputs_at(scene);
        const Comparison c =
            compare(scene, Mode::kStereo, StereoPass::kGeometryShader, options, inputs);
        const std::string what = scene.name + " stereo msaa4 ";
        EXPECT_LE(c.difference[0], 1) << what << "left: max channel difference " << c.difference[0];

        modes::FrameInputs moved = inputs;
        moved.views.head.position +=
            moved.views.head.orientation * glm::dvec3(inputs.views.ipd, 0.0, 0.0);
        moved.views.left = inputs.views.right;
        const Frame right_as_left = render(ctx(), scene, Mode::kStereo, options, moved);
        const int right_vs_layer0 = max_channel_difference(c.one.eyes[1], right_as_left.eyes[0]);
        std::cout << "  right eye vs the same camera as two passes' left eye: " << right_vs_layer0
                  << "\n";
        EXPECT_LE(right_vs_layer0, 1) << what << "right vs the same camera drawn as a left eye";

        EXPECT_LE(c.difference[1], 1)
            << what << "right: max channel difference " << c.difference[1];
    }
}

// 6. TAA in hybrid: jitter, velocity and history of the single pass's layers, over four frames.
TEST_F(SinglePassStereo, GeometryShaderHybridWithTaaEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test);
    modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
    options.anti_aliasing = AntiAliasing::kTaa;
    const Comparison c = compare(scene, Mode::kHybrid, StereoPass::kGeometryShader, options,
                                 inputs_at(scene, 8.0), 4);
    expect_within_one(c, scene.name + " hybrid m = 8 taa, frame 4");
}

// 7. The routing debug view: the single pass colours each chunk by its lists as two passes do.
TEST_F(SinglePassStereo, GeometryShaderRoutingViewEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Spheres, scenes::Detail::Test);
    modes::FrameInputs inputs = inputs_at(scene, 8.0);
    inputs.debug = modes::DebugView::kRouting;
    const Comparison c = compare(scene, Mode::kHybrid, StereoPass::kGeometryShader,
                                 options_with(StereoPass::kTwoPasses), inputs);
    expect_within_one(c, scene.name + " hybrid m = 8 routing");
}

}  // namespace
}  // namespace monoplane
