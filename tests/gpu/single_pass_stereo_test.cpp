// Single-pass stereo (plan::StereoPass, papers/001): drawing both eyes in one forward pass, by
// geometry-shader duplication, by VK_KHR_multiview or by instancing (two instances per draw, one
// per eye), draws the images two passes draw, and the vertex work it saves or spends is measured
// on pipeline-statistics counters, never on times. The reference is the same renderer
// configuration with StereoPass::kTwoPasses and the same inputs.
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

using modes::Eye;
using passes::CullView;
using plan::AntiAliasing;
using plan::Mode;
using plan::StereoPass;
using Chunks = std::vector<std::uint32_t>;

constexpr vk::Extent2D kExtent{96, 108};
constexpr std::array<scenes::SceneId, 3> kScenes = {
    scenes::SceneId::Beams, scenes::SceneId::Landscape, scenes::SceneId::Spheres};

modes::RendererOptions options_with(StereoPass pass) {
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    // Every chunk at full detail: the counters below are checked against the chunks' triangles,
    // and the MSAA check's moved head would choose other levels of detail.
    options.lod.enabled = false;
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
    // Instanced stereo's vertex shader reads gl_BaseInstance and writes gl_Layer.
    bool has_instanced_stereo() {
        const vk_core::DeviceCapabilities& caps = ctx().capabilities();
        return caps.vertex_shader_layer && caps.shader_draw_parameters;
    }
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
        std::cout << scene.name << " " << plan::mode_name(mode) << " m = " << inputs.mono_plane
                  << ", " << plan::anti_aliasing_name(options.anti_aliasing)
                  << (inputs.debug == plan::DebugView::kRouting ? ", routing view" : "") << ": "
                  << plan::stereo_pass_name(pass) << " vs two passes, max channel difference left "
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

    // Stereo drawn by `pass` in every scene, within 1/255 of two passes.
    void expect_stereo_equal(StereoPass pass, const modes::RendererOptions& options =
                                                  options_with(StereoPass::kTwoPasses)) {
        for (scenes::SceneId id : kScenes) {
            const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
            const Comparison c = compare(scene, Mode::kStereo, pass, options, inputs_at(scene));
            expect_within_one(c, scene.name + " stereo " + plan::stereo_pass_name(pass));
        }
    }

    // Hybrid's near passes drawn by `pass`, at m = 8 in every scene and at m = 3, where more of
    // the scene lies in the eyes' region, in one.
    void expect_hybrid_equal(StereoPass pass) {
        for (scenes::SceneId id : kScenes) {
            const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
            std::vector<double> planes = {8.0};
            if (id == scenes::SceneId::Spheres) planes.push_back(3.0);
            for (double m : planes) {
                const Comparison c =
                    compare(scene, Mode::kHybrid, pass, options_with(StereoPass::kTwoPasses),
                            inputs_at(scene, m));
                EXPECT_TRUE(has_pass(c.one.stats, "mono.forward"));  // C really drew the far part
                expect_within_one(c, scene.name + " hybrid m = " + std::to_string(m) + " " +
                                         plan::stereo_pass_name(pass));
            }
        }
    }

    // MSAA 4x: the single pass resolves both layers as two passes resolve their eyes. The right
    // eye is also compared with the same camera drawn as the left eye of two passes (a head moved
    // right by the IPD, with the right eye's tangents).
    void expect_msaa_equal(StereoPass pass) {
        for (scenes::SceneId id : kScenes) {
            const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
            modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
            options.anti_aliasing = AntiAliasing::kMsaa4;
            const modes::FrameInputs inputs = inputs_at(scene);
            const Comparison c = compare(scene, Mode::kStereo, pass, options, inputs);
            const std::string what =
                scene.name + " stereo msaa4 " + plan::stereo_pass_name(pass) + " ";
            EXPECT_LE(c.difference[0], 1)
                << what << "left: max channel difference " << c.difference[0];

            modes::FrameInputs moved = inputs;
            moved.views.head.position +=
                moved.views.head.orientation * glm::dvec3(inputs.views.ipd, 0.0, 0.0);
            moved.views.left = inputs.views.right;
            const Frame right_as_left = render(ctx(), scene, Mode::kStereo, options, moved);
            const int right_vs_layer0 =
                max_channel_difference(c.one.eyes[1], right_as_left.eyes[0]);
            std::cout << "  right eye vs the same camera as two passes' left eye: "
                      << right_vs_layer0 << "\n";
            EXPECT_LE(right_vs_layer0, 1) << what << "right vs the same camera drawn as a left eye";
            EXPECT_LE(c.difference[1], 1)
                << what << "right: max channel difference " << c.difference[1];
        }
    }

    // TAA in hybrid: jitter, velocity and history of the single pass's layers, over four frames.
    void expect_hybrid_taa_equal(StereoPass pass) {
        const scenes::Scene scene =
            scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test);
        modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
        options.anti_aliasing = AntiAliasing::kTaa;
        const Comparison c = compare(scene, Mode::kHybrid, pass, options, inputs_at(scene, 8.0), 4);
        expect_within_one(c, scene.name + " hybrid m = 8 taa, frame 4");
    }

    // The routing debug view: the single pass colours each chunk by its lists as two passes do.
    void expect_routing_equal(StereoPass pass) {
        const scenes::Scene scene =
            scenes::generate_scene(scenes::SceneId::Spheres, scenes::Detail::Test);
        modes::FrameInputs inputs = inputs_at(scene, 8.0);
        inputs.debug = plan::DebugView::kRouting;
        const Comparison c =
            compare(scene, Mode::kHybrid, pass, options_with(StereoPass::kTwoPasses), inputs);
        expect_within_one(c, scene.name + " hybrid m = 8 routing");
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
    expect_stereo_equal(StereoPass::kGeometryShader);
}

// 2. Hybrid: the near passes drawn in one pass.
TEST_F(SinglePassStereo, GeometryShaderHybridEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    expect_hybrid_equal(StereoPass::kGeometryShader);
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

// Two passes' and a single pass's frame of one scene's default view, with the chunks each drew.
struct CountedFrames {
    Chunks left_drawn, right_drawn, both_drawn;                 // in draw order (nearest first)
    Chunks left, right, both;                                   // as sets
    std::vector<vk::DrawIndexedIndirectCommand> both_commands;  // the single pass's draws
    profile::FrameStats two, one;
};

// Renders both and checks the single pass's both-eyes list: the chunks either eye draws, once
// each, in the eyes' order. Spheres' default view: both eyes draw the same chunks. Landscape's:
// the right eye also draws chunk 13, so the union is the right list.
CountedFrames counted_frames(const vk_core::Context& ctx, const scenes::Scene& scene,
                             StereoPass pass, const modes::FrameInputs& inputs) {
    modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
    options.read_back_draw_lists = true;
    modes::ModeRenderer two(ctx, scene, Mode::kStereo, kExtent, options);
    options.stereo_pass = pass;
    modes::ModeRenderer one(ctx, scene, Mode::kStereo, kExtent, options);
    CountedFrames f;
    f.two = two.render_frame(inputs);
    f.one = one.render_frame(inputs);
    f.left_drawn = two.drawn_chunks(CullView::kLeft);
    f.right_drawn = two.drawn_chunks(CullView::kRight);
    f.both_drawn = one.drawn_chunks(CullView::kBothEyes);
    f.both_commands = one.drawn_commands(CullView::kBothEyes);
    f.left = ascending(f.left_drawn);
    f.right = ascending(f.right_drawn);
    f.both = ascending(f.both_drawn);
    std::cout << scene.name << " default: left " << list_text(f.left_drawn) << "\n  right "
              << list_text(f.right_drawn) << "\n  both eyes (" << plan::stereo_pass_name(pass)
              << ") " << list_text(f.both_drawn) << " of " << scene.chunks.size() << " chunks\n";

    Chunks either;
    std::set_union(f.left.begin(), f.left.end(), f.right.begin(), f.right.end(),
                   std::back_inserter(either));
    EXPECT_FALSE(f.left.empty());
    EXPECT_EQ(f.both, either);
    EXPECT_EQ(f.both.size(), f.both_drawn.size());
    EXPECT_TRUE(is_subsequence(f.left_drawn, f.both_drawn));
    EXPECT_TRUE(is_subsequence(f.right_drawn, f.both_drawn));
    if (scene.name == "spheres") {
        EXPECT_EQ(f.left, f.right);
    } else {
        EXPECT_NE(f.left, f.right);
        EXPECT_TRUE(std::includes(f.right.begin(), f.right.end(), f.left.begin(), f.left.end()));
        EXPECT_EQ(f.both, f.right);
    }
    return f;
}

// The single pass's draws as the culling pass wrote them: one per chunk of the both-eyes list,
// in its order, each `instances` instances from the chunk's index.
void expect_instances(const CountedFrames& f, std::uint32_t instances) {
    ASSERT_EQ(f.both_commands.size(), f.both_drawn.size());
    for (std::size_t i = 0; i < f.both_commands.size(); ++i) {
        EXPECT_EQ(f.both_commands[i].instanceCount, instances) << "draw " << i;
        EXPECT_EQ(f.both_commands[i].firstInstance, f.both_drawn[i]) << "draw " << i;
    }
}

void print_counters(const profile::ViewStatistics& l, const profile::ViewStatistics& r,
                    const profile::ViewStatistics& eyes, StereoPass pass) {
    std::cout << "  two passes: left vertices " << l.vertex_invocations << ", primitives "
              << l.input_primitives << ", fragments " << l.fragment_invocations
              << "; right vertices " << r.vertex_invocations << ", primitives "
              << r.input_primitives << ", fragments " << r.fragment_invocations << "\n  "
              << plan::stereo_pass_name(pass) << ": draws " << eyes.draws << ", vertices "
              << eyes.vertex_invocations << ", primitives " << eyes.input_primitives
              << ", geometry invocations " << eyes.geometry_invocations << ", geometry primitives "
              << eyes.geometry_primitives << ", fragments " << eyes.fragment_invocations << "\n";
}

// 4. The work single-pass stereo saves, on pipeline-statistics counters: the single pass draws
// the union of the eyes' lists once, so its vertex shader runs once per vertex for both eyes,
// its geometry shader once per triangle, and it shades the fragments the two passes shade.
TEST_F(SinglePassStereo, GeometryShaderDrawsTheUnionOnceAndHalvesTheVertexWork) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    for (scenes::SceneId id : {scenes::SceneId::Spheres, scenes::SceneId::Landscape}) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        SCOPED_TRACE(scene.name);
        const bool same_lists = id == scenes::SceneId::Spheres;
        const CountedFrames f =
            counted_frames(ctx(), scene, StereoPass::kGeometryShader, inputs_at(scene));
        expect_instances(f, 1);  // the geometry shader duplicates, not the draw
        if (!statistics()) {
            GTEST_SKIP() << "no pipelineStatisticsQuery: the counters are not checked";
        }
        const profile::ViewStatistics& l = view_of(f.two, "left");
        const profile::ViewStatistics& r = view_of(f.two, "right");
        const profile::ViewStatistics& eyes = view_of(f.one, "eyes");
        print_counters(l, r, eyes, StereoPass::kGeometryShader);
        EXPECT_EQ(eyes.draws, f.both.size());
        // Each pass draws its chunks' triangles and the sky's full-screen triangle.
        EXPECT_EQ(l.input_primitives, triangles(scene, f.left) + 1);
        EXPECT_EQ(r.input_primitives, triangles(scene, f.right) + 1);
        EXPECT_EQ(eyes.input_primitives, triangles(scene, f.both) + 1);
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

// 4b. Instanced stereo: one draw per chunk of the union (the GPU's draw count; read back, each
// command has instance count 2 and the chunk as first instance), so the input assembler counts
// every triangle (and the sky's) twice and the vertex shader runs once per vertex and eye: two
// passes' work where both eyes draw the same chunks, twice the union's where they do not. No
// geometry shader runs; the same pixels are shaded.
TEST_F(SinglePassStereo, InstancedDrawsEachChunkOnceWithTwoInstances) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    for (scenes::SceneId id : {scenes::SceneId::Spheres, scenes::SceneId::Landscape}) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        SCOPED_TRACE(scene.name);
        const bool same_lists = id == scenes::SceneId::Spheres;
        const CountedFrames f =
            counted_frames(ctx(), scene, StereoPass::kInstanced, inputs_at(scene));
        expect_instances(f, 2);
        if (!statistics()) {
            GTEST_SKIP() << "no pipelineStatisticsQuery: the counters are not checked";
        }
        const profile::ViewStatistics& l = view_of(f.two, "left");
        const profile::ViewStatistics& r = view_of(f.two, "right");
        const profile::ViewStatistics& eyes = view_of(f.one, "eyes");
        print_counters(l, r, eyes, StereoPass::kInstanced);
        EXPECT_EQ(eyes.draws, f.both.size());
        EXPECT_EQ(l.draws + r.draws, f.left.size() + f.right.size());
        EXPECT_EQ(eyes.input_primitives, 2 * (triangles(scene, f.both) + 1));
        EXPECT_EQ(eyes.geometry_invocations, 0u);
        EXPECT_EQ(eyes.geometry_primitives, 0u);
        EXPECT_EQ(eyes.fragment_invocations, l.fragment_invocations + r.fragment_invocations);
        EXPECT_GT(eyes.vertex_invocations, 0u);
        if (same_lists) {
            EXPECT_EQ(eyes.vertex_invocations, l.vertex_invocations + r.vertex_invocations);
            EXPECT_EQ(eyes.input_primitives, l.input_primitives + r.input_primitives);
        } else {
            // The union is right's list: right's pass drawn twice.
            EXPECT_EQ(eyes.vertex_invocations, 2 * r.vertex_invocations);
            EXPECT_EQ(eyes.input_primitives, 2 * r.input_primitives);
        }
    }
}

// 5. MSAA 4x. This check found that lavapipe 22.3 resolves MSAA into layer 0 of a layered image
// only; two-pass stereo now keeps an image per eye.
TEST_F(SinglePassStereo, GeometryShaderStereoWithMsaaEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    expect_msaa_equal(StereoPass::kGeometryShader);
}

// 6. TAA in hybrid.
TEST_F(SinglePassStereo, GeometryShaderHybridWithTaaEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    expect_hybrid_taa_equal(StereoPass::kGeometryShader);
}

// 7. The routing debug view.
TEST_F(SinglePassStereo, GeometryShaderRoutingViewEqualsTwoPasses) {
    if (!has_geometry_shader()) GTEST_SKIP() << "the device has no geometry shader";
    expect_routing_equal(StereoPass::kGeometryShader);
}

// 8. Instanced stereo (Unity's Single Pass Instanced, Unreal's Instanced Stereo): every draw of the
// both-eyes list has two instances, the vertex shader takes the eye from the instance and writes
// its layer. Its images are two passes' in every scene and configuration the geometry shader's
// are checked in.
TEST_F(SinglePassStereo, InstancedStereoEqualsTwoPasses) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    expect_stereo_equal(StereoPass::kInstanced);
}

TEST_F(SinglePassStereo, InstancedHybridEqualsTwoPasses) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    expect_hybrid_equal(StereoPass::kInstanced);
}

TEST_F(SinglePassStereo, InstancedStereoWithMsaaEqualsTwoPasses) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    expect_msaa_equal(StereoPass::kInstanced);
}

TEST_F(SinglePassStereo, InstancedHybridWithTaaEqualsTwoPasses) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    expect_hybrid_taa_equal(StereoPass::kInstanced);
}

TEST_F(SinglePassStereo, InstancedRoutingViewEqualsTwoPasses) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    expect_routing_equal(StereoPass::kInstanced);
}

// The depth pre-pass runs the instanced vertex shader without a fragment shader: the shading
// pipeline after it must find, per layer, exactly the depths it left.
TEST_F(SinglePassStereo, InstancedStereoWithDepthPrepassEqualsTwoPasses) {
    if (!has_instanced_stereo())
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    modes::RendererOptions options = options_with(StereoPass::kTwoPasses);
    options.depth_prepass = true;
    expect_stereo_equal(StereoPass::kInstanced, options);
}

}  // namespace
}  // namespace monoplane
