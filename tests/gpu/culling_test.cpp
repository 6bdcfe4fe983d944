// GPU chunk culling (renderer/passes/culling) checked on counters, never on times: which chunks
// each view draws (read-back draw lists and indirect draw counts), the primitives each view's
// pipeline statistics count, and which passes run. Every expected value comes from the
// construction of a small scene, by hand from the rig's equations, or from the CPU reference
// (modes::visible_chunks, double precision) with the same matrices.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "hmd/profile.h"
#include "renderer/modes/frustum_culling.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/modes/scene_resources.h"
#include "renderer/vk/memory.h"
#include "scenes/generate.h"
#include "tests/gpu/frame_checks.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using testing::has_pass;
using testing::max_channel_difference;
using testing::view_of;

using modes::Eye;
using passes::CullView;
using plan::Mode;
using plan::MonoCulling;
using Chunks = std::vector<std::uint32_t>;

// A square headset: both eyes see 45 degrees left, right, up and down. Then C sits s = d / 2
// behind the eyes (eq. 1: where the outer frustum planes cross the axis, d / (2 tan)), and the
// overlap is eps = k s m = 0.064 m per metre of m (eq. 3, k = 2): C's near plane lies 0.936 m
// in front of the eyes per metre of m (7.488 m for m = 8).
constexpr double kIpd = 0.064;
constexpr rig::Tangents kSquare{-1.0, 1.0, -1.0, 1.0};
const glm::dvec3 kHead(0.0, 1.6, 0.0);
constexpr vk::Extent2D kExtent{96, 108};

double square_overlap(double m) {
    return 2.0 * (kIpd / 2.0) * m;
}

rig::Pose standing() {
    rig::Pose head;
    head.position = kHead;
    return head;
}

modes::FrameInputs square_inputs(double m, const rig::Pose& head = standing()) {
    modes::FrameInputs inputs;
    inputs.views.head = head;
    inputs.views.ipd = kIpd;
    inputs.views.left = kSquare;
    inputs.views.right = kSquare;
    inputs.mono_plane = m;
    // The layouts here are placed around the paper's eps (square_overlap); the growth of eps for
    // grazing surfaces is tested in hybrid_accuracy_test.
    inputs.grazing_angle = 0.0;
    return inputs;
}

// A draw list as a set (ascending chunk indices), for tests of which chunks a view drew; the
// order they were drawn in is tested by compare_with_reference.
Chunks sorted(Chunks chunks) {
    std::sort(chunks.begin(), chunks.end());
    return chunks;
}

modes::RendererOptions test_options() {
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    options.read_back_draw_lists = true;
    // These tests count the chunks' full triangles; level of detail's choice has its own tests
    // (lod_test.cpp).
    options.lod.enabled = false;
    return options;
}

std::uint64_t triangles(const scenes::Scene& scene, const Chunks& chunks) {
    std::uint64_t count = 0;
    for (std::uint32_t c : chunks) count += scene.chunks[c].index_count / 3;
    return count;
}

// A square quad facing +z (the viewer at the origin looking down -z), centred at `centre`.
void add_facing_square(scenes::Scene& scene, glm::vec3 centre, float half, int cells = 1) {
    testing::add_quad(scene, centre - glm::vec3(half, half, 0.0f), {2 * half, 0.0f, 0.0f},
                      {0.0f, 2 * half, 0.0f}, scenes::pack_rgba8(0.7f, 0.3f, 0.2f), cells);
}

// Merges the scene's last `count` chunks (appended one after another, as add_quad does) into one
// chunk with `flags`: a chunk whose box is much larger than its pieces, like far terrain.
void merge_last_chunks(scenes::Scene& scene, std::size_t count, std::uint32_t flags) {
    const std::size_t first = scene.chunks.size() - count;
    scenes::Chunk merged = scene.chunks[first];
    for (std::size_t c = first + 1; c < scene.chunks.size(); ++c) {
        const scenes::Chunk& piece = scene.chunks[c];
        // Indices are chunk-relative: rebase each piece onto the first piece's vertex offset.
        const auto shift = static_cast<std::uint32_t>(piece.vertex_offset - merged.vertex_offset);
        for (std::uint32_t i = 0; i < piece.index_count; ++i) {
            scene.indices[piece.first_index + i] += shift;
        }
        merged.index_count += piece.index_count;
        merged.bounds.min = glm::min(merged.bounds.min, piece.bounds.min);
        merged.bounds.max = glm::max(merged.bounds.max, piece.bounds.max);
    }
    merged.flags = flags;
    scene.chunks.resize(first);
    scene.chunks.push_back(merged);
}

class Culling : public testing::GpuTest {
  protected:
    bool statistics() { return ctx().capabilities().pipeline_statistics; }
    bool predicated() { return ctx().capabilities().conditional_rendering; }
};

// 1. Three chunks at m = 8 (C's near plane at 7.488 m): one wholly nearer than m - eps is drawn
// by both eyes only, one wholly beyond m by C only, one straddling the plane by all three.
// Laid out side by side so that none hides another in either eye: nothing is occlusion culled.
scenes::Scene three_depths_scene() {
    scenes::Scene scene;
    // 0: near, at 3 m, left of the axis: 2 x 2 cells, 8 triangles.
    add_facing_square(scene, {-1.0f, 1.6f, -3.0f}, 0.5f, 2);
    // 1: far, at 20 m, right of the axis: 3 x 3 cells, 18 triangles.
    add_facing_square(scene, {4.0f, 1.6f, -20.0f}, 1.0f, 3);
    // 2: a floor strip from 4 to 15 m, a metre below the eyes: 4 x 4 cells, 32 triangles.
    testing::add_quad(scene, {0.5f, 0.6f, -4.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -11.0f},
                      scenes::pack_rgba8(0.4f, 0.5f, 0.3f), 4);
    testing::finish_bounds(scene);
    return scene;
}

TEST_F(Culling, ChunksLandInTheViewsTheirDepthsSelect) {
    const scenes::Scene scene = three_depths_scene();
    ASSERT_LT(3.0, 8.0 - square_overlap(8.0));  // the near chunk ends before C's near plane
    const Chunks near_and_straddling = {0, 2};
    const Chunks far_and_straddling = {1, 2};
    for (MonoCulling variant :
         {MonoCulling::kNoOpt, MonoCulling::kDiscard, MonoCulling::kOcclusionCull}) {
        SCOPED_TRACE(plan::mono_culling_name(variant));
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        modes::FrameInputs inputs = square_inputs(8.0);
        inputs.mono_culling = variant;
        const profile::FrameStats stats = hybrid.render_frame(inputs);
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kLeft)), near_and_straddling);
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kRight)), near_and_straddling);
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kMono)), far_and_straddling);
        if (!statistics()) continue;
        // So the near chunk is drawn twice, the far one once, the straddling one three times.
        EXPECT_EQ(view_of(stats, "left").draws, 2u);
        EXPECT_EQ(view_of(stats, "right").draws, 2u);
        EXPECT_EQ(view_of(stats, "mono").draws, 2u);
        EXPECT_EQ(view_of(stats, "mono").draws_before_occlusion_culling, 2u);  // none hidden

        // The eyes draw their chunks' triangles and nothing else: C has content, so the eyes'
        // own sky (a full-screen triangle under the inverted "C has chunks" predicate) is
        // skipped, and skipped draws count no primitives. (Without conditional rendering the
        // eyes' sky is not even recorded and C's always is: the same counts.)
        for (const char* eye : {"left", "right"}) {
            EXPECT_EQ(view_of(stats, eye).input_primitives, triangles(scene, near_and_straddling))
                << eye;
            EXPECT_EQ(view_of(stats, eye).input_primitives, 8u + 32u) << eye;
        }
        // C draws its chunks' triangles plus its sky, one full-screen triangle: the sky is
        // always C's in hybrid when C has anything to draw. The depth-tested variants add one
        // more full-screen triangle first: the mask of the pixels hidden in both eyes.
        const profile::ViewStatistics& mono = view_of(stats, "mono");
        const std::uint64_t mask = variant == MonoCulling::kNoOpt ? 0u : 1u;
        EXPECT_EQ(mono.input_primitives, triangles(scene, far_and_straddling) + 1 + mask);
        EXPECT_EQ(mono.input_primitives, 18u + 32u + 1u + mask);
        // Each composite is one full-screen triangle that copies C into the eye, and one that
        // tone maps the eye's own pixels: it writes the display image (issue 33).
        for (const char* composite : {"left.composite", "right.composite"}) {
            EXPECT_EQ(view_of(stats, composite).input_primitives, 2u) << composite;
        }
    }
}

// The debug view "routing" colours each chunk by its lists: at the pixel where each chunk of
// the three-depths scene lies (projected by hand through the square frustum), the near chunk is
// green (eyes only), the far one blue (C only, seen through the composite) and the straddling
// strip magenta, in every variant.
TEST_F(Culling, RoutingDebugViewColoursChunksByTheirLists) {
    const scenes::Scene scene = three_depths_scene();
    // Left eye at x = -0.032: tangents of a point (x, 1.6 + dy, -z) are ((x + 0.032) / z, dy / z),
    // pixel ((tan_x + 1) / 2 W, (1 - tan_y) / 2 H).
    auto pixel_of = [](double x, double dy, double z) {
        const double tan_x = (x + kIpd / 2.0) / z;
        const double tan_y = dy / z;
        return glm::ivec2(static_cast<int>((tan_x + 1.0) / 2.0 * kExtent.width),
                          static_cast<int>((1.0 - tan_y) / 2.0 * kExtent.height));
    };
    const glm::ivec2 near_pixel = pixel_of(-1.0, 0.0, 3.0);   // chunk 0's centre
    const glm::ivec2 far_pixel = pixel_of(4.0, 0.0, 20.0);    // chunk 1's centre
    const glm::ivec2 strip_pixel = pixel_of(1.0, -1.0, 5.0);  // chunk 2, 5 m ahead
    for (MonoCulling variant :
         {MonoCulling::kNoOpt, MonoCulling::kDiscard, MonoCulling::kOcclusionCull}) {
        SCOPED_TRACE(plan::mono_culling_name(variant));
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        modes::FrameInputs inputs = square_inputs(8.0);
        inputs.mono_culling = variant;
        inputs.debug = plan::DebugView::kRouting;
        hybrid.render_frame(inputs);
        const modes::RgbaImage& image = hybrid.eye_image(Eye::kLeft);
        auto rgb = [&](glm::ivec2 p) {
            const std::size_t i = (static_cast<std::size_t>(p.y) * image.width + p.x) * 4;
            return glm::ivec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
        };
        const glm::ivec3 near = rgb(near_pixel);
        EXPECT_GT(near.g, near.r + 40);
        EXPECT_GT(near.g, near.b + 40);
        const glm::ivec3 far = rgb(far_pixel);
        EXPECT_GT(far.b, far.r + 40);
        EXPECT_GT(far.b, far.g + 20);
        const glm::ivec3 strip = rgb(strip_pixel);
        EXPECT_GT(strip.r, strip.g + 40);
        EXPECT_GT(strip.b, strip.g + 40);
    }
}

// The plane of `planes` nearest to deciding the box's fate: the smallest |distance| in metres,
// over the planes, of the box's corner furthest along each (normalised) plane normal. The GPU
// tests float planes against float bounds; within a millimetre its answer may differ from the
// double-precision reference without either being wrong.
double decision_margin(const std::array<glm::dvec4, 6>& planes, const scenes::Aabb& box) {
    double margin = std::numeric_limits<double>::infinity();
    for (const glm::dvec4& p : planes) {
        const glm::dvec3 normal(p);
        const double length = glm::length(normal);
        const glm::dvec3 corner(p.x >= 0 ? box.max.x : box.min.x, p.y >= 0 ? box.max.y : box.min.y,
                                p.z >= 0 ? box.max.z : box.min.z);
        margin = std::min(margin, std::abs((glm::dot(normal, corner) + p.w) / length));
    }
    return margin;
}

struct Comparison {
    int compared = 0;
    int borderline = 0;
    int drawn = 0;

    Comparison& operator+=(const Comparison& other) {
        compared += other.compared;
        borderline += other.borderline;
        drawn += other.drawn;
        return *this;
    }
};

// The distance from a viewer to a box (0 inside): the nearest point of the box, axis by axis.
double distance_to_box(const glm::dvec3& viewer, const scenes::Aabb& box) {
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double below = static_cast<double>(box.min[axis]) - viewer[axis];
        const double above = viewer[axis] - static_cast<double>(box.max[axis]);
        const double gap = std::max({below, above, 0.0});
        squared += gap * gap;
    }
    return std::sqrt(squared);
}

// The GPU's list of one view against the CPU reference for the same world -> clip matrix, and
// its order: nearest chunk first as seen from the viewer (ties by index), each chunk once.
Comparison compare_with_reference(const scenes::Scene& scene, const glm::dmat4& view_proj,
                                  const glm::dvec3& viewer, const Chunks& gpu,
                                  const std::string& what) {
    SCOPED_TRACE(what);
    for (std::size_t i = 1; i < gpu.size(); ++i) {
        const double before = distance_to_box(viewer, scene.chunks[gpu[i - 1]].bounds);
        const double after = distance_to_box(viewer, scene.chunks[gpu[i]].bounds);
        EXPECT_TRUE(before < after || (before == after && gpu[i - 1] < gpu[i]))
            << "draw " << i << ": chunk " << gpu[i - 1] << " at " << before << " m before chunk "
            << gpu[i] << " at " << after << " m";
    }
    const std::set<std::uint32_t> distinct(gpu.begin(), gpu.end());
    EXPECT_EQ(distinct.size(), gpu.size());
    const Chunks cpu = modes::visible_chunks(scene, view_proj);
    const std::set<std::uint32_t> on_gpu(gpu.begin(), gpu.end());
    const std::set<std::uint32_t> on_cpu(cpu.begin(), cpu.end());
    const auto planes = modes::frustum_planes(view_proj);
    Comparison result;
    for (std::uint32_t c = 0; c < scene.chunks.size(); ++c) {
        if (decision_margin(planes, scene.chunks[c].bounds) < 1e-3) {
            ++result.borderline;
            continue;
        }
        ++result.compared;
        result.drawn += on_cpu.count(c) ? 1 : 0;
        EXPECT_EQ(on_gpu.count(c), on_cpu.count(c)) << "chunk " << c;
    }
    return result;
}

// 2. The GPU lists equal the CPU reference on the generated test scenes, in stereo (two
// viewpoints) and in hybrid at m = 3 and m = 12 with the rig's matrices.
TEST_F(Culling, GpuListsEqualTheCpuReference) {
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    Comparison total;
    for (scenes::SceneId id :
         {scenes::SceneId::Beams, scenes::SceneId::Landscape, scenes::SceneId::Spheres}) {
        scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test, 7);
        // The reference knows nothing of routing flags (test ForceFlags covers them): with no
        // routing the renderer honours none, so the lists are pure frustum culling.
        scene.routing = {};
        ASSERT_GE(scene.viewpoints.size(), 4u);
        SCOPED_TRACE(scene.name);
        auto vive_inputs = [&](const rig::Pose& head, double m) {
            modes::FrameInputs inputs = testing::profile_inputs(vive, head, m);
            inputs.mono_culling = MonoCulling::kNoOpt;  // C's list is its frustum's alone
            return inputs;
        };
        modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, kExtent, test_options());
        for (const char* name : {"default", "bench-side"}) {
            const scenes::Viewpoint* viewpoint = scene.find_viewpoint(name);
            ASSERT_NE(viewpoint, nullptr) << name;
            const modes::FrameInputs inputs = vive_inputs(viewpoint->head, 1000.0);
            const profile::FrameStats stats = stereo.render_frame(inputs);
            for (Eye eye : {Eye::kLeft, Eye::kRight}) {
                const auto view = static_cast<CullView>(eye);
                const Chunks gpu = stereo.drawn_chunks(view);
                const Comparison c = compare_with_reference(
                    scene, modes::eye_view_proj(inputs.views, eye), viewpoint->head.position, gpu,
                    std::string("stereo ") + name + " " + modes::eye_name(eye));
                if (statistics()) {
                    EXPECT_EQ(view_of(stats, modes::eye_name(eye)).draws, gpu.size());
                }
                total += c;
            }
        }
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        modes::ModeRenderer culled(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        const rig::Pose head = scene.viewpoints.front().head;
        for (double m : {3.0, 12.0}) {
            modes::FrameInputs inputs = vive_inputs(head, m);
            const profile::FrameStats stats = hybrid.render_frame(inputs);
            ASSERT_TRUE(hybrid.last_rig().has_value());
            const rig::Rig& rig = *hybrid.last_rig();
            ASSERT_FALSE(rig.mono_skipped);
            const std::string where = "hybrid m = " + std::to_string(static_cast<int>(m)) + " ";
            for (Eye eye : {Eye::kLeft, Eye::kRight}) {
                const glm::dmat4 view_proj =
                    rig.eye_projection[static_cast<int>(eye)] *
                    rig::view_matrix(head, modes::eye_offset(eye, inputs.views.ipd));
                const Comparison c = compare_with_reference(
                    scene, view_proj, head.position,
                    hybrid.drawn_chunks(static_cast<CullView>(eye)), where + modes::eye_name(eye));
                total += c;
            }
            const glm::dmat4 mono_view_proj =
                rig.mono_projection * rig::view_matrix(head, rig.mono_position);
            const Chunks mono = hybrid.drawn_chunks(CullView::kMono);
            const Comparison c =
                compare_with_reference(scene, mono_view_proj, head.position, mono, where + "mono");
            if (statistics()) {
                EXPECT_EQ(view_of(stats, "mono").draws, mono.size());
            }
            total += c;

            // Occlusion culling only removes chunks from C's frustum list: a subset of it, and
            // the count before it is the frustum list's length.
            inputs.mono_culling = MonoCulling::kOcclusionCull;
            const profile::FrameStats culled_stats = culled.render_frame(inputs);
            const Chunks after = sorted(culled.drawn_chunks(CullView::kMono));
            const Chunks before = sorted(mono);
            EXPECT_TRUE(std::includes(before.begin(), before.end(), after.begin(), after.end()))
                << where;
            if (statistics()) {
                const profile::ViewStatistics& culled_mono = view_of(culled_stats, "mono");
                EXPECT_EQ(culled_mono.draws_before_occlusion_culling, mono.size()) << where;
                EXPECT_EQ(culled_mono.draws, after.size()) << where;
            }
        }
    }
    std::cout << "chunk decisions compared " << total.compared << " (drawn " << total.drawn
              << "), within 1 mm of a plane and left out " << total.borderline << "\n";
    // The comparison has substance: many decisions, both ways, few left out.
    EXPECT_GT(total.drawn, 100);
    EXPECT_GT(total.compared - total.drawn, 100);
    EXPECT_LT(total.borderline, total.compared / 100 + 1);
}

// 3. A wall 3 m ahead hides everything behind it in both eyes except past its right edge: the
// chunks behind it are occlusion culled, those past the edge are not.
struct OcclusionScene {
    scenes::Scene scene;
    Chunks hidden;   // behind the wall in both eyes, by construction
    Chunks visible;  // past the wall's edge
};

OcclusionScene occlusion_scene() {
    OcclusionScene s;
    // Chunk 0, the wall: x from -8 to 0.6 m, y from -5 to 8 m, at 3 m. Both eyes (tangents up to
    // 1) see it across their whole height and from their left border to the tangent
    // (0.6 +- 0.032) / 3 ~ 0.19..0.21 of its right edge; everything left of that is wall.
    testing::add_quad(s.scene, {-8.0f, -5.0f, -3.0f}, {8.6f, 0.0f, 0.0f}, {0.0f, 13.0f, 0.0f},
                      scenes::pack_rgba8(0.5f, 0.5f, 0.5f), 4);
    // Behind it, small squares (tangent half-size 0.02: about two pixels wide) at tangents
    // x in [-0.9, -0.4] and y in [-0.5, 0.5]: 0.57 or more (27 eye pixels, over 3 texels of C's
    // pyramid, 4 x 4 pixels each at its finest level) inside the wall's silhouette, so every eye
    // pixel that would read them from C shows the wall, however the conservative lookup rounds
    // (it reads at most 2 x 2 texels around a box).
    for (double depth : {20.0, 30.0, 45.0, 60.0}) {
        for (double tx : {-0.9, -0.65, -0.4}) {
            for (double ty : {-0.5, 0.0, 0.5}) {
                s.hidden.push_back(static_cast<std::uint32_t>(s.scene.chunks.size()));
                const glm::dvec3 centre = kHead + depth * glm::dvec3(tx, ty, -1.0);
                add_facing_square(s.scene, glm::vec3(centre), static_cast<float>(0.02 * depth));
            }
        }
    }
    // Beside it, past its edge at tangents 0.6 and 0.8 (0.37 or more from the edge), with sky
    // around them: C must draw these. 2 x 2 cells each, to tell them apart in the counts.
    for (double depth : {25.0, 50.0}) {
        for (double tx : {0.6, 0.8}) {
            s.visible.push_back(static_cast<std::uint32_t>(s.scene.chunks.size()));
            const glm::dvec3 centre = kHead + depth * glm::dvec3(tx, 0.2, -1.0);
            add_facing_square(s.scene, glm::vec3(centre), static_cast<float>(0.02 * depth), 2);
        }
    }
    testing::finish_bounds(s.scene);
    return s;
}

TEST_F(Culling, OcclusionCullingDrawsOnlyWhatTheWallDoesNotHide) {
    const OcclusionScene s = occlusion_scene();
    const scenes::Scene& scene = s.scene;
    Chunks beyond_the_plane = s.hidden;
    beyond_the_plane.insert(beyond_the_plane.end(), s.visible.begin(), s.visible.end());
    std::sort(beyond_the_plane.begin(), beyond_the_plane.end());
    // Hidden: 36 squares of 2 triangles; visible: 4 of 8.
    ASSERT_EQ(triangles(scene, s.hidden), 72u);
    ASSERT_EQ(triangles(scene, s.visible), 32u);

    struct Result {
        profile::FrameStats stats;
        Chunks mono;
        std::array<modes::RgbaImage, 2> eyes;
    };
    auto render = [&](MonoCulling variant) {
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        modes::FrameInputs inputs = square_inputs(8.0);
        inputs.mono_culling = variant;
        Result r;
        r.stats = hybrid.render_frame(inputs);
        r.mono = sorted(hybrid.drawn_chunks(CullView::kMono));
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            // Only the wall is nearer than m.
            EXPECT_EQ(sorted(hybrid.drawn_chunks(static_cast<CullView>(eye))), Chunks{0})
                << plan::mono_culling_name(variant);
            r.eyes[static_cast<int>(eye)] = hybrid.eye_image(eye);
        }
        return r;
    };
    const Result no_opt = render(MonoCulling::kNoOpt);
    const Result discard = render(MonoCulling::kDiscard);
    const Result culled = render(MonoCulling::kOcclusionCull);

    // Frustum culling alone keeps everything beyond the plane; occlusion culling keeps exactly
    // the squares past the wall's edge.
    EXPECT_EQ(no_opt.mono, beyond_the_plane);
    EXPECT_EQ(discard.mono, beyond_the_plane);
    EXPECT_EQ(culled.mono, s.visible);
    EXPECT_TRUE(has_pass(culled.stats, "occlusion_culling"));
    EXPECT_FALSE(has_pass(discard.stats, "occlusion_culling"));
    EXPECT_TRUE(has_pass(discard.stats, "depth_pyramid"));
    EXPECT_FALSE(has_pass(no_opt.stats, "depth_pyramid"));

    if (statistics()) {
        EXPECT_EQ(view_of(no_opt.stats, "mono").draws, 40u);
        EXPECT_EQ(view_of(discard.stats, "mono").draws, 40u);
        EXPECT_EQ(view_of(culled.stats, "mono").draws, 4u);
        EXPECT_EQ(view_of(culled.stats, "mono").draws_before_occlusion_culling, 40u);
        // C's chunks plus its sky triangle: discard shades fewer fragments but draws the same
        // chunks, and one full-screen triangle more, the mask of the pixels hidden in both eyes.
        EXPECT_EQ(view_of(no_opt.stats, "mono").input_primitives, 72u + 32u + 1u);
        EXPECT_EQ(view_of(discard.stats, "mono").input_primitives, 72u + 32u + 1u + 1u);
        EXPECT_EQ(view_of(culled.stats, "mono").input_primitives, 32u + 1u + 1u);
    }
    // What C saves must not show: the eyes' images are the same in all three variants.
    for (int e = 0; e < 2; ++e) {
        SCOPED_TRACE(e == 0 ? "left" : "right");
        EXPECT_LE(max_channel_difference(no_opt.eyes[e], discard.eyes[e]), 1);
        EXPECT_LE(max_channel_difference(no_opt.eyes[e], culled.eyes[e]), 1);
    }
}

// 4 (a). Nothing beyond m - eps: C's list is empty, so on the GPU C's draws, its sky and both
// composites are skipped and the eyes draw their own sky; the images are stereo's.
TEST_F(Culling, NothingBeyondThePlaneSkipsCAndTheComposites) {
    if (!predicated()) GTEST_SKIP() << "no VK_EXT_conditional_rendering: no pass is skipped";
    scenes::Scene scene;
    add_facing_square(scene, {-0.8f, 1.4f, -2.0f}, 0.3f, 2);
    add_facing_square(scene, {0.5f, 1.9f, -2.9f}, 0.4f, 3);
    testing::add_quad(scene, {-1.0f, 0.8f, -1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.9f},
                      scenes::pack_rgba8(0.4f, 0.5f, 0.3f), 2);
    testing::finish_bounds(scene);
    ASSERT_GT(-scene.bounds.max.z, 0.9f);
    ASSERT_LT(-scene.bounds.min.z, 3.0f);  // everything within 3 m, C's near plane at 7.488 m

    const modes::FrameInputs inputs = square_inputs(8.0);
    modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, kExtent, test_options());
    modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
    stereo.render_frame(inputs);
    const profile::FrameStats stats = hybrid.render_frame(inputs);
    EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kMono)), Chunks{});
    EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kLeft)), (Chunks{0, 1, 2}));
    EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kRight)), (Chunks{0, 1, 2}));
    if (statistics()) {
        // Recorded (the command buffer serves every culling outcome) and skipped on the GPU.
        for (const char* name : {"mono", "left.composite", "right.composite"}) {
            EXPECT_EQ(view_of(stats, name).input_primitives, 0u) << name;
            EXPECT_EQ(view_of(stats, name).fragment_invocations, 0u) << name;
        }
        // The eyes: their chunks and their own sky triangle.
        for (const char* eye : {"left", "right"}) {
            EXPECT_EQ(view_of(stats, eye).input_primitives, triangles(scene, {0, 1, 2}) + 1) << eye;
        }
    }
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        EXPECT_LE(max_channel_difference(stereo.eye_image(eye), hybrid.eye_image(eye)), 1)
            << modes::eye_name(eye);
    }
}

// 4 (b). Nothing nearer than m: the eyes' lists are empty and their sky is C's, so the eyes'
// views count no primitives and no fragments (the composite fills them).
TEST_F(Culling, NothingNearerThanThePlaneLeavesTheEyesIdle) {
    if (!predicated()) GTEST_SKIP() << "no VK_EXT_conditional_rendering: no pass is skipped";
    scenes::Scene scene;
    add_facing_square(scene, {-6.0f, 1.6f, -30.0f}, 2.0f, 2);
    add_facing_square(scene, {8.0f, 4.0f, -45.0f}, 3.0f, 2);
    testing::add_quad(scene, {-20.0f, 0.0f, -30.0f}, {40.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -40.0f},
                      scenes::pack_rgba8(0.4f, 0.5f, 0.3f), 4);
    testing::finish_bounds(scene);
    ASSERT_GE(-scene.bounds.max.z, 30.0f);

    // No eye content means no depth pyramid: C draws its chunks without it in every variant.
    for (MonoCulling variant :
         {MonoCulling::kNoOpt, MonoCulling::kDiscard, MonoCulling::kOcclusionCull}) {
        SCOPED_TRACE(plan::mono_culling_name(variant));
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        modes::FrameInputs inputs = square_inputs(8.0);
        inputs.mono_culling = variant;
        const profile::FrameStats stats = hybrid.render_frame(inputs);
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kLeft)), Chunks{});
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kRight)), Chunks{});
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kMono)), (Chunks{0, 1, 2}));
        if (!statistics()) continue;
        for (const char* eye : {"left", "right"}) {
            EXPECT_EQ(view_of(stats, eye).input_primitives, 0u) << eye;
            EXPECT_EQ(view_of(stats, eye).fragment_invocations, 0u) << eye;
        }
        // C: its chunks and its sky; each composite: two full-screen triangles (C's pixels, and
        // the eye's own tone mapped: it writes the display image).
        EXPECT_EQ(view_of(stats, "mono").input_primitives, triangles(scene, {0, 1, 2}) + 1);
        for (const char* composite : {"left.composite", "right.composite"}) {
            EXPECT_EQ(view_of(stats, composite).input_primitives, 2u) << composite;
        }
    }
}

// 5. Routing flags, honoured only where decide_routing proves them harmless.
//
// Force mono: a chunk of two pieces outside the vertical cylinder of radius R about the y axis,
// one 10 m ahead and one 7 m to the right at 1 m depth, outside the eyes' view: its box spans
// depths 1 to 10 m and so crosses m = 3 (eyes: 0.1..3 m, C: from 2.808 m). The flag is honoured
// when (R - |head_xz| - d / 2) cos(theta) >= m, where theta is the widest angle of the square
// frusta (cos = 1 / sqrt(1 + 1 + 1)): R = 6 gives 3.45 >= 3, R = 4 gives 2.29 < 3.
scenes::Scene force_mono_scene(float radius) {
    scenes::Scene scene;
    for (std::uint32_t flags : {scenes::kChunkForceMono, scenes::kChunkNone}) {
        // The unflagged twin, half a metre lower, is drawn by all three views either way.
        const float y = flags == scenes::kChunkNone ? 0.5f : 1.0f;
        testing::add_quad(scene, {-1.0f, y, -10.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.4f, 0.0f},
                          scenes::pack_rgba8(0.6f, 0.6f, 0.2f), 2);
        testing::add_quad(scene, {7.0f, y, -1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.4f, 0.0f},
                          scenes::pack_rgba8(0.6f, 0.6f, 0.2f), 1);
        merge_last_chunks(scene, 2, flags);
    }
    testing::finish_bounds(scene);
    scene.routing.force_mono_outside_radius = radius;
    return scene;
}

// Force stereo: with the head turned 45 degrees left, a chunk of three pieces within 6.24 m of
// the head (one 3 m ahead, one 6 m along -x, one 6 m along -z) has a box whose far corner lies
// 6.2 sqrt(2) = 8.8 m ahead, beyond C's near plane m - eps = 7.488 m for m = 8. Honoured when
// |head - centre| + r + d / 2 <= m - eps: r = 6.3 gives 6.33, r = 7.6 gives 7.63 (too far).
scenes::Scene force_stereo_scene(float radius, const rig::Pose& head) {
    scenes::Scene scene;
    const glm::dvec3 forward = head.orientation * glm::dvec3(0.0, 0.0, -1.0);
    const glm::dvec3 right = head.orientation * glm::dvec3(1.0, 0.0, 0.0);
    const glm::vec3 ahead(head.position + 3.0 * forward - 0.2 * right - glm::dvec3(0, 0.2, 0));
    const std::uint32_t albedo = scenes::pack_rgba8(0.2f, 0.6f, 0.6f);
    testing::add_quad(scene, ahead, glm::vec3(0.4 * right), {0.0f, 0.4f, 0.0f}, albedo, 2);
    testing::add_quad(scene, {-6.2f, 1.4f, -0.6f}, {0.4f, 0.0f, 0.0f}, {0.0f, 0.4f, 0.0f}, albedo);
    testing::add_quad(scene, {-0.6f, 1.4f, -5.8f}, {0.0f, 0.4f, 0.0f}, {0.0f, 0.0f, -0.4f}, albedo);
    merge_last_chunks(scene, 3, scenes::kChunkForceStereo);
    testing::finish_bounds(scene);
    scene.routing.force_stereo_inside_radius = radius;
    scene.routing.force_stereo_centre = glm::vec3(head.position);
    return scene;
}

TEST_F(Culling, ForceFlagsAreHonouredOnlyWhereHarmless) {
    {
        SCOPED_TRACE("force mono, honoured (R = 6, m = 3)");
        const scenes::Scene scene = force_mono_scene(6.0f);
        for (const scenes::Vertex& v : scene.vertices) {
            ASSERT_GE(glm::length(glm::vec2(v.position.x, v.position.z)), 7.0f);
        }
        const scenes::Aabb& box = scene.chunks[0].bounds;
        ASSERT_LT(-box.max.z, 3.0f - square_overlap(3.0));  // the box straddles the plane
        ASSERT_GT(-box.min.z, 3.0f);
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        hybrid.render_frame(square_inputs(3.0));
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kLeft)), Chunks{1});
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kRight)), Chunks{1});
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kMono)), (Chunks{0, 1}));
    }
    {
        SCOPED_TRACE("force mono, radius too small to honour (R = 4, m = 3)");
        const scenes::Scene scene = force_mono_scene(4.0f);
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        hybrid.render_frame(square_inputs(3.0));
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kLeft)), (Chunks{0, 1}));
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kRight)), (Chunks{0, 1}));
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kMono)), (Chunks{0, 1}));
    }
    rig::Pose turned;
    turned.position = kHead;
    turned.orientation = rig::orientation_from_yaw_pitch(std::acos(-1.0) / 4.0, 0.0);
    const glm::dvec3 forward = turned.orientation * glm::dvec3(0.0, 0.0, -1.0);
    ASSERT_NEAR(forward.x, -std::sqrt(0.5), 1e-9);  // 45 degrees left of -z
    ASSERT_NEAR(forward.z, -std::sqrt(0.5), 1e-9);
    for (float radius : {6.3f, 7.6f}) {
        const bool honoured = radius < 7.0f;
        SCOPED_TRACE("force stereo, r = " + std::to_string(radius));
        const scenes::Scene scene = force_stereo_scene(radius, turned);
        for (const scenes::Vertex& v : scene.vertices) {
            ASSERT_LE(glm::length(glm::dvec3(v.position) - kHead), 6.25);
        }
        // The box's corner farthest ahead lies beyond C's near plane.
        const scenes::Aabb& box = scene.chunks[0].bounds;
        const double farthest = glm::dot(glm::dvec3(box.min.x, 1.6, box.min.z) - kHead, forward);
        ASSERT_GT(farthest, 8.0 - square_overlap(8.0) + 0.5);
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, kExtent, test_options());
        hybrid.render_frame(square_inputs(8.0, turned));
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kLeft)), Chunks{0});
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kRight)), Chunks{0});
        EXPECT_EQ(sorted(hybrid.drawn_chunks(CullView::kMono)), honoured ? Chunks{} : Chunks{0});
    }
}

// 6. Work not repeated: the shadow map is drawn only when the light's region changes, so a
// second frame from the same pose has no shadow pass; the culling pass always comes first.
TEST_F(Culling, SecondFrameFromTheSamePoseDrawsNoShadowMap) {
    const scenes::Scene scene = three_depths_scene();
    for (Mode mode : {Mode::kStereo, Mode::kHybrid}) {
        SCOPED_TRACE(plan::mode_name(mode));
        modes::ModeRenderer renderer(ctx(), scene, mode, kExtent, test_options());
        const profile::FrameStats first = renderer.render_frame(square_inputs(8.0));
        const profile::FrameStats second = renderer.render_frame(square_inputs(8.0));
        ASSERT_FALSE(first.passes.empty());
        ASSERT_FALSE(second.passes.empty());
        EXPECT_EQ(first.passes.front().name, "culling");
        EXPECT_EQ(second.passes.front().name, "culling");
        EXPECT_TRUE(has_pass(first, "shadow"));
        EXPECT_FALSE(has_pass(second, "shadow"));
        // The second frame still draws every list (stereo: all three chunks lie within f).
        EXPECT_EQ(sorted(renderer.drawn_chunks(CullView::kLeft)),
                  mode == Mode::kStereo ? Chunks({0, 1, 2}) : Chunks({0, 2}));
        EXPECT_EQ(sorted(renderer.drawn_chunks(CullView::kMono)),
                  mode == Mode::kStereo ? Chunks{} : Chunks({1, 2}));
    }
}

// A study's renderers of one scene (one per alternative) share its upload: the second renderer
// costs the scene's vertex and index bytes less than one with its own copy, and the shadow map
// one renderer drew serves the next from the same pose.
TEST_F(Culling, RenderersOfOneSceneShareItsUploadAndShadowMap) {
    const scenes::Scene scene = three_depths_scene();
    const std::uint64_t geometry_bytes = scene.vertices.size() * sizeof(scenes::Vertex) +
                                         scene.indices.size() * sizeof(std::uint32_t);
    ASSERT_GT(geometry_bytes, 0u);

    std::uint64_t before = vk_core::live_device_bytes();
    modes::ModeRenderer own(ctx(), scene, Mode::kHybrid, kExtent, test_options());
    const std::uint64_t own_bytes = vk_core::live_device_bytes() - before;

    auto shared = std::make_shared<modes::SceneResources>(ctx(), scene, test_options().shadow);
    modes::ModeRenderer stereo(ctx(), shared, Mode::kStereo, kExtent, test_options());
    before = vk_core::live_device_bytes();
    modes::ModeRenderer hybrid(ctx(), shared, Mode::kHybrid, kExtent, test_options());
    const std::uint64_t shared_bytes = vk_core::live_device_bytes() - before;
    EXPECT_LE(shared_bytes + geometry_bytes, own_bytes)
        << "own " << own_bytes << " B, shared " << shared_bytes << " B";

    // The stereo renderer draws the shadow map; the hybrid one, from the same pose, reuses it
    // and shows what a renderer that drew its own shows.
    const profile::FrameStats first = stereo.render_frame(square_inputs(8.0));
    const profile::FrameStats second = hybrid.render_frame(square_inputs(8.0));
    const profile::FrameStats reference = own.render_frame(square_inputs(8.0));
    EXPECT_TRUE(has_pass(first, "shadow"));
    EXPECT_FALSE(has_pass(second, "shadow"));
    EXPECT_TRUE(has_pass(reference, "shadow"));
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        EXPECT_EQ(hybrid.eye_image(eye).pixels, own.eye_image(eye).pixels) << modes::eye_name(eye);
    }

    // Resources made for other shadow parameters are refused.
    modes::RendererOptions other = test_options();
    other.shadow.resolution = 512;
    EXPECT_THROW(modes::ModeRenderer(ctx(), shared, Mode::kStereo, kExtent, other), UserError);
}

// --variant auto measures the three variants on the frames it renders, interleaved, then keeps
// one; every frame shows what no-opt shows (the variants draw identical images).
TEST_F(Culling, AutoVariantTriesEachVariantAndChangesNoPixel) {
    const scenes::Scene scene = three_depths_scene();
    modes::ModeRenderer automatic(ctx(), scene, Mode::kHybrid, kExtent, test_options());
    modes::ModeRenderer reference(ctx(), scene, Mode::kHybrid, kExtent, test_options());
    modes::FrameInputs inputs = square_inputs(8.0);
    modes::FrameInputs reference_inputs = inputs;
    inputs.mono_culling = MonoCulling::kAuto;
    reference_inputs.mono_culling = MonoCulling::kNoOpt;
    const int trial = plan::VariantChooserParams{}.rounds_per_trial * 3;
    for (int frame = 0; frame < trial + 2; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame));
        automatic.render_frame(inputs);
        reference.render_frame(reference_inputs);
        const MonoCulling used = automatic.last_variant();
        if (frame < trial) {
            EXPECT_EQ(used, plan::VariantChooser::kCandidates[static_cast<std::size_t>(frame % 3)]);
        }
        EXPECT_NE(used, MonoCulling::kAuto);
        // The plan follows the variant in use.
        const plan::PlannedPass* pyramid =
            automatic.last_plan().find(plan::PassKind::kDepthPyramid);
        ASSERT_NE(pyramid, nullptr);
        EXPECT_EQ(!pyramid->skipped.has_value(), used != MonoCulling::kNoOpt);
        for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
            EXPECT_EQ(automatic.eye_image(eye).pixels, reference.eye_image(eye).pixels);
        }
    }
}

// The depth pre-pass (RendererOptions::depth_prepass) shades each pixel once; it must not change
// what is shown: the same images on every scene in stereo, hybrid (with C's hidden-pixel mask)
// and single-pass stereo. The counters show the pre-pass ran: a forward pass then clips its
// chunks twice.
TEST_F(Culling, DepthPrepassChangesNoPixel) {
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    for (scenes::SceneId id :
         {scenes::SceneId::Beams, scenes::SceneId::Landscape, scenes::SceneId::Spheres}) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        SCOPED_TRACE(scene.name);
        const modes::FrameInputs inputs =
            testing::profile_inputs(vive, scene.find_viewpoint("default")->head, 8.0);
        for (const auto& [mode, pass] :
             {std::pair{Mode::kStereo, plan::StereoPass::kTwoPasses},
              std::pair{Mode::kHybrid, plan::StereoPass::kTwoPasses},
              std::pair{Mode::kStereo, plan::StereoPass::kGeometryShader}}) {
            SCOPED_TRACE(plan::render_mode_name({mode, pass}));
            modes::RendererOptions options = test_options();
            options.stereo_pass = pass;
            modes::ModeRenderer plain(ctx(), scene, mode, kExtent, options);
            options.depth_prepass = true;
            modes::ModeRenderer prepassed(ctx(), scene, mode, kExtent, options);
            const profile::FrameStats without = plain.render_frame(inputs);
            const profile::FrameStats with = prepassed.render_frame(inputs);
            for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
                EXPECT_EQ(
                    testing::max_channel_difference(plain.eye_image(eye), prepassed.eye_image(eye)),
                    0)
                    << modes::eye_name(eye);
            }
            if (!statistics()) continue;
            const char* view = pass == plan::StereoPass::kTwoPasses ? "left" : "eyes";
            // The sky's full-screen triangle is drawn once; the chunks twice with the pre-pass.
            const std::uint64_t sky = mode == Mode::kStereo ? 1u : 0u;
            EXPECT_EQ(view_of(with, view).input_primitives - sky,
                      2 * (view_of(without, view).input_primitives - sky));
        }
    }
}

}  // namespace
}  // namespace monoplane
